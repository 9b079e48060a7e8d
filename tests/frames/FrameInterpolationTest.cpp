// Frames between two frames of a trajectory against analytic motion: matching by id and by
// order, periodic boundaries (orthogonal, triclinic, scaled), points that vanish and appear,
// Catmull-Rom through four frames, and the cases that cannot be matched.

#include <osgGlyphsData/FrameInterpolation>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <thread>
#include <vector>

using namespace osgGlyphsData;

namespace
{

/** A column to put in a frame: values in the file's units, stored as offsets from origin. */
struct Column
{
    Column(const std::string& name_, const std::vector<double>& values_, double origin_ = 0.0,
           const std::vector<std::string>& labels_ = {})
        : name(name_), values(values_), origin(origin_), labels(labels_)
    {
    }

    std::string name;
    std::vector<double> values;
    double origin;
    std::vector<std::string> labels;
};

osg::ref_ptr<PointData> makeFrame(const std::string& source, int64_t timestep,
                                  const std::vector<Column>& columns)
{
    osg::ref_ptr<PointData> frame = new PointData(columns.empty() ? 0 : columns.front().values.size());
    frame->setSource(source);
    frame->setTimestep(timestep);
    for (const Column& column : columns)
    {
        std::vector<float> offsets;
        for (double value : column.values)
            offsets.push_back(static_cast<float>(value - column.origin));
        EXPECT_TRUE(frame->addColumn(column.name, std::move(offsets)));
        frame->setColumnOrigin(column.name, column.origin);
        if (!column.labels.empty())
            frame->setColumnLabels(column.name, column.labels);
    }
    return frame;
}

/** The value of a point in the named column, in the file's units. */
double valueOf(const PointData& frame, const std::string& name, std::size_t point)
{
    const int column = frame.findColumn(name);
    EXPECT_GE(column, 0) << name;
    return column < 0 ? std::numeric_limits<double>::quiet_NaN() : frame.getValue(column, point);
}

/** The ids of a frame's points, in order. */
std::vector<double> idsOf(const PointData& frame)
{
    std::vector<double> ids;
    for (std::size_t point = 0; point < frame.getNumPoints(); ++point)
        ids.push_back(valueOf(frame, "id", point));
    return ids;
}

/** Whether actual is expected to about single precision (relative to its size, and to 1). */
::testing::AssertionResult near(double actual, double expected, double tolerance = 1e-5)
{
    if (std::fabs(actual - expected) <= tolerance * std::max(1.0, std::fabs(expected)))
        return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << actual << " instead of " << expected;
}

/** A point moving on a straight line: position and velocity. */
struct Mover
{
    double id;
    osg::Vec3d start;
    osg::Vec3d velocity;
    double energy;
    double energyRate;

    osg::Vec3d at(double time) const { return start + velocity * time; }
};

std::vector<Mover> makeMovers(std::size_t count, unsigned seed)
{
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> place(-10.0, 10.0), speed(-1.0, 1.0);
    std::vector<Mover> movers;
    for (std::size_t index = 0; index < count; ++index)
    {
        movers.push_back(
            Mover{static_cast<double>(index + 1), osg::Vec3d(place(random), place(random), place(random)),
                  osg::Vec3d(speed(random), speed(random), speed(random)), place(random), speed(random)});
    }
    return movers;
}

/** The movers at time, in a shuffled order: id, x y z, a scalar and a vector (the velocity). */
osg::ref_ptr<PointData> frameOfMovers(std::vector<Mover> movers, double time, int64_t timestep, unsigned seed)
{
    std::shuffle(movers.begin(), movers.end(), std::mt19937(seed));
    std::vector<Column> columns = {{"id", {}},   {"x", {}},  {"y", {}},  {"z", {}},
                                   {"c_pe", {}}, {"vx", {}}, {"vy", {}}, {"vz", {}}};
    for (const Mover& mover : movers)
    {
        const osg::Vec3d p = mover.at(time);
        const double values[] = {mover.id,
                                 p.x(),
                                 p.y(),
                                 p.z(),
                                 mover.energy + mover.energyRate * time,
                                 mover.velocity.x() * (1.0 + time),
                                 mover.velocity.y() * (1.0 + time),
                                 mover.velocity.z() * (1.0 + time)};
        for (std::size_t column = 0; column < columns.size(); ++column)
            columns[column].values.push_back(values[column]);
    }
    osg::ref_ptr<PointData> frame = makeFrame("movers.dump", timestep, columns);
    frame->setBox(osg::BoundingBoxd(-100, -100, -100, 100, 100, 100));
    return frame;
}

/** Checks every point of a frame of movers against their analytic motion at time. */
void expectMoversAt(const PointData& frame, const std::vector<Mover>& movers, double time)
{
    ASSERT_EQ(frame.getNumPoints(), movers.size());
    for (std::size_t point = 0; point < frame.getNumPoints(); ++point)
    {
        const Mover& mover = movers.at(static_cast<std::size_t>(valueOf(frame, "id", point)) - 1);
        const osg::Vec3d p = mover.at(time);
        EXPECT_TRUE(near(valueOf(frame, "x", point), p.x())) << "id " << mover.id << " at " << time;
        EXPECT_TRUE(near(valueOf(frame, "y", point), p.y())) << "id " << mover.id << " at " << time;
        EXPECT_TRUE(near(valueOf(frame, "z", point), p.z())) << "id " << mover.id << " at " << time;
        EXPECT_TRUE(near(valueOf(frame, "c_pe", point), mover.energy + mover.energyRate * time));
        EXPECT_TRUE(near(valueOf(frame, "vx", point), mover.velocity.x() * (1.0 + time)));
        EXPECT_TRUE(near(valueOf(frame, "vy", point), mover.velocity.y() * (1.0 + time)));
        EXPECT_TRUE(near(valueOf(frame, "vz", point), mover.velocity.z() * (1.0 + time)));
    }
}

/** The value, in the named column, of the point of an id. */
double xOfId(const PointData& frame, double id, const std::string& name = "x")
{
    for (std::size_t point = 0; point < frame.getNumPoints(); ++point)
    {
        if (valueOf(frame, "id", point) == id)
            return valueOf(frame, name, point);
    }
    ADD_FAILURE() << "no id " << id;
    return std::numeric_limits<double>::quiet_NaN();
}

FrameInterpolationOptions smooth()
{
    FrameInterpolationOptions options;
    options.method = FrameInterpolationOptions::Method::Smooth;
    return options;
}

}

