// The samples shipped in share/data, one per format, read through readPointFile.

#include "ReaderTestUtil.h"

#include <algorithm>

#include <osgGlyphsData/Elements>

using namespace osgGlyphsData;
using namespace readertest;

namespace
{

osg::ref_ptr<PointDataset> readSample(const std::string& name)
{
    std::string error;
    osg::ref_ptr<PointDataset> dataset =
        readPointFile(std::string(OSGGLYPHS_SAMPLE_DATA_DIR) + "/" + name, PointReadOptions(), error);
    EXPECT_TRUE(dataset.valid()) << error;
    return dataset.valid() ? dataset : osg::ref_ptr<PointDataset>(new PointDataset);
}

void expectPositions(const PointData& frame)
{
    std::vector<osg::Vec3f> positions;
    std::string error;
    EXPECT_TRUE(getPositions(frame, {}, positions, error)) << error;
    EXPECT_EQ(positions.size(), frame.getNumPoints());
}

} // namespace

TEST(SampleData, LammpsDumpHasThreeTimestepsOf500Atoms)
{
    osg::ref_ptr<PointDataset> dataset = readSample("melt500.lammpstrj");
    ASSERT_EQ(dataset->getNumFrames(), 3u);
    for (std::size_t i = 0; i < 3; ++i)
    {
        const PointData& frame = *dataset->getFrame(i);
        EXPECT_EQ(frame.getTimestep(), static_cast<int64_t>(100 * i));
        EXPECT_EQ(frame.getNumPoints(), 500u);
        EXPECT_EQ(frame.getColumnNames(),
                  (std::vector<std::string>{"id", "type", "x", "y", "z", "vx", "vy", "vz"}));
        EXPECT_TRUE(frame.hasBox());
        expectPositions(frame);
    }
    EXPECT_EQ((*dataset->getFrame(2)->getColumn("id"))[499], 500.0f);
}

TEST(SampleData, TheLammpsMeltHasThreeTimestepsOf4000AtomsWithACoreOfType2)
{
    osg::ref_ptr<PointDataset> dataset = readSample("melt4k.lammpstrj");
    ASSERT_EQ(dataset->getNumFrames(), 3u);
    for (std::size_t i = 0; i < 3; ++i)
    {
        const PointData& frame = *dataset->getFrame(i);
        EXPECT_EQ(frame.getTimestep(), static_cast<int64_t>(50 * i));
        EXPECT_EQ(frame.getNumPoints(), 4000u);
        EXPECT_TRUE(frame.hasBox());
        expectPositions(frame);
        const std::vector<float>& types = *frame.getColumn("type");
        EXPECT_EQ(std::count(types.begin(), types.end(), 2.0f), 249);
    }
}

TEST(SampleData, ExtendedXyzHasTwoFramesOfWater)
{
    osg::ref_ptr<PointDataset> dataset = readSample("water64.xyz");
    ASSERT_EQ(dataset->getNumFrames(), 2u);
    const PointData& frame = *dataset->getFrame(1);
    EXPECT_EQ(frame.getNumPoints(), 192u);
    EXPECT_EQ(frame.getTimestep(), 500);
    EXPECT_EQ(frame.getColumnLabels("species"), (std::vector<std::string>{"O", "H"}));
    EXPECT_EQ((*frame.getColumn("element"))[0], 8.0f);
    EXPECT_TRUE(frame.hasColumn("velo_z"));
    EXPECT_TRUE(frame.hasBox());
    expectPositions(frame);
}

TEST(SampleData, CsvHasProbeSamples)
{
    osg::ref_ptr<PointDataset> dataset = readSample("probes.csv");
    const PointData& frame = *dataset->getFrame(0);
    EXPECT_EQ(frame.getNumPoints(), 1000u);
    EXPECT_EQ(frame.getColumnNames(), (std::vector<std::string>{"x", "y", "z", "temperature", "density"}));
    expectPositions(frame);
}

TEST(SampleData, PlyIsABinaryTorusCloud)
{
    osg::ref_ptr<PointDataset> dataset = readSample("torus.ply");
    const PointData& frame = *dataset->getFrame(0);
    EXPECT_EQ(frame.getNumPoints(), 2000u);
    EXPECT_EQ(frame.getColumnNames(),
              (std::vector<std::string>{"x", "y", "z", "nx", "ny", "nz", "red", "green", "blue"}));
    expectPositions(frame);
}

TEST(SampleData, VtkIsAGalaxyWithMassesAndVelocities)
{
    osg::ref_ptr<PointDataset> dataset = readSample("galaxy.vtk");
    const PointData& frame = *dataset->getFrame(0);
    EXPECT_EQ(frame.getNumPoints(), 400u);
    EXPECT_EQ(frame.getColumnNames(),
              (std::vector<std::string>{"x", "y", "z", "mass", "velocity_x", "velocity_y", "velocity_z"}));
    expectPositions(frame);
}
