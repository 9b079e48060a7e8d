// LAMMPS text dumps (dump atom, dump custom): ITEM: sections, one frame per ITEM: ATOMS.

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

bool isItemLine(std::string_view line)
{
    return startsWith(trim(line), "ITEM:");
}

// What the items before ITEM: ATOMS said about the coming frame.
struct FrameHeader
{
    uint64_t firstLine = 0;
    bool hasTimestep = false;
    int64_t timestep = 0;
    bool hasCount = false;
    uint64_t count = 0;
    bool hasBox = false;
    osg::BoundingBoxd box;
    osg::Vec3d tilt = osg::Vec3d(0.0, 0.0, 0.0);
};

void readTimestep(TextScanner& scanner, FrameHeader& header)
{
    const std::string_view field = trim(scanner.requireLine("the timestep after ITEM: TIMESTEP"));
    if (!parseInt64(field, header.timestep))
        scanner.fail("ITEM: TIMESTEP: " + quote(field) + " is not an integer timestep");
    header.hasTimestep = true;
}

void readCount(TextScanner& scanner, FrameHeader& header)
{
    const std::string_view field = trim(scanner.requireLine("the atom count after ITEM: NUMBER OF ATOMS"));
    if (!parseUInt64(field, header.count))
        scanner.fail("ITEM: NUMBER OF ATOMS: " + quote(field) + " is not a count");
    header.hasCount = true;
}

// ITEM: BOX BOUNDS [xy xz yz] <boundary flags>, then three lines "lo hi [tilt]".
void readBox(TextScanner& scanner, std::string_view item, FrameHeader& header)
{
    std::vector<std::string_view> words;
    splitBlanks(item, words);
    const bool triclinic = std::find(words.begin(), words.end(), "xy") != words.end();
    if (std::find(words.begin(), words.end(), "abc") != words.end())
        scanner.fail("ITEM: BOX BOUNDS abc origin (general triclinic boxes) is not supported");

    static const char* const axes[] = {"x", "y", "z"};
    double lo[3], hi[3], tilt[3] = {0.0, 0.0, 0.0};
    std::vector<std::string_view> fields;
    for (int axis = 0; axis < 3; ++axis)
    {
        const std::string what = std::string(axes[axis]) + " bounds of ITEM: BOX BOUNDS";
        splitBlanks(scanner.requireLine("the " + what), fields);
        const std::size_t expected = triclinic ? 3 : 2;
        if (fields.size() != expected)
            scanner.fail(what + ": " + std::to_string(fields.size()) + " numbers, expected " +
                         std::to_string(expected) + (triclinic ? " (lo hi tilt)" : " (lo hi)"));
        double* targets[] = {&lo[axis], &hi[axis], &tilt[axis]};
        for (std::size_t i = 0; i < expected; ++i)
        {
            if (!parseDouble(fields[i], *targets[i]) || !std::isfinite(*targets[i]))
                scanner.fail(what + ": " + quote(fields[i]) + " is not a finite number");
        }
        if (lo[axis] > hi[axis])
            scanner.fail(what + ": the lower bound is above the upper bound");
    }
    if (triclinic)
    {
        // The file gives the bounding box of the tilted cell; LAMMPS' own xlo..zhi are inside it.
        const double xy = tilt[0], xz = tilt[1], yz = tilt[2];
        lo[0] -= std::min({0.0, xy, xz, xy + xz});
        hi[0] -= std::max({0.0, xy, xz, xy + xz});
        lo[1] -= std::min(0.0, yz);
        hi[1] -= std::max(0.0, yz);
        if (lo[0] > hi[0] || lo[1] > hi[1])
            scanner.fail("ITEM: BOX BOUNDS: the tilt factors are larger than the box");
    }
    header.box.set(lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]);
    header.tilt.set(tilt[0], tilt[1], tilt[2]);
    header.hasBox = true;
}

// Very old dumps wrote "ITEM: ATOMS" without names: id type xs ys zs [ix iy iz].
std::vector<std::string> legacyColumns(std::size_t fieldCount)
{
    if (fieldCount == 5)
        return {"id", "type", "xs", "ys", "zs"};
    if (fieldCount == 8)
        return {"id", "type", "xs", "ys", "zs", "ix", "iy", "iz"};
    return {};
}

