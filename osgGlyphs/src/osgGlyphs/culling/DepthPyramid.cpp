#include "DepthPyramid.h"

#include <algorithm>

using namespace osgGlyphs::detail;

void DepthPyramid::build(std::vector<float> depth, int width, int height)
{
    _levels.clear();
    _widths.clear();
    _heights.clear();
    if (width <= 0 || height <= 0 || depth.size() < size_t(width) * size_t(height))
        return;
    _levels.push_back(std::move(depth));
    _widths.push_back(width);
    _heights.push_back(height);
    while (_widths.back() > 1 || _heights.back() > 1)
    {
        const std::vector<float>& fine = _levels.back();
        const int fineWidth = _widths.back(), fineHeight = _heights.back();
        const int w = std::max(1, fineWidth / 2), h = std::max(1, fineHeight / 2);
        std::vector<float> coarse(size_t(w) * size_t(h));
        for (int y = 0; y < h; ++y)
        {
            // The last row and column take what rounding down leaves over.
            const int yEnd = y == h - 1 ? fineHeight : 2 * y + 2;
            for (int x = 0; x < w; ++x)
            {
                const int xEnd = x == w - 1 ? fineWidth : 2 * x + 2;
                float farthest = 0.0f;
                for (int fy = 2 * y; fy < yEnd; ++fy)
                    for (int fx = 2 * x; fx < xEnd; ++fx)
                        farthest = std::max(farthest, fine[size_t(fy) * fineWidth + fx]);
                coarse[size_t(y) * w + x] = farthest;
            }
        }
        _levels.push_back(std::move(coarse));
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
    const std::vector<float>& values = _levels[level];
    float farthest = 0.0f;
    for (int y = std::min(y0 >> level, h - 1); y <= std::min(y1 >> level, h - 1); ++y)
        for (int x = std::min(x0 >> level, w - 1); x <= std::min(x1 >> level, w - 1); ++x)
            farthest = std::max(farthest, values[size_t(y) * w + x]);
    return farthest;
}
