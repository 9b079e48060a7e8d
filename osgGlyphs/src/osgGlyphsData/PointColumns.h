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

/** The three columns of names; false when names are not three or the frame lacks one of them. */
bool getColumnTriple(const PointData& data, const std::vector<std::string>& names,
                     const std::vector<float>* columns[3]);

/** The columns of the first of candidates (triples of names) that the frame has all three of,
 * and that candidate's index; -1 when it has none of them. */
int findColumnTriple(const PointData& data, const std::vector<std::vector<std::string>>& candidates,
                     const std::vector<float>* columns[3]);

}
}

#endif
