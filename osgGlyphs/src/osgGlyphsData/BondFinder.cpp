#include <osgGlyphsData/BondFinder>
#include <osgGlyphsData/PointData>

#include "CellCoordinates.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <new>
#include <sstream>
#include <thread>

#ifdef __linux__
#include <sys/mman.h>
#endif

using namespace osgGlyphsData;

namespace
{

/** Types that the cutoffs name at most: their table of squared cutoffs has (1 + this)^2 entries. */
const std::size_t MAX_NAMED_TYPES = 4096;

/** How far (in box lengths) an atom may lie from a periodic box: image counts fit an int32_t. */
const double MAX_BOX_LENGTHS = 536870912.0; // 2^29

/** Cells of the grid at most, whatever the number of atoms: any axis count fits an int. */
const double MAX_CELLS = 1 << 30;

/** Bonds per atom at most (on average), and at least this many bonds in all: more means cutoffs
 * far too long for the atoms' density, which would take memory without bound. */
const std::size_t MAX_BONDS_PER_ATOM = 64;
const std::size_t MIN_BOND_LIMIT = std::size_t(1) << 20;

/** The rounding of positions wrapped into the box (in single precision), relative to the size of
 * the coordinates: a pair first passes through the wrapped positions with a cutoff longer by this
 * (about 16 times the rounding of a float), then through the positions as given. */
const double WRAPPED_ROUNDING = 1e-6;

/** Atoms a thread takes at least, and threads at most. */
const std::size_t MIN_ATOMS_PER_THREAD = 512;
const std::size_t MAX_THREADS = 8;

/** Cells are this much larger than the largest cutoff, against rounding at their faces. */
const double CELL_MARGIN = 1.0 + 1e-6;

std::string describe(const osg::Vec3f& p)
{
    std::ostringstream text;
    text << "(" << p.x() << ", " << p.y() << ", " << p.z() << ")";
    return text.str();
}

std::string describe(const osg::Vec3d& p)
{
    std::ostringstream text;
    text.precision(17);
    text << "(" << p.x() << ", " << p.y() << ", " << p.z() << ")";
    return text.str();
}

/** Memory of transient arrays: blocks of 2 MiB and more as huge pages where the system lends them
 * on request (Linux's transparent huge pages in madvise mode): the first touch of a million
 * atoms' arrays in 4 KiB pages can cost more than the search. */
template <typename T>
struct ScratchAllocator
{
    typedef T value_type;

    ScratchAllocator() = default;
    template <typename U>
    ScratchAllocator(const ScratchAllocator<U>&)
    {
    }

    static const std::size_t HUGE_PAGE = std::size_t(2) << 20;

    T* allocate(std::size_t n)
    {
        if (n > (std::numeric_limits<std::size_t>::max() - 2 * HUGE_PAGE) / sizeof(T))
            throw std::bad_alloc();
        const std::size_t bytes = n * sizeof(T);
        if (bytes < HUGE_PAGE)
            return static_cast<T*>(::operator new(bytes));
        // Through operator new (which a program may meter), aligned to a huge page by hand: the
        // block it handed out is stored just before.
        const std::size_t rounded = (bytes + HUGE_PAGE - 1) / HUGE_PAGE * HUGE_PAGE;
        char* block = static_cast<char*>(::operator new(rounded + HUGE_PAGE));
        const std::uintptr_t after = reinterpret_cast<std::uintptr_t>(block) + sizeof(void*);
        char* aligned = block + ((after + HUGE_PAGE - 1) / HUGE_PAGE * HUGE_PAGE -
                                 reinterpret_cast<std::uintptr_t>(block));
        std::memcpy(aligned - sizeof(void*), &block, sizeof(void*));
#ifdef MADV_HUGEPAGE
        madvise(aligned, rounded, MADV_HUGEPAGE);
#endif
        return reinterpret_cast<T*>(aligned);
    }

    void deallocate(T* memory, std::size_t n)
    {
        if (n * sizeof(T) < HUGE_PAGE)
        {
            ::operator delete(memory);
            return;
        }
        char* block = nullptr;
        std::memcpy(&block, reinterpret_cast<char*>(memory) - sizeof(void*), sizeof(void*));
        ::operator delete(block);
    }