TEST(FrameInterpolation, FollowsStraightMotionWithIdsShuffledDifferently)
{
    const std::vector<Mover> movers = makeMovers(200, 1);
    osg::ref_ptr<PointData> a = frameOfMovers(movers, 0.0, 100, 2);
    osg::ref_ptr<PointData> b = frameOfMovers(movers, 1.0, 200, 3);
    osg::ref_ptr<FrameInterpolator> interpolator = new FrameInterpolator(nullptr, *a, *b, nullptr);
    ASSERT_TRUE(interpolator->isValid()) << interpolator->getError();
    EXPECT_EQ(interpolator->getNumMatched(), 200u);
    EXPECT_EQ(interpolator->getNumVanishing(), 0u);
    EXPECT_EQ(interpolator->getNumAppearing(), 0u);
    for (double t : {0.0, 0.25, 0.5, 0.75, 1.0})
    {
        osg::ref_ptr<PointData> frame = interpolator->interpolate(t);
        ASSERT_TRUE(frame.valid());
        expectMoversAt(*frame, movers, t);
        // a's order, a's timestep and source, the columns in a's order.
        EXPECT_EQ(idsOf(*frame), idsOf(*a));
        EXPECT_EQ(frame->getTimestep(), 100);
        EXPECT_EQ(frame->getSource(), "movers.dump");
        EXPECT_EQ(frame->getColumnNames(), a->getColumnNames());
    }
    // t beyond the interval is clamped to it.
    expectMoversAt(*interpolator->interpolate(-1.0), movers, 0.0);
    expectMoversAt(*interpolator->interpolate(2.0), movers, 1.0);
}

TEST(FrameInterpolation, KeepsEachColumnsOriginAndBlendsInDouble)
{
    // Far coordinates: b's column has another origin than a's; the output has a's.
    const Column idA{"id", {1, 2}}, idB{"id", {2, 1}};
    osg::ref_ptr<PointData> a = makeFrame("a", 0, {idA, {"x", {6378137.25, 6378140.5}, 6378137.0}});
    osg::ref_ptr<PointData> b = makeFrame("b", 1, {idB, {"x", {6378150.5, 6378139.25}, 6378150.0}});
    osg::ref_ptr<FrameInterpolator> interpolator = new FrameInterpolator(nullptr, *a, *b, nullptr);
    osg::ref_ptr<PointData> frame = interpolator->interpolate(0.25);
    EXPECT_EQ(frame->getColumnOrigin("x"), 6378137.0);
    EXPECT_EQ(xOfId(*frame, 1), 6378137.25 + 0.25 * 2.0);
    EXPECT_EQ(xOfId(*frame, 2), 6378140.5 + 0.25 * 10.0);
}

