// LAMMPS data files (what write_data writes and read_data reads): a title line; header lines of
// counts and the box ("500 atoms", "2 atom types", "0 8.4 xlo xhi", "0 0 0 xy xz yz"); then
// sections, each a keyword line ("Masses", "Atoms # full") and its lines. Read: the atom count and
// types, the box, Masses (each atom's type's mass, as a column "mass"), Atoms of the styles atomic,
// charge, molecular (bond, angle) and full (id, mol, type, q, x y z; ix iy iz where the image flags
// are given) and sphere (diameter, density), Velocities (vx vy vz) and Bonds (the frame's bond
// list). The other sections (coefficients, Angles, type labels, ...) are read past. One frame: the
// atoms sorted by id
// (LAMMPS writes them in its own order), so that they match a trajectory written in id order (a
// dump sorted by id, DCD and XTC of LAMMPS or of MDAnalysis), as its topology.

#include "Fields.h"
#include "Readers.h"

#include "../ListedBonds.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <unordered_map>

using namespace osgGlyphsData;
using namespace osgGlyphsData::readers;

namespace
{

/** An atom style: its fields in the order of the Atoms section. */
struct AtomStyle
{
    const char* name;
    std::vector<std::string> fields;
};

const std::vector<AtomStyle>& atomStyles()
{
    static const std::vector<AtomStyle> styles = {
        {"atomic", {"id", "type", "x", "y", "z"}},
        {"charge", {"id", "type", "q", "x", "y", "z"}},
        {"molecular", {"id", "mol", "type", "x", "y", "z"}},
        {"bond", {"id", "mol", "type", "x", "y", "z"}},
        {"angle", {"id", "mol", "type", "x", "y", "z"}},
        {"full", {"id", "mol", "type", "q", "x", "y", "z"}},
        {"sphere", {"id", "type", "diameter", "density", "x", "y", "z"}},
    };
    return styles;
}

std::string styleNames()
{
    std::string names;
    for (const AtomStyle& style : atomStyles())
        names += (names.empty() ? "" : ", ") + std::string(style.name);
    return names;
}

/** A line without its comment, trimmed; the comment (after '#') trimmed in comment. */
std::string_view stripComment(std::string_view line, std::string_view* comment = nullptr)
{
    const std::size_t hash = line.find('#');
    if (comment)
        *comment = hash == std::string_view::npos ? std::string_view() : trim(line.substr(hash + 1));
    return trim(line.substr(0, hash));
}

bool isKeywordLine(std::string_view text)
{
    return !text.empty() && ((text[0] >= 'A' && text[0] <= 'Z') || (text[0] >= 'a' && text[0] <= 'z'));
}

class DataFile
{
public:
    explicit DataFile(TextScanner& scanner) : _scanner(scanner) {}

    void read()
    {
        const std::string title(_scanner.requireLine("the title line"));
        readTitleTimestep(title);
        std::string_view line;
        std::string keyword;
        while (_scanner.nextLine(line))
        {
            const std::string_view text = stripComment(line);
            if (text.empty())
                continue;
            if (isKeywordLine(text))
            {
                keyword = std::string(line);
                break;
            }
            readHeaderLine(text);
        }
        while (!keyword.empty())
            keyword = readSection(keyword);
        if (_atomsLine == 0)
            _scanner.fail("no Atoms section");
    }

