#include "Hdf5Particles.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <set>
#include <sstream>

using namespace osgGlyphsData;
using namespace osgGlyphsHdf5::detail;

namespace
{

/** The particles' values of a column in the frame being read, offsets from origin. */
struct OutColumn
{
    std::vector<float> values;
    double origin = 0.0;
    bool originChosen = false;
};

using OutColumns = std::map<std::string, OutColumn>;

const std::map<std::string, std::string>& vectorPrefixes()
{
    static const std::map<std::string, std::string> prefixes = {
        {"position", ""}, {"Coordinates", ""}, {"velocity", "v"}, {"Velocities", "v"},
        {"force", "f"},   {"Forces", "f"},     {"image", "i"},    {"Accelerations", "a"}};
    return prefixes;
}

const std::map<std::string, std::string>& scalarNames()
{
    static const std::map<std::string, std::string> names = {
        {"id", "id"},         {"ParticleIDs", "id"}, {"mass", "mass"},   {"Masses", "mass"},
        {"charge", "charge"}, {"Charges", "charge"}, {"species", "type"}};
    return names;
}

template <typename T>
std::vector<T> readSeries(hid_t file, const std::string& path, hsize_t count, const std::string& valuePath,
                          const Place& place)
{
    const DatasetInfo info = describeDataset(file, path, place);
    requireNumbers(info, place);
    std::vector<T> series(static_cast<std::size_t>(count));
    if (info.dims.empty())
    {
        // A fixed interval: value i at offset + i * interval (the offset attribute, 0 without it).
        const std::vector<double> interval = readAllDoubles(info, 1, place);
        const double offset = hasAttribute(file, path, "offset")
                                  ? readAttributeNumbers(file, path, "offset", 1, place).at(0)
                                  : 0.0;
        for (std::size_t i = 0; i < series.size(); ++i)
        {
            const double value = offset + double(i) * interval[0];
            // A step beyond int64 (or not finite) cannot be converted: an error, not a wrapped step.
            if constexpr (!std::is_same_v<T, double>)
            {
                if (!(std::fabs(value) < 9.2e18))
                    place.fail(path, "gives step " + std::to_string(value) + " to value " +
                                         std::to_string(i) + ", beyond a 64-bit integer");
            }
            series[i] = static_cast<T>(value);
        }
        return series;
    }
    if (info.dims.size() != 1 || info.dims[0] != count)
        place.fail(path, "holds " + std::to_string(info.countFrom(0)) + " values for the " +
                             std::to_string(count) + " of " + valuePath);
    if constexpr (std::is_same_v<T, double>)
        return readAllDoubles(info, count, place);
    else
        return readAllIntegers(info, count, place);
}

void checkIncreasing(const std::vector<int64_t>& steps, const std::string& path, const Place& place)
{
    for (std::size_t i = 1; i < steps.size(); ++i)
    {
        if (steps[i] < steps[i - 1])
            place.fail(path, "step " + std::to_string(steps[i]) + " at index " + std::to_string(i) +
                                 " comes after step " + std::to_string(steps[i - 1]));
    }
}

void checkWidth(const Element& element, const Place& place)
{
    const hsize_t width = element.width();
    if (element.kind == ElementKind::Position && width != 2 && width != 3)
        place.fail(element.value.path,
                   "has " + std::to_string(width) + " values a particle; positions have 2 or 3");
    if (element.kind == ElementKind::Species && width != 1)
        place.fail(element.value.path, "has " + std::to_string(width) + " values a particle; species have 1");
    if (width == 0 || width > MaxWidth)
        place.fail(element.value.path, "has " + std::to_string(width) + " values a particle; 1 to " +
                                           std::to_string(MaxWidth) + " are read");
}

/** Values from here on lose decimals as floats that a double origin keeps (a float near 1000 is
 * good to about 6e-5). */
constexpr double FarFromZero = 1000.0;

/** The origin of each column of a double-precision element far from zero: its first particle's
 * value, rounded, so that every share chooses the same. Columns already chosen by an earlier group keep
 * theirs. */
void chooseOrigins(const Element& element, const std::vector<hsize_t>& leading, OutColumns& columns,
                   const Place& place)
{
    bool open = false;
    for (const std::string& name : element.columns)
        open = open || !columns[name].originChosen;
    if (!open)
        return;
    std::vector<double> first(element.columns.size(), 0.0);
    if (element.value.isWide() && element.kind != ElementKind::Species && element.rows() > 0)
        readRows(element.value, leading, 0, 1, place,
                 RowSink<double>([&first](hsize_t, const double* values, hsize_t)
                                 { std::copy(values, values + first.size(), first.begin()); }));
    for (std::size_t c = 0; c < element.columns.size(); ++c)
    {
        OutColumn& column = columns[element.columns[c]];
        if (column.originChosen)
            continue;
        column.originChosen = true;
        if (std::isfinite(first[c]) && std::fabs(first[c]) >= FarFromZero && std::fabs(first[c]) < 1e300)
            column.origin = std::round(first[c]);
    }
}

[[noreturn]] void failNotFinite(const Element& element, hsize_t row, const Place& place)
{
    place.fail(element.value.path,
               "the position of particle " + std::to_string(row) + " is not a finite number");
}

/** Whether a value is a finite number: a comparison that also fails for NaN. */
template <typename T>
bool isFinite(T value)
{
    return std::fabs(value) <= std::numeric_limits<T>::max();
}

/** Whether every value is finite: no value has the exponent bits all set (infinity, NaN), tested
 * on the bits so that the loop vectorises. */
template <typename T>
bool allFinite(const T* values, std::size_t count)
{
    using Bits = std::conditional_t<sizeof(T) == 4, uint32_t, uint64_t>;
    const Bits exponent = sizeof(T) == 4 ? Bits(0x7f800000u) : Bits(0x7ff0000000000000ull);
    unsigned int bad = 0;
    for (std::size_t i = 0; i < count; ++i)
    {
        Bits bits;
        std::memcpy(&bits, values + i, sizeof(bits));
        bad |= (bits & exponent) == exponent;
    }
    return bad == 0;
}

/** Spreads rows of width values into the columns at targets, less the columns' origins. */
template <typename T>
void spreadRows(const T* values, std::size_t rows, const std::vector<OutColumn*>& targets, std::size_t at)
{
    const std::size_t width = targets.size();
    bool offsets = false;
    for (const OutColumn* target : targets)
        offsets = offsets || target->origin != 0.0;
    if (width == 3 && !offsets)
    {
        float* x = targets[0]->values.data() + at;
        float* y = targets[1]->values.data() + at;
        float* z = targets[2]->values.data() + at;
        for (std::size_t r = 0; r < rows; ++r)
        {
            x[r] = static_cast<float>(values[3 * r]);
            y[r] = static_cast<float>(values[3 * r + 1]);
            z[r] = static_cast<float>(values[3 * r + 2]);
        }
        return;
    }
    for (std::size_t c = 0; c < width; ++c)
    {
        float* target = targets[c]->values.data() + at;
        const T origin = static_cast<T>(targets[c]->origin);
        for (std::size_t r = 0; r < rows; ++r)
            target[r] = static_cast<float>(values[r * width + c] - origin);
    }
}

/** Copies rows into the element's columns at out (the frame's row of the segment's first). */
template <typename T>
void copyRows(const Element& element, const std::vector<hsize_t>& leading, hsize_t begin, hsize_t end,
              std::size_t out, OutColumns& columns, const Place& place)
{
    std::vector<OutColumn*> targets;
    for (const std::string& name : element.columns)
        targets.push_back(&columns[name]);
    const bool positions = element.kind == ElementKind::Position;
    RowSink<T> sink = [&](hsize_t row, const T* values, hsize_t rows)
    {
        const std::size_t count = static_cast<std::size_t>(rows) * targets.size();
        if (positions && !allFinite(values, count))
        {
            std::size_t bad = 0;
            while (isFinite(values[bad]))
                ++bad;
            failNotFinite(element, row + bad / targets.size(), place);
        }
        spreadRows(values, static_cast<std::size_t>(rows), targets,
                   out + static_cast<std::size_t>(row - begin));
    };
    readRows(element.value, leading, begin, end, place, sink);
}

std::vector<const Element*> elementsOf(const ParticleGroup& group)
{
    std::vector<const Element*> elements = {&group.position};
    for (const Element& element : group.elements)
        elements.push_back(&element);
    return elements;
}

void checkRows(const Element& element, const ParticleGroup& group, const Place& place)
{
    if (!element.problem.empty())
        place.fail(element.problemDataset, element.problem);
    if (element.rows() != group.count())
        place.fail(element.value.path, "holds " + std::to_string(element.rows()) + " values for the " +
                                           std::to_string(group.count()) + " particles of " +
                                           group.position.value.path);
}

std::vector<hsize_t> leadingAt(const Element& element, int64_t step, const Place& place)
{
    if (!element.timed)
        return {};
    return {indexAt(element, step, place)};
}

void readInto(const Element& element, const std::vector<hsize_t>& leading, hsize_t begin, hsize_t end,
              std::size_t out, OutColumns& columns, const Place& place)
{
    // Floats as they are (HDF5 converts nothing); anything else through doubles.
    if (element.value.isFloat32())
        copyRows<float>(element, leading, begin, end, out, columns, place);
    else
        copyRows<double>(element, leading, begin, end, out, columns, place);
}

std::string labelOf(double value)
{
    std::ostringstream text;
    text.precision(15);
    text << value;
    return text.str();
}

/** "species" from "type" (already in data): the index of each particle's value among the values
 * of the frame, in increasing order. */
void addSpecies(PointData& data, const std::string& name)
{
    const std::vector<float>& type = *data.getColumn("type");
    const double origin = data.getColumnOrigin("type");
    // Particles of a type often follow each other: a value like the one before costs no search.
    std::set<double> distinct;
    float previous = std::numeric_limits<float>::quiet_NaN();
    for (float value : type)
    {
        if (value != previous)
            distinct.insert(origin + double(value));
        previous = value;
    }
    const std::vector<double> ordered(distinct.begin(), distinct.end());
    std::vector<float> species(type.size());
    float previousIndex = 0.0f;
    previous = std::numeric_limits<float>::quiet_NaN();
    for (std::size_t i = 0; i < species.size(); ++i)
    {
        if (type[i] != previous)
        {
            const double value = origin + double(type[i]);
            previousIndex = float(std::lower_bound(ordered.begin(), ordered.end(), value) - ordered.begin());
            previous = type[i];
        }
        species[i] = previousIndex;
    }
    std::vector<std::string> labels;
    for (double value : ordered)
        labels.push_back(labelOf(value));
    data.addColumn(name, std::move(species));
    data.setColumnLabels(name, std::move(labels));
}

bool hasSpecies(const std::vector<ParticleGroup>& groups)
{
    for (const ParticleGroup& group : groups)
    {
        for (const Element& element : group.elements)
        {
            if (element.kind == ElementKind::Species)
                return true;
        }
    }
    return false;
}

}