TEST(FrameInterpolation, CrossesAPeriodicBoundaryTheShortWay)
{
    // x in [-2, 3]: id 1 leaves through xhi, id 2 through xlo, id 3 stays in the middle.
    const double xlo = -2.0, xhi = 3.0;
    const osg::BoundingBoxd box(xlo, 0, 0, xhi, 5, 5);
    osg::ref_ptr<PointData> a = makeFrame(
        "a", 0, {{"id", {1, 2, 3}}, {"x", {xhi - 0.1, xlo + 0.1, 0.5}}, {"y", {1, 2, 3}}, {"z", {1, 2, 3}}});
    osg::ref_ptr<PointData> b = makeFrame(
        "b", 1, {{"id", {3, 2, 1}}, {"x", {0.8, xhi - 0.1, xlo + 0.1}}, {"y", {3, 2, 1}}, {"z", {3, 2, 1}}});
    a->setBox(box);
    b->setBox(box);
    osg::ref_ptr<FrameInterpolator> interpolator = new FrameInterpolator(nullptr, *a, *b, nullptr);
    ASSERT_TRUE(interpolator->isValid()) << interpolator->getError();

    EXPECT_TRUE(near(xOfId(*interpolator->interpolate(0.25), 1), xhi - 0.05));
    EXPECT_TRUE(near(xOfId(*interpolator->interpolate(0.75), 1), xlo + 0.05));
    const double middle = xOfId(*interpolator->interpolate(0.5), 1);
    EXPECT_TRUE(near(middle, xlo) || near(middle, xhi)) << middle;
    EXPECT_TRUE(near(xOfId(*interpolator->interpolate(0.25), 2), xlo + 0.05));
    EXPECT_TRUE(near(xOfId(*interpolator->interpolate(0.75), 2), xhi - 0.05));
    EXPECT_TRUE(near(xOfId(*interpolator->interpolate(0.5), 3), 0.65));
    EXPECT_EQ(xOfId(*interpolator->interpolate(1.0), 1), b->getValue(1, 2));

    // Never in the middle of the box, always in it.
    for (int step = 0; step <= 100; ++step)
    {
        osg::ref_ptr<PointData> frame = interpolator->interpolate(step / 100.0);
        for (double id : {1.0, 2.0})
        {
            const double x = xOfId(*frame, id);
            EXPECT_TRUE(x >= xlo - 1e-6 && x <= xhi + 1e-6) << x;
            EXPECT_TRUE(x < xlo + 0.11 || x > xhi - 0.11) << x;
        }
        EXPECT_TRUE(near(valueOf(*frame, "y", 0), 1.0));
    }

    // Without unwrapping, the point goes across the box.
    FrameInterpolationOptions options;
    options.unwrapPeriodic = false;
    interpolator = new FrameInterpolator(nullptr, *a, *b, nullptr, options);
    EXPECT_TRUE(near(xOfId(*interpolator->interpolate(0.5), 1), 0.5 * (xlo + xhi)));
}

TEST(FrameInterpolation, LeavesAPointOutsideTheBoxAlongTheEdgesItDoesNotCross)
{
    // LAMMPS wraps atoms at reneighbouring only: id 1 slightly beyond xhi in both frames; id 2
    // crosses xhi with its y beyond yhi, where y stays.
    osg::ref_ptr<PointData> a = makeFrame("a", 0, {{"id", {1, 2}}, {"x", {5.02, 4.9}}, {"y", {1, 5.01}}});
    osg::ref_ptr<PointData> b = makeFrame("b", 1, {{"id", {1, 2}}, {"x", {5.06, 0.1}}, {"y", {1, 5.03}}});
    a->setBox(osg::BoundingBoxd(0, 0, 0, 5, 5, 5));
    b->setBox(osg::BoundingBoxd(0, 0, 0, 5, 5, 5));
    osg::ref_ptr<FrameInterpolator> interpolator = new FrameInterpolator(nullptr, *a, *b, nullptr);
    EXPECT_TRUE(near(xOfId(*interpolator->interpolate(0.0), 1), 5.02));
    EXPECT_TRUE(near(xOfId(*interpolator->interpolate(0.5), 1), 5.04));
    EXPECT_TRUE(near(xOfId(*interpolator->interpolate(0.75), 2), 0.05));
    EXPECT_TRUE(near(xOfId(*interpolator->interpolate(0.75), 2, "y"), 5.025));
}