    osg::ref_ptr<PointData> finish(const PointShare& share)
    {
        std::vector<std::size_t> order(_ids.size());
        std::iota(order.begin(), order.end(), std::size_t(0));
        std::stable_sort(order.begin(), order.end(),
                         [this](std::size_t a, std::size_t b) { return _ids[a] < _ids[b]; });
        for (std::size_t i = 1; i < order.size(); ++i)
        {
            if (_ids[order[i]] == _ids[order[i - 1]])
                _scanner.failAtLine(_lines[order[i]],
                                    "Atoms: atom id " + std::to_string(_ids[order[i]]) + " again (line " +
                                        std::to_string(_lines[order[i - 1]]) + " has it too)");
        }
        const PointRange range = getShareRange(share, order.size());
        const std::size_t count = static_cast<std::size_t>(range.end - range.begin);
        osg::ref_ptr<PointData> frame = new PointData(count);
        auto addColumn = [&](const std::string& name, const std::vector<double>& values)
        {
            std::vector<float> column(count);
            for (std::size_t i = 0; i < count; ++i)
                column[i] = static_cast<float>(values[order[range.begin + i]]);
            frame->addColumn(name, std::move(column));
        };
        for (std::size_t field = 0; field < _names.size(); ++field)
            addColumn(_names[field], _values[field]);
        if (_velocityCount > 0)
        {
            for (int axis = 0; axis < 3; ++axis)
                addColumn(std::string("v") + "xyz"[axis], _velocities[axis]);
        }
        if (!_masses.empty())
            addColumn("mass", atomMasses());
        if (_hasBounds[0] && _hasBounds[1] && _hasBounds[2])
            frame->setBox(osg::BoundingBoxd(_lo[0], _lo[1], _lo[2], _hi[0], _hi[1], _hi[2]), _tilt);
        if (_bondsLine != 0)
        {
            std::vector<uint32_t> frameIndexOfRow(order.size(), NOT_IN_FRAME);
            for (std::size_t i = 0; i < count; ++i)
                frameIndexOfRow[order[range.begin + i]] = static_cast<uint32_t>(i);
            frame->setBonds(makeListedBonds(_bonds, frameIndexOfRow));
        }
        frame->setTimestep(_timestep);
        frame->setFilePointCount(order.size());
        return frame;
    }

private:
    void readTitleTimestep(const std::string& title)
    {
        const std::size_t at = title.find("timestep =");
        int64_t step = 0;
        if (at != std::string::npos && parseInt64(trim(std::string_view(title).substr(at + 10)), step))
            _timestep = step;
    }

    uint64_t parseCount(std::string_view field, const char* what)
    {
        uint64_t value = 0;
        if (!parseUInt64(field, value))
            _scanner.fail(std::string(what) + ": " + quote(field) + " is not a count");
        return value;
    }

    double parseFinite(std::string_view field, const std::string& what)
    {
        double value = 0.0;
        if (!parseDouble(field, value) || !std::isfinite(value))
            _scanner.fail(what + ": " + quote(field) + " is not a finite number");
        if (std::abs(value) > std::numeric_limits<float>::max())
            _scanner.fail(what + ": " + quote(field) + " is out of the range of a float");
        return value;
    }

    void readHeaderLine(std::string_view text)
    {
        std::vector<std::string_view> words;
        splitBlanks(text, words);
        if (words.size() == 2 && words[1] == "atoms")
            _atoms = parseCount(words[0], "the atom count");
        else if (words.size() == 3 && words[1] == "atom" && words[2] == "types")
            _types = parseCount(words[0], "the atom type count");
        else if (words.size() == 2 && words[1] == "bonds")
            _bondCount = parseCount(words[0], "the bond count");
        else if (words.size() == 3 && words[1] == "bond" && words[2] == "types")
            _bondTypes = parseCount(words[0], "the bond type count");
        else if (words.size() == 6 && words[3] == "xy" && words[4] == "xz" && words[5] == "yz")
            _tilt.set(parseFinite(words[0], "xy"), parseFinite(words[1], "xz"), parseFinite(words[2], "yz"));
        else if (words.size() == 4)
        {
            for (int axis = 0; axis < 3; ++axis)
            {
                const std::string lo = std::string(1, "xyz"[axis]) + "lo";
                const std::string hi = std::string(1, "xyz"[axis]) + "hi";
                if (words[2] != lo || words[3] != hi)
                    continue;
                _lo[axis] = parseFinite(words[0], lo);
                _hi[axis] = parseFinite(words[1], hi);
                if (_lo[axis] > _hi[axis])
                    _scanner.fail(lo + " " + hi + ": the lower bound is above the upper bound");
                _hasBounds[axis] = true;
            }
        }
        // Other counts (angles, ellipsoids, extra ... per atom) are of sections not read.
    }

