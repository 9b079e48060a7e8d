#include "FrameRange.h"

#include <algorithm>
#include <cstdlib>

namespace
{

/** The largest step taken, so that frame + step cannot overflow. */
const unsigned long long MAX_STEP = 1000000;

bool parseCount(const std::string& text, unsigned long long& value)
{
    if (text.empty() || text.size() > 18 || text.find_first_not_of("0123456789") != std::string::npos)
        return false;
    value = std::strtoull(text.c_str(), nullptr, 10);
    return true;
}

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
    const std::size_t colon = text.find(':');
    if (colon == std::string::npos)
        return false;
    const std::size_t second = text.find(':', colon + 1);
    const std::string last =
        text.substr(colon + 1, second == std::string::npos ? std::string::npos : second - colon - 1);
    unsigned long long first = 0, end = 0, step = 1;
    if (!parseCount(text.substr(0, colon), first) || (!last.empty() && !parseCount(last, end)) ||
        (second != std::string::npos && !parseCount(text.substr(second + 1), step)))
        return false;
    if (step == 0 || step > MAX_STEP || (!last.empty() && end < first))
        return false;
    range.first = static_cast<std::size_t>(first);
    range.last = last.empty() ? SIZE_MAX : static_cast<std::size_t>(end);
    range.step = static_cast<std::size_t>(step);
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
