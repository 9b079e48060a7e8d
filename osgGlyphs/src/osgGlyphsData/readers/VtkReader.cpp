// Legacy VTK, ASCII or BINARY (big-endian), DATASET POLYDATA or UNSTRUCTURED_GRID: POINTS and
// POINT_DATA become columns; cells, cell data and lookup tables are read past.

#include "BinaryValues.h"
#include "ColumnTable.h"
#include "Fields.h"
#include "Readers.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>

using namespace osgGlyphsData;
using namespace osgGlyphsData::readers;

namespace
{

bool parseVtkType(std::string_view name, ScalarType& type)
{
    static const struct
    {
        const char* name;
        ScalarType type;
    } types[] = {
        {"char", ScalarType::Int8},
        {"unsigned_char", ScalarType::UInt8},
        {"short", ScalarType::Int16},
        {"unsigned_short", ScalarType::UInt16},
        {"int", ScalarType::Int32},
        {"unsigned_int", ScalarType::UInt32},
        {"long", ScalarType::Int64},
        {"unsigned_long", ScalarType::UInt64},
        {"float", ScalarType::Float32},
        {"double", ScalarType::Float64},
        {"vtkidtype", ScalarType::Int32},
        {"vtktypeint8", ScalarType::Int8},
        {"vtktypeuint8", ScalarType::UInt8},
        {"vtktypeint16", ScalarType::Int16},
        {"vtktypeuint16", ScalarType::UInt16},
        {"vtktypeint32", ScalarType::Int32},
        {"vtktypeuint32", ScalarType::UInt32},
        {"vtktypeint64", ScalarType::Int64},
        {"vtktypeuint64", ScalarType::UInt64},
        {"vtktypefloat32", ScalarType::Float32},
        {"vtktypefloat64", ScalarType::Float64},
    };
    const std::string lower = toLower(name);
    for (const auto& candidate : types)
    {
        if (lower == candidate.name)
        {
            type = candidate.type;
            return true;
        }
    }
    return false;
}

// VTK writes blanks and other special characters in names as %XX.
std::string decodeName(std::string_view name)
{
    std::string decoded;
    for (std::size_t i = 0; i < name.size(); ++i)
    {
        const auto hex = [](char c) -> int
        {
            if (c >= '0' && c <= '9')
                return c - '0';
            if (c >= 'a' && c <= 'f')
                return c - 'a' + 10;
            if (c >= 'A' && c <= 'F')
                return c - 'A' + 10;
            return -1;
        };
        if (name[i] == '%' && i + 2 < name.size() && hex(name[i + 1]) >= 0 && hex(name[i + 2]) >= 0)
        {
            decoded += static_cast<char>(hex(name[i + 1]) * 16 + hex(name[i + 2]));
            i += 2;
        }
        else
        {
            decoded += name[i];
        }
    }
    return decoded;
}

/** The magnitudes of a section's floating-point values. Read in the wrong byte order, values
 * have random exponents: some are subnormal or not finite, and they lie many decades apart. */
class MagnitudeSpread
{
public:
    void add(double value, ScalarType type)
    {
        if (value == 0.0)
            return;
        const int kind =
            type == ScalarType::Float32 ? std::fpclassify(static_cast<float>(value)) : std::fpclassify(value);
        if (kind != FP_NORMAL)
        {
            _abnormal = true;
            return;
        }
        _smallest = std::min(_smallest, std::fabs(value));
        _largest = std::max(_largest, std::fabs(value));
    }

    /** Values no data set holds: not finite, subnormal, or more than 40 decades apart. */
    bool isAbsurd() const { return _abnormal || _largest > 1e40 * _smallest; }

    /** Values as data sets hold them: normal and within 20 decades. */
    bool isPlausible() const { return !_abnormal && !(_largest > 1e20 * _smallest); }