std::vector<std::string> osgGlyphsHdf5::detail::conventionalColumns(const std::string& name, hsize_t width)
{
    static const char* const axes[3] = {"x", "y", "z"};
    const auto scalar = scalarNames().find(name);
    if (width == 1)
        return {scalar != scalarNames().end() ? scalar->second : name};
    std::vector<std::string> columns;
    const auto prefix = vectorPrefixes().find(name);
    for (hsize_t i = 0; i < width; ++i)
    {
        if (width <= 3 && prefix != vectorPrefixes().end())
            columns.push_back(prefix->second + axes[i]);
        else if (width <= 3)
            columns.push_back(name + "_" + axes[i]);
        else
            columns.push_back(name + "_" + std::to_string(i));
    }
    return columns;
}

Element osgGlyphsHdf5::detail::describeElement(hid_t file, const std::string& path, ElementKind kind,
                                               const Place& place)
{
    Element element;
    element.name = baseName(path);
    element.kind = kind;
    element.timed = objectType(file, path) == H5O_TYPE_GROUP;
    const std::string valuePath = element.timed ? path + "/value" : path;
    element.value = describeDataset(file, valuePath, place);
    requireNumbers(element.value, place);
    if (element.value.dims.size() < element.rowAxis() + 1)
        place.fail(valuePath, "has " + std::to_string(element.value.dims.size()) + " axes; " +
                                  (element.timed ? "a time-dependent value has the time, then the particles"
                                                 : "a per-particle dataset has the particles first"));
    checkWidth(element, place);
    if (element.timed)
    {
        const hsize_t count = element.value.dims[0];
        element.steps = readSeries<int64_t>(file, path + "/step", count, valuePath, place);
        checkIncreasing(element.steps, path + "/step", place);
        element.hasTimes = objectType(file, path + "/time") != H5O_TYPE_UNKNOWN;
        if (element.hasTimes)
            element.times = readSeries<double>(file, path + "/time", count, valuePath, place);
    }
    if (kind == ElementKind::Position)
    {
        // 2-D positions give x and y; z stays 0.
        element.columns = {"x", "y", "z"};
        element.columns.resize(static_cast<std::size_t>(element.width()));
    }
    else
        element.columns = conventionalColumns(element.name, element.width());
    return element;
}

