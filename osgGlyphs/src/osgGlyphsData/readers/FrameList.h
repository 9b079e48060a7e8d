/* osgGlyphs - private: the frames of a multi-frame format (XYZ, LAMMPS) as a reader finds them. */

#ifndef OSGGLYPHS_READERS_FRAMELIST_H
#define OSGGLYPHS_READERS_FRAMELIST_H 1

#include "TextScanner.h"

#include <osgGlyphsData/PointReader>

#include <cstdint>
#include <string>

namespace osgGlyphsData
{
namespace readers
{

/** Adds the frames of a multi-frame file to the dataset as the reader completes them, and keeps
 * the dataset's end of complete frames. Frames without points are left out: they would cost
 * memory and show nothing; one warning counts them. A last frame that the stream cuts short
 * (a dump still being written) is left out with a warning, when frames before it were read. */
class FrameList
{
public:
    FrameList(TextScanner& scanner, PointDataset& dataset, const PointReadOptions& options);

    /** The index in the file of the frame being read, from 0: frames left out and the frames
     * before PointReadOptions::start count too. */
    uint64_t getFileFrame() const { return _fileFrame; }

    /** True when the dataset has PointReadOptions::maxFrames frames: the reader stops. */
    bool isFull() const { return _options.maxFrames > 0 && _dataset.getNumFrames() >= _options.maxFrames; }

    /** A frame the reader has read to its end, whose first line was firstLine and which holds
     * filePoints points in the file (of which frame holds its share). In a growing file a frame
     * whose last line has no end yet is incomplete: it is left out, with a warning. A frame
     * without points in the file is left out; an empty share of a frame is kept, so that every
     * share has the same frames. */
    void add(PointData* frame, uint64_t firstLine, uint64_t filePoints);

    /** True when error is the stream ending inside the frame being read, and that frame may be
     * left out: frames were read before it, or the reading may be empty (a growing file, or a
     * start after the first frame). The warning then names the frame. */
    bool leavesOutCutFrame(const ReadError& error);

    /** After the last frame: warns about the frames without points. Fails when no frame has
     * points and the reading may not be empty: naming the empty frames if there were any, else
     * with noFrames. */
    void finish(const std::string& noFrames);

private:
    TextScanner& _scanner;
    PointDataset& _dataset;
    const PointReadOptions& _options;
    uint64_t _fileFrame;
    uint64_t _emptyFrames = 0;
    uint64_t _firstEmptyFrame = 0;
    uint64_t _firstEmptyLine = 0;
};

} // namespace readers
}

#endif
