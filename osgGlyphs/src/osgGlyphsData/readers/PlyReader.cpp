// PLY: ascii, binary_little_endian and binary_big_endian. Scalar properties of element vertex
// become columns; other elements and list properties are read past.

#include "BinaryValues.h"
#include "ColumnTable.h"
#include "Fields.h"
#include "Readers.h"

#include <algorithm>
#include <limits>
#include <set>

using namespace osgGlyphsData;
using namespace osgGlyphsData::readers;

namespace
{

enum class Encoding
{
    Ascii,
    LittleEndian,
    BigEndian
};

struct Property
{
    std::string name;
    bool isList = false;
    ScalarType type = ScalarType::Float32; // of the value, or of the list items
    ScalarType countType = ScalarType::UInt8;
    std::size_t column = std::numeric_limits<std::size_t>::max(); // in the table, for vertex scalars
};

struct Element
{
    std::string name;
    uint64_t count = 0;
    uint64_t line = 0;
    std::vector<Property> properties;
    bool hasLists = false;
    std::size_t fixedSize = 0; // scalars and list counts, in binary
    bool isVertex = false;
    std::set<std::string> propertyNames;
};

struct Header
{
    Encoding encoding = Encoding::Ascii;
    bool hasFormat = false;
    std::vector<Element> elements;
    std::set<std::string> elementNames;
};

bool parseType(std::string_view name, ScalarType& type)
{
    static const struct
    {
        const char* name;
        ScalarType type;
    } types[] = {
        {"char", ScalarType::Int8},       {"int8", ScalarType::Int8},       {"uchar", ScalarType::UInt8},
        {"uint8", ScalarType::UInt8},     {"short", ScalarType::Int16},     {"int16", ScalarType::Int16},
        {"ushort", ScalarType::UInt16},   {"uint16", ScalarType::UInt16},   {"int", ScalarType::Int32},
        {"int32", ScalarType::Int32},     {"uint", ScalarType::UInt32},     {"uint32", ScalarType::UInt32},
        {"float", ScalarType::Float32},   {"float32", ScalarType::Float32}, {"double", ScalarType::Float64},
        {"float64", ScalarType::Float64},
    };
    for (const auto& candidate : types)
    {
        if (name == candidate.name)
        {
            type = candidate.type;
            return true;
        }
    }
    return false;
}

ScalarType requireType(TextScanner& scanner, std::string_view name)
{
    ScalarType type = ScalarType::Float32;
    if (!parseType(name, type))
        scanner.fail("unknown property type " + quote(name) +
                     " (char, uchar, short, ushort, int, uint, float, double or int8 ... float64)");
    return type;
}

void readProperty(TextScanner& scanner, const std::vector<std::string_view>& fields, Header& header)
{
    if (header.elements.empty())
        scanner.fail("'property' before any 'element'");
    Element& element = header.elements.back();
    Property property;
    if (fields.size() == 5 && fields[1] == "list")
    {
        property.isList = true;
        property.countType = requireType(scanner, fields[2]);
        property.type = requireType(scanner, fields[3]);
        if (!isIntegerType(property.countType))
            scanner.fail("the count type of list " + quote(fields[4]) + " must be an integer type");
        element.hasLists = true;
        element.fixedSize += scalarSize(property.countType);
    }
    else if (fields.size() == 3 && fields[1] != "list")
    {
        property.type = requireType(scanner, fields[1]);
        element.fixedSize += scalarSize(property.type);
    }
    else
    {
        scanner.fail("malformed property line: expected 'property <type> <name>' or "
                     "'property list <count type> <item type> <name>'");
    }
    property.name = std::string(fields.back());
    if (!element.propertyNames.insert(property.name).second)
        scanner.fail("duplicate property " + quote(property.name) + " in element " + quote(element.name));
    if (element.properties.size() >= ColumnTable::MaxColumns)
        scanner.fail("element " + quote(element.name) + " has more than " +
                     std::to_string(ColumnTable::MaxColumns) + " properties");
    element.properties.push_back(property);
}

Header readHeader(TextScanner& scanner)
{
    Header header;
    if (trim(scanner.requireLine("'ply'")) != "ply")
        scanner.fail("not a PLY file: the first line must be 'ply'");
    std::string_view line;
    std::vector<std::string_view> fields;
    while (scanner.nextLine(line))
    {
        splitBlanks(line, fields);
        if (fields.empty() || fields[0] == "comment" || fields[0] == "obj_info")
            continue;
        if (fields[0] == "end_header")
        {
            if (!header.hasFormat)
                scanner.fail("the header has no 'format' line");
            return header;
        }
        if (fields[0] == "format")
        {
            if (fields.size() != 3 || (fields[2] != "1.0" && fields[2] != "1"))
                scanner.fail("malformed format line: expected 'format <encoding> 1.0'");
            if (fields[1] == "ascii")
                header.encoding = Encoding::Ascii;
            else if (fields[1] == "binary_little_endian")
                header.encoding = Encoding::LittleEndian;
            else if (fields[1] == "binary_big_endian")
                header.encoding = Encoding::BigEndian;
            else
                scanner.fail("unknown PLY format " + quote(fields[1]) +
                             " (ascii, binary_little_endian or binary_big_endian)");
            header.hasFormat = true;
        }
        else if (fields[0] == "element")
        {
            Element element;
            if (fields.size() != 3 || !parseUInt64(fields[2], element.count))
                scanner.fail("malformed element line: expected 'element <name> <count>'");
            element.name = std::string(fields[1]);
            element.line = scanner.getLineNumber();
            element.isVertex = element.name == "vertex";
            if (!header.elementNames.insert(element.name).second)
                scanner.fail("duplicate element " + quote(element.name));
            header.elements.push_back(element);
        }
        else if (fields[0] == "property")
        {
            readProperty(scanner, fields, header);
        }
        else
        {
            scanner.fail("unknown header keyword " + quote(fields[0]));
        }
    }
    scanner.fail("unexpected end of file in the header: no 'end_header'");
}

// Every element must fit into what follows the header, before anything is reserved.
void checkSizes(TextScanner& scanner, const Header& header)
{
    const uint64_t remaining = scanner.getRemainingBytes();
    uint64_t needed = 0;
    for (const Element& element : header.elements)
    {
        const uint64_t each =
            header.encoding == Encoding::Ascii ? 2 * element.properties.size() : element.fixedSize;
        if (each == 0 || element.count == 0)
            continue;
        if (element.count > (remaining - needed) / each)
            scanner.failAtLine(element.line,
                               "element " + quote(element.name) + " declares " +
                                   std::to_string(element.count) + " items of at least " +
                                   std::to_string(each) + " bytes, but " +
                                   (remaining == std::numeric_limits<uint64_t>::max()
                                        ? std::string("with the elements before it that is more than a "
                                                      "stream can hold (2^64 bytes)")
                                        : "only " + std::to_string(remaining) + " bytes follow the header"));
        needed += element.count * each;
    }
}

class BinaryBody
{
public:
    BinaryBody(TextScanner& scanner, ColumnTable& table, bool bigEndian)
        : _scanner(scanner), _table(table), _bigEndian(bigEndian)
    {
    }

