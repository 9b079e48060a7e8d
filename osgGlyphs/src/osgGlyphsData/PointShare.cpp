#include <osgGlyphsData/PointShare>

using namespace osgGlyphsData;

bool osgGlyphsData::checkPointShare(const PointShare& share, std::string& error)
{
    if (share.count == 0)
        error = "share " + std::to_string(share.index) + " of 0: a dataset splits into at least 1 share";
    else if (share.index >= share.count)
        error = "share " + std::to_string(share.index) + " of " + std::to_string(share.count) +
                ": shares are counted from 0 to " + std::to_string(share.count - 1);
    else
        return true;
    return false;
}

PointRange osgGlyphsData::getShareRange(const PointShare& share, uint64_t total)
{
    // total * index / count without overflow: total = q * count + r.
    const auto begin = [&](uint64_t index)
    {
        const uint64_t q = total / share.count, r = total % share.count;
        return q * index + r * index / share.count;
    };
    if (share.count == 0 || share.index >= share.count)
        return PointRange{0, 0};
    return PointRange{begin(share.index), begin(share.index + 1)};
}

void ShareReduction::minimum(std::vector<double>&) const {}

void ShareReduction::maximum(std::vector<double>&) const {}

void ShareReduction::sum(std::vector<double>&) const {}

void ShareReduction::gather(std::vector<double>&) const {}

void ShareReduction::gather(std::vector<std::string>&) const {}

PointShare ShareReduction::getShare() const
{
    return PointShare();
}