osg::ref_ptr<PointData> readAtoms(TextScanner& scanner, std::string_view names, const FrameHeader& header,
                                  const PointShare& share)
{
    const uint64_t itemLine = scanner.getLineNumber();
    if (!header.hasCount)
        scanner.fail("ITEM: ATOMS before ITEM: NUMBER OF ATOMS");

    std::vector<std::string_view> fields;
    splitBlanks(names, fields);
    std::vector<std::string> columns(fields.begin(), fields.end());
    std::string_view first;
    const bool legacy = columns.empty() && header.count > 0;
    if (legacy)
    {
        // Look at the first row to tell the old layout; it stays valid until the next read.
        first = scanner.requireLine("the first atom");
        columns = legacyColumns(countFields(first));
        if (columns.empty())
            scanner.failAtLine(itemLine,
                               "ITEM: ATOMS names no columns, and the rows have neither 5 nor 8 fields");
    }

    const bool byBytes = sharesRowsByBytes(scanner, share, header.count);
    ColumnTable table(scanner, byBytes ? PointShare() : share);
    if (!byBytes)
        table.setRowCount(header.count);
    for (const std::string& name : columns)
        table.addColumn(name, name == "element" ? ColumnTable::Species : ColumnTable::Number);
    const uint64_t minBytes = 2 * std::max<uint64_t>(columns.size(), 1);
    if (byBytes)
    {
        const uint64_t body = legacy ? scanner.getLineOffset() : scanner.getOffset();
        readShareOfRows(scanner, table, body, header.count, minBytes, share, isItemLine, "ITEM: ATOMS",
                        legacy ? std::optional<std::string>(first) : std::nullopt);
        return table.finish();
    }
    // What is reserved, the rest of the file can hold. A larger count fails where the rows end,
    // in a file as in a pipe: a last frame cut short, or a row that does not fit the columns.
    table.reserve(scanner.boundedReserve(header.count, minBytes));
    if (legacy)
        table.appendRow(first);
    table.readRows(legacy ? 1 : 0, header.count, "ITEM: ATOMS", "ITEM:");
    return table.finish();
}

} // namespace

namespace
{

// Reads the items of a dump, a frame at each ITEM: ATOMS.
void readItems(TextScanner& scanner, FrameList& frames, const PointShare& share)
{
    FrameHeader header;
    std::string_view line;
    while (!frames.isFull() && scanner.nextLine(line))
    {
        const std::string_view text = trim(line);
        if (text.empty())
            continue;
        if (!startsWith(text, "ITEM:"))
        {
            scanner.fail(std::string(frames.getFileFrame() == 0 && !header.hasTimestep
                                         ? "not a LAMMPS dump: expected 'ITEM: TIMESTEP', found "
                                         : "expected an 'ITEM:' line, found ") +
                         quote(text));
        }
        if (header.firstLine == 0)
            header.firstLine = scanner.getLineNumber();
        const std::string_view item = trim(text.substr(5));
        if (item == "TIMESTEP")
        {
            readTimestep(scanner, header);
        }
        else if (item == "NUMBER OF ATOMS")
        {
            readCount(scanner, header);
        }
        else if (startsWith(item, "BOX BOUNDS"))
        {
            readBox(scanner, item.substr(10), header);
        }
        else if (item == "TIME" || item == "UNITS")
        {
            scanner.requireLine("a value after ITEM: " + std::string(item));
        }
        else if (item == "ATOMS" || startsWith(item, "ATOMS "))
        {
            osg::ref_ptr<PointData> frame = readAtoms(scanner, item.substr(5), header, share);
            frame->setTimestep(header.hasTimestep ? header.timestep
                                                  : static_cast<int64_t>(frames.getFileFrame()));
            if (header.hasBox)
                frame->setBox(header.box, header.tilt);
            frames.add(frame.get(), header.firstLine, header.count);
            header = FrameHeader();
        }
        else
        {
            scanner.fail("unknown item " + quote(text));
        }
    }
    if (header.hasTimestep || header.hasCount || header.hasBox)
        scanner.failEndOfFile(": the last timestep has no ITEM: ATOMS section");
}

} // namespace

void osgGlyphsData::readers::readLammps(TextScanner& scanner, PointDataset& dataset,
                                        const PointReadOptions& options)
{
    FrameList frames(scanner, dataset, options);
    try
    {
        readItems(scanner, frames, options.share);
    }
    catch (const ReadError& error)
    {
        if (!frames.leavesOutCutFrame(error))
            throw;
    }
    frames.finish("no ITEM: ATOMS section: not a LAMMPS dump");
}
