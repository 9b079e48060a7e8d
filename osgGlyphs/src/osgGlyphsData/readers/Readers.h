/* osgGlyphs - private: the point readers, one per format, behind osgGlyphs/PointReader. */

#ifndef OSGGLYPHS_READERS_READERS_H
#define OSGGLYPHS_READERS_READERS_H 1

#include "TextScanner.h"

#include <osgGlyphsData/PointData>

namespace osgGlyphsData
{
namespace readers
{

/** Each reader fills dataset with the frames of the scanner's stream, or throws ReadError. */
void readCsv(TextScanner& scanner, PointDataset& dataset);
void readXyz(TextScanner& scanner, PointDataset& dataset);
void readLammps(TextScanner& scanner, PointDataset& dataset);
void readPly(TextScanner& scanner, PointDataset& dataset);
void readVtk(TextScanner& scanner, PointDataset& dataset);

} // namespace readers
}

#endif
