// PDB (Protein Data Bank) coordinate files: 80-column text records, named by their first 6 columns.
// Read:
//   ATOM, HETATM: serial (columns 7-11, decimal or hybrid-36) -> id, atom name (13-16) -> name,
//     residue name (18-21) -> residue, chain (22) -> chain, residue number (23-26) -> residue_id,
//     x y z (31-54, Angstrom) , occupancy (55-60, 1 where blank) -> occupancy, temperature factor
//     (61-66, 0 where blank) -> bfactor, element (77-78, else guessed from the atom name) -> element
//     and species;
//   CRYST1: the cell (a b c alpha beta gamma), for the frames after it;
//   MODEL ... ENDMDL: each model a frame; in a file without MODEL records, the atoms up to each END
//     (VMD's trajectories), or the whole file, are a frame.
//   CONECT: bonds between atoms named by their serials (columns 7-11 and 12-31), wherever they are
//     in the file, for every frame (PointData::getBonds()); each bond once though listed from both
//     atoms.
// Read past: everything else (REMARK, TER, ANISOU, ...).
// The file's lines are scanned once at opening for the frames' byte ranges and atom counts.

#include "CellBox.h"
#include "FormatFrameFile.h"
#include "Formats.h"
#include "TextLines.h"

#include "../ListedBonds.h"
#include "../readers/Fields.h"

#include <cmath>
#include <unordered_map>

using namespace osgGlyphsData;
using namespace osgGlyphsData::formats;
using readers::quote;

namespace
{

/** The record name: columns 1-6, trailing blanks trimmed. */
std::string_view recordOf(std::string_view line)
{
    std::string_view name = line.substr(0, std::min<std::size_t>(line.size(), 6));
    while (!name.empty() && name.back() == ' ')
        name.remove_suffix(1);
    return name;
}

bool isAtom(std::string_view record)
{
    return record == "ATOM" || record == "HETATM";
}

/** A CRYST1 record's cell. */
struct Cell
{
    bool known = false;
    double lengths[3] = {0.0, 0.0, 0.0};
    double angles[3] = {90.0, 90.0, 90.0};
};

Cell readCell(const TextLines& lines, std::string_view line)
{
    static const struct
    {
        std::size_t first, last;
        const char* what;
    } fields[6] = {{7, 15, "a"},      {16, 24, "b"},    {25, 33, "c"},
                   {34, 40, "alpha"}, {41, 47, "beta"}, {48, 54, "gamma"}};
    Cell cell;
    for (int i = 0; i < 6; ++i)
    {
        const double value = parseFixedNumber(lines, columns(line, fields[i].first, fields[i].last),
                                              fields[i].first, fields[i].last, fields[i].what);
        (i < 3 ? cell.lengths[i] : cell.angles[i - 3]) = value;
    }
    // CRYST1 1 1 1 (a cell of 1 Angstrom) is what writers put where there is no cell.
    cell.known = !(cell.lengths[0] == 1.0 && cell.lengths[1] == 1.0 && cell.lengths[2] == 1.0);
    return cell;
}

/** A frame as the scan found it: its byte range and atoms, and the cell of a CRYST1 before it. */
struct PdbFrame
{
    FrameInfo info;
    Cell cell;
};

/** The columns of a frame's atoms while they are read. */
struct AtomColumns
{
    std::vector<float> ids, residueIds, x, y, z, occupancy, bfactor;
    LabelColumn names, residues, chains;
    ElementColumns elements;

    explicit AtomColumns(std::size_t count)
    {
        for (std::vector<float>* column : {&ids, &residueIds, &x, &y, &z, &occupancy, &bfactor})
            column->reserve(count);
        names.reserve(count);
        residues.reserve(count);
        chains.reserve(count);
        elements.reserve(count);
    }