    void read(const Element& element)
    {
        if (!element.hasLists && !element.isVertex)
        {
            const uint64_t start = _scanner.getOffset();
            if (element.fixedSize > 0 &&
                element.count > std::numeric_limits<uint64_t>::max() / element.fixedSize)
                _scanner.failAtByte(start, "element " + quote(element.name) + " is larger than any file");
            if (!_scanner.skipBytes(element.count * element.fixedSize))
                failEnd(element, (_scanner.getOffset() - start) / element.fixedSize);
            return;
        }
        for (uint64_t item = 0; item < element.count;)
        {
            if (element.hasLists)
                readItem(element, item++);
            else if (item == 0)
                readRecord(element, item++); // in every share: it gives the columns their origins
            else if (!_table.keepsRow(item))
                item = skipRecords(element, item);
            else if (const uint64_t done = readRecords(element, item))
                item += done;
            else
                readRecord(element, item++);
        }
    }

private:
    [[noreturn]] void failEnd(const Element& element, uint64_t item)
    {
        _scanner.failAtByte(_scanner.getOffset(), "unexpected end of file: element " + quote(element.name) +
                                                      " has " + std::to_string(item) + " of " +
                                                      std::to_string(element.count) + " items");
    }

    // A vertex without lists: one fixed-size record.
    void readRecord(const Element& element, uint64_t item)
    {
        const char* record = _scanner.peekBytes(element.fixedSize);
        if (!record)
            failEnd(element, item);
        const uint64_t offset = _scanner.getOffset();
        std::size_t at = 0;
        for (const Property& property : element.properties)
        {
            _table.appendValue(property.column, decodeScalar(record + at, property.type, _bigEndian),
                               offset + at);
            at += scalarSize(property.type);
        }
        _scanner.consume(element.fixedSize);
    }

