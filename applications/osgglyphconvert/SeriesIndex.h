/* osgglyphconvert: a time series of tile archives (--frame-range ... out.osgt): one archive per
 * frame beside an index, a TileSeries, that osgglyphviewer and osgDB read. */

#ifndef OSGGLYPHCONVERT_SERIESINDEX_H
#define OSGGLYPHCONVERT_SERIESINDEX_H 1

#include <osgGlyphsTiles/TileSeries>

#include <string>

/** Whether output names a series index (.osgt or .osgb) rather than an archive or a pattern. */
bool isSeriesIndex(const std::string& output);

/** The pattern of the frames' archives of the index at output: out.osgt -> out_%06d.osga. */
std::string seriesFramePattern(const std::string& output);

/** Writes series (its frames named relative to output's folder) to output; false with error. */
bool writeSeriesIndex(const osgGlyphsTiles::TileSeries& series, const std::string& output,
                      std::string& error);

#endif