    void append(const TextLines& lines, std::string_view line)
    {
        if (line.size() < 54)
            lines.fail("an atom record of " + std::to_string(line.size()) +
                       " characters: x y z need columns 31-54");
        ids.push_back(static_cast<float>(parseFixedInteger(lines, columns(line, 7, 11), 7, 11, "serial")));
        const std::string_view nameField = line.substr(12, 4);
        names.append(readers::trim(nameField));
        residues.append(columns(line, 18, 21));
        chains.append(columns(line, 22, 22));
        residueIds.push_back(
            static_cast<float>(parseFixedInteger(lines, columns(line, 23, 26), 23, 26, "residue number")));
        static const char* const axes[3] = {"x", "y", "z"};
        std::vector<float>* targets[3] = {&x, &y, &z};
        for (std::size_t axis = 0; axis < 3; ++axis)
        {
            const std::size_t first = 31 + 8 * axis;
            const double value =
                parseFixedNumber(lines, columns(line, first, first + 7), first, first + 7, axes[axis]);
            targets[axis]->push_back(static_cast<float>(value));
        }
        occupancy.push_back(optionalNumber(lines, line, 55, 60, "occupancy", 1.0));
        bfactor.push_back(optionalNumber(lines, line, 61, 66, "temperature factor", 0.0));
        const std::string_view element = columns(line, 77, 78);
        const unsigned int number = guessElement(element, nameField, true);
        elements.append(number, element.empty() ? readers::trim(nameField) : element);
    }

    static float optionalNumber(const TextLines& lines, std::string_view line, std::size_t first,
                                std::size_t last, const char* what, double blank)
    {
        const std::string_view field = columns(line, first, last);
        return static_cast<float>(field.empty() ? blank : parseFixedNumber(lines, field, first, last, what));
    }

    osg::ref_ptr<PointData> finish()
    {
        osg::ref_ptr<PointData> frame = new PointData(x.size());
        frame->addColumn("id", std::move(ids));
        names.addTo(*frame, "name");
        residues.addTo(*frame, "residue");
        chains.addTo(*frame, "chain");
        frame->addColumn("residue_id", std::move(residueIds));
        frame->addColumn("x", std::move(x));
        frame->addColumn("y", std::move(y));
        frame->addColumn("z", std::move(z));
        frame->addColumn("occupancy", std::move(occupancy));
        frame->addColumn("bfactor", std::move(bfactor));
        elements.addTo(*frame);
        return frame;
    }
};

class PdbFile : public FormatFrameFile
{
public:
    explicit PdbFile(const std::string& path) : FormatFrameFile(path, "pdb", OutOfMemory::Reported) {}

    void findFrames() override
    {
        TextLines lines(_file, TextPlace{&_path}, 0, _file.getSize(), 0);
        Block block;
        block.start(lines);
        std::string_view line;
        while (lines.next(line))
        {
            const std::string_view record = recordOf(line);
            if (isAtom(record))
                atomRecord(lines, block);
            else if (record == "CRYST1")
                _cell = readCell(lines, line);
            else if (record == "CONECT")
                conectRecord(lines, line);
            else if (record == "MODEL")
                modelRecord(lines, block);
            else if (record == "ENDMDL")
                endModelRecord(lines, block);
            else if (record == "END" && endRecord(lines, block))
                break;
        }
        finishScan(lines, block);
    }

    std::size_t getNumFrames() const override { return _frames.size(); }

    FrameInfo getFrameInfo(std::size_t frame) const override
    {
        return frame < _frames.size() ? _frames[frame].info : FrameInfo();
    }

private:
    /** The frame the scan is in: where it began and what it holds so far. */
    struct Block
    {
        uint64_t offset = 0, line = 0, atoms = 0, firstAtomLine = 0;
        /** The line of the MODEL record that opened it; 0 outside a model. */
        uint64_t modelLine = 0;

        /** A block starting after the line that lines returned last. */
        void start(const TextLines& lines)
        {
            offset = lines.getOffset();
            line = lines.getLineNumber();
            atoms = firstAtomLine = modelLine = 0;
        }
    };

    void atomRecord(const TextLines& lines, Block& block)
    {
        if (_models && block.modelLine == 0)
            lines.fail("an atom record outside MODEL ... ENDMDL in a file of models");
        if (block.atoms++ == 0)
            block.firstAtomLine = lines.getLineNumber();
    }

