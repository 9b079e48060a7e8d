#include <osgGlyphsData/FrameInterpolation>

#include "CellCoordinates.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <locale>
#include <new>
#include <sstream>

using namespace osgGlyphsData;

namespace
{

/** A point's index in a frame. 32 bits halve the memory, and the time, of matching; frames of
 * more than MAX_POINTS points are refused. */
typedef uint32_t Index;

/** No point: where a vanishing point is in b, an appearing one in a, a missing neighbour. */
const Index NO_POINT = std::numeric_limits<Index>::max();

/** The most points of a frame: those of a and b together are numbered in one table. */
const std::size_t MAX_POINTS = std::numeric_limits<Index>::max() / 2;

/** The four frames of a segment, in time order. */
enum Frame
{
    BEFORE = 0,
    A = 1,
    B = 2,
    AFTER = 3
};

/** "'run.dump' at timestep 200", for the errors. */
std::string describeFrame(const PointData& frame)
{
    const std::string source =
        frame.getSource().empty() ? std::string("a frame") : "'" + frame.getSource() + "'";
    return source + " at timestep " + std::to_string(frame.getTimestep());
}

/** An id as the file most likely wrote it: integers without decimals. */
std::string formatId(double value)
{
    if (std::isfinite(value) && value == std::floor(value) && std::fabs(value) < 9.0e15)
        return std::to_string(static_cast<int64_t>(value));
    std::ostringstream stream;
    stream.imbue(std::locale::classic());
    stream.precision(17);
    stream << value;
    return stream.str();
}

/** The values of an id column: origin + offset, in double. */
struct Ids
{
    const float* offsets;
    double origin;
    std::size_t count;

    Ids(const PointData& frame, int column)
        : offsets(frame.getColumn(static_cast<std::size_t>(column))->data()),
          origin(frame.getColumnOrigin(static_cast<std::size_t>(column))), count(frame.getNumPoints())
    {
    }

    double operator[](std::size_t point) const { return origin + static_cast<double>(offsets[point]); }
};

/** Whether a value is an integer (a cast, where std::floor is a call into libm). */
bool isInteger(double value)
{
    return std::fabs(value) < 9.0e15 && static_cast<double>(static_cast<int64_t>(value)) == value;
}

/** std::floor, without a call into libm (x86-64 has an instruction for it from SSE4.1 only):
 * NaN, infinities and integers too large for decimals come back as they are. */
double getFloor(double value)
{
    if (!(std::fabs(value) < 4.0e15))
        return value;
    const double truncated = static_cast<double>(static_cast<int64_t>(value));
    return truncated > value ? truncated - 1.0 : truncated;
}

/** The nearest integer (halves up), as quickly. */
double getNearest(double value)
{
    return getFloor(value + 0.5);
}

/** The span of ids, and whether they are all integers; NaN ids are left aside. */
struct IdSpan
{
    double min = std::numeric_limits<double>::infinity();
    double max = -std::numeric_limits<double>::infinity();
    bool integers = true;

    void add(const Ids& ids)
    {
        for (std::size_t point = 0; point < ids.count; ++point)
        {
            const double id = ids[point];
            if (std::isnan(id))
                continue;
            min = std::min(min, id);
            max = std::max(max, id);
            integers = integers && isInteger(id);
        }
    }
};

/** Ids to point indices: the ids of one frame, or of two numbered one after the other. Integer
 * ids in a span not much wider than their count (LAMMPS' 1 to N) index an array; others go
 * through a hash table, at most half full, that holds indices only and compares the frames' ids.
 * NaN ids are never found. Slots hold index + 1 (0: empty), so that the table comes zeroed from
 * calloc rather than being filled. */
class IdTable
{
public:
    /** For the ids of first and (numbered after them) second, all in span. */
    IdTable(const Ids& first, const Ids* second, const IdSpan& span)
        : _first(first), _second(second), _min(span.min), _size(0), _mask(0), _slots(nullptr, &std::free)
    {
        const std::size_t count = first.count + (second ? second->count : 0);
        const double width = span.max - span.min;
        _dense = span.integers && width < 2.0 * static_cast<double>(count) + 1024.0;
        if (_dense)
            _size = static_cast<std::size_t>(width) + 1;
        else
        {
            _size = 16;
            while (_size < 2 * count)
                _size *= 2;
            _mask = _size - 1;
        }
        _slots.reset(static_cast<Index*>(std::calloc(_size, sizeof(Index))));
        if (!_slots)
            throw std::bad_alloc();
    }

