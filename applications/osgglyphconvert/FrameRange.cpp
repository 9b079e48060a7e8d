#include "FrameRange.h"

#include <algorithm>

namespace
{

/** "11 frames, 0 to 10" */
std::string describeFrames(std::size_t count)
{
    if (count < 2)
        return std::to_string(count) + (count == 1 ? " frame, 0" : " frames");
    return std::to_string(count) + " frames, 0 to " + std::to_string(count - 1);
}

}

bool parseFrameRange(const std::string& text, FrameRange& range)
{
    if (!osgGlyphsData::parseFrameRange(text, range))
        return false;
    range.option = "--frame-range " + text;
    return true;
}

std::vector<std::size_t> listFrames(const FrameRange& range, const std::string& file, std::size_t numFrames,
                                    std::string& error)
{
    std::vector<std::size_t> frames;
    if (range.first >= numFrames || (range.last != SIZE_MAX && range.last >= numFrames))
    {
        error = range.option + " is past the last frame of " + file + " (" + describeFrames(numFrames) + ")";
        return frames;
    }
    const std::size_t last = std::min(range.last, numFrames - 1);
    for (std::size_t frame = range.first; frame <= last; frame += range.step)
    {
        frames.push_back(frame);
        if (last - frame < range.step)
            break;
    }
    return frames;
}
