#include "H5mdConnectivity.h"

#include "ListedBonds.h"

#include <cmath>
#include <unordered_map>

using namespace osgGlyphsData;
using namespace osgGlyphsHdf5::detail;

namespace
{

const Element* findElement(const ParticleGroup& group, const std::string& name)
{
    for (const Element& element : group.elements)
        if (element.name == name)
            return &element;
    return nullptr;
}

std::vector<hsize_t> leadingAt(const Element& element, int64_t step, const Place& place)
{
    return element.timed ? std::vector<hsize_t>{indexAt(element, step, place)} : std::vector<hsize_t>{};
}

/** The group's rows by id at step. */
std::unordered_map<int64_t, uint32_t> rowsById(const ParticleGroup& group, int64_t step, const Place& place)
{
    const Element& ids = *findElement(group, "id");
    if (!ids.problem.empty())
        place.fail(ids.problemDataset, ids.problem);
    std::unordered_map<int64_t, uint32_t> rows;
    rows.reserve(static_cast<std::size_t>(group.count()));
    readRows(ids.value, leadingAt(ids, step, place), 0, group.count(), place,
             RowSink<double>(
                 [&rows, &ids, &place](hsize_t row, const double* values, hsize_t count)
                 {
                     for (hsize_t i = 0; i < count; ++i)
                     {
                         const auto [at, added] =
                             rows.emplace(static_cast<int64_t>(values[i]), static_cast<uint32_t>(row + i));
                         if (!added)
                             place.fail(ids.value.path, "id " + std::to_string(at->first) +
                                                            " is held by rows " + std::to_string(at->second) +
                                                            " and " + std::to_string(row + i) +
                                                            ": bonds cannot name them");
                     }
                 }));
    return rows;
}

}

std::vector<PairList> osgGlyphsHdf5::detail::describeConnectivity(hid_t file,
                                                                  const std::vector<ParticleGroup>& groups,
                                                                  std::vector<std::string>& warnings,
                                                                  const Place& place)
{
    std::vector<PairList> lists;
    if (objectType(file, "/connectivity") != H5O_TYPE_GROUP)
        return lists;
    for (const std::string& name : listMembers(file, "/connectivity", place))
    {
        const std::string path = "/connectivity/" + name;
        try
        {
            PairList list;
            list.pairs = describeElement(file, path, ElementKind::Numbers, place);
            if (list.pairs.value.typeClass != H5T_INTEGER)
                place.fail(list.pairs.value.path, "holds no integers: not particle indices");
            if (list.pairs.width() != 2)
            {
                warnings.push_back(place.describe(path, "tuples of " + std::to_string(list.pairs.width()) +
                                                            " particles, not bonds: left out"));
                continue;
            }
            std::string group = groups.size() == 1 ? "/particles/" + groups.front().name : std::string();
            if (hasAttribute(file, path, "particles_group"))
                group = readObjectReference(file, path, "particles_group", place);
            if (group.empty())
                place.fail(path, "names no particles_group, and the file has several");
            list.group = groups.size();
            for (std::size_t g = 0; g < groups.size(); ++g)
                if (group == "/particles/" + groups[g].name)
                    list.group = g;
            if (list.group == groups.size())
                place.fail(path, "refers to " + group + ", not a particle group read");
            list.byId = findElement(groups[list.group], "id") != nullptr;
            list.hasFill = readIntegerFillValue(list.pairs.value, list.fill);
            lists.push_back(std::move(list));
        }
        catch (const Hdf5Error& failure)
        {
            warnings.push_back(failure.message + ": its bonds are left out");
        }
    }
    return lists;
}

bool osgGlyphsHdf5::detail::isFixedConnectivity(const std::vector<PairList>& lists,
                                                const std::vector<ParticleGroup>& groups)
{
    for (const PairList& list : lists)
    {
        const Element* ids = list.byId ? findElement(groups[list.group], "id") : nullptr;
        if (list.pairs.timed || (ids && ids->timed))
            return false;
    }
    return true;
}

std::shared_ptr<const PointData::BondList>
osgGlyphsHdf5::detail::readConnectivity(const std::vector<PairList>& lists,
                                        const std::vector<ParticleGroup>& groups, int64_t step,
                                        const PointRange& range, const Place& place)
{
    std::vector<hsize_t> firstRow(groups.size(), 0);
    hsize_t total = 0;
    for (std::size_t g = 0; g < groups.size(); ++g)
    {
        firstRow[g] = total;
        total += groups[g].count();
    }
    if (total >= NOT_IN_FRAME)
        place.fail("/particles", std::to_string(total) + " particles: too many for a bond list");
    std::vector<std::pair<uint32_t, uint32_t>> rows;
    for (const PairList& list : lists)
    {
        const ParticleGroup& group = groups[list.group];
        const std::string& dataset = list.pairs.value.path;
        std::unordered_map<int64_t, uint32_t> byId;
        if (list.byId)
            byId = rowsById(group, step, place);
        const auto rowOf = [&](int64_t value, hsize_t pair) -> uint32_t
        {
            if (list.byId)
            {
                const auto row = byId.find(value);
                if (row == byId.end())
                    place.fail(dataset, "pair " + std::to_string(pair) + " names id " +
                                            std::to_string(value) + ", which no particle of /particles/" +
                                            group.name + " has");
                return static_cast<uint32_t>(firstRow[list.group] + row->second);
            }
            if (value < 0 || static_cast<uint64_t>(value) >= group.count())
                place.fail(dataset, "pair " + std::to_string(pair) + " names particle " +
                                        std::to_string(value) + ", past the " +
                                        std::to_string(group.count()) + " particles of /particles/" +
                                        group.name);
            return static_cast<uint32_t>(firstRow[list.group] + static_cast<hsize_t>(value));
        };
        readRows(list.pairs.value, leadingAt(list.pairs, step, place), 0, list.pairs.rows(), place,
                 RowSink<double>(
                     [&](hsize_t first, const double* values, hsize_t count)
                     {
                         for (hsize_t i = 0; i < count; ++i)
                         {
                             const int64_t a = static_cast<int64_t>(values[2 * i]);
                             const int64_t b = static_cast<int64_t>(values[2 * i + 1]);
                             if (list.hasFill && (a == list.fill || b == list.fill))
                                 continue;
                             const uint32_t rowA = rowOf(a, first + i), rowB = rowOf(b, first + i);
                             if (rowA == rowB)
                                 place.fail(dataset, "pair " + std::to_string(first + i) +
                                                         " bonds particle " + std::to_string(a) +
                                                         " to itself");
                             rows.emplace_back(rowA, rowB);
                         }
                     }));
    }
    std::vector<uint32_t> frameIndexOfRow(static_cast<std::size_t>(total), NOT_IN_FRAME);
    for (uint64_t row = range.begin; row < range.end; ++row)
        frameIndexOfRow[static_cast<std::size_t>(row)] = static_cast<uint32_t>(row - range.begin);
    return makeListedBonds(rows, frameIndexOfRow);
}
