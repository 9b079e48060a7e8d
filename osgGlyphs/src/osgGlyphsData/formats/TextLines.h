/* osgGlyphs - private: the lines of a text file read as a frame file (PDB, GRO), and what their
 * readers share: messages that name a line, fixed-column fields, categorical columns, elements. */

#ifndef OSGGLYPHS_FORMATS_TEXTLINES_H
#define OSGGLYPHS_FORMATS_TEXTLINES_H 1

#include "BinaryFile.h"

#include <osgGlyphsData/PointData>

#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace osgGlyphsData
{
namespace formats
{

/** Where in a text file a reader is, for messages: "<file>:<line>: frame <n>: <what>". */
struct TextPlace
{
    const std::string* path = nullptr;
    /** The frame (0-based, printed as such); SIZE_MAX while indexing the file. */
    std::size_t frame = SIZE_MAX;

    std::string describe(uint64_t line, const std::string& what) const;
    /** Throws FormatError with describe(line, what). */
    [[noreturn]] void fail(uint64_t line, const std::string& what) const;
};

/** The lines of a byte range of a file, read in blocks with pread (BinaryFile), so that any number
 * of readers may read one file at once. Lines come without their end ("\n" or "\r\n"); a last
 * line without "\n" is a line too. Holds a block plus the longest line. */
class TextLines
{
public:
    static constexpr std::size_t BlockSize = std::size_t(1) << 20;
    /** Longer lines are an error (a binary file, usually). */
    static constexpr std::size_t MaxLineLength = std::size_t(1) << 20;

    /** The lines of [begin, end) of file; the first is line linesBefore + 1 of the file. */
    TextLines(const BinaryFile& file, const TextPlace& place, uint64_t begin, uint64_t end,
              uint64_t linesBefore);

    /** The next line, valid until the next call; false at the end of the range. */
    bool next(std::string_view& line);

    /** Skips up to count lines without looking at them; returns how many there were. */
    uint64_t skip(uint64_t count);

    /** The file's number (from 1) of the line next() returned last, or of the last line skipped. */
    uint64_t getLineNumber() const { return _lineNumber; }
    /** Where that line starts in the file. */
    uint64_t getLineOffset() const { return _lineOffset; }
    /** Where the line after it starts. */
    uint64_t getOffset() const { return _bufferOffset + _begin; }

    const TextPlace& getPlace() const { return _place; }
    /** Throws "<file>:<line>: [frame <n>: ]<what>" at the line returned last. */
    [[noreturn]] void fail(const std::string& what) const { _place.fail(_lineNumber, what); }

private:
    /** Reads more of the range after what the buffer holds; false at the end of the range. */
    bool fill();
    /** The first "\n" of the buffer from index from on, or nullptr. */
    const char* findLineEnd(std::size_t from) const;

    const BinaryFile& _file;
    TextPlace _place;
    uint64_t _end;
    std::vector<char> _buffer;
    std::size_t _begin = 0;
    std::size_t _filled = 0;
    uint64_t _bufferOffset;
    uint64_t _lineNumber;
    uint64_t _lineOffset;
};

/** The characters [first, last] (1-based columns, as format specifications count them) of a line,
 * blanks trimmed; empty where the line is shorter. */
std::string_view columns(std::string_view line, std::size_t first, std::size_t last);

/** The value of a number field (blanks around it allowed); fails at the line with "columns a-b
 * (<what>): '<field>' is not a number" (or "... is not a finite number", "... is out of the range of
 * a float"). */
double parseFixedNumber(const TextLines& lines, std::string_view field, std::size_t first, std::size_t last,
                        const char* what);

/** An integer of a fixed-width field of width digits: decimal, or hybrid-36 (what writers put in
 * PDB's 5-column serials past 99999: A0000 is 100000); fails at the line like parseFixedNumber(). */
int64_t parseFixedInteger(const TextLines& lines, std::string_view field, std::size_t first, std::size_t last,
                          const char* what);

/** A categorical column filled as labels come: the index of each label's first appearance. */
class LabelColumn
{
public:
    void reserve(std::size_t count) { _values.reserve(count); }
    void append(std::string_view label);
    /** Adds the column, with its labels, to frame. */
    void addTo(PointData& frame, const std::string& name);

private:
    std::vector<float> _values;
    std::vector<std::string> _labels;
    std::map<std::string, float, std::less<>> _indices;
};

/** The atomic number of an atom from its element symbol, or where that is blank from its name, as
 * PDB readers guess it: a name in mixed case ("Cl", "Ar") is its element; in a PDB name field
 * (pdbField: the 4 columns 13-16, not trimmed) the symbol is right-justified in columns 13-14, so
 * that " CA " is carbon and "CA  " calcium, and 4-character names starting with H are hydrogens;
 * leading digits ("1HB") are passed over. Elsewhere (GRO) an atom named as its residue is an ion
 * of a two-letter element (NA in NA, CL in CL), and otherwise the first letter decides where it is
 * an element (N, O, C, ...), else the first two. 0 when no element fits. */
unsigned int guessElement(std::string_view element, std::string_view name, bool pdbField,
                          std::string_view residue = std::string_view());

/** Adds "element" (atomic numbers) and "species" (their symbols as labels; the atom's name where
 * the element is unknown) from the atoms' numbers and names. */
class ElementColumns
{
public:
    void reserve(std::size_t count);
    void append(unsigned int element, std::string_view name);
    void addTo(PointData& frame);

private:
    std::vector<float> _elements;
    LabelColumn _species;
};

} // namespace formats
}

#endif