    // Fixed-size vertex records from item on, as many as the table keeps one after the other and
    // the scanner holds (at most BlockValues values), decoded column by column and appended at
    // once; returns how many. 0 when record item has to be read value by value (readRecord()).
    uint64_t readRecords(const Element& element, uint64_t item)
    {
        const char* records = _scanner.peekBytes(element.fixedSize);
        if (!records)
            failEnd(element, item);
        const std::size_t rows = static_cast<std::size_t>(
            std::min<uint64_t>({_scanner.getAvailableBytes() / element.fixedSize,
                                std::max<uint64_t>(BlockValues / element.properties.size(), 1),
                                _table.getKeptRun(item, element.count)}));
        _values.resize(rows * element.properties.size());
        std::size_t at = 0;
        for (const Property& property : element.properties)
        {
            decodeScalars(records + at, element.fixedSize, rows, property.type, _bigEndian,
                          _values.data() + property.column * rows);
            at += scalarSize(property.type);
        }
        const std::size_t done = _table.appendRows(_values.data(), rows);
        _scanner.consume(done * element.fixedSize);
        return done;
    }

    // Fixed-size vertex records from item up to the next the share holds (or the end), unread;
    // returns that next item. Record 0 is read in every share: it gives the columns their origins.
    uint64_t skipRecords(const Element& element, uint64_t item)
    {
        const uint64_t next = _table.getNextKeptRow(item, element.count);
        const uint64_t start = _scanner.getOffset();
        if (!_scanner.skipBytes((next - item) * element.fixedSize))
            failEnd(element, item + (_scanner.getOffset() - start) / element.fixedSize);
        _table.skipRows(next - item);
        return next;
    }

    // An item with lists, property by property.
    void readItem(const Element& element, uint64_t item)
    {
        for (const Property& property : element.properties)
        {
            const uint64_t offset = _scanner.getOffset();
            if (!property.isList)
            {
                const char* value = _scanner.peekBytes(scalarSize(property.type));
                if (!value)
                    failEnd(element, item);
                if (element.isVertex)
                    _table.appendValue(property.column, decodeScalar(value, property.type, _bigEndian),
                                       offset);
                _scanner.consume(scalarSize(property.type));
                continue;
            }
            const char* countBytes = _scanner.peekBytes(scalarSize(property.countType));
            uint64_t count = 0;
            if (!countBytes)
                failEnd(element, item);
            if (!decodeCount(countBytes, property.countType, _bigEndian, count))
                _scanner.failAtByte(offset, "list " + quote(property.name) + " of element " +
                                                quote(element.name) + " has a negative count");
            _scanner.consume(scalarSize(property.countType));
            const uint64_t itemSize = scalarSize(property.type);
            if (count > _scanner.getMaxItems(itemSize) ||
                count > std::numeric_limits<uint64_t>::max() / itemSize ||
                !_scanner.skipBytes(count * itemSize))
                _scanner.failAtByte(offset, "list " + quote(property.name) + " of element " +
                                                quote(element.name) + " has " + std::to_string(count) +
                                                " items, more than the rest of the file holds");
        }
    }

    // Values decoded at once: 32 KiB.
    static constexpr std::size_t BlockValues = 4096;