TEST(FrameInterpolation, CrossesATriclinicBoundaryThroughTheTilt)
{
    // Points at fractional coordinates moving up to 0.3 of an edge, many across a face.
    const osg::BoundingBoxd box(-1, 0, 2, 9, 8, 12);
    const osg::Vec3d tilt(2.0, 1.0, -1.5);
    osg::ref_ptr<PointData> cell = new PointData;
    cell->setBox(box, tilt);
    std::mt19937 random(7);
    std::uniform_real_distribution<double> place(0.0, 1.0), step(-0.3, 0.3);
    std::vector<osg::Vec3d> starts, steps;
    Column id{"id", {}}, xa{"x", {}}, ya{"y", {}}, za{"z", {}}, xb{"x", {}}, yb{"y", {}}, zb{"z", {}};
    const auto wrap = [](const osg::Vec3d& s)
    { return osg::Vec3d(s.x() - std::floor(s.x()), s.y() - std::floor(s.y()), s.z() - std::floor(s.z())); };
    for (int point = 0; point < 100; ++point)
    {
        starts.emplace_back(place(random), place(random), place(random));
        steps.emplace_back(step(random), step(random), step(random));
        const osg::Vec3d pa = cell->scaledToCartesian(starts.back());
        const osg::Vec3d pb = cell->scaledToCartesian(wrap(starts.back() + steps.back()));
        id.values.push_back(point + 1);
        xa.values.push_back(pa.x());
        ya.values.push_back(pa.y());
        za.values.push_back(pa.z());
        xb.values.push_back(pb.x());
        yb.values.push_back(pb.y());
        zb.values.push_back(pb.z());
    }
    osg::ref_ptr<PointData> a = makeFrame("a", 0, {id, xa, ya, za});
    osg::ref_ptr<PointData> b = makeFrame("b", 1, {id, xb, yb, zb});
    a->setBox(box, tilt);
    b->setBox(box, tilt);
    osg::ref_ptr<FrameInterpolator> interpolator = new FrameInterpolator(nullptr, *a, *b, nullptr);
    for (double t : {0.25, 0.5, 0.75})
    {
        osg::ref_ptr<PointData> frame = interpolator->interpolate(t);
        EXPECT_EQ(frame->getTilt(), tilt);
        for (std::size_t point = 0; point < starts.size(); ++point)
        {
            const osg::Vec3d expected = cell->scaledToCartesian(wrap(starts[point] + steps[point] * t));
            EXPECT_TRUE(near(valueOf(*frame, "x", point), expected.x())) << point << " at " << t;
            EXPECT_TRUE(near(valueOf(*frame, "y", point), expected.y())) << point << " at " << t;
            EXPECT_TRUE(near(valueOf(*frame, "z", point), expected.z())) << point << " at " << t;
        }
    }
}

TEST(FrameInterpolation, WrapsScaledCoordinatesWithAPeriodOfOneAndNeverUnwrappedOnes)
{
    // xs wraps (period 1); xsu and xu are unwrapped: straight through, even out of the box.
    const std::vector<Column> columnsA = {{"id", {1}},   {"xs", {0.95}},  {"xsu", {0.95}},
                                          {"xu", {4.9}}, {"ysu", {0.95}}, {"yu", {4.9}}};
    const std::vector<Column> columnsB = {{"id", {1}},   {"xs", {0.05}},  {"xsu", {1.05}},
                                          {"xu", {5.1}}, {"ysu", {0.05}}, {"yu", {0.1}}};
    osg::ref_ptr<PointData> a = makeFrame("a", 0, columnsA);
    osg::ref_ptr<PointData> b = makeFrame("b", 1, columnsB);
    a->setBox(osg::BoundingBoxd(0, 0, 0, 5, 5, 5));
    b->setBox(osg::BoundingBoxd(0, 0, 0, 5, 5, 5));
    osg::ref_ptr<FrameInterpolator> interpolator = new FrameInterpolator(nullptr, *a, *b, nullptr);
    osg::ref_ptr<PointData> quarter = interpolator->interpolate(0.25),
                            threeQuarters = interpolator->interpolate(0.75);
    EXPECT_TRUE(near(xOfId(*quarter, 1, "xs"), 0.975));
    EXPECT_TRUE(near(xOfId(*threeQuarters, 1, "xs"), 0.025));
    EXPECT_TRUE(near(xOfId(*threeQuarters, 1, "xsu"), 1.025));
    EXPECT_TRUE(near(xOfId(*threeQuarters, 1, "xu"), 5.05));
    EXPECT_TRUE(near(xOfId(*quarter, 1, "ysu"), 0.725));
    EXPECT_TRUE(near(xOfId(*quarter, 1, "yu"), 3.7));
}

TEST(FrameInterpolation, PointsVanishAndAppearAtTheMiddle)
{
    // 2 and 4 vanish, 5 and 6 appear; 1 and 3 move.
    osg::ref_ptr<PointData> a = makeFrame("a", 0, {{"id", {1, 2, 3, 4}}, {"x", {10, 20, 30, 40}}});
    osg::ref_ptr<PointData> b = makeFrame("b", 1, {{"id", {5, 3, 1, 6}}, {"x", {50, 34, 14, 60}}});
    osg::ref_ptr<FrameInterpolator> interpolator = new FrameInterpolator(nullptr, *a, *b, nullptr);
    EXPECT_EQ(interpolator->getNumMatched(), 2u);
    EXPECT_EQ(interpolator->getNumVanishing(), 2u);
    EXPECT_EQ(interpolator->getNumAppearing(), 2u);
    for (double t : {0.0, 0.25, 0.4999})
    {
        osg::ref_ptr<PointData> frame = interpolator->interpolate(t);
        EXPECT_EQ(idsOf(*frame), (std::vector<double>{1, 2, 3, 4})) << t;
        EXPECT_TRUE(near(xOfId(*frame, 1), 10 + 4 * t));
        EXPECT_EQ(xOfId(*frame, 2), 20);
        EXPECT_TRUE(near(xOfId(*frame, 3), 30 + 4 * t));
        EXPECT_EQ(xOfId(*frame, 4), 40);
    }
    for (double t : {0.5, 0.75, 1.0})
    {
        osg::ref_ptr<PointData> frame = interpolator->interpolate(t);
        EXPECT_EQ(idsOf(*frame), (std::vector<double>{1, 3, 5, 6})) << t;
        EXPECT_TRUE(near(xOfId(*frame, 1), 10 + 4 * t));
        EXPECT_TRUE(near(xOfId(*frame, 3), 30 + 4 * t));
        EXPECT_EQ(xOfId(*frame, 5), 50);
        EXPECT_EQ(xOfId(*frame, 6), 60);
    }
}