    /** "<smallest> and <largest>" magnitude, 0 and 0 when every value is zero. */
    std::string describe() const
    {
        std::ostringstream text;
        text.precision(3);
        if (_largest > 0.0)
            text << _smallest << " and " << _largest;
        else
            text << "0 and 0";
        return text.str();
    }

private:
    bool _abnormal = false;
    double _smallest = std::numeric_limits<double>::infinity();
    double _largest = 0.0;
};

class VtkReader
{
public:
    /** Arrays of more components per tuple are refused (a header of garbage, usually). */
    static constexpr uint64_t MaxComponents = 1024;

    VtkReader(TextScanner& scanner, const PointShare& share) : _scanner(scanner), _table(scanner, share) {}

    osg::ref_ptr<PointData> read()
    {
        readHeader();
        while (nextKeywordLine())
            readSection();
        if (!_hasPoints)
            _scanner.fail("unexpected end of file: no POINTS section");
        return _table.finish();
    }

private:
    enum Mode
    {
        Global,
        Points,
        Cells
    };

    void readHeader()
    {
        if (!startsWith(_scanner.requireLine("'# vtk DataFile Version'"), "# vtk DataFile Version"))
            _scanner.fail("not a legacy VTK file: the first line must be '# vtk DataFile Version <n>'");
        _scanner.requireLine("the title line");
        const std::string encoding = toLower(trim(_scanner.requireLine("ASCII or BINARY")));
        if (encoding != "ascii" && encoding != "binary")
            _scanner.fail("expected ASCII or BINARY, found " + quote(encoding));
        _binary = encoding == "binary";
    }

    // The next non-blank line as words, false at the end of the file.
    bool nextKeywordLine()
    {
        if (_cursor < _lineEnd && skipBlanks(_cursor, _lineEnd) != _lineEnd)
            _scanner.fail("unexpected " + quote(trim(std::string_view(_cursor, _lineEnd - _cursor))) +
                          " after the values of " + _section);
        _cursor = _lineEnd = nullptr;
        std::string_view line;
        do
        {
            if (!_scanner.nextLine(line))
                return false;
            splitBlanks(line, _fields);
        } while (_fields.empty());
        _words.assign(_fields.begin(), _fields.end());
        _keyword = toLower(_words[0]);
        return true;
    }

    // The next word in the file, in lower case, looked at without reading it: VTK reads keywords
    // in any case and after any blanks. Words beyond the next PeekBytes bytes are not seen.
    std::string peekWord()
    {
        static const std::size_t PeekBytes = 256;
        std::size_t length = PeekBytes;
        const char* bytes = _scanner.peekBytes(length);
        if (!bytes)
        {
            length = _scanner.getAvailableBytes();
            bytes = _scanner.peekBytes(length);
        }
        const char* end = bytes + length;
        const char* word = bytes;
        while (word < end && (isBlank(*word) || *word == '\n'))
            ++word;
        const char* stop = word;
        while (stop < end && !isBlank(*stop) && *stop != '\n')
            ++stop;
        return toLower(std::string_view(word, static_cast<std::size_t>(stop - word)));
    }

    void expectWords(std::size_t minimum, std::size_t maximum, const char* form)
    {
        if (_words.size() < minimum || _words.size() > maximum)
            _scanner.fail("malformed " + _words[0] + " line: expected '" + form + "'");
    }

    uint64_t count(std::size_t index)
    {
        uint64_t value = 0;
        if (!parseUInt64(_words[index], value))
            _scanner.fail(_words[0] + ": " + quote(_words[index]) + " is not a count");
        return value;
    }

    ScalarType type(std::size_t index)
    {
        ScalarType result = ScalarType::Float32;
        if (!parseVtkType(_words[index], result))
            _scanner.fail(_words[0] + ": unknown data type " + quote(_words[index]));
        return result;
    }