    /** The index of the point with the id of point index, which the table gets when it had none
     * (a NaN id: index). */
    Index insert(Index index)
    {
        const double id = getId(index);
        if (std::isnan(id))
            return index;
        Index& slot = _slots[_dense ? static_cast<std::size_t>(id - _min) : probe(id)];
        if (slot == 0)
            slot = index + 1;
        return slot - 1;
    }

    /** The index of id, NO_POINT when the table does not have it. */
    Index find(double id) const
    {
        if (std::isnan(id))
            return NO_POINT;
        if (!_dense)
            return _slots[probe(id)] - 1;
        const double slot = id - _min;
        return slot >= 0.0 && slot < static_cast<double>(_size) && isInteger(slot)
                   ? _slots[static_cast<std::size_t>(slot)] - 1
                   : NO_POINT;
    }

private:
    double getId(Index index) const
    {
        return index < _first.count ? _first[index] : (*_second)[index - _first.count];
    }

    /** The slot of id, or the empty one where it would go. */
    std::size_t probe(double id) const
    {
        // The bits of the id (-0 as 0), through the finalizer of splitmix64: ids that differ in a
        // few low bits spread over the table.
        if (id == 0.0)
            id = 0.0;
        uint64_t hash;
        std::memcpy(&hash, &id, sizeof hash);
        hash = (hash ^ (hash >> 30)) * 0xbf58476d1ce4e5b9ull;
        hash = (hash ^ (hash >> 27)) * 0x94d049bb133111ebull;
        hash ^= hash >> 31;
        std::size_t slot = static_cast<std::size_t>(hash) & _mask;
        while (_slots[slot] != 0 && getId(_slots[slot] - 1) != id)
            slot = (slot + 1) & _mask;
        return slot;
    }

    const Ids& _first;
    const Ids* _second;
    bool _dense;
    double _min;
    std::size_t _size;
    std::size_t _mask;
    std::unique_ptr<Index[], void (*)(void*)> _slots;
};

/** A periodic cell: the corner of the box and its edges a = (lx, 0, 0), b = (xy, ly, 0),
 * c = (xz, yz, lz), as PointData::scaledToCartesian() has them. */
struct Cell
{
    osg::Vec3d corner;
    /** lx, ly, lz. */
    osg::Vec3d length;
    /** xy, xz, yz. */
    osg::Vec3d tilt;
    /** 1 / lx, 1 / ly, 1 / lz: a point takes no division. */
    osg::Vec3d inverse;

    Cell() {}

    Cell(const osg::Vec3d& corner_, const osg::Vec3d& length_, const osg::Vec3d& tilt_)
        : corner(corner_), length(length_), tilt(tilt_),
          inverse(1.0 / length_.x(), 1.0 / length_.y(), 1.0 / length_.z())
    {
    }

    static Cell of(const PointData& frame)
    {
        const osg::BoundingBoxd& box = frame.getBox();
        return Cell(box._min, box._max - box._min, frame.getTilt());
    }

    static Cell blend(const Cell& a, const Cell& b, double t)
    {
        return Cell(a.corner + (b.corner - a.corner) * t, a.length + (b.length - a.length) * t,
                    a.tilt + (b.tilt - a.tilt) * t);
    }

    /** Whether positions can be wrapped in it: finite, with edges of positive lengths. */
    bool isUsable() const
    {
        return corner.valid() && tilt.valid() && length.valid() && length.x() > 0.0 && length.y() > 0.0 &&
               length.z() > 0.0;
    }

    /** The fractional coordinates (in edges) of a displacement. */
    osg::Vec3d toFractional(const osg::Vec3d& d) const { return detail::toCellFractional(d, tilt, inverse); }

    /** The displacement of fractional coordinates. */
    osg::Vec3d toCartesian(const osg::Vec3d& s) const { return detail::toCellCartesian(s, length, tilt); }