    template <typename U>
    bool operator==(const ScratchAllocator<U>&) const
    {
        return true;
    }
    template <typename U>
    bool operator!=(const ScratchAllocator<U>&) const
    {
        return false;
    }
};

/** A transient array. */
template <typename T>
using Scratch = std::vector<T, ScratchAllocator<T>>;

/** The cell as edges and their reciprocals: fractional coordinates of a displacement and back. */
struct Cell
{
    osg::Vec3d length{1.0, 1.0, 1.0};
    osg::Vec3d tilt{0.0, 0.0, 0.0};
    osg::Vec3d inverse{1.0, 1.0, 1.0};
    bool periodic[3] = {false, false, false};

    osg::Vec3d toFractional(const osg::Vec3d& d) const { return detail::toCellFractional(d, tilt, inverse); }

    osg::Vec3d toCartesian(const osg::Vec3d& s) const { return detail::toCellCartesian(s, length, tilt); }

    /** The distances between the cell's opposite faces, across a, b and c. */
    osg::Vec3d getWidths() const
    {
        const osg::Vec3d a(length.x(), 0.0, 0.0), b(tilt.x(), length.y(), 0.0),
            c(tilt.y(), tilt.z(), length.z());
        const double volume = length.x() * length.y() * length.z();
        return osg::Vec3d(volume / (b ^ c).length(), volume / (c ^ a).length(), volume / (a ^ b).length());
    }
};

std::string describeCutoff(const std::pair<int, int>* pair)
{
    if (!pair)
        return "the default cutoff";
    std::ostringstream text;
    text << "the cutoff of types " << pair->first << " and " << pair->second;
    return text.str();
}

/** The squared cutoffs of the pairs of type classes: class 0 for the types the cutoffs do not
 * name, 1 + i for the i-th named type. */
struct CutoffTable
{
    std::vector<int> named;
    std::vector<double> squared;
    /** The squared cutoffs grown by a distance that covers the rounding of wrapped positions. */
    std::vector<float> loose;
    std::size_t classes = 1;

    bool build(const BondCutoffs& cutoffs, std::string& error)
    {
        for (const auto& entry : cutoffs.getPairCutoffs())
        {
            named.push_back(entry.first.first);
            named.push_back(entry.first.second);
        }
        std::sort(named.begin(), named.end());
        named.erase(std::unique(named.begin(), named.end()), named.end());
        if (named.size() > MAX_NAMED_TYPES)
        {
            std::ostringstream text;
            text << "the bond cutoffs name " << named.size() << " types, more than " << MAX_NAMED_TYPES;
            error = text.str();
            return false;
        }
        classes = named.size() + 1;
        const double fallback = cutoffs.getDefaultCutoff();
        std::vector<double> cutoff(classes * classes, fallback);
        for (const auto& entry : cutoffs.getPairCutoffs())
        {
            const std::size_t a = classOf(entry.first.first), b = classOf(entry.first.second);
            cutoff[a * classes + b] = cutoff[b * classes + a] = entry.second;
        }
        // A cutoff of 0 bonds nothing, not even atoms at one place: below any squared distance.
        squared.resize(cutoff.size());
        for (std::size_t c = 0; c < cutoff.size(); ++c)
            squared[c] = cutoff[c] > 0.0 ? cutoff[c] * cutoff[c] : -1.0;
        return true;
    }

    /** Sets loose for a rounding of the wrapped positions of at most slack. */
    void setSlack(double slack)
    {
        loose.resize(squared.size());
        for (std::size_t c = 0; c < squared.size(); ++c)
            loose[c] =
                squared[c] >= 0.0 ? (std::sqrt(squared[c]) + slack) * (std::sqrt(squared[c]) + slack) : -1.0;
    }

