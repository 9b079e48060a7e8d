#include "NeighbourDistance.h"

#include <osg/Vec3d>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>

namespace
{

/** The work one nearest-neighbour search may do: every ring of cells it goes through, cell it
 * looks into and point it compares counts one. 2000 samples take at most 10 million steps. */
const std::size_t SEARCH_BUDGET = 5000;

/** Points in a cell beyond which the grid keeps one point of each position. */
const std::ptrdiff_t CROWDED_CELL = 8;

/** Cells of the grid at most, whatever the number of points: any axis count fits an int. */
const double MAX_CELLS = 1 << 30;

osg::Vec3d toDouble(const osg::Vec3f& p)
{
    return osg::Vec3d(p.x(), p.y(), p.z());
}

bool lessByPosition(const osg::Vec3f& a, const osg::Vec3f& b)
{
    return a.x() != b.x() ? a.x() < b.x() : a.y() != b.y() ? a.y() < b.y() : a.z() < b.z();
}

/** Points sorted into a uniform grid of about as many cells as points. Geometry is in
 * double: the extent of float positions can exceed the range of a float. */
class PointGrid
{
public:
    PointGrid(const std::vector<osg::Vec3f>& positions, const std::vector<uint32_t>& indices,
              const osg::Vec3d& boxMin, const osg::Vec3d& boxMax)
        : _positions(positions), _origin(boxMin)
    {
        const osg::Vec3d extent = boxMax - boxMin;
        const double largest = std::max(extent.x(), std::max(extent.y(), extent.z()));
        const double cellLimit = std::min(2.0 * indices.size() + 8.0, MAX_CELLS);
        double volume = 1.0;
        for (int axis = 0; axis < 3; ++axis)
            volume *= std::max(extent[axis], largest * 1e-3);
        _cellSize = std::cbrt(volume / indices.size());
        while (true)
        {
            double cells = 1.0;
            for (int axis = 0; axis < 3; ++axis)
            {
                const double along = std::ceil(extent[axis] / _cellSize);
                _dims[axis] = static_cast<int>(std::min(std::max(along, 1.0), cellLimit));
                cells *= _dims[axis];
            }
            if (cells <= cellLimit)
                break;
            _cellSize *= 1.25;
        }
        sortIntoCells(indices);
    }

    /** The points the grid holds: one of each position in crowded cells. */
    const std::vector<uint32_t>& getPoints() const { return _sorted; }

    /** The squared distance from point index to its nearest neighbour at a distance > 0, or
     * infinity when none is found within SEARCH_BUDGET. The search looks into shells of cells
     * around the point's cell, only at the cells of each shell that lie in the grid. */
    double nearestDistance2(uint32_t index) const { return nearestDistance2(toDouble(_positions[index])); }

    /** The same for any point, in the grid or not. */
    double nearestDistance2(const osg::Vec3d& point) const
    {
        Search search{point, cellOf(point)};
        const Cell& c = search.centre;
        const int lastRing =
            std::max({c.i, _dims[0] - 1 - c.i, c.j, _dims[1] - 1 - c.j, c.k, _dims[2] - 1 - c.k});
        visitBlock(search, {c.i, c.i}, {c.j, c.j}, {c.k, c.k});
        for (int ring = 1; ring <= lastRing && search.work < SEARCH_BUDGET; ++ring)
        {
            // The shell's faces: two across i, then across j and k without the cells already seen.
            const Range j = clamp({c.j - ring, c.j + ring}, 1), k = clamp({c.k - ring, c.k + ring}, 2);
            const Range iInside = clamp({c.i - ring + 1, c.i + ring - 1}, 0);
            const Range jInside = clamp({c.j - ring + 1, c.j + ring - 1}, 1);
            for (int side : {-ring, ring})
            {
                visitBlock(search, clamp({c.i + side, c.i + side}, 0), j, k);
                visitBlock(search, iInside, clamp({c.j + side, c.j + side}, 1), k);
                visitBlock(search, iInside, jInside, clamp({c.k + side, c.k + side}, 2));
            }
            ++search.work;
            // Points beyond this ring are at least ring cells away.
            const double reach = ring * _cellSize;
            if (search.best <= reach * reach)
                break;
        }
        return search.best;
    }

private:
    struct Cell
    {
        int i, j, k;
    };

    /** Cells first to last along an axis; empty when last < first. */
    struct Range
    {
        int first, last;
    };