Element osgGlyphsHdf5::detail::brokenElement(const std::string& name, const Hdf5Error& error)
{
    Element element;
    element.name = name;
    element.problemDataset = error.dataset;
    element.problem = error.what;
    return element;
}

hsize_t osgGlyphsHdf5::detail::indexAt(const Element& element, int64_t step, const Place& place)
{
    const auto after = std::upper_bound(element.steps.begin(), element.steps.end(), step);
    if (after == element.steps.begin())
        place.fail(element.value.path, "has no value at step " + std::to_string(step) + " or before it");
    return static_cast<hsize_t>(after - element.steps.begin() - 1);
}

std::vector<std::string> osgGlyphsHdf5::detail::planColumns(const std::vector<ParticleGroup>& groups,
                                                            const std::string& groupColumn,
                                                            const std::string& file,
                                                            std::vector<std::string>& warnings)
{
    std::vector<std::string> order = {"x", "y", "z"};
    auto add = [&order](const std::string& name)
    {
        if (std::find(order.begin(), order.end(), name) == order.end())
            order.push_back(name);
    };
    for (const ParticleGroup& group : groups)
    {
        for (const Element& element : group.elements)
        {
            for (const std::string& name : element.columns)
                add(name);
            if (element.kind == ElementKind::Species)
                add("species");
        }
    }
    for (const ParticleGroup& group : groups)
    {
        std::set<std::string> has = {"x", "y", "z", "species"};
        for (const Element& element : group.elements)
            has.insert(element.columns.begin(), element.columns.end());
        for (const std::string& name : order)
        {
            if (has.count(name) == 0 && name != "species")
            {
                const auto value = group.defaults.find(name);
                warnings.push_back(file + ": " + group.name + " has no " + name + "; its particles get " +
                                   (value != group.defaults.end() ? labelOf(value->second) : "0") +
                                   (value != group.defaults.end() ? " (from the header)" : ""));
            }
        }
    }
    if (groups.size() > 1)
        add(groupColumn);
    return order;
}