    /** The shortest periodic image of a displacement, d + crossed edges: crossed counts the
     * boundaries that the short way crosses along each edge (positive up the edge). */
    osg::Vec3d getMinimumImage(const osg::Vec3d& d, osg::Vec3d& crossed) const
    {
        const osg::Vec3d s = toFractional(d);
        crossed.set(-getNearest(s.x()), -getNearest(s.y()), -getNearest(s.z()));
        return d + toCartesian(crossed);
    }

    osg::Vec3d getMinimumImage(const osg::Vec3d& d) const
    {
        osg::Vec3d crossed;
        return getMinimumImage(d, crossed);
    }
};

/** The image of the box (counted in edges from a's) to take a point back from: the one its
 * fractional position is in, kept between a's (0) and b's (crossed, the boundaries crossed on
 * the way). A point that crosses no boundary is never moved; one that does goes to the other
 * side when it crosses, and comes to b's place at the end. */
double getDrawnImage(double position, double crossed)
{
    return std::min(std::max(getFloor(position), std::min(0.0, crossed)), std::max(0.0, crossed));
}

/** Where a segment is at t: p = p1 + along * (p2 - p1) + start * m1 + end * m2, a cubic Hermite
 * segment with tangents m1, m2 (a straight line for along = t, start = end = 0). Written around
 * p1 and the difference so that equal ends give the end exactly. */
struct Weights
{
    double along;
    double start;
    double end;

    static Weights linear(double t) { return Weights{t, 0.0, 0.0}; }

    static Weights hermite(double t)
    {
        const double t2 = t * t, t3 = t2 * t;
        return Weights{3.0 * t2 - 2.0 * t3, t3 - 2.0 * t2 + t, t3 - t2};
    }

    double apply(double p1, double d, double m1, double m2) const
    {
        return p1 + along * d + start * m1 + end * m2;
    }

    osg::Vec3d apply(const osg::Vec3d& p1, const osg::Vec3d& d, const osg::Vec3d& m1,
                     const osg::Vec3d& m2) const
    {
        return p1 + d * along + m1 * start + m2 * end;
    }
};

/** The values of a column in one frame relative to the output's origin (a's): shift + offset,
 * in double. Empty (no values) where the frame does not have the column. */
struct Values
{
    const float* offsets = nullptr;
    double shift = 0.0;

    bool has() const { return offsets != nullptr; }
    double operator[](std::size_t point) const { return shift + static_cast<double>(offsets[point]); }
};

/** How the frames' values of a column become the output's. */
enum class Blend
{
    /** Interpolated. */
    Numeric,
    /** Box-scaled coordinates xs ys zs: interpolated the short way around a period of 1. */
    Scaled,
    /** Cartesian x y z: interpolated together the short way through the box. */
    Cartesian,
    /** Categorical columns and the id: the value of the frame the point comes from. */
    Copied
};

/** One column of the output. */
struct ColumnPlan
{
    std::string name;
    Blend blend = Blend::Numeric;
    /** x, y, z: 0, 1, 2 for Blend::Cartesian. */
    int axis = -1;
    /** The column's index in before, a, b, after; -1 where that frame does not have it. */
    int columns[4] = {-1, -1, -1, -1};
    /** Blend::Copied: the output's labels (a's, then b's that a does not have). */
    std::vector<std::string> labels;
    /** Blend::Copied: b's label indices as the output's; empty when b's column has no labels. */
    std::vector<double> labelsOfB;
};

int getAxis(const std::string& name, const char* x, const char* y, const char* z)
{
    return name == x ? 0 : name == y ? 1 : name == z ? 2 : -1;
}

}

/** Everything the constructor works out: which points go together, how each column blends. */
struct FrameInterpolator::Matching
{
    osg::ref_ptr<const PointData> frames[4];

    /** For each point of a, its point in b, or NO_POINT when it vanishes. */
    std::vector<Index> bOfA;
    /** Points of b that a does not have, in b's order. */
    std::vector<Index> appearing;
    std::size_t numMatched = 0;
    /** For each point of a, its point in before and after (Smooth); empty when that frame is not
     * there or its points cannot be matched. */
    std::vector<Index> beforeOfA;
    std::vector<Index> afterOfA;

