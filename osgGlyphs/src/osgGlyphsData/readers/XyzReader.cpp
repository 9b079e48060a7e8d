// XYZ and extended XYZ: atom count, comment (key=value pairs in extended XYZ), one atom a line.

#include "ColumnTable.h"
#include "Fields.h"
#include "FrameList.h"
#include "Readers.h"
#include "RowShare.h"

#include <algorithm>
#include <cmath>

using namespace osgGlyphsData;
using namespace osgGlyphsData::readers;

namespace
{

struct KeyValue
{
    std::string key;
    std::string value;
};

// Splits an extended XYZ comment into key=value pairs; values may be "quoted" or {braced}.
// A key without '=' is a flag with an empty value.
std::vector<KeyValue> parseComment(std::string_view text)
{
    std::vector<KeyValue> pairs;
    std::size_t i = 0;
    while (i < text.size())
    {
        while (i < text.size() && isBlank(text[i]))
            ++i;
        const std::size_t keyStart = i;
        while (i < text.size() && !isBlank(text[i]) && text[i] != '=')
            ++i;
        KeyValue pair;
        pair.key = toLower(text.substr(keyStart, i - keyStart));
        if (i < text.size() && text[i] == '=')
        {
            ++i;
            if (i < text.size() && (text[i] == '"' || text[i] == '{'))
            {
                const char close = text[i] == '"' ? '"' : '}';
                ++i;
                while (i < text.size() && text[i] != close)
                {
                    if (text[i] == '\\' && i + 1 < text.size())
                        ++i;
                    pair.value += text[i++];
                }
                ++i;
            }
            else
            {
                const std::size_t valueStart = i;
                while (i < text.size() && !isBlank(text[i]))
                    ++i;
                pair.value = std::string(text.substr(valueStart, i - valueStart));
            }
        }
        if (!pair.key.empty())
            pairs.push_back(std::move(pair));
    }
    return pairs;
}

const KeyValue* findKey(const std::vector<KeyValue>& pairs, const char* key)
{
    for (const KeyValue& pair : pairs)
    {
        if (pair.key == key)
            return &pair;
    }
    return nullptr;
}

// Properties=name:type:count:... into the table's columns.
void addPropertyColumns(TextScanner& scanner, ColumnTable& table, const std::string& properties)
{
    std::vector<std::string> parts;
    std::size_t start = 0;
    for (std::size_t i = 0; i <= properties.size(); ++i)
    {
        if (i == properties.size() || properties[i] == ':')
        {
            parts.push_back(properties.substr(start, i - start));
            start = i + 1;
        }
    }
    if (parts.size() % 3 != 0)
        scanner.fail("Properties=" + quote(properties) + " is not a list of name:type:count triples");
    for (std::size_t i = 0; i < parts.size(); i += 3)
    {
        const std::string& name = parts[i];
        const std::string type = toLower(parts[i + 1]);
        uint64_t count = 0;
        if (!parseUInt64(parts[i + 2], count) || count == 0 || count > 1000)
            scanner.fail("Properties: " + quote(name) + " has the component count " + quote(parts[i + 2]));
        if (type != "s" && type != "r" && type != "i" && type != "l")
            scanner.fail("Properties: " + quote(name) + " has the type " + quote(parts[i + 1]) +
                         ", expected S, R, I or L");
        if (name == "species" && type == "s" && count == 1)
        {
            table.addColumn(name, ColumnTable::Species);
            continue;
        }
        const std::vector<std::string> names = name == "pos" && count == 3
                                                   ? std::vector<std::string>{"x", "y", "z"}
                                                   : componentNames(name, count);
        const ColumnTable::Kind kind = type == "s"   ? ColumnTable::Category
                                       : type == "l" ? ColumnTable::Logical
                                                     : ColumnTable::Number;
        for (const std::string& column : names)
            table.addColumn(column, kind);
    }
}

// Lattice="ax ay az bx by bz cx cy cz": a box when a lies along x and b in the xy plane.
// Fails at the scanner's line, the comment.
bool parseLattice(TextScanner& scanner, const std::string& lattice, osg::BoundingBoxd& box, osg::Vec3d& tilt)
{
    std::vector<std::string_view> fields;
    splitBlanks(lattice, fields);
    double v[9];
    if (fields.size() != 9)
        scanner.fail("Lattice=" + quote(lattice) + " does not have 9 numbers");
    for (int i = 0; i < 9; ++i)
    {
        if (!parseDouble(fields[i], v[i]) || !std::isfinite(v[i]))
            scanner.fail("Lattice: " + quote(fields[i]) + " is not a finite number");
    }
    if (v[1] != 0.0 || v[2] != 0.0 || v[5] != 0.0)
        return false; // a rotated cell: no LAMMPS-style box describes it
    box.set(0.0, 0.0, 0.0, v[0], v[4], v[8]);
    tilt.set(v[3], v[6], v[7]);
    return true;
}

/** Whether a line follows a frame's atoms: blank, or the next frame's count (atoms have 3 or more
 * fields). */
bool isFrameStart(std::string_view line)
{
    return countFields(line) <= 1;
}

osg::ref_ptr<PointData> readFrame(TextScanner& scanner, uint64_t count, uint64_t frameIndex,
                                  const PointShare& share)
{
    const std::vector<KeyValue> pairs =
        parseComment(scanner.requireLine("the comment line after the atom count"));
    osg::BoundingBoxd box;
    osg::Vec3d tilt;
    const KeyValue* lattice = findKey(pairs, "lattice");
    const bool hasBox = lattice && parseLattice(scanner, lattice->value, box, tilt);

    const bool byBytes = sharesRowsByBytes(scanner, share, count);
    ColumnTable table(scanner, byBytes ? PointShare() : share);
    if (!byBytes)
        table.setRowCount(count);
    std::string_view first;
    bool hasFirst = false;
    const KeyValue* properties = findKey(pairs, "properties");
    if (properties)
    {
        addPropertyColumns(scanner, table, properties->value);
    }
    else if (count > 0)
    {
        // Plain XYZ: species x y z, and numbered columns for anything further.
        first = scanner.requireLine("the first atom");
        hasFirst = true;
        const std::size_t fieldCount = countFields(first);
        if (fieldCount < 4)
            scanner.fail("an atom line needs at least 4 fields (species x y z), this one has " +
                         std::to_string(fieldCount));
        table.addColumn("species", ColumnTable::Species);
        for (const char* axis : {"x", "y", "z"})
            table.addColumn(axis);
        for (std::size_t i = 4; i < fieldCount; ++i)
            table.addColumn("column_" + std::to_string(i + 1));
    }

    const uint64_t minBytes = 2 * std::max<uint64_t>(table.getNumColumns(), 1);
    const std::string section = "frame " + std::to_string(frameIndex + 1);
    if (byBytes)
    {
        const uint64_t body = hasFirst ? scanner.getLineOffset() : scanner.getOffset();
        readShareOfRows(scanner, table, body, count, minBytes, share, isFrameStart, section,
                        hasFirst ? std::optional<std::string>(first) : std::nullopt);
    }
    else
    {
        // What is reserved, the rest of the file can hold. A larger count fails where the rows
        // end, in a file as in a pipe: a last frame cut short, or a row that does not fit.
        table.reserve(scanner.boundedReserve(count, minBytes));
        if (hasFirst)
            table.appendRow(first);
        table.readRows(hasFirst ? 1 : 0, count, section);
    }

    osg::ref_ptr<PointData> frame = table.finish();
    frame->setTimestep(static_cast<int64_t>(frameIndex));
    for (const char* key : {"step", "timestep"})
    {
        const KeyValue* step = findKey(pairs, key);
        int64_t timestep = 0;
        if (step && parseInt64(step->value, timestep))
            frame->setTimestep(timestep);
    }
    if (hasBox)
        frame->setBox(box, tilt);
    return frame;
}

} // namespace

void osgGlyphsData::readers::readXyz(TextScanner& scanner, PointDataset& dataset,
                                     const PointReadOptions& options)
{
    FrameList frames(scanner, dataset, options);
    std::string_view line;
    try
    {
        while (!frames.isFull() && scanner.nextLine(line))
        {
            const std::string_view text = trim(line);
            if (text.empty())
                continue; // blank lines between frames and at the end
            uint64_t count = 0;
            const uint64_t frame = frames.getFileFrame();
            if (!parseUInt64(text, count))
                scanner.fail(std::string(frame == 0 ? "not an XYZ file: " : "") +
                             "expected the number of atoms of frame " + std::to_string(frame + 1) +
                             ", found " + quote(text));
            const uint64_t countLine = scanner.getLineNumber();
            frames.add(readFrame(scanner, count, frame, options.share).get(), countLine, count);
        }
    }
    catch (const ReadError& error)
    {
        if (!frames.leavesOutCutFrame(error))
            throw;
    }
    frames.finish("no atoms: the file has only blank lines");
}