    uint32_t classOf(int type) const
    {
        const auto found = std::lower_bound(named.begin(), named.end(), type);
        return found != named.end() && *found == type ? static_cast<uint32_t>(found - named.begin() + 1) : 0u;
    }
};

/** The largest cutoff, and which it is (nullptr: the default). False for a bad cutoff. */
bool findLargestCutoff(const BondCutoffs& cutoffs, double& largest, const std::pair<int, int>*& which,
                       std::string& error)
{
    auto check = [&](double cutoff, const std::pair<int, int>* pair)
    {
        if (!std::isfinite(cutoff) || cutoff < 0.0)
        {
            std::ostringstream text;
            text << describeCutoff(pair) << " is " << cutoff << ": a cutoff must be finite and not negative";
            error = text.str();
            return false;
        }
        if (cutoff > largest)
        {
            largest = cutoff;
            which = pair;
        }
        return true;
    };
    largest = 0.0;
    which = nullptr;
    if (!check(cutoffs.getDefaultCutoff(), nullptr))
        return false;
    for (const auto& entry : cutoffs.getPairCutoffs())
    {
        if (!check(entry.second, &entry.first))
            return false;
    }
    return true;
}

/** The integer nearest to x (halves away from zero), |x| < 2^62, without a call to round(). */
int32_t nearestInteger(double x)
{
    return static_cast<int32_t>(static_cast<int64_t>(x < 0.0 ? x - 0.5 : x + 0.5));
}

/** The cells within one of cell along an axis, each once: wrapped around a periodic axis, cut at
 * the ends of an open one. Returns their number. */
int neighbourCells(int cell, int count, bool periodic, int out[3])
{
    int n = 0;
    for (int offset = -1; offset <= 1; ++offset)
    {
        int c = cell + offset;
        if (periodic)
            c = (c + count) % count;
        else if (c < 0 || c >= count)
            continue;
        if (std::find(out, out + n, c) == out + n)
            out[n++] = c;
    }
    return n;
}

/** The bonds of runs of cells of the grid: atoms sorted by cell, start[c] the first of cell c. */
struct PairSearch
{
    const Cell& cell;
    const int* dims;
    bool halfStencil;
    const Scratch<uint32_t>& start;
    const Scratch<uint32_t>& order;
    /** The atoms' positions as given, in cell order. */
    const Scratch<osg::Vec3f>& positions;
    /** Their positions wrapped into the box along periodic edges, relative to its corner. */
    const Scratch<osg::Vec3f>& wrapped;
    const Scratch<uint32_t>& classes;
    const CutoffTable& table;
    std::size_t bondLimit;

    /** A cell near another, and the offset of the image of its atoms next to that cell. */
    struct Neighbour
    {
        uint32_t cell;
        osg::Vec3f offset;
    };

    /** The bonds from the cells first to last (excluded) into found; false past bondLimit. */
    bool run(std::size_t first, std::size_t last, Scratch<Bond>& found) const
    {
        found.clear();
        found.reserve((start[last] - start[first]) * 3);
        std::vector<Neighbour> neighbours;
        neighbours.reserve(27);
        for (std::size_t here = first; here < last; ++here)
        {
            if (start[here] == start[here + 1])
                continue;
            const int c[3] = {static_cast<int>(here % dims[0]), static_cast<int>(here / dims[0] % dims[1]),
                              static_cast<int>(here / dims[0] / dims[1])};
            neighbours.clear();
            if (halfStencil)
            {
                // Wrapped positions first, each pair near the cutoff then from the positions given.
                for (int dk = 0; dk <= 1; ++dk)
                    for (int dj = dk == 0 ? 0 : -1; dj <= 1; ++dj)
                        for (int di = dk == 0 && dj == 0 ? 1 : -1; di <= 1; ++di)
                            addNeighbour(neighbours, c[0] + di, c[1] + dj, c[2] + dk);
                for (uint32_t a = start[here]; a < start[here + 1]; ++a)
                {
                    visitWrapped(found, a, a + 1, start[here + 1], osg::Vec3f());
                    for (const Neighbour& n : neighbours)
                        visitWrapped(found, a, start[n.cell], start[n.cell + 1], n.offset);
                }
            }
            else
            {
                int near[3][3], numNear[3];
                for (int axis = 0; axis < 3; ++axis)
                    numNear[axis] = neighbourCells(c[axis], dims[axis], cell.periodic[axis], near[axis]);
                for (int k = 0; k < numNear[2]; ++k)
                    for (int j = 0; j < numNear[1]; ++j)
                        for (int i = 0; i < numNear[0]; ++i)
                            addNeighbour(neighbours, near[0][i], near[1][j], near[2][k]);
                for (uint32_t a = start[here]; a < start[here + 1]; ++a)
                    for (const Neighbour& n : neighbours)
                        for (uint32_t b = start[n.cell]; b < start[n.cell + 1]; ++b)
                        {
                            if (order[b] > order[a])
                                visit(found, a, b);
                        }
            }
            if (found.size() > bondLimit)
                return false;
        }
        return true;
    }