    TextScanner& _scanner;
    ColumnTable& _table;
    bool _bigEndian;
    std::vector<double> _values; // of readRecords(), column after column
};

void readAsciiItem(TextScanner& scanner, ColumnTable& table, const Element& element, std::string_view line,
                   std::vector<std::string_view>& fields)
{
    if (element.isVertex && !element.hasLists)
    {
        table.appendRow(line);
        return;
    }
    splitBlanks(line, fields);
    std::size_t at = 0;
    for (const Property& property : element.properties)
    {
        if (at >= fields.size())
            scanner.fail("element " + quote(element.name) + ": too few values, " + quote(property.name) +
                         " is missing");
        uint64_t count = 1;
        if (property.isList && !parseUInt64(fields[at++], count))
            scanner.fail("list " + quote(property.name) + ": " + quote(fields[at - 1]) + " is not a count");
        if (count > fields.size() - at)
            scanner.fail("list " + quote(property.name) + " declares " + std::to_string(count) +
                         " items, the line has " + std::to_string(fields.size() - at) + " values left");
        for (uint64_t i = 0; i < count; ++i, ++at)
        {
            double value = 0.0;
            if (element.isVertex && !property.isList)
                table.appendField(property.column, fields[at]);
            else if (!parseDouble(fields[at], value))
                scanner.fail("property " + quote(property.name) + ": " + quote(fields[at]) +
                             " is not a number");
        }
    }
    if (at != fields.size())
        scanner.fail("element " + quote(element.name) + ": " + std::to_string(fields.size()) +
                     " values, more than its properties take (" + std::to_string(at) + ")");
}

void readAsciiBody(TextScanner& scanner, ColumnTable& table, const std::vector<Element>& elements)
{
    std::vector<std::string_view> fields;
    std::string_view line;
    for (const Element& element : elements)
    {
        if (element.properties.empty())
            continue;
        for (uint64_t item = 0; item < element.count;)
        {
            if (!scanner.nextLine(line))
                scanner.fail("unexpected end of file: element " + quote(element.name) + " has " +
                             std::to_string(item) + " of " + std::to_string(element.count) + " items");
            if (trim(line).empty())
                continue;
            readAsciiItem(scanner, table, element, line, fields);
            ++item;
        }
    }
    while (scanner.nextLine(line))
    {
        if (!trim(line).empty())
            scanner.fail("data after the last element: the header declares fewer items than the file has");
    }
}

} // namespace

void osgGlyphsData::readers::readPly(TextScanner& scanner, PointDataset& dataset,
                                     const PointReadOptions& options)
{
    Header header = readHeader(scanner);
    Element* vertex = nullptr;
    for (Element& element : header.elements)
    {
        if (element.isVertex)
            vertex = &element;
    }
    if (!vertex)
        scanner.fail("the header has no 'element vertex'");
    if (vertex->properties.empty() && vertex->count > 0)
        scanner.failAtLine(vertex->line, "element 'vertex' has no properties");
    checkSizes(scanner, header);

    ColumnTable table(scanner, options.share);
    table.setRowCount(vertex->count);
    for (Property& property : vertex->properties)
    {
        if (!property.isList)
            property.column = table.addColumn(property.name);
    }
    const uint64_t minBytes =
        header.encoding == Encoding::Ascii ? 2 * vertex->properties.size() : vertex->fixedSize;
    table.reserve(scanner.boundedReserve(vertex->count, minBytes));

    if (header.encoding == Encoding::Ascii)
    {
        readAsciiBody(scanner, table, header.elements);
    }
    else
    {
        BinaryBody body(scanner, table, header.encoding == Encoding::BigEndian);
        for (const Element& element : header.elements)
            body.read(element);
        if (!scanner.atEnd())
        {
            const uint64_t offset = scanner.getOffset();
            const uint64_t extra = scanner.getRemainingBytes();
            scanner.failAtByte(
                offset, (extra == std::numeric_limits<uint64_t>::max() ? std::string("data")
                                                                       : std::to_string(extra) + " bytes") +
                            " after the last element: the header declares less data than the file has");
        }
    }
    if (table.getNumColumns() == 0)
        table.addEmptyRows(vertex->count);
    osg::ref_ptr<PointData> frame = table.finish();
    frame->setFilePointCount(vertex->count);
    addOnlyFrame(scanner, dataset, options, frame.get());
}