    std::vector<ColumnPlan> columns;
    /** The plans of x, y, z (Blend::Cartesian), -1 for each the output does not have. */
    int cartesian[3] = {-1, -1, -1};
    /** Whether the Cartesian positions of before and after can give tangents. */
    bool cartesianNeighbours[4] = {false, false, false, false};

    /** The boxes of a and b and their mean, the one of the minimum image between them; the mean
     * boxes of before and a, and b and after (or the first one where those have none). */
    Cell cells[4];
    Cell cellA;
    Cell cellB;
    bool hasBox = false;

    /** A Smooth tangent at a, (p2 - p0) * startScale, and at b, (p3 - p1) * endScale: both 1/2
     * for evenly spaced frames, scaled by their timesteps otherwise. */
    double startScale = 0.5;
    double endScale = 0.5;

    const PointData& frame(int which) const { return *frames[which]; }

    bool matchPoints(const std::string& idColumn, std::string& error);
    bool matchById(int idA, int idB, std::string& error);
    bool matchNeighbour(Frame which, const std::string& idColumn, const IdTable& table,
                        std::vector<Index>& ofA, std::string& error) const;
    void planColumns(const FrameInterpolationOptions& options);
    void planCopied(ColumnPlan& plan) const;
    void planSpacing();

    std::size_t getNumPoints(bool second) const
    {
        return second ? numMatched + appearing.size() : bOfA.size();
    }

    Index getBefore(Index pointA) const { return beforeOfA.empty() ? NO_POINT : beforeOfA[pointA]; }
    Index getAfter(Index pointA) const { return afterOfA.empty() ? NO_POINT : afterOfA[pointA]; }

    Values getValues(const ColumnPlan& plan, int which) const
    {
        Values values;
        const int column = plan.columns[which];
        if (column < 0 || !frames[which])
            return values;
        const PointData& data = frame(which);
        values.offsets = data.getColumn(static_cast<std::size_t>(column))->data();
        values.shift = data.getColumnOrigin(static_cast<std::size_t>(column)) -
                       frame(A).getColumnOrigin(static_cast<std::size_t>(plan.columns[A]));
        return values;
    }

    /** Calls visit(pointA, pointB) for each point of the frame, in its order: a's (matched and,
     * in the first half, vanishing, whose pointB is NO_POINT), then in the second half the
     * appearing ones (pointA NO_POINT). */
    template <class Visit>
    void forEachRow(bool second, Visit visit) const
    {
        const Index numA = static_cast<Index>(bOfA.size());
        for (Index pointA = 0; pointA < numA; ++pointA)
        {
            if (!second || bOfA[pointA] != NO_POINT)
                visit(pointA, bOfA[pointA]);
        }
        if (second)
        {
            for (Index pointB : appearing)
                visit(NO_POINT, pointB);
        }
    }

    /** The fill functions append each row's value of their column(s) to out, reserved. */
    void fillNumeric(const ColumnPlan& plan, const Weights& weights, bool second,
                     std::vector<float>& out) const;
    void fillScaled(const ColumnPlan& plan, const Weights& weights, bool second,
                    std::vector<float>& out) const;
    void fillCartesian(double t, const Weights& weights, bool second, std::vector<float>* out) const;
    void fillCopied(const ColumnPlan& plan, bool second, std::vector<float>& out) const;
};

bool FrameInterpolator::Matching::matchPoints(const std::string& idColumn, std::string& error)
{
    const PointData& a = frame(A);
    const PointData& b = frame(B);
    for (const osg::ref_ptr<const PointData>& data : frames)
    {
        if (data && data->getNumPoints() > MAX_POINTS)
        {
            error = describeFrame(*data) + " has " + std::to_string(data->getNumPoints()) +
                    " points, more than frames can be interpolated with (" + std::to_string(MAX_POINTS) + ")";
            return false;
        }
    }
    const int idA = a.findColumn(idColumn), idB = b.findColumn(idColumn);
    if (idA >= 0 && idB >= 0)
        return matchById(idA, idB, error);
    if (a.getNumPoints() != b.getNumPoints())
    {
        error =
            "no '" + idColumn +
            "' column in both frames to match their points by, and their counts differ: " + describeFrame(a) +
            " has " + std::to_string(a.getNumPoints()) + " points, " + describeFrame(b) + " has " +
            std::to_string(b.getNumPoints());
        return false;
    }
    bOfA.resize(a.getNumPoints());
    for (Index point = 0; point < bOfA.size(); ++point)
        bOfA[point] = point;
    numMatched = bOfA.size();
    // By order: before goes with a, after with b, when their counts agree.
    if (frames[BEFORE] && frame(BEFORE).getNumPoints() == bOfA.size())
        beforeOfA = bOfA;
    if (frames[AFTER] && frame(AFTER).getNumPoints() == bOfA.size())
        afterOfA = bOfA;
    return true;
}

