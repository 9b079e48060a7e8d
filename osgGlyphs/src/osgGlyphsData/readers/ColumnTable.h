/* osgGlyphs - private: the columns of one frame while a reader fills them. */

#ifndef OSGGLYPHS_READERS_COLUMNTABLE_H
#define OSGGLYPHS_READERS_COLUMNTABLE_H 1

#include "TextScanner.h"

#include <osgGlyphsData/PointData>
#include <osgGlyphsData/PointShare>

#include <cstddef>
#include <functional>
#include <map>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace osgGlyphsData
{
namespace readers
{

/** Column names for a property of count components: name itself for 1; name_x, name_y, name_z
 * for 3; name_0 .. name_{count-1} otherwise. */
std::vector<std::string> componentNames(const std::string& name, std::size_t count);

/** Named float columns of one frame, filled row by row from text fields or binary values.
 * Every bad value throws through the scanner, naming the column, at the scanner's current line
 * (text) or at the given byte offset (binary).
 *
 * Numbers are read in double precision. A numeric column whose first value (row 0 of the file,
 * in every share) is FarFromZero or more from zero gets that value, rounded to an integer, as its
 * origin, and keeps the offsets from it (PointData::getColumnOrigin()): coordinates 1e7 from zero
 * keep their decimals. A value farther from the origin than from zero takes the column back to
 * plain values. */
class ColumnTable
{
public:
    /** How a text field becomes a float. */
    enum Kind
    {
        Number,   ///< a finite number
        Species,  ///< a chemical symbol: becomes columns "element" (atomic number) and "species"
        Category, ///< any string: the index of its first appearance, labels kept
        Logical   ///< T/F, True/False, 1/0: 1 or 0
    };

    /** More columns than this are refused (a header of garbage, usually). */
    static constexpr std::size_t MaxColumns = 4096;

    /** More distinct labels in a column are refused: category indices are stored as floats,
     * beyond 2^24 they would no longer be exact. */
    static constexpr std::size_t MaxLabels = std::size_t(1) << 24;

    /** Where float values lose a thousandth of a unit (2^16: floats step by 1/128 there). */
    static constexpr double FarFromZero = 65536.0;

    /** A table of the rows of share: with setRowCount(), the share's range of the rows (see
     * getShareRange()); without, every share.count-th row from row share.index. The other rows are
     * counted and skipped unparsed. */
    explicit ColumnTable(TextScanner& scanner, const PointShare& share = PointShare());

    /** The number of rows the file says the table has, which decides the rows of the share. */
    void setRowCount(uint64_t rows);

    /** Adds a column; fails at the scanner's current line when the name (or, for Species, one of
     * "element" and "species") is taken or empty. Returns its index. */
    std::size_t addColumn(const std::string& name, Kind kind = Number);

    /** True when a column (or a Species column's "element" or "species") has that name. */
    bool hasColumn(const std::string& name) const { return _outputNames.count(name) != 0; }

    std::size_t getNumColumns() const { return _columns.size(); }
    const std::string& getName(std::size_t column) const { return _columns[column].name; }
    std::size_t getNumRows() const { return _columns.empty() ? _rows : _columns[0].values.size(); }

    void reserve(std::size_t rows);

    /** Appends one row from a line of blank-separated fields, exactly one per column. */
    void appendRow(std::string_view line);

    /** Reads rows done .. count-1 with appendRow() (the first done rows were appended already). At
     * the end of the file fails naming section and how many rows it had; a line starting with
     * stopMarker (when not empty) fails the same way. */
    void readRows(uint64_t done, uint64_t count, const std::string& section,
                  std::string_view stopMarker = std::string_view());

    /** Appends one text field to a column. */
    void appendField(std::size_t column, std::string_view field);

    /** Chooses the origins of the numeric columns from the fields of row 0 of the file, for a
     * share that does not read that row as its own (a share that starts past it). */
    void chooseOrigins(const std::vector<std::string_view>& fields);

    /** Appends one binary value read at offset. */
    void appendValue(std::size_t column, double value, uint64_t offset);

    /** Appends rows consecutive rows of binary values, given column after column: values[c * rows
     * + r] is row r of column c. Appends the leading rows whose values need nothing but storing
     * (no failure, no change of origin; rows the table keeps, after row 0) and returns how many:
     * the caller appends the next row with appendValue(). All columns must be Number columns at
     * the same row. */
    std::size_t appendRows(const double* values, std::size_t rows);

    /** Whether the table keeps row (of the file, from 0): it is in the share. */
    bool keepsRow(uint64_t row) const { return keeps(row); }

    /** How many rows from row on (before end) the table keeps one after the other. */
    uint64_t getKeptRun(uint64_t row, uint64_t end) const;

    /** The first row from row on (at most end) that the table keeps. */
    uint64_t getNextKeptRow(uint64_t row, uint64_t end) const;

    /** Counts count rows of other shares as read, without their values. */
    void skipRows(uint64_t count);

    /** For tables without columns: counts rows. */
    void addEmptyRows(uint64_t count) { _rows += static_cast<std::size_t>(count); }

    /** Fails at the current line because it has fieldCount fields instead of one per column. */
    [[noreturn]] void failFieldCount(std::size_t fieldCount) const;

    /** Moves the columns into a new frame. */
    osg::ref_ptr<PointData> finish();

private:
    struct Column
    {
        std::string name;
        Kind kind;
        std::vector<float> values;
        uint64_t seen = 0; // rows of the file, in the share and out of it
        double origin = 0.0;
        bool originChosen = false;
        std::vector<std::string> labels;
        std::map<std::string, float, std::less<>> indices;
    };

    /** Whether the table keeps row (of the file, from 0): it is in the share. */
    bool keeps(uint64_t row) const
    {
        return _hasRowCount ? row >= _range.begin && row < _range.end : row % _share.count == _share.index;
    }
    void appendLabel(Column& column, std::string_view field);
    /** Appends a finite number within the range of a float. */
    static void appendNumber(Column& column, double value);
    /** The origin of a column from its value in row 0 of the file, in every share alike. */
    static void chooseOrigin(Column& column, double value);
    /** The same from a field of row 0 that the share does not hold: a bad field leaves the column
     * without an origin (the share that holds it reports it). */
    static void chooseOrigin(Column& column, std::string_view field);

    TextScanner& _scanner;
    std::vector<Column> _columns;
    std::set<std::string> _outputNames;
    std::size_t _rows;
    PointShare _share;
    bool _hasRowCount = false;
    PointRange _range;
};

} // namespace readers
}

#endif
