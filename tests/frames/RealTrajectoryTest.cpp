// Trajectories that LAMMPS wrote (tests/data/trajectory, made by make_trajectories.sh): its plain,
// gzip and zstd dumps give the same frames; its XYZ dump the same positions; interpolation moves
// the atoms that cross the periodic box the short way, and handles atoms that evaporate.

#include <osgGlyphsData/FrameInterpolation>
#include <osgGlyphsData/FrameSource>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

using namespace osgGlyphsData;

namespace
{

const std::string DATA = OSGGLYPHS_TRAJECTORY_DATA_DIR;

osg::ref_ptr<FrameSource> openData(const std::string& name)
{
    FrameSourceOptions options;
    options.indexLocation = FrameIndexLocation::None; // the source folder stays as committed
    options.warning = [](const std::string& warning) { ADD_FAILURE() << warning; };
    std::string error;
    osg::ref_ptr<FrameSource> source = FrameSource::open(DATA + "/" + name, options, error);
    EXPECT_TRUE(source.valid()) << error;
    if (source.valid())
        source->waitForIndex();
    return source;
}

osg::ref_ptr<PointData> frameOf(const FrameSource& source, std::size_t frame)
{
    std::string error;
    osg::ref_ptr<PointData> data = source.readFrame(frame, error);
    EXPECT_TRUE(data.valid()) << error;
    return data;
}

}

TEST(RealTrajectory, LammpsPlainGzipAndZstdDumpsAreTheSameFrames)
{
    osg::ref_ptr<FrameSource> plain = openData("melt500.lammpstrj");
    ASSERT_TRUE(plain.valid());
    ASSERT_EQ(plain->getNumFrames(), 11u);
    for (const char* name : {"melt500.lammpstrj.gz", "melt500.lammpstrj.zst"})
    {
        osg::ref_ptr<FrameSource> compressed = openData(name);
        ASSERT_TRUE(compressed.valid());
        ASSERT_EQ(compressed->getNumFrames(), 11u) << name;
        for (std::size_t f : {10u, 3u, 0u, 7u, 1u})
        {
            osg::ref_ptr<PointData> a = frameOf(*plain, f), b = frameOf(*compressed, f);
            ASSERT_TRUE(a.valid() && b.valid());
            EXPECT_EQ(a->getTimestep(), int64_t(20 * f));
            ASSERT_EQ(a->getColumnNames(), b->getColumnNames());
            for (std::size_t c = 0; c < a->getNumColumns(); ++c)
                EXPECT_EQ(*a->getColumn(c), *b->getColumn(c)) << name << " frame " << f;
        }
    }
}

TEST(RealTrajectory, TheXyzDumpHasTheSamePositions)
{
    osg::ref_ptr<FrameSource> dump = openData("melt500.lammpstrj");
    osg::ref_ptr<FrameSource> xyz = openData("melt500.xyz");
    ASSERT_TRUE(dump.valid() && xyz.valid());
    ASSERT_EQ(xyz->getNumFrames(), 11u);
    osg::ref_ptr<PointData> a = frameOf(*dump, 6), b = frameOf(*xyz, 6);
    ASSERT_EQ(b->getNumPoints(), 500u);
    const std::vector<float>& ids = *a->getColumn("id");
    for (std::size_t i = 0; i < ids.size(); ++i)
    {
        const std::size_t row = static_cast<std::size_t>(ids[i]) - 1; // the XYZ dump is sorted by id
        for (const char* axis : {"x", "y", "z"})
            EXPECT_NEAR((*a->getColumn(axis))[i], (*b->getColumn(axis))[row], 1e-5) << "id " << ids[i];
    }
}

TEST(RealTrajectory, AtomsCrossingTheBoxMoveTheShortWay)
{
    osg::ref_ptr<FrameSource> source = openData("melt500.lammpstrj");
    ASSERT_TRUE(source.valid());
    std::size_t crossings = 0;
    for (std::size_t f = 0; f + 1 < source->getNumFrames(); ++f)
    {
        osg::ref_ptr<PointData> a = frameOf(*source, f), b = frameOf(*source, f + 1);
        osg::ref_ptr<FrameInterpolator> interpolator = new FrameInterpolator(nullptr, *a, *b, nullptr);
        ASSERT_TRUE(interpolator->isValid()) << interpolator->getError();
        EXPECT_EQ(interpolator->getNumMatched(), 500u);
        osg::ref_ptr<PointData> half = interpolator->interpolate(0.5);
        const double length = a->getBox().xMax() - a->getBox().xMin();
        // Rows of the half-way frame are a's: find each atom in b by id.
        std::vector<std::size_t> rowInB(501);
        for (std::size_t i = 0; i < b->getNumPoints(); ++i)
            rowInB[static_cast<std::size_t>((*b->getColumn("id"))[i])] = i;
        for (std::size_t i = 0; i < a->getNumPoints(); ++i)
        {
            const std::size_t j = rowInB[static_cast<std::size_t>((*a->getColumn("id"))[i])];
            for (const char* axis : {"x", "y", "z"})
            {
                const double from = (*a->getColumn(axis))[i], to = (*b->getColumn(axis))[j];
                const double mid = (*half->getColumn(axis))[i];
                const double step = to - from - length * std::round((to - from) / length);
                if (std::abs(to - from) > length / 2)
                    ++crossings;
                // Half the short way from a, brought back into the box.
                const double expected = from + 0.5 * step - length * std::floor((from + 0.5 * step) / length);
                const double wrapped = mid - expected - length * std::round((mid - expected) / length);
                EXPECT_NEAR(wrapped, 0.0, 1e-4)
                    << axis << " of id " << (*a->getColumn("id"))[i] << " frame " << f;
                EXPECT_GE(mid, -0.5) << "inside the box, give or take what LAMMPS has not wrapped yet";
                EXPECT_LE(mid, length + 0.5);
            }
        }
    }
    EXPECT_GT(crossings, 10u) << "the data must hold atoms that cross the box";
}

TEST(RealTrajectory, EvaporatedAtomsVanishHalfWay)
{
    osg::ref_ptr<FrameSource> source = openData("evaporate.lammpstrj");
    ASSERT_TRUE(source.valid());
    ASSERT_EQ(source->getNumFrames(), 11u);
    osg::ref_ptr<PointData> a = frameOf(*source, 0), b = frameOf(*source, 1);
    ASSERT_EQ(a->getNumPoints(), 550u);
    ASSERT_EQ(b->getNumPoints(), 535u);
    osg::ref_ptr<FrameInterpolator> interpolator = new FrameInterpolator(nullptr, *a, *b, nullptr);
    ASSERT_TRUE(interpolator->isValid()) << interpolator->getError();
    EXPECT_EQ(interpolator->getNumVanishing(), 15u);
    EXPECT_EQ(interpolator->getNumAppearing(), 0u);
    EXPECT_EQ(interpolator->interpolate(0.25)->getNumPoints(), 550u);
    EXPECT_EQ(interpolator->interpolate(0.75)->getNumPoints(), 535u);
}