bool FrameInterpolator::Matching::matchById(int idA, int idB, std::string& error)
{
    const Ids idsA(frame(A), idA), idsB(frame(B), idB);
    const Index numA = static_cast<Index>(idsA.count), numB = static_cast<Index>(idsB.count);
    const std::string& name = frame(A).getColumnNames()[idA];
    bOfA.assign(numA, NO_POINT);
    // One table: a's ids, then b's that a does not have, as numA + their index in b.
    IdSpan span;
    span.add(idsA);
    span.add(idsB);
    IdTable table(idsA, &idsB, span);
    for (Index point = 0; point < numA; ++point)
    {
        if (table.insert(point) != point)
        {
            error = "duplicate " + name + " " + formatId(idsA[point]) + " in " + describeFrame(frame(A));
            return false;
        }
    }
    for (Index point = 0; point < numB; ++point)
    {
        const Index found = table.insert(numA + point);
        if (found == numA + point)
            appearing.push_back(point);
        else if (found >= numA || bOfA[found] != NO_POINT)
        {
            error = "duplicate " + name + " " + formatId(idsB[point]) + " in " + describeFrame(frame(B));
            return false;
        }
        else
        {
            bOfA[found] = point;
            ++numMatched;
        }
    }
    return matchNeighbour(BEFORE, name, table, beforeOfA, error) &&
           matchNeighbour(AFTER, name, table, afterOfA, error);
}

bool FrameInterpolator::Matching::matchNeighbour(Frame which, const std::string& idColumn,
                                                 const IdTable& table, std::vector<Index>& ofA,
                                                 std::string& error) const
{
    const int id = frames[which] ? frame(which).findColumn(idColumn) : -1;
    if (id < 0)
        return true;
    // The neighbour's ids through a and b's table: only the matched points need a neighbour.
    const Ids ids(frame(which), id);
    const Index numA = static_cast<Index>(bOfA.size());
    ofA.assign(numA, NO_POINT);
    for (Index point = 0; point < ids.count; ++point)
    {
        const Index pointA = table.find(ids[point]);
        if (pointA >= numA || bOfA[pointA] == NO_POINT)
            continue;
        if (ofA[pointA] != NO_POINT)
        {
            error =
                "duplicate " + idColumn + " " + formatId(ids[point]) + " in " + describeFrame(frame(which));
            return false;
        }
        ofA[pointA] = point;
    }
    return true;
}

void FrameInterpolator::Matching::planCopied(ColumnPlan& plan) const
{
    plan.blend = Blend::Copied;
    plan.labels = frame(A).getColumnLabels(plan.name);
    const std::vector<std::string>& labelsB = frame(B).getColumnLabels(plan.name);
    for (const std::string& label : labelsB)
    {
        const auto found = std::find(plan.labels.begin(), plan.labels.end(), label);
        plan.labelsOfB.push_back(static_cast<double>(found - plan.labels.begin()));
        if (found == plan.labels.end())
            plan.labels.push_back(label);
    }
}