TEST(FrameInterpolation, MatchesByOrderWithoutAnIdInBothFrames)
{
    osg::ref_ptr<PointData> a = makeFrame("a", 0, {{"x", {1, 2, 3}}, {"y", {0, 0, 0}}});
    osg::ref_ptr<PointData> b = makeFrame("b", 1, {{"x", {3, 4, 5}}, {"y", {1, 2, 3}}});
    osg::ref_ptr<FrameInterpolator> interpolator = new FrameInterpolator(nullptr, *a, *b, nullptr);
    ASSERT_TRUE(interpolator->isValid()) << interpolator->getError();
    osg::ref_ptr<PointData> frame = interpolator->interpolate(0.5);
    for (std::size_t point = 0; point < 3; ++point)
    {
        EXPECT_TRUE(near(valueOf(*frame, "x", point), 2.0 + point));
        EXPECT_TRUE(near(valueOf(*frame, "y", point), 0.5 * (point + 1)));
    }

    // An id in one frame only: by order too, and the id is left out with the columns b lacks.
    osg::ref_ptr<PointData> withId = makeFrame("c", 0, {{"id", {3, 2, 1}}, {"x", {1, 2, 3}}});
    interpolator = new FrameInterpolator(nullptr, *withId, *b, nullptr);
    ASSERT_TRUE(interpolator->isValid()) << interpolator->getError();
    frame = interpolator->interpolate(0.5);
    EXPECT_EQ(frame->getColumnNames(), (std::vector<std::string>{"x"}));
    EXPECT_TRUE(near(valueOf(*frame, "x", 2), 4.0));

    // Smooth: the frames around by order too (x = time^2 + point at times 0 to 3), and a frame
    // around of another count gives straight tangents.
    std::vector<osg::ref_ptr<PointData>> frames;
    for (int time = 0; time < 4; ++time)
        frames.push_back(makeFrame("", time, {{"x", {time * time + 0.0, time * time + 1.0}}}));
    osg::ref_ptr<PointData> other = makeFrame("", 3, {{"x", {9}}});
    interpolator = new FrameInterpolator(frames[0].get(), *frames[1], *frames[2], frames[3].get(), smooth());
    EXPECT_TRUE(near(valueOf(*interpolator->interpolate(0.5), "x", 1), 3.25));
    interpolator = new FrameInterpolator(frames[0].get(), *frames[1], *frames[2], other.get(), smooth());
    EXPECT_TRUE(near(valueOf(*interpolator->interpolate(0.5), "x", 1), 3.375));
}

TEST(FrameInterpolation, RefusesRepeatedIdsAndDifferentCountsWithoutIds)
{
    osg::ref_ptr<PointData> a = makeFrame("a.dump", 100, {{"id", {1, 7, 3}}, {"x", {1, 2, 3}}});
    osg::ref_ptr<PointData> repeatedInA = makeFrame("a.dump", 100, {{"id", {1, 7, 7}}, {"x", {1, 2, 3}}});
    osg::ref_ptr<PointData> repeatedInB = makeFrame("b.dump", 200, {{"id", {7, 3, 7}}, {"x", {1, 2, 3}}});
    osg::ref_ptr<PointData> repeatedNewInB = makeFrame("b.dump", 200, {{"id", {9, 3, 9}}, {"x", {1, 2, 3}}});
    osg::ref_ptr<PointData> b = makeFrame("b.dump", 200, {{"id", {3, 1, 7}}, {"x", {1, 2, 3}}});
    // In the frames around a and b, a repeated id that a and b have; one they lack does not matter.
    osg::ref_ptr<PointData> repeatedBefore = makeFrame("", 0, {{"id", {7, 7}}, {"x", {1, 2}}});
    osg::ref_ptr<PointData> repeatedAfter =
        makeFrame("c.dump", 300, {{"id", {2, 1, 1, 2}}, {"x", {1, 2, 3, 4}}});
    osg::ref_ptr<PointData> repeatedElsewhere =
        makeFrame("c.dump", 300, {{"id", {2, 2, 1}}, {"x", {1, 2, 3}}});

    const auto errorOf = [](const PointData* before, const PointData& first, const PointData& second,
                            const FrameInterpolationOptions& options = FrameInterpolationOptions())
    {
        osg::ref_ptr<FrameInterpolator> interpolator =
            new FrameInterpolator(before, first, second, nullptr, options);
        if (!interpolator->isValid())
        {
            EXPECT_EQ(interpolator->interpolate(0.5), nullptr);
            EXPECT_EQ(interpolator->getNumMatched() + interpolator->getNumAppearing(), 0u);
        }
        return interpolator->getError();
    };
    EXPECT_EQ(errorOf(nullptr, *a, *b), "");
    EXPECT_EQ(errorOf(nullptr, *repeatedInA, *b), "duplicate id 7 in 'a.dump' at timestep 100");
    EXPECT_EQ(errorOf(nullptr, *a, *repeatedInB), "duplicate id 7 in 'b.dump' at timestep 200");
    EXPECT_EQ(errorOf(nullptr, *a, *repeatedNewInB), "duplicate id 9 in 'b.dump' at timestep 200");
    EXPECT_EQ(errorOf(repeatedBefore.get(), *a, *b, smooth()), "duplicate id 7 in a frame at timestep 0");
    osg::ref_ptr<FrameInterpolator> withAfter =
        new FrameInterpolator(nullptr, *a, *b, repeatedAfter.get(), smooth());
    EXPECT_EQ(withAfter->getError(), "duplicate id 1 in 'c.dump' at timestep 300");
    withAfter = new FrameInterpolator(nullptr, *a, *b, repeatedElsewhere.get(), smooth());
    EXPECT_EQ(withAfter->getError(), "");
    // Method::Linear does not look at before.
    EXPECT_EQ(errorOf(repeatedBefore.get(), *a, *b), "");

    osg::ref_ptr<PointData> three = makeFrame("a.dump", 100, {{"x", {1, 2, 3}}});
    osg::ref_ptr<PointData> four = makeFrame("b.dump", 200, {{"x", {1, 2, 3, 4}}});
    EXPECT_EQ(errorOf(nullptr, *three, *four),
              "no 'id' column in both frames to match their points by, and their counts differ: "
              "'a.dump' at timestep 100 has 3 points, 'b.dump' at timestep 200 has 4");
}