    // Reads tuples * components values of a section. With names (one a component) they become
    // columns, otherwise they are read past. binaryScale multiplies binary values (colour bytes).
    void readValues(const std::string& section, uint64_t tuples, uint64_t components, ScalarType valueType,
                    const std::vector<std::string>& names, double binaryScale = 1.0)
    {
        _section = section;
        const bool store = !names.empty();
        const uint64_t bytesEach = _binary ? scalarSize(valueType) : 2;
        if (tuples > _scanner.getMaxItems(bytesEach * components))
            _scanner.fail(_section + ": " + std::to_string(tuples) + " tuples of " +
                          std::to_string(components) + " values are more than the " +
                          std::to_string(_scanner.getRemainingBytes()) + " bytes left in the file hold");
        if (tuples > std::numeric_limits<uint64_t>::max() / (bytesEach * components))
            _scanner.fail(_section + ": " + std::to_string(tuples) + " tuples are more than any file holds");
        const uint64_t total = tuples * components;
        std::vector<std::size_t> columns;
        for (const std::string& name : names)
            columns.push_back(_table.addColumn(name));
        if (store)
            _table.reserve(_scanner.boundedReserve(tuples, bytesEach * components));
        if (_binary && !store)
        {
            if (!_scanner.skipBytes(total * bytesEach))
                _scanner.failAtByte(_scanner.getOffset(), "unexpected end of file in " + _section);
            return;
        }
        if (_binary)
        {
            readBinaryValues(columns, total, valueType, binaryScale);
            return;
        }
        for (uint64_t i = 0; i < total; ++i)
        {
            const std::string_view token = nextToken(i, total);
            double value = 0.0;
            if (store)
                _table.appendField(columns[i % components], token);
            else if (!parseDouble(token, value))
                _scanner.fail(_section + ": " + quote(token) + " is not a number");
        }
    }

    // Binary values into the columns, a component each in turn. Legacy VTK binary data is
    // big-endian; floating-point data that make sense only in the other byte order fail.
    void readBinaryValues(const std::vector<std::size_t>& columns, uint64_t total, ScalarType valueType,
                          double binaryScale)
    {
        const std::size_t bytesEach = scalarSize(valueType);
        const uint64_t start = _scanner.getOffset();
        MagnitudeSpread bigEndian, littleEndian;
        for (uint64_t i = 0; i < total; ++i)
        {
            const uint64_t offset = _scanner.getOffset();
            const char* bytes = _scanner.peekBytes(bytesEach);
            if (!bytes)
                _scanner.failAtByte(offset, "unexpected end of file in " + _section + ": " +
                                                std::to_string(i) + " of " + std::to_string(total) +
                                                " values");
            const double value = binaryScale * decodeScalar(bytes, valueType, true);
            if (!isIntegerType(valueType))
            {
                bigEndian.add(value, valueType);
                littleEndian.add(decodeScalar(bytes, valueType, false), valueType);
                if (!std::isfinite(value) && littleEndian.isPlausible())
                    failLittleEndian(start, littleEndian);
            }
            _table.appendValue(columns[i % columns.size()], value, offset);
            _scanner.consume(bytesEach);
        }
        if (bigEndian.isAbsurd() && littleEndian.isPlausible())
            failLittleEndian(start, littleEndian);
    }

    [[noreturn]] void failLittleEndian(uint64_t offset, const MagnitudeSpread& littleEndian) const
    {
        _scanner.failAtByte(offset, _section +
                                        ": the values look little-endian: read big-endian, as legacy VTK "
                                        "binary data is, they are not finite, subnormal or more than " +
                                        "1e40 apart; read little-endian they lie within " +
                                        littleEndian.describe() + ". Write the file big-endian");
    }

    // The columns of an array of so many components: none in CELL_DATA, whose values are read past.
    // A name that the points or an earlier array took gets a suffix: SCALARS x becomes x_2.
    std::vector<std::string> arrayColumns(const std::string& section, const std::string& name,
                                          uint64_t components)
    {
        if (components == 0 || components > MaxComponents)
            _scanner.fail(section + ": " + std::to_string(components) + " components per tuple (at most " +
                          std::to_string(MaxComponents) + ")");
        if (_mode != Points)
            return {};
        const std::size_t count = static_cast<std::size_t>(components);
        std::vector<std::string> names = componentNames(name, count);
        int& suffix = _nextSuffix[name];
        while (std::any_of(names.begin(), names.end(),
                           [this](const std::string& column) { return _table.hasColumn(column); }))
        {
            suffix = std::max(suffix, 2);
            names = componentNames(name + "_" + std::to_string(suffix++), count);
        }
        return names;
    }