void FrameInterpolator::Matching::planColumns(const FrameInterpolationOptions& options)
{
    const PointData& a = frame(A);
    const PointData& b = frame(B);
    hasBox = a.hasBox() && b.hasBox();
    cellA = Cell::of(a);
    cellB = Cell::of(b);
    cells[A] = Cell::blend(cellA, cellB, 0.5);
    cells[B] = cells[A];
    const bool periodic = options.unwrapPeriodic && hasBox;
    const bool periodicCartesian = periodic && cellA.isUsable() && cellB.isUsable();
    for (int which : {BEFORE, AFTER})
    {
        const int next = which == BEFORE ? A : B;
        cells[which] = cells[A];
        if (frames[which] && frame(which).hasBox() && Cell::of(frame(which)).isUsable())
            cells[which] = Cell::blend(Cell::of(frame(which)), Cell::of(frame(next)), 0.5);
    }

    for (std::size_t index = 0; index < a.getNumColumns(); ++index)
    {
        ColumnPlan plan;
        plan.name = a.getColumnNames()[index];
        plan.columns[A] = static_cast<int>(index);
        plan.columns[B] = b.findColumn(plan.name);
        if (plan.columns[B] < 0)
            continue;
        for (int which : {BEFORE, AFTER})
            plan.columns[which] = frames[which] ? frame(which).findColumn(plan.name) : -1;
        const int cartesianAxis = getAxis(plan.name, "x", "y", "z");
        if (plan.name == options.idColumn || !a.getColumnLabels(plan.name).empty() ||
            !b.getColumnLabels(plan.name).empty())
            planCopied(plan);
        else if (periodicCartesian && cartesianAxis >= 0)
        {
            plan.blend = Blend::Cartesian;
            plan.axis = cartesianAxis;
            cartesian[cartesianAxis] = static_cast<int>(columns.size());
        }
        else if (periodic && getAxis(plan.name, "xs", "ys", "zs") >= 0)
            plan.blend = Blend::Scaled;
        columns.push_back(std::move(plan));
    }

    // Positions are a whole: a neighbour gives their tangents only with all the axes a and b have.
    for (int which : {BEFORE, AFTER})
    {
        cartesianNeighbours[which] = true;
        for (int plan : cartesian)
        {
            if (plan >= 0 && columns[plan].columns[which] < 0)
                cartesianNeighbours[which] = false;
        }
    }
}

void FrameInterpolator::Matching::planSpacing()
{
    // Tangents from timesteps when they increase, so that uneven dumps keep straight motion straight.
    const double ta = static_cast<double>(frame(A).getTimestep());
    const double tb = static_cast<double>(frame(B).getTimestep());
    if (!(ta < tb))
        return;
    if (frames[BEFORE] && static_cast<double>(frame(BEFORE).getTimestep()) < ta)
        startScale = (tb - ta) / (tb - static_cast<double>(frame(BEFORE).getTimestep()));
    if (frames[AFTER] && static_cast<double>(frame(AFTER).getTimestep()) > tb)
        endScale = (tb - ta) / (static_cast<double>(frame(AFTER).getTimestep()) - ta);
}

void FrameInterpolator::Matching::fillNumeric(const ColumnPlan& plan, const Weights& weights, bool second,
                                              std::vector<float>& out) const
{
    const Values before = getValues(plan, BEFORE), a = getValues(plan, A), b = getValues(plan, B),
                 after = getValues(plan, AFTER);
    forEachRow(second,
               [&](Index pointA, Index pointB)
               {
                   if (pointB == NO_POINT)
                       out.push_back(a.offsets[pointA]);
                   else if (pointA == NO_POINT)
                       out.push_back(static_cast<float>(b[pointB]));
                   else
                   {
                       const double p1 = a[pointA], d = b[pointB] - p1;
                       const Index pointBefore = getBefore(pointA), pointAfter = getAfter(pointA);
                       const double m1 = pointBefore != NO_POINT && before.has()
                                             ? (d + p1 - before[pointBefore]) * startScale
                                             : d;
                       const double m2 = pointAfter != NO_POINT && after.has()
                                             ? (after[pointAfter] - b[pointB] + d) * endScale
                                             : d;
                       out.push_back(static_cast<float>(weights.apply(p1, d, m1, m2)));
                   }
               });
}