    struct Search
    {
        osg::Vec3d point;
        Cell centre;
        double best = std::numeric_limits<double>::infinity();
        std::size_t work = 0;
    };

    Range clamp(Range range, int axis) const
    {
        return Range{std::max(range.first, 0), std::min(range.last, _dims[axis] - 1)};
    }

    /** Compares the point of the search with those of a block of cells, within the budget. */
    void visitBlock(Search& search, Range i, Range j, Range k) const
    {
        if (i.first > i.last || j.first > j.last || k.first > k.last)
            return;
        for (int ci = i.first; ci <= i.last && search.work < SEARCH_BUDGET; ++ci)
            for (int cj = j.first; cj <= j.last && search.work < SEARCH_BUDGET; ++cj)
                for (int ck = k.first; ck <= k.last && search.work < SEARCH_BUDGET; ++ck)
                {
                    const std::size_t cell = cellIndex(Cell{ci, cj, ck});
                    ++search.work;
                    for (uint32_t s = _cellStart[cell];
                         s < _cellStart[cell + 1] && search.work < SEARCH_BUDGET; ++s, ++search.work)
                    {
                        const double d2 = (toDouble(_positions[_sorted[s]]) - search.point).length2();
                        if (d2 > 0.0 && d2 < search.best)
                            search.best = d2;
                    }
                }
    }

    /** A counting sort of the points by cell, keeping one point of each position in crowded cells. */
    void sortIntoCells(const std::vector<uint32_t>& indices)
    {
        std::vector<uint32_t> start(static_cast<std::size_t>(_dims[0]) * _dims[1] * _dims[2] + 1, 0);
        for (uint32_t index : indices)
            ++start[cellIndex(cellOf(toDouble(_positions[index]))) + 1];
        for (std::size_t cell = 1; cell < start.size(); ++cell)
            start[cell] += start[cell - 1];
        std::vector<uint32_t> sorted(indices.size());
        std::vector<uint32_t> next(start.begin(), start.end() - 1);
        for (uint32_t index : indices)
            sorted[next[cellIndex(cellOf(toDouble(_positions[index])))]++] = index;

        auto byPosition = [this](uint32_t a, uint32_t b)
        { return lessByPosition(_positions[a], _positions[b]); };
        auto samePosition = [this](uint32_t a, uint32_t b) { return _positions[a] == _positions[b]; };
        _cellStart.assign(start.size(), 0);
        _sorted.reserve(sorted.size());
        for (std::size_t cell = 0; cell + 1 < start.size(); ++cell)
        {
            const auto first = sorted.begin() + start[cell];
            const auto last = sorted.begin() + start[cell + 1];
            // Only crowded cells are worth the sort: a search through a few points is quick.
            if (last - first > CROWDED_CELL)
            {
                std::sort(first, last, byPosition);
                _sorted.insert(_sorted.end(), first, std::unique(first, last, samePosition));
            }
            else
                _sorted.insert(_sorted.end(), first, last);
            _cellStart[cell + 1] = static_cast<uint32_t>(_sorted.size());
        }
    }

    Cell cellOf(const osg::Vec3d& p) const
    {
        auto axis = [&](int a)
        {
            const double c = (p[a] - _origin[a]) / _cellSize;
            return static_cast<int>(std::min(std::max(c, 0.0), _dims[a] - 1.0)); // truncates: c >= 0
        };
        return Cell{axis(0), axis(1), axis(2)};
    }

    std::size_t cellIndex(const Cell& cell) const
    {
        return (static_cast<std::size_t>(cell.k) * _dims[1] + cell.j) * _dims[0] + cell.i;
    }

    const std::vector<osg::Vec3f>& _positions;
    osg::Vec3d _origin;
    double _cellSize = 1.0;
    int _dims[3] = {1, 1, 1};
    std::vector<uint32_t> _cellStart;
    std::vector<uint32_t> _sorted;
};

/** The indices of the finite positions and their box (empty: +infinity to -infinity). */
void findFinite(const std::vector<osg::Vec3f>& positions, std::vector<uint32_t>& finite, osg::Vec3d& boxMin,
                osg::Vec3d& boxMax)
{
    finite.reserve(positions.size());
    boxMin.set(std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
               std::numeric_limits<double>::infinity());
    boxMax = -boxMin;
    for (std::size_t i = 0; i < positions.size() && i < std::numeric_limits<uint32_t>::max(); ++i)
    {
        const osg::Vec3f& p = positions[i];
        if (std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z()))
        {
            finite.push_back(static_cast<uint32_t>(i));
            for (int axis = 0; axis < 3; ++axis)
            {
                boxMin[axis] = std::min(boxMin[axis], static_cast<double>(p[axis]));
                boxMax[axis] = std::max(boxMax[axis], static_cast<double>(p[axis]));
            }
        }
    }
}

