// GRO (GROMACS coordinate files), one frame after the other, each:
//   a title line (GROMACS writes "t= <time> step= <step>" into it: read where present);
//   the atom count;
//   a line per atom in fixed columns: residue number (1-5) -> residue_id, residue name (6-10) ->
//     residue, atom name (11-15) -> name and, guessed from it, element and species, atom number
//     (16-20) -> id; from column 21, x y z in nm and, where the line is long enough, vx vy vz in
//     nm/ps, in fields as wide as the distance between the decimal points of the frame's first
//     atom line (8 in "%8.3f");
//   the box: 3 lengths, or the 9 numbers of a triclinic cell (v1x v2y v3z v1y v1z v2x v2z v3x v3y).
// Each frame is a known number of lines: the lines are counted once at opening for the frames'
// byte ranges, and a frame's atom lines outside a share are counted past, not parsed.

#include "CellBox.h"
#include "FormatFrameFile.h"
#include "Formats.h"
#include "TextLines.h"

#include "../readers/Fields.h"

#include <cmath>

using namespace osgGlyphsData;
using namespace osgGlyphsData::formats;
using readers::quote;

namespace
{

/** The number after key ("t=", "step=") in a title, if it is there. */
template <typename Number>
bool findTitleValue(std::string_view title, std::string_view key, Number& value)
{
    std::size_t at = title.find(key);
    // "t=" is also the end of "step=" or "at=": a key starts a word.
    while (at != std::string_view::npos && at > 0 && !readers::isBlank(title[at - 1]))
        at = title.find(key, at + 1);
    if (at == std::string_view::npos)
        return false;
    std::vector<std::string_view> words;
    readers::splitBlanks(title.substr(at + key.size()), words);
    if (words.empty())
        return false;
    if constexpr (std::is_integral_v<Number>)
        return readers::parseInt64(words[0], value);
    else
        return readers::parseDouble(words[0], value) && std::isfinite(value);
}

/** The layout of a frame's atom lines, from its first: the width of the number fields, and
 * whether they hold velocities. */
struct AtomLayout
{
    std::size_t width = 8;
    bool velocities = false;

    /** Where a number field starts (0-based): x y z, then vx vy vz. */
    std::size_t start(std::size_t field) const { return 20 + field * width; }
};

AtomLayout findLayout(const TextLines& lines, std::string_view line)
{
    const std::size_t first = line.find('.', 20);
    const std::size_t second = first == std::string_view::npos ? first : line.find('.', first + 1);
    if (second == std::string_view::npos)
        lines.fail("the first atom line has no two numbers with decimal points from column 21: "
                   "cannot tell the width of its fields");
    AtomLayout layout;
    layout.width = second - first;
    if (layout.width < 3 || first >= 20 + layout.width)
        lines.fail("the first atom line's decimal points (columns " + std::to_string(first + 1) + " and " +
                   std::to_string(second + 1) + ") make no fields of x y z from column 21");
    std::string_view text = line;
    while (!text.empty() && readers::isBlank(text.back()))
        text.remove_suffix(1);
    layout.velocities = text.size() > layout.start(3);
    return layout;
}

/** The columns of a frame's atoms while they are read. */
struct AtomColumns
{
    AtomLayout layout;
    std::vector<float> ids, residueIds, numbers[6];
    LabelColumn names, residues;
    ElementColumns elements;

    AtomColumns(const AtomLayout& atomLayout, std::size_t count) : layout(atomLayout)
    {
        ids.reserve(count);
        residueIds.reserve(count);
        for (std::size_t i = 0; i < (layout.velocities ? 6u : 3u); ++i)
            numbers[i].reserve(count);
        names.reserve(count);
        residues.reserve(count);
        elements.reserve(count);
    }

    void append(const TextLines& lines, std::string_view line)
    {
        const std::size_t fields = layout.velocities ? 6 : 3;
        if (line.size() < layout.start(fields))
            lines.fail("an atom line of " + std::to_string(line.size()) +
                       " characters: " + (layout.velocities ? "x y z vx vy vz need" : "x y z need") +
                       " columns 21-" + std::to_string(layout.start(fields)) + " (fields of " +
                       std::to_string(layout.width) + " characters, as in the frame's first atom line)");
        residueIds.push_back(
            static_cast<float>(parseFixedInteger(lines, columns(line, 1, 5), 1, 5, "residue number")));
        const std::string_view residue = columns(line, 6, 10);
        residues.append(residue);
        const std::string_view name = columns(line, 11, 15);
        names.append(name);
        ids.push_back(
            static_cast<float>(parseFixedInteger(lines, columns(line, 16, 20), 16, 20, "atom number")));
        static const char* const what[6] = {"x", "y", "z", "vx", "vy", "vz"};
        for (std::size_t i = 0; i < fields; ++i)
        {
            const std::size_t first = layout.start(i) + 1;
            const std::size_t last = first + layout.width - 1;
            const double value = parseFixedNumber(lines, columns(line, first, last), first, last, what[i]);
            numbers[i].push_back(static_cast<float>(value));
        }
        elements.append(guessElement(std::string_view(), name, false, residue), name);
    }

