#include "ColumnTable.h"

#include "Fields.h"

#include <osgGlyphsData/Elements>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

using namespace osgGlyphsData;
using namespace osgGlyphsData::readers;

namespace
{

bool withinFloatRange(double value)
{
    return std::abs(value) <= std::numeric_limits<float>::max(); // false for NaN
}

// Whether value takes a column with that origin back to plain values: it is farther from the
// origin than from zero, or its offset is out of the range of a float.
bool needsPlainValues(double origin, double value)
{
    const double offset = value - origin;
    return origin != 0.0 && (std::abs(offset) > std::abs(value) || !withinFloatRange(offset));
}

// The atomic number of a species label: a symbol, or the number itself; 0 when unknown.
unsigned int elementNumber(const std::string& label)
{
    uint64_t number = 0;
    if (parseUInt64(label, number))
        return number <= getMaxAtomicNumber() ? static_cast<unsigned int>(number) : 0u;
    return getElementBySymbol(label).number;
}

} // namespace

std::vector<std::string> osgGlyphsData::readers::componentNames(const std::string& name, std::size_t count)
{
    std::vector<std::string> names;
    if (count == 1)
    {
        names.push_back(name);
    }
    else if (count == 3)
    {
        for (const char* axis : {"_x", "_y", "_z"})
            names.push_back(name + axis);
    }
    else
    {
        for (std::size_t i = 0; i < count; ++i)
            names.push_back(name + "_" + std::to_string(i));
    }
    return names;
}

ColumnTable::ColumnTable(TextScanner& scanner, const PointShare& share)
    : _scanner(scanner), _rows(0), _share(share)
{
}

void ColumnTable::setRowCount(uint64_t rows)
{
    _hasRowCount = true;
    _range = getShareRange(_share, rows);
}

std::size_t ColumnTable::addColumn(const std::string& name, Kind kind)
{
    if (_columns.size() >= MaxColumns)
        _scanner.fail("more than " + std::to_string(MaxColumns) + " columns");
    std::vector<std::string> outputs;
    if (kind == Species)
        outputs = {"element", "species"};
    else
        outputs = {name};
    for (const std::string& output : outputs)
    {
        if (output.empty())
            _scanner.fail("empty column name");
        if (_outputNames.count(output))
            _scanner.fail("duplicate column " + quote(output));
    }
    _outputNames.insert(outputs.begin(), outputs.end());
    Column column;
    column.name = name;
    column.kind = kind;
    _columns.push_back(std::move(column));
    return _columns.size() - 1;
}

void ColumnTable::reserve(std::size_t rows)
{
    if (_hasRowCount)
        rows = static_cast<std::size_t>(std::min<uint64_t>(rows, _range.end - _range.begin));
    for (Column& column : _columns)
        column.values.reserve(rows);
}

void ColumnTable::failFieldCount(std::size_t fieldCount) const
{
    std::string names;
    for (std::size_t i = 0; i < _columns.size() && i < 12; ++i)
        names += (i ? " " : "") + _columns[i].name;
    if (_columns.size() > 12)
        names += " ...";
    _scanner.fail("wrong number of columns: " + std::to_string(fieldCount) + " fields, expected " +
                  std::to_string(_columns.size()) + " (" + names + ")");
}