TEST(FrameInterpolation, IdsThatAreNaNMatchNothing)
{
    const double nan = std::numeric_limits<double>::quiet_NaN();
    osg::ref_ptr<PointData> a = makeFrame("a", 0, {{"id", {nan, 1, nan}}, {"x", {1, 2, nan}}});
    osg::ref_ptr<PointData> b = makeFrame("b", 1, {{"id", {1, nan}}, {"x", {4, 5}}});
    osg::ref_ptr<FrameInterpolator> interpolator = new FrameInterpolator(nullptr, *a, *b, nullptr);
    ASSERT_TRUE(interpolator->isValid()) << interpolator->getError();
    EXPECT_EQ(interpolator->getNumMatched(), 1u);
    EXPECT_EQ(interpolator->getNumVanishing(), 2u);
    EXPECT_EQ(interpolator->getNumAppearing(), 1u);
    osg::ref_ptr<PointData> frame = interpolator->interpolate(0.25);
    EXPECT_TRUE(near(valueOf(*frame, "x", 1), 2.5));
    EXPECT_TRUE(std::isnan(valueOf(*frame, "x", 2)));
}

TEST(FrameInterpolation, PropagatesNaNValues)
{
    const double nan = std::numeric_limits<double>::quiet_NaN();
    osg::ref_ptr<PointData> a =
        makeFrame("a", 0, {{"id", {1, 2}}, {"x", {nan, 1}}, {"y", {1, 1}}, {"c", {nan, 1}}});
    osg::ref_ptr<PointData> b =
        makeFrame("b", 1, {{"id", {2, 1}}, {"x", {2, nan}}, {"y", {2, 2}}, {"c", {3, 2}}});
    a->setBox(osg::BoundingBoxd(0, 0, 0, 5, 5, 5));
    b->setBox(osg::BoundingBoxd(0, 0, 0, 5, 5, 5));
    for (const FrameInterpolationOptions& options : {FrameInterpolationOptions(), smooth()})
    {
        osg::ref_ptr<FrameInterpolator> interpolator =
            new FrameInterpolator(a.get(), *a, *b, b.get(), options);
        osg::ref_ptr<PointData> frame = interpolator->interpolate(0.5);
        EXPECT_TRUE(std::isnan(valueOf(*frame, "x", 0)));
        EXPECT_TRUE(std::isnan(valueOf(*frame, "c", 0)));
        EXPECT_TRUE(near(valueOf(*frame, "x", 1), 1.5));
        EXPECT_TRUE(near(valueOf(*frame, "c", 1), 2.0));
    }
}

TEST(FrameInterpolation, SmoothIsExactForStraightMotion)
{
    const std::vector<Mover> movers = makeMovers(100, 11);
    // Evenly spaced frames, then unevenly spaced ones (the timesteps scale the tangents).
    for (const std::vector<int64_t>& timesteps :
         {std::vector<int64_t>{0, 100, 200, 300}, {0, 100, 200, 500}, {-300, 100, 200, 300}})
    {
        std::vector<osg::ref_ptr<PointData>> frames;
        for (std::size_t frame = 0; frame < 4; ++frame)
        {
            const double time = timesteps[frame] / 100.0 - 1.0;
            frames.push_back(
                frameOfMovers(movers, time, timesteps[frame], static_cast<unsigned>(20 + frame)));
        }
        osg::ref_ptr<FrameInterpolator> interpolator =
            new FrameInterpolator(frames[0].get(), *frames[1], *frames[2], frames[3].get(), smooth());
        ASSERT_TRUE(interpolator->isValid()) << interpolator->getError();
        for (double t : {0.25, 0.5, 0.75})
            expectMoversAt(*interpolator->interpolate(t), movers, t);
    }
}