    /** Reads the section of a keyword line; returns the next keyword line, empty at the end. */
    std::string readSection(const std::string& keywordLine)
    {
        std::string_view comment;
        const std::string keyword(stripComment(keywordLine, &comment));
        const std::string style(comment);
        if (keyword == "Masses")
            readLines(_types, "Masses", "atom type", [this](std::string_view text) { readMass(text); });
        else if (keyword == "Atoms")
            readAtoms(style);
        else if (keyword == "Velocities")
            readVelocities();
        else if (keyword == "Bonds")
            readBonds();
        else
            return skipSection();
        return nextKeyword(keyword);
    }

    template <typename LineReader>
    void readLines(uint64_t count, const char* section, const char* what, LineReader readLine)
    {
        if (count == 0)
            _scanner.fail(std::string(section) + " without a count of " + what + "s in the header");
        for (uint64_t done = 0; done < count;)
        {
            const std::string_view text =
                stripComment(_scanner.requireLine(std::string("line ") + std::to_string(done + 1) +
                                                  " of the " + std::to_string(count) + " of " + section));
            if (text.empty())
                continue;
            readLine(text);
            ++done;
        }
    }

    void readMass(std::string_view text)
    {
        std::vector<std::string_view> words;
        splitBlanks(text, words);
        if (words.size() != 2)
            _scanner.fail("Masses: " + std::to_string(words.size()) + " fields, expected 2 (type mass)");
        const uint64_t type = parseType(words[0], "Masses");
        _masses[type] = parseFinite(words[1], "the mass of type " + std::to_string(type));
        _massesLine = _scanner.getLineNumber();
    }

    uint64_t parseType(std::string_view field, const char* section)
    {
        uint64_t type = 0;
        if (!parseUInt64(field, type) || type == 0 || type > _types)
            _scanner.fail(std::string(section) + ": the type " + quote(field) + " is not one of the " +
                          std::to_string(_types) + " atom types");
        return type;
    }

    void chooseStyle(const std::string& hint, std::size_t fieldCount)
    {
        const AtomStyle* chosen = nullptr;
        for (const AtomStyle& style : atomStyles())
        {
            const bool fits = fieldCount == style.fields.size() || fieldCount == style.fields.size() + 3;
            if (hint == style.name)
            {
                if (!fits)
                    _scanner.fail("Atoms # " + hint + ": " + std::to_string(fieldCount) +
                                  " fields, expected " + std::to_string(style.fields.size()) + " or " +
                                  std::to_string(style.fields.size() + 3) + " with image flags");
                chosen = &style;
                break;
            }
            if (!hint.empty() || !fits)
                continue;
            if (chosen && chosen->fields != style.fields)
                _scanner.fail("Atoms: " + std::to_string(fieldCount) + " fields are of the styles " +
                              chosen->name + " and " + style.name + ": name the style ('Atoms # " +
                              chosen->name + "')");
            chosen = chosen ? chosen : &style;
        }
        if (!chosen && !hint.empty())
            _scanner.failAtLine(_atomsLine, "Atoms # " + hint + ": the atom style " + quote(hint) +
                                                " is not read (" + styleNames() + ")");
        if (!chosen)
            _scanner.fail("Atoms: " + std::to_string(fieldCount) + " fields fit no atom style (" +
                          styleNames() + "): name it ('Atoms # full')");
        _names = chosen->fields;
        if (fieldCount == _names.size() + 3)
            _names.insert(_names.end(), {"ix", "iy", "iz"});
    }