    /** Adds the cell (i, j, k), wrapped along periodic edges, if it is in the grid. */
    void addNeighbour(std::vector<Neighbour>& neighbours, int i, int j, int k) const
    {
        int c[3] = {i, j, k};
        osg::Vec3d image;
        for (int axis = 0; axis < 3; ++axis)
        {
            // Within one cell of the grid: wrapped without a division.
            if (c[axis] >= 0 && c[axis] < dims[axis])
                continue;
            if (!cell.periodic[axis])
                return;
            image[axis] = c[axis] < 0 ? -1.0 : 1.0;
            c[axis] += c[axis] < 0 ? dims[axis] : -dims[axis];
        }
        neighbours.push_back(Neighbour{
            static_cast<uint32_t>((static_cast<std::size_t>(c[2]) * dims[1] + c[1]) * dims[0] + c[0]),
            cell.toCartesian(image)});
    }

    /** The pairs of sorted atom a with the sorted atoms from to last (excluded), whose images
     * next to a's cell are offset from their wrapped positions: those that the wrapped positions
     * put within the loose cutoff, through visit(). */
    void visitWrapped(Scratch<Bond>& found, uint32_t a, uint32_t from, uint32_t last,
                      const osg::Vec3f& offset) const
    {
        const osg::Vec3f wa = wrapped[a] - offset;
        const float* row = table.loose.data() + classes[a] * table.classes;
        for (uint32_t b = from; b < last; ++b)
        {
            if ((wrapped[b] - wa).length2() <= row[classes[b]])
                visit(found, a, b);
        }
    }

    /** The pair of sorted atoms a and b from their positions as given: a bond into found if
     * the nearest image is within their cutoff. */
    void visit(Scratch<Bond>& found, uint32_t a, uint32_t b) const
    {
        const osg::Vec3f& pa = positions[a];
        const osg::Vec3f& pb = positions[b];
        osg::Vec3d d(double(pb.x()) - pa.x(), double(pb.y()) - pa.y(), double(pb.z()) - pa.z());
        int32_t image[3] = {0, 0, 0};
        if (cell.periodic[0] || cell.periodic[1] || cell.periodic[2])
        {
            const osg::Vec3d f = cell.toFractional(d);
            for (int axis = 0; axis < 3; ++axis)
                image[axis] = cell.periodic[axis] ? -nearestInteger(f[axis]) : 0;
            d += cell.toCartesian(osg::Vec3d(image[0], image[1], image[2]));
        }
        if (d.length2() <= table.squared[classes[a] * table.classes + classes[b]])
        {
            const uint32_t ia = order[a], ib = order[b];
            if (ia < ib)
                found.push_back(Bond{ia, ib, {image[0], image[1], image[2]}});
            else
                found.push_back(Bond{ib, ia, {-image[0], -image[1], -image[2]}});
        }
    }
};

}

PeriodicBox::PeriodicBox()
    : corner(0.0, 0.0, 0.0), lengths(1.0, 1.0, 1.0), tilt(0.0, 0.0, 0.0), periodic{true, true, true}
{
}

PeriodicBox::PeriodicBox(const osg::BoundingBoxd& box, const osg::Vec3d& tilt_, bool periodicA,
                         bool periodicB, bool periodicC)
    : corner(box._min), lengths(box._max - box._min), tilt(tilt_), periodic{periodicA, periodicB, periodicC}
{
}

osg::Vec3d PeriodicBox::getImageOffset(const int32_t image[3]) const
{
    const double i = image[0], j = image[1], k = image[2];
    return osg::Vec3d(lengths.x() * i + tilt.x() * j + tilt.y() * k, lengths.y() * j + tilt.z() * k,
                      lengths.z() * k);
}

namespace
{

/** findBonds(), but for the memory it takes. */
bool findBondsInMemory(const std::vector<osg::Vec3f>& positions, const std::vector<int>& types,
                       const BondCutoffs& cutoffs, const PeriodicBox* box, std::vector<Bond>& bonds,
                       std::string& error)
{
    bonds.clear();
    error.clear();
    const std::size_t count = positions.size();
    if (count > std::numeric_limits<uint32_t>::max())
    {
        std::ostringstream text;
        text << count << " atoms are more than bonds can index (" << std::numeric_limits<uint32_t>::max()
             << ")";
        error = text.str();
        return false;
    }
    if (!types.empty() && types.size() != count)
    {
        std::ostringstream text;
        text << types.size() << " atom types for " << count << " atoms: give one type per atom, or none";
        error = text.str();
        return false;
    }
    for (std::size_t i = 0; i < count; ++i)
    {
        const osg::Vec3f& p = positions[i];
        if (!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z()))
        {
            std::ostringstream text;
            text << "atom " << i << " has a non-finite position " << describe(p);
            error = text.str();
            return false;
        }
    }
    double largest = 0.0;
    const std::pair<int, int>* largestPair = nullptr;
    if (!findLargestCutoff(cutoffs, largest, largestPair, error))
        return false;

