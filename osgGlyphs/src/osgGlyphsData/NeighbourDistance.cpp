#include "NeighbourDistance.h"

#include <osg/Vec3d>

#include <algorithm>
#include <bitset>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>

namespace
{

/** The work one nearest-neighbour search may do: every ring of cells it goes through, cell it
 * looks into and point it compares counts one. 2000 samples take at most 10 million steps. */
const std::size_t SEARCH_BUDGET = 5000;

/** Points in a cell beyond which the grid keeps one point of each position. */
const std::ptrdiff_t CROWDED_CELL = 8;

/** Cells of the grid at most, whatever the number of points: any axis count fits an int. */
const double MAX_CELLS = 1 << 30;

/** Rings of cells around the samples whose points a search grid holds at first: enough for about
 * every sample of evenly spread points. */
const int NEAR_RINGS = 2;

osg::Vec3d toDouble(const osg::Vec3f& p)
{
    return osg::Vec3d(p.x(), p.y(), p.z());
}

bool lessByPosition(const osg::Vec3f& a, const osg::Vec3f& b)
{
    return a.x() != b.x() ? a.x() < b.x() : a.y() != b.y() ? a.y() < b.y() : a.z() < b.z();
}

/** A set of cells of a grid, all of them or those inserted, which numbers its cells in order
 * (call number() after the last insert). */
class CellSet
{
public:
    CellSet(std::size_t cells, bool all) : _cells(cells), _all(all), _words(all ? 0 : (cells + 63) / 64, 0) {}

    bool isAll() const { return _all; }
    void insert(std::size_t cell) { _words[cell / 64] |= uint64_t(1) << cell % 64; }
    bool contains(std::size_t cell) const { return _all || _words[cell / 64] >> cell % 64 & 1; }

    /** Numbers the cells of the set; returns their count. */
    std::size_t number()
    {
        _before.resize(_words.size());
        std::size_t count = _all ? _cells : 0;
        for (std::size_t word = 0; word < _words.size(); ++word)
        {
            _before[word] = static_cast<uint32_t>(count);
            count += std::bitset<64>(_words[word]).count();
        }
        return count;
    }

    /** The number of a cell of the set: how many of its cells come before. */
    std::size_t rank(std::size_t cell) const
    {
        const uint64_t below = (uint64_t(1) << cell % 64) - 1;
        return _all ? cell : _before[cell / 64] + std::bitset<64>(_words[cell / 64] & below).count();
    }

private:
    std::size_t _cells;
    bool _all;
    std::vector<uint64_t> _words;
    std::vector<uint32_t> _before;
};

/** How a nearest-neighbour search ended: exact, cut by SEARCH_BUDGET (with the nearest found by
 * then), or at a cell whose points the grid does not hold (no result). */
enum class Outcome
{
    Exact,
    OverBudget,
    OutsideCells
};

struct Nearest
{
    double distance2;
    Outcome outcome;
};

/** A uniform grid of about as many cells as points, which holds the points of some of its
 * cells. Geometry is in double: the extent of float positions can exceed the range of a float. */
class PointGrid
{
public:
    /** The grid of the points of indices in the box, holding none of them yet. */
    PointGrid(const std::vector<osg::Vec3f>& positions, const std::vector<uint32_t>& indices,
              const osg::Vec3d& boxMin, const osg::Vec3d& boxMax)
        : _positions(positions), _indices(indices), _origin(boxMin)
    {
        const std::size_t count = indices.size();
        const osg::Vec3d extent = boxMax - boxMin;
        const double largest = std::max(extent.x(), std::max(extent.y(), extent.z()));
        const double cellLimit = std::min(2.0 * count + 8.0, MAX_CELLS);
        double volume = 1.0;
        for (int axis = 0; axis < 3; ++axis)
            volume *= std::max(extent[axis], largest * 1e-3);
        _cellSize = std::cbrt(volume / count);
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
        _cellsPerUnit = 1.0 / _cellSize;
        _pointCells.resize(count);
        for (std::size_t point = 0; point < count; ++point)
            _pointCells[point] =
                static_cast<uint32_t>(cellIndex(cellOf(toDouble(_positions[indices[point]]))));
    }

    std::size_t getCellCount() const { return static_cast<std::size_t>(_dims[0]) * _dims[1] * _dims[2]; }
    /** Whether the grid holds the points of every cell that has any. */
    bool holdsAllPoints() const { return _heldPoints == _pointCells.size(); }