    /** A CONECT record: the atom of columns 7-11 bonded to each of columns 12-31 given. */
    void conectRecord(const TextLines& lines, std::string_view line)
    {
        const int64_t atom = parseFixedInteger(lines, columns(line, 7, 11), 7, 11, "CONECT's atom serial");
        for (std::size_t first = 12; first <= 27; first += 5)
        {
            const std::string_view field = columns(line, first, first + 4);
            if (field.empty())
                continue;
            const int64_t other = parseFixedInteger(lines, field, first, first + 4, "CONECT's bonded serial");
            if (other == atom)
                lines.fail("CONECT: atom " + std::to_string(atom) + " bonded to itself");
            _conect.push_back({atom, other, lines.getLineNumber()});
        }
    }

    void modelRecord(const TextLines& lines, Block& block)
    {
        if (block.modelLine != 0)
            lines.fail("MODEL inside the model that MODEL at line " + std::to_string(block.modelLine) +
                       " opened: ENDMDL is missing");
        if (block.atoms > 0)
            lines.fail("MODEL after atom records outside a model (from line " +
                       std::to_string(block.firstAtomLine) + ")");
        _models = true;
        block.offset = lines.getLineOffset();
        block.line = lines.getLineNumber() - 1;
        block.atoms = block.firstAtomLine = 0;
        block.modelLine = lines.getLineNumber();
    }

    void endModelRecord(const TextLines& lines, Block& block)
    {
        if (block.modelLine == 0)
            lines.fail("ENDMDL without MODEL");
        addFrame(lines, block);
        block.start(lines);
    }

    /** END: the end of the file in a file of models, the end of a frame in one without (VMD).
     * Returns whether the scan stops. */
    bool endRecord(const TextLines& lines, Block& block)
    {
        if (block.modelLine != 0)
            lines.fail("END inside the model that MODEL at line " + std::to_string(block.modelLine) +
                       " opened: ENDMDL is missing");
        if (_models)
            return true;
        addFrame(lines, block);
        block.start(lines);
        return false;
    }

    void finishScan(const TextLines& lines, const Block& block)
    {
        if (block.modelLine != 0)
        {
            const std::string what = "the model that MODEL at line " + std::to_string(block.modelLine) +
                                     " opened has no ENDMDL: the file ends at line " +
                                     std::to_string(lines.getLineNumber());
            if (_frames.empty())
                TextPlace{&_path}.fail(block.modelLine, what);
            _warnings.push_back(TextPlace{&_path, _frames.size()}.describe(
                block.modelLine, what + "; the model is cut short and left out"));
        }
        else if (!_models)
            addFrame(lines, block);
        if (_emptyModels > 0)
            _warnings.push_back(_path + ": " + std::to_string(_emptyModels) +
                                " model(s) without atoms left out");
        if (_frames.empty())
            TextPlace{&_path}.fail(lines.getLineNumber(), "no ATOM or HETATM records");
    }

    /** The block up to the line that lines returned last is a frame, if it holds atoms. */
    void addFrame(const TextLines& lines, const Block& block)
    {
        if (block.atoms == 0)
        {
            _emptyModels += block.modelLine != 0 ? 1 : 0;
            return;
        }
        PdbFrame frame;
        frame.info.offset = block.offset;
        frame.info.line = block.line;
        frame.info.end = lines.getOffset();
        frame.info.points = block.atoms;
        frame.info.timestep = static_cast<int64_t>(_frames.size());
        frame.info.fileFrame = _frames.size() + _emptyModels;
        frame.cell = _cell;
        _frames.push_back(frame);
    }