void FrameInterpolator::Matching::fillScaled(const ColumnPlan& plan, const Weights& weights, bool second,
                                             std::vector<float>& out) const
{
    const Values before = getValues(plan, BEFORE), a = getValues(plan, A), b = getValues(plan, B),
                 after = getValues(plan, AFTER);
    const double origin = frame(A).getColumnOrigin(static_cast<std::size_t>(plan.columns[A]));
    const auto wrap = [](double d) { return d - getNearest(d); };
    forEachRow(second,
               [&](Index pointA, Index pointB)
               {
                   if (pointB == NO_POINT)
                       out.push_back(a.offsets[pointA]);
                   else if (pointA == NO_POINT)
                       out.push_back(static_cast<float>(b[pointB]));
                   else
                   {
                       const double p1 = a[pointA], crossed = -getNearest(b[pointB] - p1),
                                    d = b[pointB] - p1 + crossed;
                       const Index pointBefore = getBefore(pointA), pointAfter = getAfter(pointA);
                       const double m1 = pointBefore != NO_POINT && before.has()
                                             ? (d + wrap(p1 - before[pointBefore])) * startScale
                                             : d;
                       const double m2 = pointAfter != NO_POINT && after.has()
                                             ? (wrap(after[pointAfter] - b[pointB]) + d) * endScale
                                             : d;
                       const double p = weights.apply(p1, d, m1, m2);
                       out.push_back(static_cast<float>(p - getDrawnImage(origin + p, crossed)));
                   }
               });
}

void FrameInterpolator::Matching::fillCartesian(double t, const Weights& weights, bool second,
                                                std::vector<float>* out) const
{
    // Missing axes read as 0 in every frame: no displacement, and a place on the box's corner.
    Values before[3], a[3], b[3], after[3];
    const Cell cell = Cell::blend(cellA, cellB, t);
    osg::Vec3d corner;
    for (int axis = 0; axis < 3; ++axis)
    {
        if (cartesian[axis] < 0)
            continue;
        const ColumnPlan& plan = columns[cartesian[axis]];
        before[axis] = getValues(plan, BEFORE);
        a[axis] = getValues(plan, A);
        b[axis] = getValues(plan, B);
        after[axis] = getValues(plan, AFTER);
        corner[axis] =
            cell.corner[axis] - frame(A).getColumnOrigin(static_cast<std::size_t>(plan.columns[A]));
    }
    const auto position = [](const Values* values, std::size_t point)
    {
        osg::Vec3d p;
        for (int axis = 0; axis < 3; ++axis)
            p[axis] = values[axis].has() ? values[axis][point] : 0.0;
        return p;
    };
    const auto write = [&](const osg::Vec3d& p)
    {
        for (int axis = 0; axis < 3; ++axis)
        {
            if (a[axis].has())
                out[axis].push_back(static_cast<float>(p[axis]));
        }
    };
    const bool useBefore = cartesianNeighbours[BEFORE], useAfter = cartesianNeighbours[AFTER];
    forEachRow(second,
               [&](Index pointA, Index pointB)
               {
                   if (pointB == NO_POINT || pointA == NO_POINT)
                   {
                       write(pointB == NO_POINT ? position(a, pointA) : position(b, pointB));
                       return;
                   }
                   const osg::Vec3d p1 = position(a, pointA), p2 = position(b, pointB);
                   osg::Vec3d crossed;
                   const osg::Vec3d d = cells[A].getMinimumImage(p2 - p1, crossed);
                   osg::Vec3d m1 = d, m2 = d;
                   const Index pointBefore = getBefore(pointA), pointAfter = getAfter(pointA);
                   if (useBefore && pointBefore != NO_POINT)
                       m1 = (d + cells[BEFORE].getMinimumImage(p1 - position(before, pointBefore))) *
                            startScale;
                   if (useAfter && pointAfter != NO_POINT)
                       m2 = (cells[AFTER].getMinimumImage(position(after, pointAfter) - p2) + d) * endScale;
                   osg::Vec3d p = weights.apply(p1, d, m1, m2);
                   if (crossed != osg::Vec3d(0.0, 0.0, 0.0))
                   {
                       const osg::Vec3d s = cell.toFractional(p - corner);
                       p -= cells[A].toCartesian(osg::Vec3d(getDrawnImage(s.x(), crossed.x()),
                                                            getDrawnImage(s.y(), crossed.y()),
                                                            getDrawnImage(s.z(), crossed.z())));
                   }
                   write(p);
               });
}