    /** Adds to cells those a search from point looks into up to rings, or up to where its budget
     * runs out whatever the cells hold. */
    void insertReach(CellSet& cells, const osg::Vec3d& point, int rings) const
    {
        const Cell c = cellOf(point);
        int ring = 0;
        // A search starts the next ring only if each ring and cell so far counted less than the budget.
        while (ring < std::min(rings, lastRing(c)) && blockCells(c, ring) + ring < SEARCH_BUDGET)
            ++ring;
        const Range i = block(c.i, ring, 0), j = block(c.j, ring, 1), k = block(c.k, ring, 2);
        for (int ck = k.first; ck <= k.last; ++ck)
            for (int cj = j.first; cj <= j.last; ++cj)
                for (int ci = i.first; ci <= i.last; ++ci)
                    cells.insert(cellIndex(Cell{ci, cj, ck}));
    }

    /** Holds the points that lie in cells: a counting sort by cell, keeping one point of each
     * position in crowded cells. */
    void fill(CellSet cells)
    {
        std::vector<uint32_t> held = pointsIn(cells);
        // Most points cost about as much as all of them, which leave no search outside the cells.
        if (2 * held.size() > _pointCells.size() && !cells.isAll())
        {
            cells = CellSet(getCellCount(), true);
            held = pointsIn(cells);
        }
        _cells = std::move(cells);
        _heldPoints = held.size();
        std::vector<uint32_t> start(_cells.number() + 1, 0);
        std::vector<uint32_t> heldCell(held.size());
        for (std::size_t h = 0; h < held.size(); ++h)
        {
            heldCell[h] = static_cast<uint32_t>(_cells.rank(_pointCells[held[h]]));
            ++start[heldCell[h] + 1];
            held[h] = _indices[held[h]]; // from its place in _indices to its index
        }
        for (std::size_t cell = 1; cell < start.size(); ++cell)
            start[cell] += start[cell - 1];
        std::vector<uint32_t> sorted(held.size());
        std::vector<uint32_t> next(start.begin(), start.end() - 1);
        for (std::size_t h = 0; h < held.size(); ++h)
            sorted[next[heldCell[h]]++] = held[h];

        auto byPosition = [this](uint32_t a, uint32_t b)
        { return lessByPosition(_positions[a], _positions[b]); };
        auto samePosition = [this](uint32_t a, uint32_t b) { return _positions[a] == _positions[b]; };
        _cellStart.assign(start.size(), 0);
        _sorted.clear();
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

    /** The points the grid holds: one of each position in crowded cells. */
    const std::vector<uint32_t>& getPoints() const { return _sorted; }

    /** The squared distance from point to its nearest neighbour at a distance > 0 (infinity for
     * none) and how the search ended. The search looks into shells of cells around the point's
     * cell, only at the cells of each shell that lie in the grid. */
    Nearest nearest(const osg::Vec3d& point) const
    {
        Search search{point, cellOf(point)};
        const Cell& c = search.centre;
        const int lastRing = this->lastRing(c);
        visitBlock(search, {c.i, c.i}, {c.j, c.j}, {c.k, c.k});
        for (int ring = 1; ring <= lastRing && search.going(); ++ring)
        {
            // The shell's faces: two across i, then across j and k without the cells already seen.
            const Range j = block(c.j, ring, 1), k = block(c.k, ring, 2);
            const Range iInside = block(c.i, ring - 1, 0), jInside = block(c.j, ring - 1, 1);
            for (int side : {-ring, ring})
            {
                visitBlock(search, block(c.i + side, 0, 0), j, k);
                visitBlock(search, iInside, block(c.j + side, 0, 1), k);
                visitBlock(search, iInside, jInside, block(c.k + side, 0, 2));
            }
            ++search.work;
            // Points beyond this ring are at least ring cells away.
            const double reach = ring * _cellSize;
            if (search.best <= reach * reach)
                break;
        }
        // A search that counted less than its budget saw every cell it had to.
        const Outcome outcome = search.outside                ? Outcome::OutsideCells
                                : search.work < SEARCH_BUDGET ? Outcome::Exact
                                                              : Outcome::OverBudget;
        return Nearest{search.best, outcome};
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
        bool outside = false;

        bool going() const { return work < SEARCH_BUDGET && !outside; }
    };

    /** The cells within rings of cell along an axis that lie in the grid. */
    Range block(int cell, int rings, int axis) const
    {
        return Range{std::max(cell - rings, 0), std::min(cell + rings, _dims[axis] - 1)};
    }

    std::size_t blockCells(const Cell& c, int rings) const
    {
        std::size_t cells = 1;
        for (const Range& r : {block(c.i, rings, 0), block(c.j, rings, 1), block(c.k, rings, 2)})
            cells *= static_cast<std::size_t>(r.last - r.first + 1);
        return cells;
    }

    int lastRing(const Cell& c) const
    {
        return std::max({c.i, _dims[0] - 1 - c.i, c.j, _dims[1] - 1 - c.j, c.k, _dims[2] - 1 - c.k});
    }

    /** Compares the point of the search with those of a block of cells, within the budget and
     * the cells the grid holds. */
    void visitBlock(Search& search, Range i, Range j, Range k) const
    {
        if (i.first > i.last || j.first > j.last || k.first > k.last)
            return;
        for (int ci = i.first; ci <= i.last && search.going(); ++ci)
            for (int cj = j.first; cj <= j.last && search.going(); ++cj)
                for (int ck = k.first; ck <= k.last && search.going(); ++ck)
                {
                    const std::size_t cell = cellIndex(Cell{ci, cj, ck});
                    ++search.work;
                    // A cell not held is empty if the grid holds every point.
                    if (!_cells.contains(cell))
                    {
                        search.outside = !holdsAllPoints();
                        continue;
                    }
                    const std::size_t held = _cells.rank(cell);
                    for (uint32_t s = _cellStart[held];
                         s < _cellStart[held + 1] && search.work < SEARCH_BUDGET; ++s, ++search.work)
                    {
                        const double d2 = (toDouble(_positions[_sorted[s]]) - search.point).length2();
                        if (d2 > 0.0 && d2 < search.best)
                            search.best = d2;
                    }
                }
    }

    /** The points that lie in cells, by their place in _indices. */
    std::vector<uint32_t> pointsIn(const CellSet& cells) const
    {
        std::vector<uint32_t> points(cells.isAll() ? _pointCells.size() : 0);
        std::iota(points.begin(), points.end(), 0u);
        for (std::size_t point = 0; point < _pointCells.size() && !cells.isAll(); ++point)
        {
            if (cells.contains(_pointCells[point]))
                points.push_back(static_cast<uint32_t>(point));
        }
        return points;
    }

    Cell cellOf(const osg::Vec3d& p) const
    {
        auto axis = [&](int a)
        {
            const double c = (p[a] - _origin[a]) * _cellsPerUnit;
            return static_cast<int>(std::min(std::max(c, 0.0), _dims[a] - 1.0)); // truncates: c >= 0
        };
        return Cell{axis(0), axis(1), axis(2)};
    }

    std::size_t cellIndex(const Cell& cell) const
    {
        return (static_cast<std::size_t>(cell.k) * _dims[1] + cell.j) * _dims[0] + cell.i;
    }

    const std::vector<osg::Vec3f>& _positions;
    const std::vector<uint32_t>& _indices;
    std::vector<uint32_t> _pointCells;
    osg::Vec3d _origin;
    double _cellSize = 1.0;
    double _cellsPerUnit = 1.0;
    int _dims[3] = {1, 1, 1};
    CellSet _cells{0, false};
    std::size_t _heldPoints = 0;
    std::vector<uint32_t> _cellStart;
    std::vector<uint32_t> _sorted;
};

/** The squared distance from each sample to its nearest point of indices at a distance > 0
 * (infinity for none), each search cut after SEARCH_BUDGET with the nearest found by then. */
std::vector<double> nearestDistances2(const std::vector<osg::Vec3f>& positions,
                                      const std::vector<uint32_t>& indices, const osg::Vec3d& boxMin,
                                      const osg::Vec3d& boxMax, const std::vector<osg::Vec3d>& samples)
{
    PointGrid grid(positions, indices, boxMin, boxMax);
    std::vector<double> distances2(samples.size(), std::numeric_limits<double>::infinity());
    std::vector<std::size_t> pending(samples.size()), overBudget;
    std::iota(pending.begin(), pending.end(), std::size_t(0));
    // Positions repeated many times make cells small for their spacing: when the positions left in
    // a grid of all points are few, searches go through a grid of those.
    auto fewPositions = [&]
    { return grid.holdsAllPoints() && 2 * grid.getPoints().size() <= indices.size(); };
    // The grid holds only the points near the samples: first those within NEAR_RINGS, then for
    // the searches that go further those they can reach within their budget. It holds all of them
    // when the samples are many for the cells, or once a search has run out of budget.
    for (int rings : {NEAR_RINGS, std::numeric_limits<int>::max()})
    {
        if (pending.empty())
            break;
        const std::size_t side = 2 * NEAR_RINGS + 1;
        CellSet cells(grid.getCellCount(),
                      !overBudget.empty() || 2 * pending.size() * side * side * side > grid.getCellCount());
        if (!cells.isAll())
        {
            for (std::size_t s : pending)
                grid.insertReach(cells, samples[s], rings);
        }
        grid.fill(std::move(cells));
        if (fewPositions())
            break;
        std::vector<std::size_t> further;
        for (std::size_t s : pending)
        {
            const Nearest nearest = grid.nearest(samples[s]);
            if (nearest.outcome == Outcome::OutsideCells)
                further.push_back(s);
            else
                distances2[s] = nearest.distance2;
            if (nearest.outcome == Outcome::OverBudget)
                overBudget.push_back(s);
        }
        pending.swap(further);
    }
    if (!overBudget.empty() && !grid.holdsAllPoints())
        grid.fill(CellSet(grid.getCellCount(), true));
    if (fewPositions())
    {
        PointGrid distinct(positions, grid.getPoints(), boxMin, boxMax);
        distinct.fill(CellSet(distinct.getCellCount(), true));
        pending.insert(pending.end(), overBudget.begin(), overBudget.end());
        for (std::size_t s : pending)
            distances2[s] = std::min(distances2[s], distinct.nearest(samples[s]).distance2);
    }
    return distances2;
}

/** The indices of the finite positions and their box (empty: +infinity to -infinity). */
void findFinite(const std::vector<osg::Vec3f>& positions, std::vector<uint32_t>& finite, osg::Vec3d& boxMin,
                osg::Vec3d& boxMax)
{
    finite.reserve(positions.size());
    const float infinity = std::numeric_limits<float>::infinity();
    osg::Vec3f low(infinity, infinity, infinity), high = -low;
    for (std::size_t i = 0; i < positions.size() && i < std::numeric_limits<uint32_t>::max(); ++i)
    {
        const osg::Vec3f& p = positions[i];
        if (std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z()))
        {
            finite.push_back(static_cast<uint32_t>(i));
            for (int axis = 0; axis < 3; ++axis)
            {
                low[axis] = std::min(low[axis], p[axis]);
                high[axis] = std::max(high[axis], p[axis]);
            }
        }
    }
    boxMin = toDouble(low);
    boxMax = toDouble(high);
}

double medianDistance(std::vector<double>& distances2)
{
    distances2.erase(
        std::remove_if(distances2.begin(), distances2.end(), [](double d2) { return !std::isfinite(d2); }),
        distances2.end());
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

    const std::size_t stride = std::max<std::size_t>(1, finite.size() / std::max(1u, maxSamples));
    std::vector<osg::Vec3d> samples;
    for (std::size_t s = 0; s < finite.size(); s += stride)
        samples.push_back(toDouble(positions[finite[s]]));
    std::vector<double> distances2 = nearestDistances2(positions, finite, boxMin, boxMax, samples);
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
    std::vector<double> coordinates;
    for (uint64_t s = (first + stride - 1) / stride * stride; s < first + finite.size(); s += stride)
    {
        const osg::Vec3f& p = positions[finite[s - first]];
        coordinates.insert(coordinates.end(), {double(p.x()), double(p.y()), double(p.z())});
    }
    reduction.gather(coordinates);
    std::vector<osg::Vec3d> samples;
    for (std::size_t s = 0; s + 2 < coordinates.size(); s += 3)
        samples.emplace_back(coordinates[s], coordinates[s + 1], coordinates[s + 2]);

    // Each sample's nearest neighbour is the nearest of those each share finds.
    std::vector<double> distances2 =
        finite.empty() ? std::vector<double>(samples.size(), std::numeric_limits<double>::infinity())
                       : nearestDistances2(positions, finite, boxMin, boxMax, samples);
    reduction.minimum(distances2);
    return medianDistance(distances2);
}