TEST(FrameInterpolation, SmoothFollowsACurveCloserThanStraightLines)
{
    // x = id + time^2 at times 0, 1, 2, 3; the middle of the interval [1, 2] is at 1.5.
    std::vector<osg::ref_ptr<PointData>> frames;
    for (int time = 0; time < 4; ++time)
    {
        Column id{"id", {1, 2, 3}}, x{"x", {}};
        if (time == 1)
            id.values = {3, 1, 2};
        for (double value : id.values)
            x.values.push_back(value + time * time);
        frames.push_back(makeFrame("curve", time, {id, x}));
    }
    osg::ref_ptr<FrameInterpolator> smoothed =
        new FrameInterpolator(frames[0].get(), *frames[1], *frames[2], frames[3].get(), smooth());
    osg::ref_ptr<FrameInterpolator> straight =
        new FrameInterpolator(nullptr, *frames[1], *frames[2], nullptr);
    for (double t : {0.25, 0.5, 0.75})
    {
        for (double id : {1.0, 2.0, 3.0})
        {
            const double truth = id + (1.0 + t) * (1.0 + t);
            const double curve = xOfId(*smoothed->interpolate(t), id),
                         line = xOfId(*straight->interpolate(t), id);
            EXPECT_LT(std::fabs(curve - truth), 0.5 * std::fabs(line - truth)) << "id " << id << " at " << t;
            // Catmull-Rom reproduces a quadratic through evenly spaced frames.
            EXPECT_TRUE(near(curve, truth));
        }
    }

    // Without the frame after, id 1 has the straight tangent at b: between the two.
    osg::ref_ptr<FrameInterpolator> halfSmoothed =
        new FrameInterpolator(frames[0].get(), *frames[1], *frames[2], nullptr, smooth());
    const double half = xOfId(*halfSmoothed->interpolate(0.5), 1);
    EXPECT_LT(std::fabs(half - 3.25), std::fabs(xOfId(*straight->interpolate(0.5), 1) - 3.25));
    EXPECT_GT(std::fabs(half - 3.25), 1e-3);
}

TEST(FrameInterpolation, SmoothUnwrapsTheFourFramesAcrossTheBoundary)
{
    // Unwrapped x = 4.5 + 0.2 time^2 in a box [0, 5]: 4.5, 4.7, 5.3 (0.3), 6.3 (1.3); a point
    // missing in before and after (id 2) moves in a straight line.
    const double stored[] = {4.5, 4.7, 0.3, 1.3};
    std::vector<osg::ref_ptr<PointData>> frames;
    for (int time = 0; time < 4; ++time)
    {
        const bool inner = time == 1 || time == 2;
        frames.push_back(makeFrame("wrap", time,
                                   {{"id", inner ? std::vector<double>{2, 1} : std::vector<double>{1}},
                                    {"x", inner ? std::vector<double>{1.0 + time, stored[time]}
                                                : std::vector<double>{stored[time]}}}));
        frames.back()->setBox(osg::BoundingBoxd(0, 0, 0, 5, 5, 5));
    }
    osg::ref_ptr<FrameInterpolator> interpolator =
        new FrameInterpolator(frames[0].get(), *frames[1], *frames[2], frames[3].get(), smooth());
    ASSERT_TRUE(interpolator->isValid()) << interpolator->getError();
    EXPECT_TRUE(near(xOfId(*interpolator->interpolate(0.5), 1), 4.5 + 0.2 * 2.25));
    EXPECT_TRUE(near(xOfId(*interpolator->interpolate(0.75), 1), 4.5 + 0.2 * 1.75 * 1.75 - 5.0));
    EXPECT_TRUE(near(xOfId(*interpolator->interpolate(0.25), 2), 2.25));

    // Unwrapped x = 0.8 + 0.35 time + 0.02 time^2 in a box [0, 1]: 0.8, 1.17 (0.17), 1.58 (0.58),
    // 2.03 (0.03); the boundary is crossed before a and after b, not between them. xs the same.
    const double crossing[] = {0.8, 0.17, 0.58, 0.03};
    for (int time = 0; time < 4; ++time)
    {
        frames[time] =
            makeFrame("wrap", time, {{"id", {1}}, {"x", {crossing[time]}}, {"xs", {crossing[time]}}});
        frames[time]->setBox(osg::BoundingBoxd(0, 0, 0, 1, 1, 1));
    }
    interpolator = new FrameInterpolator(frames[0].get(), *frames[1], *frames[2], frames[3].get(), smooth());
    for (double t : {0.25, 0.5, 0.75})
    {
        const double time = 1.0 + t;
        const double expected = 0.35 * time + 0.02 * time * time - 0.2;
        EXPECT_TRUE(near(xOfId(*interpolator->interpolate(t), 1), expected)) << t;
        EXPECT_TRUE(near(xOfId(*interpolator->interpolate(t), 1, "xs"), expected)) << t;
    }
}