    // Values of a POINT_DATA attribute are kept, of CELL_DATA read past.
    void readAttribute(const std::string& name, uint64_t components, ScalarType valueType,
                       double binaryScale = 1.0)
    {
        const std::string section = _words[0] + " " + name;
        readValues(section, attributeTuples(), components, valueType, arrayColumns(section, name, components),
                   binaryScale);
    }

    std::string_view nextToken(uint64_t index, uint64_t total)
    {
        for (;;)
        {
            _cursor = skipBlanks(_cursor, _lineEnd);
            if (_cursor < _lineEnd)
            {
                const char* stop = skipField(_cursor, _lineEnd);
                const std::string_view token(_cursor, static_cast<std::size_t>(stop - _cursor));
                _cursor = stop;
                return token;
            }
            std::string_view line;
            if (!_scanner.nextLine(line))
                _scanner.fail("unexpected end of file in " + _section + ": " + std::to_string(index) +
                              " of " + std::to_string(total) + " values");
            _cursor = line.data();
            _lineEnd = line.data() + line.size();
        }
    }

    uint64_t attributeTuples() const { return _mode == Cells ? _numCells : _numPoints; }

    void requireAttributeMode()
    {
        if (_mode == Global)
            _scanner.fail(_words[0] + " outside POINT_DATA and CELL_DATA");
    }

    void readCells()
    {
        expectWords(3, 3, "<keyword> <count> <size>");
        const uint64_t cells = count(1);
        const uint64_t size = count(2);
        if (peekWord() == "offsets")
        {
            // File version 5: offsets and connectivity arrays with their types.
            for (const char* keyword : {"OFFSETS", "CONNECTIVITY"})
            {
                const std::string parent(_words[0]);
                if (!nextKeywordLine() || toLower(_words[0]) != toLower(keyword) || _words.size() != 2)
                    _scanner.fail("expected '" + std::string(keyword) + " <type>' in " + parent);
                const uint64_t values = std::string(keyword) == "OFFSETS" ? cells : size;
                readValues(parent + " " + keyword, values, 1, type(1), {});
            }
            return;
        }
        readValues(_words[0], size, 1, ScalarType::Int32, {});
    }

    void readField()
    {
        expectWords(3, 3, "FIELD <name> <number of arrays>");
        const uint64_t arrays = count(2);
        for (uint64_t i = 0; i < arrays; ++i)
        {
            if (!nextKeywordLine())
                _scanner.fail("unexpected end of file: FIELD has " + std::to_string(i) + " of " +
                              std::to_string(arrays) + " arrays");
            if (_keyword == "metadata")
            {
                skipMetadata();
                --i;
                continue;
            }
            if (_keyword == "null_array")
                continue;
            expectWords(4, 4, "<array name> <components> <tuples> <type>");
            const uint64_t components = count(1);
            const uint64_t tuples = count(2);
            const std::string name = decodeName(_words[0]);
            if (_mode == Points && tuples != _numPoints)
                _scanner.fail("FIELD array " + quote(name) + " has " + std::to_string(tuples) +
                              " tuples, POINT_DATA has " + std::to_string(_numPoints));
            const std::string section = "FIELD array " + name;
            readValues(section, tuples, components, type(3), arrayColumns(section, name, components));
        }
    }

    void skipMetadata()
    {
        std::string_view line;
        while (_scanner.nextLine(line) && !trim(line).empty())
        {
        }
    }