    osg::ref_ptr<PointData> decodeFrame(std::size_t index, const PointShare& share) const override
    {
        const TextPlace place{&_path, index};
        if (index >= _frames.size())
            place.fail(0, "no such frame (the file holds " + std::to_string(_frames.size()) + ")");
        const PdbFrame& frame = _frames[index];
        const PointRange range = getShareRange(share, frame.info.points);
        AtomColumns atoms(static_cast<std::size_t>(range.end - range.begin));
        Cell cell = frame.cell;
        TextLines lines(_file, place, frame.info.offset, frame.info.end, frame.info.line);
        std::string_view line;
        uint64_t atom = 0;
        AtomSerials serials;
        while (lines.next(line))
        {
            const std::string_view record = recordOf(line);
            if (isAtom(record))
            {
                if (atom >= range.begin && atom < range.end)
                    atoms.append(lines, line);
                if (!_conect.empty())
                    serials.add(parseFixedInteger(lines, columns(line, 7, 11), 7, 11, "serial"), atom,
                                lines.getLineNumber());
                ++atom;
            }
            else if (record == "CRYST1")
                cell = readCell(lines, line);
        }
        if (atom != frame.info.points)
            lines.fail("the frame holds " + std::to_string(atom) + " atoms, " +
                       std::to_string(frame.info.points) + " when the file was opened: it changed since");
        osg::ref_ptr<PointData> data = atoms.finish();
        if (cell.known)
            setCellLengthsAngles(*data, cell.lengths[0], cell.lengths[1], cell.lengths[2], cell.angles[0],
                                 cell.angles[1], cell.angles[2]);
        if (!_conect.empty())
            data->setBonds(conectBonds(place, serials, range, frame.info.points));
        data->setTimestep(frame.info.timestep);
        data->setFilePointCount(frame.info.points);
        return data;
    }

    /** The row in the frame of each atom serial; serials given twice, which CONECT cannot name. */
    struct AtomSerials
    {
        std::unordered_map<int64_t, uint32_t> rows;
        std::unordered_map<int64_t, uint64_t> repeated; // serial -> a line that repeats it

        void add(int64_t serial, uint64_t row, uint64_t line)
        {
            if (!rows.emplace(serial, static_cast<uint32_t>(row)).second)
                repeated.emplace(serial, line);
        }
    };

    std::shared_ptr<const PointData::BondList> conectBonds(const TextPlace& place, const AtomSerials& serials,
                                                           const PointRange& range, uint64_t atoms) const
    {
        if (atoms >= NOT_IN_FRAME)
            place.fail(_conect.front().line, "CONECT in a frame of more atoms than bonds can index");
        std::vector<std::pair<uint32_t, uint32_t>> rows;
        rows.reserve(_conect.size());
        auto rowOf = [&](int64_t serial, uint64_t line)
        {
            const auto repeated = serials.repeated.find(serial);
            if (repeated != serials.repeated.end())
                place.fail(line, "CONECT names atom serial " + std::to_string(serial) +
                                     ", which more than one atom has (line " +
                                     std::to_string(repeated->second) + " repeats it)");
            const auto row = serials.rows.find(serial);
            if (row == serials.rows.end())
                place.fail(line, "CONECT names atom serial " + std::to_string(serial) +
                                     ", which no atom of the frame has");
            return row->second;
        };
        for (const ConectBond& bond : _conect)
            rows.emplace_back(rowOf(bond.atom, bond.line), rowOf(bond.other, bond.line));
        std::vector<uint32_t> frameIndexOfRow(static_cast<std::size_t>(atoms), NOT_IN_FRAME);
        for (uint64_t row = range.begin; row < range.end; ++row)
            frameIndexOfRow[static_cast<std::size_t>(row)] = static_cast<uint32_t>(row - range.begin);
        return makeListedBonds(rows, frameIndexOfRow);
    }

    std::vector<PdbFrame> _frames;
    /** The file has MODEL records: its frames are models. */
    bool _models = false;
    std::size_t _emptyModels = 0;
    /** The cell of the last CRYST1 the scan met. */
    Cell _cell;
    /** The bonds of the CONECT records, by serial, with their lines. */
    struct ConectBond
    {
        int64_t atom, other;
        uint64_t line;
    };
    std::vector<ConectBond> _conect;
};

}

osg::ref_ptr<FrameFile> formats::openPdb(const std::string& path, const FrameFileOptions&, std::string& error)
{
    return openFormatFile<PdbFile>(path, error);
}