void ColumnTable::appendRow(std::string_view line)
{
    const char* p = line.data();
    const char* end = p + line.size();
    const std::size_t count = _columns.size();
    if (count > 0 && !keeps(_columns[0].seen))
    {
        if (_columns[0].seen == 0)
        {
            std::vector<std::string_view> fields;
            splitBlanks(line, fields);
            chooseOrigins(fields);
        }
        for (Column& column : _columns)
            ++column.seen;
        return;
    }
    for (std::size_t c = 0; c < count; ++c)
    {
        p = skipBlanks(p, end);
        if (p == end)
            failFieldCount(countFields(line));
        Column& column = _columns[c];
        if (column.kind == Number)
        {
            // The fast path: parse in place, then check that the field ends there.
            const char* start = p;
            if (*p == '+')
                ++p;
            double value = 0.0;
            const fast_float::from_chars_result result = fast_float::from_chars(p, end, value);
            if (result.ec == std::errc() && result.ptr > p && (result.ptr == end || isBlank(*result.ptr)) &&
                withinFloatRange(value))
            {
                appendNumber(column, value);
                ++column.seen;
                p = result.ptr;
                continue;
            }
            p = start;
        }
        const char* stop = skipField(p, end);
        appendField(c, std::string_view(p, static_cast<std::size_t>(stop - p)));
        p = stop;
    }
    if (skipBlanks(p, end) != end)
        failFieldCount(countFields(line));
}

uint64_t ColumnTable::getNextKeptRow(uint64_t row, uint64_t end) const
{
    uint64_t next = row;
    if (_hasRowCount)
        next = row < _range.begin ? _range.begin : row < _range.end ? row : end;
    else if (row % _share.count != _share.index)
        next =
            row - row % _share.count + _share.index + (row % _share.count > _share.index ? _share.count : 0);
    return std::min(next, end);
}

uint64_t ColumnTable::getKeptRun(uint64_t row, uint64_t end) const
{
    if (row >= end || !keeps(row))
        return 0;
    if (_hasRowCount)
        return std::min(_range.end, end) - row;
    return _share.count == 1 ? end - row : 1;
}

void ColumnTable::skipRows(uint64_t count)
{
    for (Column& column : _columns)
        column.seen += count;
}

void ColumnTable::readRows(uint64_t done, uint64_t count, const std::string& section,
                           std::string_view stopMarker)
{
    std::string_view line;
    for (uint64_t row = done; row < count; ++row)
    {
        if (!_scanner.nextLine(line))
            _scanner.failEndOfFile(": " + section + " has " + std::to_string(row) + " of " +
                                   std::to_string(count) + " rows");
        if (!stopMarker.empty() && startsWith(trim(line), stopMarker))
            _scanner.fail(quote(trim(line)) + " after " + std::to_string(row) + " of " +
                          std::to_string(count) + " rows of " + section);
        appendRow(line);
    }
}

void ColumnTable::appendField(std::size_t index, std::string_view field)
{
    Column& column = _columns[index];
    const uint64_t row = column.seen++;
    double value = 0.0;
    if (!keeps(row))
    {
        if (row == 0 && column.kind == Number)
            chooseOrigin(column, field);
        return;
    }
    switch (column.kind)
    {
    case Number:
        if (!parseDouble(field, value) || !withinFloatRange(value))
            _scanner.fail(describeBadNumber(field, column.name));
        appendNumber(column, value);
        break;
    case Logical:
    {
        const std::string lower = toLower(field);
        if (lower == "t" || lower == "true" || lower == "1")
            column.values.push_back(1.0f);
        else if (lower == "f" || lower == "false" || lower == "0")
            column.values.push_back(0.0f);
        else
            _scanner.fail("column '" + column.name + "': " + quote(field) +
                          " is not a logical value (T or F)");
        break;
    }
    case Species:
    case Category:
        if (field.empty())
            _scanner.fail("column '" + column.name + "': empty field");
        appendLabel(column, field);
        break;
    }
}

void ColumnTable::chooseOrigin(Column& column, double value)
{
    column.originChosen = true;
    if (withinFloatRange(value) && std::abs(value) >= FarFromZero)
        column.origin = std::round(value);
}

void ColumnTable::chooseOrigin(Column& column, std::string_view field)
{
    double value = 0.0;
    column.originChosen = true;
    if (parseDouble(field, value))
        chooseOrigin(column, value);
}

void ColumnTable::chooseOrigins(const std::vector<std::string_view>& fields)
{
    for (std::size_t c = 0; c < _columns.size() && c < fields.size(); ++c)
    {
        if (_columns[c].kind == Number)
            chooseOrigin(_columns[c], fields[c]);
    }
}