    void readSection()
    {
        if (_keyword == "dataset")
        {
            expectWords(2, 2, "DATASET <type>");
            const std::string dataset = toLower(_words[1]);
            if (dataset != "polydata" && dataset != "unstructured_grid")
                _scanner.fail("DATASET " + quote(_words[1]) +
                              " is not supported (POLYDATA or UNSTRUCTURED_GRID)");
            _hasDataset = true;
        }
        else if (!_hasDataset && _keyword != "field")
        {
            _scanner.fail("expected DATASET POLYDATA or DATASET UNSTRUCTURED_GRID, found " +
                          quote(_words[0]));
        }
        else if (_keyword == "points")
        {
            expectWords(3, 3, "POINTS <count> <type>");
            if (_hasPoints)
                _scanner.fail("a second POINTS section");
            _numPoints = count(1);
            _table.setRowCount(_numPoints);
            _hasPoints = true;
            readValues("POINTS", _numPoints, 3, type(2), {"x", "y", "z"});
        }
        else if (_keyword == "vertices" || _keyword == "lines" || _keyword == "polygons" ||
                 _keyword == "triangle_strips" || _keyword == "cells")
        {
            readCells();
        }
        else if (_keyword == "cell_types")
        {
            expectWords(2, 2, "CELL_TYPES <count>");
            readValues("CELL_TYPES", count(1), 1, ScalarType::Int32, {});
        }
        else if (_keyword == "point_data")
        {
            expectWords(2, 2, "POINT_DATA <count>");
            const uint64_t points = count(1);
            if (!_hasPoints)
                _scanner.fail("POINT_DATA before POINTS");
            if (points != _numPoints)
                _scanner.fail("POINT_DATA " + std::to_string(points) + " does not match POINTS " +
                              std::to_string(_numPoints));
            _mode = Points;
        }
        else if (_keyword == "cell_data")
        {
            expectWords(2, 2, "CELL_DATA <count>");
            _numCells = count(1);
            _mode = Cells;
        }
        else if (_keyword == "field")
        {
            readField();
        }
        else if (_keyword == "metadata")
        {
            skipMetadata();
        }
        else if (_keyword == "scalars")
        {
            requireAttributeMode();
            expectWords(3, 4, "SCALARS <name> <type> [components]");
            const uint64_t components = _words.size() == 4 ? count(3) : 1;
            const ScalarType valueType = type(2);
            const std::string name = decodeName(_words[1]);
            if (peekWord() == "lookup_table")
            {
                nextKeywordLine();
                expectWords(2, 2, "LOOKUP_TABLE <name>");
                _words[0] = "SCALARS";
            }
            readAttribute(name, components, valueType);
        }
        else if (_keyword == "color_scalars")
        {
            requireAttributeMode();
            expectWords(3, 3, "COLOR_SCALARS <name> <components>");
            readAttribute(decodeName(_words[1]), count(2), ScalarType::UInt8, 1.0 / 255.0);
        }
        else if (_keyword == "vectors" || _keyword == "normals" || _keyword == "tensors" ||
                 _keyword == "tensors6")
        {
            requireAttributeMode();
            expectWords(3, 3, "<VECTORS|NORMALS|TENSORS> <name> <type>");
            const uint64_t components = _keyword == "tensors" ? 9 : _keyword == "tensors6" ? 6 : 3;
            readAttribute(decodeName(_words[1]), components, type(2));
        }
        else if (_keyword == "texture_coordinates")
        {
            requireAttributeMode();
            expectWords(4, 4, "TEXTURE_COORDINATES <name> <dimension> <type>");
            readAttribute(decodeName(_words[1]), count(2), type(3));
        }
        else if (_keyword == "lookup_table")
        {
            expectWords(3, 3, "LOOKUP_TABLE <name> <size>");
            readValues("LOOKUP_TABLE", count(2), 4, ScalarType::UInt8, {});
        }
        else
        {
            _scanner.fail("unknown keyword " + quote(_words[0]));
        }
    }

    TextScanner& _scanner;
    ColumnTable _table;
    bool _binary = false;
    bool _hasDataset = false;
    bool _hasPoints = false;
    uint64_t _numPoints = 0;
    uint64_t _numCells = 0;
    Mode _mode = Global;
    std::map<std::string, int> _nextSuffix; // of array names taken: x -> 2 for x_2
    std::vector<std::string> _words;
    std::vector<std::string_view> _fields;
    std::string _keyword;
    std::string _section;
    const char* _cursor = nullptr;
    const char* _lineEnd = nullptr;
};

} // namespace

void osgGlyphsData::readers::readVtk(TextScanner& scanner, PointDataset& dataset,
                                     const PointReadOptions& options)
{
    VtkReader reader(scanner, options.share);
    addOnlyFrame(scanner, dataset, options, reader.read().get());
}