    osg::ref_ptr<PointData> finish()
    {
        static const char* const columnNames[6] = {"x", "y", "z", "vx", "vy", "vz"};
        osg::ref_ptr<PointData> frame = new PointData(ids.size());
        frame->setAngstromsPerUnit(10.0); // nm
        frame->addColumn("id", std::move(ids));
        names.addTo(*frame, "name");
        residues.addTo(*frame, "residue");
        frame->addColumn("residue_id", std::move(residueIds));
        for (std::size_t i = 0; i < (layout.velocities ? 6u : 3u); ++i)
            frame->addColumn(columnNames[i], std::move(numbers[i]));
        elements.addTo(*frame);
        return frame;
    }
};

/** The box line: 3 lengths, or 9 numbers of a triclinic cell; all zero: no box. */
void readBox(const TextLines& lines, std::string_view line, PointData& frame)
{
    std::vector<std::string_view> fields;
    readers::splitBlanks(line, fields);
    if (fields.size() != 3 && fields.size() != 9)
        lines.fail("the box line holds " + std::to_string(fields.size()) +
                   " fields, expected 3 or 9 numbers");
    double v[9] = {0.0};
    for (std::size_t i = 0; i < fields.size(); ++i)
    {
        if (!readers::parseDouble(fields[i], v[i]) || !std::isfinite(v[i]))
            lines.fail("the box line's field " + std::to_string(i + 1) + ": " + quote(fields[i]) +
                       " is not a finite number");
    }
    if (v[0] == 0.0 && v[1] == 0.0 && v[2] == 0.0)
        return;
    setCellVectors(frame, osg::Vec3d(v[0], v[3], v[4]), osg::Vec3d(v[5], v[1], v[6]),
                   osg::Vec3d(v[7], v[8], v[2]));
}

class GroFile : public FormatFrameFile
{
public:
    explicit GroFile(const std::string& path) : FormatFrameFile(path, "gro", OutOfMemory::Reported) {}

    void findFrames() override
    {
        TextLines lines(_file, TextPlace{&_path}, 0, _file.getSize(), 0);
        while (scanFrame(lines))
        {
        }
        if (_frames.empty())
            TextPlace{&_path}.fail(1, "no frames: the file is empty");
    }

    std::size_t getNumFrames() const override { return _frames.size(); }

    FrameInfo getFrameInfo(std::size_t frame) const override
    {
        return frame < _frames.size() ? _frames[frame] : FrameInfo();
    }

private:
    /** Indexes the frame that starts at the scan's position; false at the end of the file. */
    bool scanFrame(TextLines& lines)
    {
        FrameInfo info;
        info.offset = lines.getOffset();
        info.line = lines.getLineNumber();
        info.fileFrame = _frames.size();
        info.timestep = static_cast<int64_t>(_frames.size());
        const TextPlace place{&_path, _frames.size()};
        std::string_view line;
        if (!lines.next(line))
            return false;
        const std::string title(line);
        std::string_view countLine;
        if (!lines.next(countLine))
        {
            if (readers::trim(title).empty())
                return false; // a blank line at the end
            cutShort(place, info.line + 1, "the file ends after the title line, before the atom count");
            return false;
        }
        const uint64_t countLineNumber = lines.getLineNumber();
        if (!readers::parseUInt64(readers::trim(countLine), info.points))
            place.fail(countLineNumber,
                       "the atom count: " + quote(readers::trim(countLine)) + " is not a count");
        findTitleValue(title, "step=", info.timestep);
        info.hasTime = findTitleValue(title, "t=", info.time);
        const uint64_t atoms = lines.skip(info.points);
        std::string_view boxLine;
        if (atoms < info.points || !lines.next(boxLine))
        {
            cutShort(place, countLineNumber,
                     "the atom count " + std::to_string(info.points) +
                         " runs past the end of the file, which holds " + std::to_string(atoms) +
                         " atom line(s) after it" + (atoms < info.points ? "" : " and no box line"));
            return false;
        }
        info.end = lines.getOffset();
        _frames.push_back(info);
        return true;
    }

    /** A frame that the file cuts short: left out with a warning after complete frames (a file
     * being written), an error otherwise. */
    void cutShort(const TextPlace& place, uint64_t line, const std::string& what)
    {
        if (_frames.empty())
            place.fail(line, what);
        _warnings.push_back(place.describe(line, what + "; the frame is cut short and left out"));
    }

    osg::ref_ptr<PointData> decodeFrame(std::size_t index, const PointShare& share) const override
    {
        const TextPlace place{&_path, index};
        if (index >= _frames.size())
            place.fail(0, "no such frame (the file holds " + std::to_string(_frames.size()) + ")");
        const FrameInfo& info = _frames[index];
        const PointRange range = getShareRange(share, info.points);
        TextLines lines(_file, place, info.offset, info.end, info.line);
        std::string_view line;
        lines.skip(2); // the title and the count, indexed already
        AtomLayout layout;
        uint64_t atom = 0;
        std::string first;
        if (info.points > 0 && lines.next(line))
        {
            layout = findLayout(lines, line);
            first.assign(line);
            atom = 1;
        }
        AtomColumns atoms(layout, static_cast<std::size_t>(range.end - range.begin));
        if (range.begin == 0 && range.end > 0)
            atoms.append(lines, first);
        atom += lines.skip(range.begin > atom ? range.begin - atom : 0);
        for (; atom < range.end && lines.next(line); ++atom)
            atoms.append(lines, line);
        atom += lines.skip(info.points - atom);
        if (atom != info.points || !lines.next(line))
            lines.fail("the frame ends before its " + std::to_string(info.points) +
                       " atoms and box: the file changed since it was opened");
        osg::ref_ptr<PointData> data = atoms.finish();
        readBox(lines, line, *data);
        data->setTimestep(info.timestep);
        data->setFilePointCount(info.points);
        return data;
    }

    std::vector<FrameInfo> _frames;
};

}

osg::ref_ptr<FrameFile> formats::openGro(const std::string& path, const FrameFileOptions&, std::string& error)
{
    return openFormatFile<GroFile>(path, error);
}
