/* osgGlyphs - private: finding columns of a frame by name, and naming them in messages. Not installed. */

#ifndef OSGGLYPHS_POINTCOLUMNS_H
#define OSGGLYPHS_POINTCOLUMNS_H 1

#include <osgGlyphsData/PointData>

#include <string>
#include <vector>

namespace osgGlyphsData
{
namespace detail
{

/** "available columns: a b c", or "the frame has no columns": the end of a message about a
 * column the frame lacks. */
std::string listColumns(const PointData& data);

/** A column's values in the file's units, as floats: the stored values where the column's
 * origin is 0, a copy with the origin added otherwise (see PointData::getColumnOrigin()). */
class ColumnValues
{
public:
    ColumnValues() = default;
    ColumnValues(const ColumnValues&) = delete;
    ColumnValues& operator=(const ColumnValues&) = delete;

    /** False, and invalid, when the frame has no column of that name. */
    bool assign(const PointData& data, const std::string& name);
    bool valid() const { return _values != nullptr; }
    const std::vector<float>& operator*() const { return *_values; }
    const std::vector<float>* operator->() const { return _values; }

private:
    const std::vector<float>* _values = nullptr;
    std::vector<float> _shifted;
};

/** The three columns of names; false when names are not three or the frame lacks one of them. */
bool getColumnTriple(const PointData& data, const std::vector<std::string>& names, ColumnValues columns[3]);

/** The index of the first of candidates (triples of names) that the frame has all three of; -1
 * when it has none of them. */
int findColumnTriple(const PointData& data, const std::vector<std::vector<std::string>>& candidates);

}
}

#endif
