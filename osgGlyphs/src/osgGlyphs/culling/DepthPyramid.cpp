#include "DepthPyramid.h"

#include <algorithm>

using namespace osgGlyphs::detail;

void DepthPyramid::build(std::vector<float> depth, int width, int height)
{
    if (width <= 0 || height <= 0 || depth.size() < size_t(width) * size_t(height))
    {
        clear();
        return;
    }
    std::copy_n(depth.begin(), size_t(width) * size_t(height), resetImage(width, height));
    buildLevels();
}

void DepthPyramid::clear()
{
    _widths.clear();
    _heights.clear();
}

float* DepthPyramid::resetImage(int width, int height)
{
    _widths.assign(1, std::max(width, 0));
    _heights.assign(1, std::max(height, 0));
    if (_levels.empty())
        _levels.resize(1);
    _levels[0].resize(size_t(_widths[0]) * size_t(_heights[0]));
    return _levels[0].data();
}

namespace
{

/** The farthest depth over fine pixels [x0, x1) x [y0, y1). */
float farthestOver(const float* fine, int fineWidth, int x0, int x1, int y0, int y1)
{
    float farthest = 0.0f;
    for (int fy = y0; fy < y1; ++fy)
        for (int fx = x0; fx < x1; ++fx)
            farthest = std::max(farthest, fine[size_t(fy) * fineWidth + fx]);
    return farthest;
}

}

void DepthPyramid::buildLevels()
{
    if (_widths.empty() || _widths[0] <= 0 || _heights[0] <= 0)
    {
        clear();
        return;
    }
    _widths.resize(1);
    _heights.resize(1);
    // Each level's storage is kept from the last build: a read-back a round allocates nothing.
    for (size_t level = 1; _widths.back() > 1 || _heights.back() > 1; ++level)
    {
        const int fineWidth = _widths.back(), fineHeight = _heights.back();
        const int w = std::max(1, fineWidth / 2), h = std::max(1, fineHeight / 2);
        if (_levels.size() <= level)
            _levels.resize(level + 1);
        _levels[level].resize(size_t(w) * size_t(h));
        const float* fine = _levels[level - 1].data();
        float* coarse = _levels[level].data();
        for (int y = 0; y < h; ++y)
        {
            // The last row and column also take what rounding down leaves over.
            const bool lastRow = y == h - 1;
            const int yEnd = lastRow ? fineHeight : 2 * y + 2;
            const float* row0 = fine + size_t(2 * y) * fineWidth;
            const float* row1 = row0 + (fineHeight > 1 ? fineWidth : 0);
            if (lastRow && yEnd - 2 * y != 2)
                for (int x = 0; x + 1 < w; ++x)
                    coarse[size_t(y) * w + x] = farthestOver(fine, fineWidth, 2 * x, 2 * x + 2, 2 * y, yEnd);
            else
                for (int x = 0; x + 1 < w; ++x)
                    coarse[size_t(y) * w + x] = std::max(std::max(row0[2 * x], row0[2 * x + 1]),
                                                         std::max(row1[2 * x], row1[2 * x + 1]));
            coarse[size_t(y) * w + w - 1] =
                farthestOver(fine, fineWidth, 2 * (w - 1), fineWidth, 2 * y, yEnd);
        }
        _widths.push_back(w);
        _heights.push_back(h);
    }
}

int DepthPyramid::levelFor(int x0, int y0, int x1, int y1, int texels)
{
    int level = 0;
    while (((x1 >> level) - (x0 >> level)) >= texels || ((y1 >> level) - (y0 >> level)) >= texels)
        ++level;
    return level;
}

float DepthPyramid::farthest(int x0, int y0, int x1, int y1, int texels) const
{
    x0 = std::max(x0, 0);
    y0 = std::max(y0, 0);
    x1 = std::min(x1, _widths[0] - 1);
    y1 = std::min(y1, _heights[0] - 1);
    if (x0 > x1 || y0 > y1)
        return 0.0f;
    const int level = std::min(levelFor(x0, y0, x1, y1, texels), getNumLevels() - 1);
    const int w = _widths[level], h = _heights[level];
    const float* values = _levels[level].data();
    float farthest = 0.0f;
    for (int y = std::min(y0 >> level, h - 1); y <= std::min(y1 >> level, h - 1); ++y)
        for (int x = std::min(x0 >> level, w - 1); x <= std::min(x1 >> level, w - 1); ++x)
            farthest = std::max(farthest, values[size_t(y) * w + x]);
    return farthest;
}