    void readAtoms(const std::string& hint)
    {
        if (_atomsLine != 0)
            _scanner.fail("a second Atoms section (the first is at line " + std::to_string(_atomsLine) + ")");
        _atomsLine = _scanner.getLineNumber();
        const std::size_t reserve = _scanner.boundedReserve(_atoms, 10);
        _ids.reserve(reserve);
        _lines.reserve(reserve);
        std::vector<std::string_view> words;
        readLines(_atoms, "Atoms", "atom",
                  [&](std::string_view text)
                  {
                      splitBlanks(text, words);
                      if (_names.empty())
                      {
                          chooseStyle(hint, words.size());
                          _values.resize(_names.size());
                          for (std::vector<double>& values : _values)
                              values.reserve(reserve);
                      }
                      if (words.size() != _names.size())
                          _scanner.fail("Atoms: " + std::to_string(words.size()) + " fields, expected " +
                                        std::to_string(_names.size()) + " as in the first atom line");
                      readAtom(words);
                  });
    }

    void readAtom(const std::vector<std::string_view>& words)
    {
        for (std::size_t field = 0; field < words.size(); ++field)
        {
            const std::string& name = _names[field];
            double value = 0.0;
            int64_t integer = 0;
            if (name == "id" || name == "mol" || name == "ix" || name == "iy" || name == "iz")
            {
                if (!parseInt64(words[field], integer) || (name == "id" && integer <= 0))
                    _scanner.fail("Atoms: " + name + ": " + quote(words[field]) + " is not " +
                                  (name == "id" ? "a positive integer" : "an integer"));
                value = static_cast<double>(integer);
            }
            else if (name == "type")
                value = static_cast<double>(parseType(words[field], "Atoms"));
            else
                value = parseFinite(words[field], "Atoms: " + name);
            _values[field].push_back(value);
            if (name == "id")
                _ids.push_back(integer);
        }
        _lines.push_back(_scanner.getLineNumber());
    }

    void readVelocities()
    {
        if (_atomsLine == 0)
            _scanner.fail("Velocities before Atoms");
        const std::unordered_map<int64_t, std::size_t>& atomOf = rowsOfIds();
        for (std::vector<double>& axis : _velocities)
            axis.assign(_ids.size(), std::nan(""));
        std::vector<std::string_view> words;
        readLines(_atoms, "Velocities", "atom",
                  [&](std::string_view text)
                  {
                      splitBlanks(text, words);
                      int64_t id = 0;
                      if (words.size() < 4 || !parseInt64(words[0], id))
                          _scanner.fail("Velocities: expected id vx vy vz");
                      const auto atom = atomOf.find(id);
                      if (atom == atomOf.end())
                          _scanner.fail("Velocities: atom id " + std::to_string(id) + " is not in Atoms");
                      if (!std::isnan(_velocities[0][atom->second]))
                          _scanner.fail("Velocities: atom id " + std::to_string(id) + " again");
                      for (int axis = 0; axis < 3; ++axis)
                          _velocities[axis][atom->second] =
                              parseFinite(words[1 + axis], std::string("Velocities: v") + "xyz"[axis]);
                      ++_velocityCount;
                  });
    }

    /** The row of each atom id, for the sections after Atoms. */
    const std::unordered_map<int64_t, std::size_t>& rowsOfIds()
    {
        if (_rowOfId.empty())
        {
            _rowOfId.reserve(_ids.size());
            for (std::size_t i = 0; i < _ids.size(); ++i)
                _rowOfId.emplace(_ids[i], i);
        }
        return _rowOfId;
    }