void ColumnTable::appendNumber(Column& column, double value)
{
    if (!column.originChosen)
        chooseOrigin(column, value);
    if (needsPlainValues(column.origin, value))
    {
        // Values farther from the origin than from zero: the origin no longer helps, the column
        // goes back to plain values.
        for (float& stored : column.values)
            stored = static_cast<float>(column.origin + stored);
        column.origin = 0.0;
    }
    column.values.push_back(static_cast<float>(value - column.origin));
}

void ColumnTable::appendLabel(Column& column, std::string_view field)
{
    auto found = column.indices.find(field);
    if (found != column.indices.end())
    {
        column.values.push_back(found->second);
        return;
    }
    if (column.labels.size() >= MaxLabels)
        _scanner.fail("column '" + column.name + "': more than " + std::to_string(MaxLabels) +
                      " distinct labels");
    const float index = static_cast<float>(column.labels.size());
    column.labels.emplace_back(field);
    column.indices.emplace(std::string(field), index);
    column.values.push_back(index);
}

void ColumnTable::appendValue(std::size_t index, double value, uint64_t offset)
{
    Column& column = _columns[index];
    const uint64_t row = column.seen++;
    if (!keeps(row))
    {
        if (row == 0)
            chooseOrigin(column, value);
        return;
    }
    if (!withinFloatRange(value))
    {
        std::ostringstream text;
        text << "column '" << column.name << "': ";
        if (std::isfinite(value))
            text << "value " << value << " is out of the range of a float";
        else
            text << "value " << value << " is not a finite number";
        _scanner.failAtByte(offset, text.str());
    }
    appendNumber(column, value);
}

std::size_t ColumnTable::appendRows(const double* values, std::size_t rows)
{
    if (_columns.empty())
        return 0;
    const uint64_t row = _columns[0].seen;
    const std::size_t size = _columns[0].values.size();
    for (const Column& column : _columns)
    {
        if (column.kind != Number || !column.originChosen || column.seen != row ||
            column.values.size() != size)
            return 0;
    }
    // Row 0 chooses the origins: appendValue() appends it.
    std::size_t done = row == 0 ? 0 : static_cast<std::size_t>(getKeptRun(row, row + rows));
    for (std::size_t c = 0; c < _columns.size() && done > 0; ++c)
    {
        Column& column = _columns[c];
        const double origin = column.origin;
        const double* in = values + c * rows;
        column.values.resize(size + done);
        float* out = column.values.data() + size;
        for (std::size_t r = 0; r < done; ++r)
        {
            if (!withinFloatRange(in[r]) || needsPlainValues(origin, in[r]))
            {
                done = r; // the rows before it in the other columns too
                break;
            }
            out[r] = static_cast<float>(in[r] - origin);
        }
    }
    for (Column& column : _columns)
    {
        column.values.resize(size + done);
        column.seen += done;
    }
    return done;
}

osg::ref_ptr<PointData> ColumnTable::finish()
{
    osg::ref_ptr<PointData> data = new PointData(getNumRows());
    std::string error;
    for (Column& column : _columns)
    {
        if (column.kind == Species)
        {
            std::vector<float> numbers(column.labels.size());
            for (std::size_t i = 0; i < numbers.size(); ++i)
                numbers[i] = static_cast<float>(elementNumber(column.labels[i]));
            std::vector<float> elements(column.values.size());
            for (std::size_t i = 0; i < elements.size(); ++i)
                elements[i] = numbers[static_cast<std::size_t>(column.values[i])];
            data->addColumn("element", std::move(elements), error);
            data->addColumn("species", std::move(column.values), error);
            data->setColumnLabels("species", std::move(column.labels));
        }
        else
        {
            data->addColumn(column.name, std::move(column.values), error);
            data->setColumnOrigin(column.name, column.origin);
            if (column.kind == Category)
                data->setColumnLabels(column.name, std::move(column.labels));
        }
    }
    return data;
}