    Cell cell;
    osg::Vec3d corner(0.0, 0.0, 0.0);
    if (box)
    {
        if (!box->corner.valid() || !box->tilt.valid())
        {
            error = "the box's corner " + describe(box->corner) + " or tilt " + describe(box->tilt) +
                    " is not finite";
            return false;
        }
        for (int axis = 0; axis < 3; ++axis)
        {
            if (!std::isfinite(box->lengths[axis]) || !(box->lengths[axis] > 0.0))
            {
                std::ostringstream text;
                text << "the box's length along "
                     << "xyz"[axis] << " is " << box->lengths[axis] << ": it must be positive and finite";
                error = text.str();
                return false;
            }
        }
        corner = box->corner;
        cell.length = box->lengths;
        cell.tilt = box->tilt;
        cell.inverse.set(1.0 / cell.length.x(), 1.0 / cell.length.y(), 1.0 / cell.length.z());
        std::copy(box->periodic, box->periodic + 3, cell.periodic);
    }
    const osg::Vec3d widths = cell.getWidths();
    for (int axis = 0; axis < 3; ++axis)
    {
        if (cell.periodic[axis] && !(2.0 * largest < widths[axis]))
        {
            std::ostringstream text;
            text.precision(17);
            text << describeCutoff(largestPair) << ", " << largest
                 << ", is not less than half the box's width " << widths[axis] << " across its periodic edge "
                 << "abc"[axis] << ": the nearest image of an atom would be ambiguous";
            error = text.str();
            return false;
        }
    }
    CutoffTable table;
    if (!table.build(cutoffs, error))
        return false;
    if (count < 2 || largest == 0.0)
        return true;

    // Fractional coordinates, wrapped into the box along periodic edges, and their range.
    auto fractionalOf = [&](std::size_t i)
    {
        const osg::Vec3f& p = positions[i];
        osg::Vec3d s = cell.toFractional(osg::Vec3d(p.x(), p.y(), p.z()) - corner);
        for (int axis = 0; axis < 3; ++axis)
        {
            if (cell.periodic[axis])
            {
                s[axis] -= std::floor(s[axis]);
                if (s[axis] >= 1.0)
                    s[axis] = 0.0;
            }
        }
        return s;
    };
    osg::Vec3d low(std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
                   std::numeric_limits<double>::infinity());
    osg::Vec3d high = -low;
    // The size of the coordinates, whose rounding the wrapped positions' slack covers.
    double scale = std::fabs(cell.length.x()) + std::fabs(cell.length.y()) + std::fabs(cell.length.z()) +
                   std::fabs(cell.tilt.x()) + std::fabs(cell.tilt.y()) + std::fabs(cell.tilt.z());
    for (std::size_t i = 0; i < count; ++i)
    {
        const osg::Vec3f& p = positions[i];
        const osg::Vec3d r = osg::Vec3d(p.x(), p.y(), p.z()) - corner;
        scale = std::max({scale, std::fabs(r.x()), std::fabs(r.y()), std::fabs(r.z())});
        const osg::Vec3d s = cell.toFractional(r);
        for (int axis = 0; axis < 3; ++axis)
        {
            if (cell.periodic[axis] && !(std::fabs(s[axis]) <= MAX_BOX_LENGTHS))
            {
                std::ostringstream text;
                text << "atom " << i << " at " << describe(p) << " lies more than " << MAX_BOX_LENGTHS
                     << " box lengths from the periodic box";
                error = text.str();
                return false;
            }
            low[axis] = std::min(low[axis], s[axis]);
            high[axis] = std::max(high[axis], s[axis]);
        }
    }