void FrameInterpolator::Matching::fillCopied(const ColumnPlan& plan, bool second,
                                             std::vector<float>& out) const
{
    const Values a = getValues(plan, A), b = getValues(plan, B);
    const double originA = frame(A).getColumnOrigin(static_cast<std::size_t>(plan.columns[A]));
    const std::vector<double>& labelsOfB = plan.labelsOfB;
    const auto fromB = [&](std::size_t point)
    {
        double value = originA + b[point];
        if (value >= 0.0 && value < static_cast<double>(labelsOfB.size()) && isInteger(value))
            value = labelsOfB[static_cast<std::size_t>(value)];
        return static_cast<float>(value - originA);
    };
    forEachRow(second,
               [&](Index pointA, Index pointB)
               {
                   out.push_back(pointA != NO_POINT && (!second || pointB == NO_POINT) ? a.offsets[pointA]
                                                                                       : fromB(pointB));
               });
}

FrameInterpolator::FrameInterpolator(const PointData* before, const PointData& a, const PointData& b,
                                     const PointData* after, const FrameInterpolationOptions& options)
    : _matching(new Matching)
{
    Matching& matching = *_matching;
    const bool smooth = options.method == FrameInterpolationOptions::Method::Smooth;
    matching.frames[BEFORE] = smooth ? before : nullptr;
    matching.frames[A] = &a;
    matching.frames[B] = &b;
    matching.frames[AFTER] = smooth ? after : nullptr;
    if (!matching.matchPoints(options.idColumn, _error))
    {
        _matching.reset();
        return;
    }
    matching.planColumns(options);
    matching.planSpacing();
}

FrameInterpolator::~FrameInterpolator() {}

std::size_t FrameInterpolator::getNumMatched() const
{
    return _matching ? _matching->numMatched : 0;
}

std::size_t FrameInterpolator::getNumVanishing() const
{
    return _matching ? _matching->bOfA.size() - _matching->numMatched : 0;
}

std::size_t FrameInterpolator::getNumAppearing() const
{
    return _matching ? _matching->appearing.size() : 0;
}

osg::ref_ptr<PointData> FrameInterpolator::interpolate(double t) const
{
    if (!_matching)
        return nullptr;
    const Matching& matching = *_matching;
    const PointData& a = matching.frame(A);
    const PointData& b = matching.frame(B);
    t = t > 0.0 ? std::min(t, 1.0) : 0.0;
    const bool second = t >= 0.5;
    const std::size_t numPoints = matching.getNumPoints(second);

    osg::ref_ptr<PointData> output = new PointData(numPoints);
    output->setSource(a.getSource());
    output->setTimestep(a.getTimestep());
    output->setAngstromsPerUnit(a.getAngstromsPerUnit());
    if (matching.hasBox)
    {
        const Cell cell = Cell::blend(matching.cellA, matching.cellB, t);
        output->setBox(osg::BoundingBoxd(cell.corner, cell.corner + cell.length), cell.tilt);
    }
    else if (a.hasBox() || b.hasBox())
        output->setBox(a.hasBox() ? a.getBox() : b.getBox(), a.hasBox() ? a.getTilt() : b.getTilt());

    const Weights weights =
        matching.frames[BEFORE] || matching.frames[AFTER] ? Weights::hermite(t) : Weights::linear(t);
    // x y z together, first; then the columns in a's order.
    std::vector<float> positions[3];
    for (int axis = 0; axis < 3; ++axis)
    {
        if (matching.cartesian[axis] >= 0)
            positions[axis].reserve(numPoints);
    }
    const int* cartesian = matching.cartesian;
    if (std::any_of(cartesian, cartesian + 3, [](int plan) { return plan >= 0; }))
        matching.fillCartesian(t, weights, second, positions);
    for (const ColumnPlan& plan : matching.columns)
    {
        std::vector<float> values;
        if (plan.blend == Blend::Cartesian)
            values = std::move(positions[plan.axis]);
        else
            values.reserve(numPoints);
        if (plan.blend == Blend::Numeric)
            matching.fillNumeric(plan, weights, second, values);
        else if (plan.blend == Blend::Scaled)
            matching.fillScaled(plan, weights, second, values);
        else if (plan.blend == Blend::Copied)
            matching.fillCopied(plan, second, values);
        output->addColumn(plan.name, std::move(values));
        output->setColumnOrigin(plan.name, a.getColumnOrigin(static_cast<std::size_t>(plan.columns[A])));
        if (!plan.labels.empty())
            output->setColumnLabels(plan.name, plan.labels);
    }
    return output;
}
