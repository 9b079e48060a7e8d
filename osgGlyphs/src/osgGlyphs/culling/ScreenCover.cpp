#include "ScreenCover.h"

#include <algorithm>

using namespace osgGlyphs::detail;

namespace
{

const int CELL = SCREEN_COVER_CELL_PIXELS;

/** The cells a chunk covers, inclusive. */
struct CellRange
{
    int x0, y0, x1, y1;
};

CellRange coveredCells(const ChunkInView& chunk, int width, int height)
{
    // The last whole cell before the pixel after `last`, or the view's last cell at its edge.
    const auto lastCell = [](int last, int size)
    { return last + 1 >= size ? (size - 1) / CELL : (last + 1) / CELL - 1; };
    CellRange cells{(chunk.x0 + CELL - 1) / CELL, (chunk.y0 + CELL - 1) / CELL, lastCell(chunk.x1, width),
                    lastCell(chunk.y1, height)};
    if (cells.x0 > cells.x1 || cells.y0 > cells.y1)
    {
        cells.x0 = cells.x1 = std::clamp((chunk.x0 + chunk.x1) / 2, 0, width - 1) / CELL;
        cells.y0 = cells.y1 = std::clamp((chunk.y0 + chunk.y1) / 2, 0, height - 1) / CELL;
    }
    return cells;
}

}

std::size_t osgGlyphs::detail::putScreenCoverFirst(std::vector<ChunkInView>& inView, int width, int height)
{
    if (width <= 0 || height <= 0)
        return 0;
    const int columns = (width + CELL - 1) / CELL;
    const int rows = (height + CELL - 1) / CELL;
    std::vector<unsigned char> covered(std::size_t(columns) * std::size_t(rows), 0);
    const auto cell = [&](int x, int y) -> unsigned char&
    { return covered[std::size_t(y) * std::size_t(columns) + std::size_t(x)]; };
    std::vector<bool> covers(inView.size(), false);
    for (std::size_t k = 0; k < inView.size(); ++k)
    {
        const CellRange cells = coveredCells(inView[k], width, height);
        bool uncovered = false;
        for (int y = cells.y0; y <= cells.y1 && !uncovered; ++y)
            for (int x = cells.x0; x <= cells.x1 && !uncovered; ++x)
                uncovered = !cell(x, y);
        if (!uncovered)
            continue;
        covers[k] = true;
        for (int y = cells.y0; y <= cells.y1; ++y)
            for (int x = cells.x0; x <= cells.x1; ++x)
                cell(x, y) = 1;
    }
    std::vector<ChunkInView> reordered;
    reordered.reserve(inView.size());
    for (bool first : {true, false})
        for (std::size_t k = 0; k < inView.size(); ++k)
            if (covers[k] == first)
                reordered.push_back(inView[k]);
    inView.swap(reordered);
    return std::size_t(std::count(covers.begin(), covers.end(), true));
}
