/* osgglyphconvert: the frames of a trajectory that --frame and --frame-range name. */

#ifndef OSGGLYPHCONVERT_FRAMERANGE_H
#define OSGGLYPHCONVERT_FRAMERANGE_H 1

#include <osgGlyphsData/FrameSource>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

/** Frames first to last, every step-th, counted from 0, and the option that named them. */
struct FrameRange : osgGlyphsData::FrameRange
{
    FrameRange() { last = 0; }
    /** The option as given ("--frame-range 0:30:10", "--frame 7"), for messages. */
    std::string option = "--frame 0";

    /** Whether the range may hold more than one frame: "a:" may, whatever the file. */
    bool mayHoldSeveral() const { return last == SIZE_MAX || last - first >= step; }
};

/** Parses --frame-range's "a:b", "a:b:step" or "a:" (osgGlyphsData::parseFrameRange); false when
 * it is none of them. */
bool parseFrameRange(const std::string& text, FrameRange& range);

/** The frames of the range in a file of numFrames frames; empty, with a one-line error naming
 * the option and the file, when a frame it names lies past the file's last. */
std::vector<std::size_t> listFrames(const FrameRange& range, const std::string& file, std::size_t numFrames,
                                    std::string& error);

#endif