    // The grid: cells no thinner than the largest cutoff (in distance between faces), along each
    // edge over the box (periodic) or the atoms' range (open), at most about one cell per atom.
    double extent[3], origin[3], perCell[3];
    int dims[3];
    const double cellLimit = std::min(std::max(27.0, static_cast<double>(count)), MAX_CELLS);
    for (int axis = 0; axis < 3; ++axis)
    {
        origin[axis] = cell.periodic[axis] ? 0.0 : low[axis];
        extent[axis] = cell.periodic[axis] ? 1.0 : high[axis] - low[axis];
    }
    for (double grow = CELL_MARGIN;; grow *= 1.25)
    {
        double cells = 1.0;
        for (int axis = 0; axis < 3; ++axis)
        {
            const double along = std::floor(extent[axis] * widths[axis] / (largest * grow));
            dims[axis] = static_cast<int>(std::min(std::max(along, 1.0), cellLimit));
            cells *= dims[axis];
        }
        if (cells <= cellLimit)
            break;
    }
    for (int axis = 0; axis < 3; ++axis)
        perCell[axis] = extent[axis] > 0.0 ? dims[axis] / extent[axis] : 0.0;
    const std::size_t numCells = static_cast<std::size_t>(dims[0]) * dims[1] * dims[2];

    // A counting sort of the atoms by cell, with their positions and type classes in that order.
    Scratch<uint32_t> atomCell(count);
    Scratch<uint32_t> start(numCells + 1, 0);
    for (std::size_t i = 0; i < count; ++i)
    {
        std::size_t index = 0;
        const osg::Vec3d s = fractionalOf(i);
        for (int axis = 2; axis >= 0; --axis)
        {
            const double c = (s[axis] - origin[axis]) * perCell[axis];
            const int ci = static_cast<int>(std::min(std::max(c, 0.0), dims[axis] - 1.0));
            index = index * dims[axis] + ci;
        }
        atomCell[i] = static_cast<uint32_t>(index);
        ++start[index + 1];
    }
    for (std::size_t c = 0; c < numCells; ++c)
        start[c + 1] += start[c];
    Scratch<uint32_t> order(count);
    {
        Scratch<uint32_t> next(start.begin(), start.end() - 1);
        for (std::size_t i = 0; i < count; ++i)
            order[next[atomCell[i]]++] = static_cast<uint32_t>(i);
    }
    Scratch<uint32_t>().swap(atomCell);
    Scratch<osg::Vec3f> sortedPositions(count);
    Scratch<osg::Vec3f> sortedWrapped(count);
    Scratch<uint32_t> sortedClasses(count);
    for (std::size_t s = 0; s < count; ++s)
    {
        sortedPositions[s] = positions[order[s]];
        const osg::Vec3d w = cell.toCartesian(fractionalOf(order[s]));
        sortedWrapped[s].set(float(w.x()), float(w.y()), float(w.z()));
        sortedClasses[s] = types.empty() ? table.classOf(0) : table.classOf(types[order[s]]);
    }

    // Each pair once. Where every periodic edge has three cells or more, from each cell to itself
    // and to the 13 of its neighbours that come after it; otherwise (a neighbour would be reached
    // twice through the boundaries) from each atom to every neighbour's atoms of larger indices.
    // Threads take runs of cells of about as many atoms each, and find bonds of their own.
    bool halfStencil = true;
    for (int axis = 0; axis < 3; ++axis)
        halfStencil = halfStencil && (!cell.periodic[axis] || dims[axis] >= 3);
    const std::size_t bondLimit = std::min<std::size_t>(std::max(MIN_BOND_LIMIT, MAX_BONDS_PER_ATOM * count),
                                                        std::numeric_limits<uint32_t>::max());
    table.setSlack(WRAPPED_ROUNDING * scale);
    const PairSearch search{cell,          dims,          halfStencil, start,    order, sortedPositions,
                            sortedWrapped, sortedClasses, table,       bondLimit};
    const unsigned int hardware = std::max(1u, std::thread::hardware_concurrency());
    const std::size_t numThreads =
        count < MIN_ATOMS_PER_THREAD
            ? 1
            : std::min<std::size_t>({hardware, MAX_THREADS, count / MIN_ATOMS_PER_THREAD});
    std::vector<Scratch<Bond>> found(numThreads);
    std::vector<char> overLimit(numThreads, 0);
    {
        std::vector<std::size_t> firstCell(numThreads + 1, numCells);
        for (std::size_t t = 0; t < numThreads; ++t)
            firstCell[t] =
                std::lower_bound(start.begin(), start.end() - 1, count * t / numThreads) - start.begin();
        // 1: past the limit of bonds; 2: out of memory.
        auto runThread = [&](std::size_t t)
        {
            try
            {
                overLimit[t] = search.run(firstCell[t], firstCell[t + 1], found[t]) ? 0 : 1;
            }
            catch (const std::bad_alloc&)
            {
                overLimit[t] = 2;
            }
        };
        std::vector<std::thread> threads;
        for (std::size_t t = 1; t < numThreads; ++t)
            threads.emplace_back(runThread, t);
        runThread(0);
        for (std::thread& thread : threads)
            thread.join();
    }
    if (std::find(overLimit.begin(), overLimit.end(), 2) != overLimit.end())
        throw std::bad_alloc();
    std::size_t numBonds = 0;
    for (const Scratch<Bond>& f : found)
        numBonds += f.size();
    if (numBonds > bondLimit || std::find(overLimit.begin(), overLimit.end(), 1) != overLimit.end())
    {
        std::ostringstream text;
        text << "more than " << bondLimit << " bonds among " << count
             << " atoms: the cutoffs are far too long for the atoms' spacing";
        error = text.str();
        return false;
    }
    Scratch<uint32_t>().swap(order);
    Scratch<osg::Vec3f>().swap(sortedPositions);
    Scratch<osg::Vec3f>().swap(sortedWrapped);
    Scratch<uint32_t>().swap(sortedClasses);