osg::ref_ptr<PointData> osgGlyphsHdf5::detail::readParticles(const std::vector<ParticleGroup>& groups,
                                                             const std::vector<std::string>& columns,
                                                             const std::string& groupColumn, int64_t step,
                                                             const PointShare& share, const Place& place)
{
    uint64_t total = 0;
    for (const ParticleGroup& group : groups)
        total += group.count();
    const PointRange range = getShareRange(share, total);
    const std::size_t count = static_cast<std::size_t>(range.end - range.begin);
    OutColumns out;
    for (const std::string& name : columns)
        out[name].values.resize(count);
    // Every group's elements are checked and the origins chosen in every share alike.
    std::vector<std::vector<hsize_t>> leading;
    for (const ParticleGroup& group : groups)
    {
        for (const Element* element : elementsOf(group))
        {
            checkRows(*element, group, place);
            leading.push_back(leadingAt(*element, step, place));
            chooseOrigins(*element, leading.back(), out, place);
        }
    }
    std::vector<float> groupIndex(groups.size() > 1 ? count : 0);
    std::size_t next = 0;
    uint64_t first = 0;
    for (std::size_t g = 0; g < groups.size(); ++g)
    {
        const ParticleGroup& group = groups[g];
        const uint64_t begin = std::max<uint64_t>(first, range.begin) - first;
        const uint64_t end =
            std::max<uint64_t>(std::min<uint64_t>(first + group.count(), range.end), first) - first;
        const std::size_t at = static_cast<std::size_t>(first + begin - range.begin);
        first += group.count();
        const std::vector<const Element*> elements = elementsOf(group);
        if (begin >= end)
        {
            next += elements.size();
            continue;
        }
        std::set<std::string> given;
        for (const Element* element : elements)
        {
            readInto(*element, leading[next++], begin, end, at, out, place);
            given.insert(element->columns.begin(), element->columns.end());
        }
        for (const std::string& name : columns)
        {
            if (given.count(name) || name == "species" || name == groupColumn || !out.count(name))
                continue;
            const auto value = group.defaults.find(name);
            OutColumn& column = out[name];
            std::fill_n(
                column.values.begin() + std::ptrdiff_t(at), end - begin,
                static_cast<float>((value != group.defaults.end() ? value->second : 0.0) - column.origin));
        }
        if (!groupIndex.empty())
            std::fill_n(groupIndex.begin() + std::ptrdiff_t(at), end - begin, static_cast<float>(g));
    }
    osg::ref_ptr<PointData> data = new PointData(count);
    for (const std::string& name : columns)
    {
        if (name == "species" && hasSpecies(groups))
            addSpecies(*data, name);
        else if (name == groupColumn && groups.size() > 1)
        {
            std::vector<std::string> labels;
            for (const ParticleGroup& group : groups)
                labels.push_back(group.name);
            data->addColumn(name, std::move(groupIndex));
            data->setColumnLabels(name, std::move(labels));
        }
        else
        {
            OutColumn& column = out[name];
            data->addColumn(name, std::move(column.values));
            if (column.origin != 0.0)
                data->setColumnOrigin(name, column.origin);
        }
    }
    data->setFilePointCount(total);
    data->setTimestep(step);
    return data;
}
