/* osgGlyphs - private: the point readers, one per format, behind osgGlyphs/PointReader. */

#ifndef OSGGLYPHS_READERS_READERS_H
#define OSGGLYPHS_READERS_READERS_H 1

#include "TextScanner.h"

#include <osgGlyphsData/PointReader>

namespace osgGlyphsData
{
namespace readers
{

/** Whether a reading may find no frame: of a growing file, or after options.start. */
inline bool mayReadNothing(const PointReadOptions& options)
{
    return options.growing || options.start.frame > 0 || options.start.offset > 0;
}

/** Adds the frame of a single-frame format: its complete frames end where the stream ends. */
inline void addOnlyFrame(const TextScanner& scanner, PointDataset& dataset, const PointReadOptions& options,
                         PointData* frame)
{
    dataset.addFrame(frame);
    dataset.setEndOfCompleteFrames({scanner.getOffset(), scanner.getLineNumber(), options.start.frame + 1});
}

/** Each reader fills dataset with the frames of the scanner's stream, or throws ReadError. */
void readCsv(TextScanner& scanner, PointDataset& dataset, const PointReadOptions& options);
void readXyz(TextScanner& scanner, PointDataset& dataset, const PointReadOptions& options);
void readLammps(TextScanner& scanner, PointDataset& dataset, const PointReadOptions& options);
void readPly(TextScanner& scanner, PointDataset& dataset, const PointReadOptions& options);
void readVtk(TextScanner& scanner, PointDataset& dataset, const PointReadOptions& options);
void readLammpsData(TextScanner& scanner, PointDataset& dataset, const PointReadOptions& options);

} // namespace readers
}

#endif