    // By first atom (a counting sort), then each atom's bonds by second atom. bonds keeps its
    // memory: a caller that passes the same list frame after frame allocates it once.
    Scratch<uint32_t> firstBegin(count + 1, 0);
    for (const Scratch<Bond>& f : found)
        for (const Bond& bond : f)
            ++firstBegin[bond.first + 1];
    for (std::size_t i = 0; i < count; ++i)
        firstBegin[i + 1] += firstBegin[i];
    bonds.resize(numBonds);
    {
        Scratch<uint32_t> next(firstBegin.begin(), firstBegin.end() - 1);
        for (Scratch<Bond>& f : found)
        {
            for (const Bond& bond : f)
                bonds[next[bond.first]++] = bond;
            Scratch<Bond>().swap(f);
        }
    }
    for (std::size_t i = 0; i < count; ++i)
    {
        // Insertion sort: an atom has a few bonds.
        for (uint32_t b = firstBegin[i] + 1; b < firstBegin[i + 1]; ++b)
        {
            const Bond bond = bonds[b];
            uint32_t c = b;
            for (; c > firstBegin[i] && bonds[c - 1].second > bond.second; --c)
                bonds[c] = bonds[c - 1];
            bonds[c] = bond;
        }
    }
    return true;
}

}

bool osgGlyphsData::findBonds(const std::vector<osg::Vec3f>& positions, const std::vector<int>& types,
                              const BondCutoffs& cutoffs, const PeriodicBox* box, std::vector<Bond>& bonds,
                              std::string& error)
{
    try
    {
        return findBondsInMemory(positions, types, cutoffs, box, bonds, error);
    }
    catch (const std::bad_alloc&)
    {
        std::vector<Bond>().swap(bonds);
        std::ostringstream text;
        text << "not enough memory to find the bonds of " << positions.size() << " atoms";
        error = text.str();
        return false;
    }
}

bool osgGlyphsData::getBondTypes(const PointData& frame, const std::string& column, std::vector<int>& types,
                                 std::string& error)
{
    types.clear();
    error.clear();
    const std::vector<float>* values = frame.getColumn(column);
    if (!values)
    {
        std::ostringstream text;
        text << "no column \"" << column << "\" for the atom types; the frame has:";
        for (const std::string& name : frame.getColumnNames())
            text << " " << name;
        error = text.str();
        return false;
    }
    const double origin = frame.getColumnOrigin(column);
    types.resize(values->size());
    for (std::size_t i = 0; i < values->size(); ++i)
    {
        const double value = origin + static_cast<double>((*values)[i]);
        if (!(value == std::floor(value)) || value < std::numeric_limits<int>::min() ||
            value > std::numeric_limits<int>::max())
        {
            std::ostringstream text;
            text << "atom " << i << " has the type " << value << " in column \"" << column
                 << "\": a type must be an integer within the range of an int";
            error = text.str();
            types.clear();
            return false;
        }
        types[i] = static_cast<int>(value);
    }
    return true;
}
