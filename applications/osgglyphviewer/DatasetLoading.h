// osgglyphviewer: reading a point file, with progress on stderr.

#ifndef OSGGLYPHVIEWER_DATASETLOADING_H
#define OSGGLYPHVIEWER_DATASETLOADING_H 1

#include <osgGlyphsData/PointData>

#include <string>

/** Reads every frame of a point file through osgGlyphsData::readPointFile, in the named format or the
 * one of its extension. Files of PROGRESS_MIN_BYTES or more show a progress indicator on stderr
 * (a line updated in place on a terminal) and end with a line of the bytes, time and throughput.
 * Returns nullptr with the reader's one-line error ("<file>:<line>: <what>"). */
osg::ref_ptr<osgGlyphsData::PointDataset> loadDataset(const std::string& file, const std::string& format,
                                                      std::string& error);

/** The size from which loading shows its progress: 16 MiB. */
const unsigned long long PROGRESS_MIN_BYTES = 16ull << 20;

#endif