TEST(FrameInterpolation, KeepsCategoriesAndLeavesOutColumnsOfOneFrame)
{
    // b's labels in another order and with one more; id 2 changes species (a reaction): a point
    // has the nearer frame's.
    osg::ref_ptr<PointData> a = makeFrame("a", 0,
                                          {{"id", {1, 2, 3}},
                                           {"species", {0, 1, 1}, 0.0, {"O", "H"}},
                                           {"c_only_a", {1, 2, 3}},
                                           {"q", {1, 2, 3}}});
    osg::ref_ptr<PointData> b = makeFrame("b", 1,
                                          {{"id", {4, 2, 1}},
                                           {"q", {-1, 4, 5}},
                                           {"c_only_b", {1, 2, 3}},
                                           {"species", {0, 2, 1}, 0.0, {"H", "O", "C"}}});
    osg::ref_ptr<FrameInterpolator> interpolator = new FrameInterpolator(nullptr, *a, *b, nullptr);
    const auto speciesOf = [](const PointData& frame)
    {
        std::vector<std::string> species;
        for (std::size_t point = 0; point < frame.getNumPoints(); ++point)
        {
            const std::size_t label = static_cast<std::size_t>(valueOf(frame, "species", point));
            species.push_back(frame.getColumnLabels("species").at(label));
        }
        return species;
    };
    osg::ref_ptr<PointData> first = interpolator->interpolate(0.25), second = interpolator->interpolate(0.75);
    EXPECT_EQ(first->getColumnNames(), (std::vector<std::string>{"id", "species", "q"}));
    EXPECT_EQ(first->getColumnLabels("species"), (std::vector<std::string>{"O", "H", "C"}));
    EXPECT_EQ(speciesOf(*first), (std::vector<std::string>{"O", "H", "H"}));
    EXPECT_EQ(speciesOf(*second), (std::vector<std::string>{"O", "C", "H"}));
    EXPECT_EQ(idsOf(*second), (std::vector<double>{1, 2, 4}));
    EXPECT_TRUE(near(valueOf(*first, "q", 0), 2.0));
    EXPECT_TRUE(near(valueOf(*second, "q", 1), 3.5));
}

TEST(FrameInterpolation, InterpolatesFromSeveralThreadsAtOnce)
{
    const std::vector<Mover> movers = makeMovers(2000, 5);
    osg::ref_ptr<PointData> before = frameOfMovers(movers, -1.0, -1, 6), a = frameOfMovers(movers, 0.0, 0, 7),
                            b = frameOfMovers(movers, 1.0, 1, 8), after = frameOfMovers(movers, 2.0, 2, 9);
    osg::ref_ptr<const FrameInterpolator> interpolator =
        new FrameInterpolator(before.get(), *a, *b, after.get(), smooth());
    std::vector<osg::ref_ptr<PointData>> frames(8);
    std::vector<std::thread> threads;
    for (std::size_t index = 0; index < frames.size(); ++index)
        threads.emplace_back([&, index] { frames[index] = interpolator->interpolate(index / 7.0); });
    for (std::thread& thread : threads)
        thread.join();
    for (std::size_t index = 0; index < frames.size(); ++index)
        expectMoversAt(*frames[index], movers, index / 7.0);
}

TEST(FrameInterpolation, InterpolatesTheBox)
{
    osg::ref_ptr<PointData> a = makeFrame("a", 7, {{"x", {1}}});
    osg::ref_ptr<PointData> b = makeFrame("b", 8, {{"x", {2}}});
    a->setBox(osg::BoundingBoxd(0, 0, 0, 10, 10, 10));
    b->setBox(osg::BoundingBoxd(1, 2, 3, 12, 14, 16), osg::Vec3d(1, 2, -3));
    osg::ref_ptr<FrameInterpolator> interpolator = new FrameInterpolator(nullptr, *a, *b, nullptr);
    osg::ref_ptr<PointData> frame = interpolator->interpolate(0.5);
    EXPECT_EQ(frame->getTimestep(), 7);
    EXPECT_EQ(frame->getBox()._min, osg::Vec3d(0.5, 1, 1.5));
    EXPECT_EQ(frame->getBox()._max, osg::Vec3d(11, 12, 13));
    EXPECT_EQ(frame->getTilt(), osg::Vec3d(0.5, 1, -1.5));

    // A box in one frame only is the output's.
    a->clearBox();
    interpolator = new FrameInterpolator(nullptr, *a, *b, nullptr);
    frame = interpolator->interpolate(0.25);
    EXPECT_TRUE(frame->hasBox());
    EXPECT_EQ(frame->getBox()._min, osg::Vec3d(1, 2, 3));
}
