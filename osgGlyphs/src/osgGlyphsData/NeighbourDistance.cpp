#include "NeighbourDistance.h"

#include <osg/BoundingBox>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace
{

/** Point indices sorted into a uniform grid of about as many cells as points. */
class PointGrid
{
public:
    PointGrid(const std::vector<osg::Vec3f>& positions, const std::vector<uint32_t>& indices,
              const osg::BoundingBox& box)
        : _positions(positions), _origin(box._min)
    {
        const osg::Vec3f extent = box._max - box._min;
        const float largest = std::max(extent.x(), std::max(extent.y(), extent.z()));
        const double cellLimit = 2.0 * indices.size() + 8.0;
        double volume = 1.0;
        for (int axis = 0; axis < 3; ++axis)
            volume *= std::max(extent[axis], largest * 1e-3f);
        _cellSize = static_cast<float>(std::cbrt(volume / indices.size()));
        while (true)
        {
            double cells = 1.0;
            for (int axis = 0; axis < 3; ++axis)
            {
                _dims[axis] = std::max(1, static_cast<int>(std::ceil(extent[axis] / _cellSize)));
                cells *= _dims[axis];
            }
            if (cells <= cellLimit)
                break;
            _cellSize *= 1.25f;
        }

        // Counting sort of the points by cell.
        _cellStart.assign(static_cast<std::size_t>(_dims[0]) * _dims[1] * _dims[2] + 1, 0);
        for (uint32_t index : indices)
            ++_cellStart[cellIndex(cellOf(positions[index])) + 1];
        for (std::size_t cell = 1; cell < _cellStart.size(); ++cell)
            _cellStart[cell] += _cellStart[cell - 1];
        _sorted.resize(indices.size());
        std::vector<uint32_t> next(_cellStart.begin(), _cellStart.end() - 1);
        for (uint32_t index : indices)
            _sorted[next[cellIndex(cellOf(positions[index]))]++] = index;
    }

    /** The squared distance from point index to its nearest neighbour at a distance > 0, or
     * infinity when none is found within a bounded search. */
    float nearestDistance2(uint32_t index) const
    {
        const osg::Vec3f& p = _positions[index];
        const Cell centre = cellOf(p);
        const int maxRing = std::max(_dims[0], std::max(_dims[1], _dims[2]));
        const std::size_t cellBudget = 50000;
        std::size_t cellsVisited = 0;
        float best = std::numeric_limits<float>::infinity();
        for (int ring = 0; ring <= maxRing && cellsVisited < cellBudget; ++ring)
        {
            for (int i = centre.i - ring; i <= centre.i + ring; ++i)
                for (int j = centre.j - ring; j <= centre.j + ring; ++j)
                    for (int k = centre.k - ring; k <= centre.k + ring; ++k)
                    {
                        const bool onShell = std::abs(i - centre.i) == ring ||
                                             std::abs(j - centre.j) == ring || std::abs(k - centre.k) == ring;
                        if (!onShell || i < 0 || j < 0 || k < 0 || i >= _dims[0] || j >= _dims[1] ||
                            k >= _dims[2])
                            continue;
                        ++cellsVisited;
                        const std::size_t cell = cellIndex(Cell{i, j, k});
                        for (uint32_t s = _cellStart[cell]; s < _cellStart[cell + 1]; ++s)
                        {
                            const float d2 = (_positions[_sorted[s]] - p).length2();
                            if (d2 > 0.0f && d2 < best)
                                best = d2;
                        }
                    }
            // Points beyond this ring are at least ring cells away.
            const float reach = ring * _cellSize;
            if (best <= reach * reach)
                break;
        }
        return best;
    }

private:
    struct Cell
    {
        int i, j, k;
    };

    Cell cellOf(const osg::Vec3f& p) const
    {
        auto axis = [&](int a)
        {
            const int c = static_cast<int>((p[a] - _origin[a]) / _cellSize);
            return std::min(std::max(c, 0), _dims[a] - 1);
        };
        return Cell{axis(0), axis(1), axis(2)};
    }

    std::size_t cellIndex(const Cell& cell) const
    {
        return (static_cast<std::size_t>(cell.k) * _dims[1] + cell.j) * _dims[0] + cell.i;
    }

    const std::vector<osg::Vec3f>& _positions;
    osg::Vec3f _origin;
    float _cellSize = 1.0f;
    int _dims[3] = {1, 1, 1};
    std::vector<uint32_t> _cellStart;
    std::vector<uint32_t> _sorted;
};

}

float osgGlyphsData::detail::estimateNeighbourDistance(const std::vector<osg::Vec3f>& positions,
                                                       unsigned int maxSamples)
{
    std::vector<uint32_t> finite;
    finite.reserve(positions.size());
    osg::BoundingBox box;
    for (std::size_t i = 0; i < positions.size() && i < std::numeric_limits<uint32_t>::max(); ++i)
    {
        const osg::Vec3f& p = positions[i];
        if (std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z()))
        {
            finite.push_back(static_cast<uint32_t>(i));
            box.expandBy(p);
        }
    }
    if (finite.size() < 2 || box._min == box._max)
        return 0.0f;

    const PointGrid grid(positions, finite, box);
    const std::size_t stride = std::max<std::size_t>(1, finite.size() / std::max(1u, maxSamples));
    std::vector<float> distances2;
    for (std::size_t s = 0; s < finite.size(); s += stride)
    {
        const float d2 = grid.nearestDistance2(finite[s]);
        if (std::isfinite(d2))
            distances2.push_back(d2);
    }
    if (distances2.empty())
        return 0.0f;
    auto median = distances2.begin() + distances2.size() / 2;
    std::nth_element(distances2.begin(), median, distances2.end());
    return std::sqrt(*median);
}