    void readBonds()
    {
        if (_atomsLine == 0)
            _scanner.fail("Bonds before Atoms");
        if (_bondsLine != 0)
            _scanner.fail("a second Bonds section (the first is at line " + std::to_string(_bondsLine) + ")");
        _bondsLine = _scanner.getLineNumber();
        if (_ids.size() > NOT_IN_FRAME)
            _scanner.fail("Bonds between more atoms than bonds can index (2^32 - 1)");
        const std::unordered_map<int64_t, std::size_t>& rowOf = rowsOfIds();
        _bonds.reserve(_scanner.boundedReserve(_bondCount, 8));
        std::vector<std::string_view> words;
        readLines(_bondCount, "Bonds", "bond",
                  [&](std::string_view text)
                  {
                      splitBlanks(text, words);
                      if (words.size() != 4)
                          _scanner.fail("Bonds: " + std::to_string(words.size()) +
                                        " fields, expected 4 (id type atom1 atom2)");
                      uint64_t type = 0;
                      if (!parseUInt64(words[1], type) || type == 0 || (_bondTypes > 0 && type > _bondTypes))
                          _scanner.fail("Bonds: the bond type " + quote(words[1]) + " is not one of the " +
                                        std::to_string(_bondTypes) + " bond types");
                      std::size_t rows[2] = {0, 0};
                      for (int end = 0; end < 2; ++end)
                      {
                          int64_t id = 0;
                          if (!parseInt64(words[2 + end], id))
                              _scanner.fail("Bonds: the atom id " + quote(words[2 + end]) +
                                            " is not an integer");
                          const auto row = rowOf.find(id);
                          if (row == rowOf.end())
                              _scanner.fail("Bonds: atom id " + std::to_string(id) + " is not in Atoms");
                          rows[end] = row->second;
                      }
                      if (rows[0] == rows[1])
                          _scanner.fail("Bonds: atom id " + quote(words[2]) + " bonded to itself");
                      _bonds.emplace_back(static_cast<uint32_t>(rows[0]), static_cast<uint32_t>(rows[1]));
                  });
    }

    /** Reads past a section not read, to the next keyword line; returns it, empty at the end. */
    std::string skipSection()
    {
        std::string_view line;
        while (_scanner.nextLine(line))
        {
            if (isKeywordLine(stripComment(line)))
                return std::string(line);
        }
        return std::string();
    }

    /** After a section's lines: blank lines, then the next keyword line or the end. */
    std::string nextKeyword(const std::string& section)
    {
        std::string_view line;
        while (_scanner.nextLine(line))
        {
            const std::string_view text = stripComment(line);
            if (isKeywordLine(text))
                return std::string(line);
            if (!text.empty())
                _scanner.fail("after the " + section + " lines that the header counts, " + quote(text) +
                              ": expected a section keyword");
        }
        return std::string();
    }

    std::vector<double> atomMasses() const
    {
        const std::size_t typeField =
            static_cast<std::size_t>(std::find(_names.begin(), _names.end(), "type") - _names.begin());
        std::vector<double> masses(_ids.size());
        for (std::size_t i = 0; i < masses.size(); ++i)
        {
            const std::size_t type = static_cast<std::size_t>(_values[typeField][i]);
            const auto mass = _masses.find(type);
            if (mass == _masses.end())
                _scanner.failAtLine(_massesLine, "Masses: no mass for type " + std::to_string(type) +
                                                     " (of the atom at line " + std::to_string(_lines[i]) +
                                                     ")");
            masses[i] = mass->second;
        }
        return masses;
    }

    TextScanner& _scanner;
    int64_t _timestep = 0;
    uint64_t _atoms = 0;
    uint64_t _types = 0;
    double _lo[3] = {0.0, 0.0, 0.0};
    double _hi[3] = {0.0, 0.0, 0.0};
    bool _hasBounds[3] = {false, false, false};
    osg::Vec3d _tilt = osg::Vec3d(0.0, 0.0, 0.0);
    std::map<uint64_t, double> _masses;
    uint64_t _massesLine = 0;
    uint64_t _atomsLine = 0;
    /** The Atoms fields, each atom's values of them, its id and its line. */
    std::vector<std::string> _names;
    std::vector<std::vector<double>> _values;
    std::vector<int64_t> _ids;
    std::vector<uint64_t> _lines;
    std::vector<double> _velocities[3];
    std::size_t _velocityCount = 0;
    uint64_t _bondCount = 0;
    uint64_t _bondTypes = 0;
    uint64_t _bondsLine = 0;
    /** The bonds, by the rows of their atoms. */
    std::vector<std::pair<uint32_t, uint32_t>> _bonds;
    std::unordered_map<int64_t, std::size_t> _rowOfId;
};

}

void osgGlyphsData::readers::readLammpsData(TextScanner& scanner, PointDataset& dataset,
                                            const PointReadOptions& options)
{
    DataFile file(scanner);
    file.read();
    addOnlyFrame(scanner, dataset, options, file.finish(options.share).get());
}