double medianDistance(std::vector<double>& distances2)
{
    if (distances2.empty())
        return 0.0;
    auto median = distances2.begin() + distances2.size() / 2;
    std::nth_element(distances2.begin(), median, distances2.end());
    return std::sqrt(*median);
}

}

double osgGlyphsData::detail::estimateNeighbourDistance(const std::vector<osg::Vec3f>& positions,
                                                        unsigned int maxSamples)
{
    std::vector<uint32_t> finite;
    osg::Vec3d boxMin, boxMax;
    findFinite(positions, finite, boxMin, boxMax);
    if (finite.size() < 2 || boxMin == boxMax)
        return 0.0;

    const PointGrid grid(positions, finite, boxMin, boxMax);
    // Positions repeated many times make cells small for their spacing: grid the distinct ones.
    std::unique_ptr<PointGrid> distinct;
    if (2 * grid.getPoints().size() <= finite.size())
        distinct = std::make_unique<PointGrid>(positions, grid.getPoints(), boxMin, boxMax);
    const PointGrid& search = distinct ? *distinct : grid;
    const std::size_t stride = std::max<std::size_t>(1, finite.size() / std::max(1u, maxSamples));
    std::vector<double> distances2;
    for (std::size_t s = 0; s < finite.size(); s += stride)
    {
        const double d2 = search.nearestDistance2(finite[s]);
        if (std::isfinite(d2))
            distances2.push_back(d2);
    }
    return medianDistance(distances2);
}

double osgGlyphsData::detail::estimateNeighbourDistance(const std::vector<osg::Vec3f>& positions,
                                                        const ShareReduction& reduction,
                                                        unsigned int maxSamples)
{
    std::vector<uint32_t> finite;
    osg::Vec3d boxMin, boxMax;
    findFinite(positions, finite, boxMin, boxMax);
    std::vector<double> low(boxMin.ptr(), boxMin.ptr() + 3), high(boxMax.ptr(), boxMax.ptr() + 3);
    reduction.minimum(low);
    reduction.maximum(high);
    // Where this share's finite points are among all of them, in share order.
    std::vector<double> counts{static_cast<double>(finite.size())};
    reduction.gather(counts);
    const unsigned int index = reduction.getShare().index;
    uint64_t total = 0, first = 0;
    for (std::size_t share = 0; share < counts.size(); ++share)
    {
        first += share < index ? static_cast<uint64_t>(counts[share]) : 0;
        total += static_cast<uint64_t>(counts[share]);
    }
    boxMin.set(low[0], low[1], low[2]);
    boxMax.set(high[0], high[1], high[2]);
    if (total < 2 || boxMin == boxMax)
        return 0.0;

    // The samples of one process holding every point, every stride-th finite point, to all.
    const uint64_t stride = std::max<uint64_t>(1, total / std::max(1u, maxSamples));
    std::vector<double> samples;
    for (uint64_t s = (first + stride - 1) / stride * stride; s < first + finite.size(); s += stride)
    {
        const osg::Vec3f& p = positions[finite[s - first]];
        samples.insert(samples.end(), {double(p.x()), double(p.y()), double(p.z())});
    }
    reduction.gather(samples);

    // Each sample's nearest neighbour is the nearest of those each share finds.
    std::vector<double> distances2(samples.size() / 3, std::numeric_limits<double>::infinity());
    if (!finite.empty())
    {
        const PointGrid grid(positions, finite, boxMin, boxMax);
        std::unique_ptr<PointGrid> distinct;
        if (2 * grid.getPoints().size() <= finite.size())
            distinct = std::make_unique<PointGrid>(positions, grid.getPoints(), boxMin, boxMax);
        const PointGrid& search = distinct ? *distinct : grid;
        for (std::size_t s = 0; s < distances2.size(); ++s)
            distances2[s] =
                search.nearestDistance2(osg::Vec3d(samples[3 * s], samples[3 * s + 1], samples[3 * s + 2]));
    }
    reduction.minimum(distances2);
    distances2.erase(
        std::remove_if(distances2.begin(), distances2.end(), [](double d2) { return !std::isfinite(d2); }),
        distances2.end());
    return medianDistance(distances2);
}
