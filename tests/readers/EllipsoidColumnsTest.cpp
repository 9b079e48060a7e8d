// Ellipsoids from data: a Gay-Berne liquid dumped by Debian's LAMMPS (tests/data/lammps/ellipsoids,
// make.sh) maps to ellipsoids of its shape diameters halved, turned by its quaternions; OVITO's
// column names give semi-axes; a point particle (shape 0 0 0) is a sphere; --glyph chooses over the
// data; an ellipsoid asked of data without shapes is one error naming the option.

#include "ReaderTestUtil.h"

#include <osgGlyphsData/GlyphMapping>

#include <osgGlyphs/GlyphCloud>

using namespace osgGlyphsData;
using namespace readertest;

namespace
{

const std::string LAMMPS_ELLIPSOIDS = std::string(OSGGLYPHS_LAMMPS_DATA_DIR) + "/ellipsoids/dump.ellipsoids";

osg::ref_ptr<osgGlyphs::GlyphCloud> mapFrame(const PointDataset& dataset, std::size_t frame,
                                             const GlyphMappingOptions& options, std::string& error)
{
    GlyphMapper mapper(options);
    if (!mapper.prepare(dataset, frame, error))
        return nullptr;
    return mapper.createCloud(*dataset.getFrame(frame), error);
}

osg::ref_ptr<osgGlyphs::GlyphCloud> mapCsv(const std::string& text, const GlyphMappingOptions& options,
                                           std::string& error)
{
    osg::ref_ptr<PointDataset> dataset = readString(text, "csv", error, "ellipsoids.csv");
    return dataset.valid() ? mapFrame(*dataset, 0, options, error) : nullptr;
}

}

TEST(EllipsoidColumns, LammpsShapesAndQuaternionsMakeEllipsoids)
{
    std::string error;
    osg::ref_ptr<PointDataset> dataset = readPointFile(LAMMPS_ELLIPSOIDS, PointReadOptions(), error);
    ASSERT_TRUE(dataset.valid()) << error;
    ASSERT_EQ(dataset->getNumFrames(), 5u);
    const std::size_t last = dataset->getNumFrames() - 1;
    osg::ref_ptr<osgGlyphs::GlyphCloud> cloud = mapFrame(*dataset, last, GlyphMappingOptions(), error);
    ASSERT_TRUE(cloud.valid()) << error;
    EXPECT_EQ(cloud->getShape(), osgGlyphs::GlyphShape::Ellipsoid);
    ASSERT_NE(cloud->getSemiAxes(), nullptr);
    ASSERT_NE(cloud->getOrientations(), nullptr);
    ASSERT_EQ(cloud->getNumGlyphs(), 144u);
    EXPECT_EQ(cloud->getNumSkippedGlyphs(), 0u);
    const PointData& data = *dataset->getFrame(last);
    const std::vector<float> w = column(data, "quatw"), i = column(data, "quati"), j = column(data, "quatj"),
                             k = column(data, "quatk");
    for (std::size_t n = 0; n < 144; ++n)
    {
        // set type 1 shape 3 1 1: diameters, so semi-axes 1.5, 0.5, 0.5.
        EXPECT_EQ((*cloud->getSemiAxes())[n], osg::Vec3(1.5f, 0.5f, 0.5f)) << "atom " << n;
        EXPECT_EQ((*cloud->getOrientations())[n], osg::Vec4(i[n], j[n], k[n], w[n])) << "atom " << n;
    }
}

TEST(EllipsoidColumns, FollowTheirAtomsFromFrameToFrame)
{
    std::string error;
    osg::ref_ptr<PointDataset> dataset = readPointFile(LAMMPS_ELLIPSOIDS, PointReadOptions(), error);
    ASSERT_TRUE(dataset.valid()) << error;
    GlyphMapper mapper{GlyphMappingOptions()};
    ASSERT_TRUE(mapper.prepare(*dataset, 0, error)) << error;
    osg::ref_ptr<osgGlyphs::GlyphCloud> cloud = mapper.createCloud(*dataset->getFrame(0), error);
    ASSERT_TRUE(cloud.valid()) << error;
    const osg::Vec4 first = (*cloud->getOrientations())[7];
    ASSERT_TRUE(mapper.updateCloud(*cloud, *dataset->getFrame(4), error)) << error;
    const std::vector<float> w = column(*dataset->getFrame(4), "quatw");
    EXPECT_EQ((*cloud->getOrientations())[7].w(), w[7]);
    EXPECT_NE((*cloud->getOrientations())[7], first) << "the particles turn in 1000 steps";
}

TEST(EllipsoidColumns, OvitoNamesAreSemiAxesAndPointParticlesAreSpheres)
{
    std::string error;
    GlyphMappingOptions options;
    options.radius = 0.25f;
    osg::ref_ptr<osgGlyphs::GlyphCloud> cloud =
        mapCsv("x,y,z,Aspherical Shape.X,Aspherical Shape.Y,Aspherical Shape.Z,Orientation.X,Orientation.Y,"
               "Orientation.Z,Orientation.W\n0,0,0,2,1,0.5,0,0,0.6,0.8\n3,0,0,0,0,0,0,0,0,1\n",
               options, error);
    ASSERT_TRUE(cloud.valid()) << error;
    EXPECT_EQ(cloud->getShape(), osgGlyphs::GlyphShape::Ellipsoid);
    EXPECT_EQ((*cloud->getSemiAxes())[0], osg::Vec3(2.0f, 1.0f, 0.5f));
    EXPECT_EQ((*cloud->getOrientations())[0], osg::Vec4(0.0f, 0.0f, 0.6f, 0.8f));
    EXPECT_EQ((*cloud->getSemiAxes())[1], osg::Vec3(0.25f, 0.25f, 0.25f));
    EXPECT_EQ(cloud->getNumSkippedGlyphs(), 0u);
}

TEST(EllipsoidColumns, WithoutAQuaternionTheBodyAxesAreTheLabs)
{
    std::string error;
    osg::ref_ptr<osgGlyphs::GlyphCloud> cloud =
        mapCsv("x,y,z,shapex,shapey,shapez\n0,0,0,2,1,1\n", GlyphMappingOptions(), error);
    ASSERT_TRUE(cloud.valid()) << error;
    EXPECT_EQ(cloud->getOrientations(), nullptr);
    EXPECT_EQ((*cloud->getSemiAxes())[0], osg::Vec3(1.0f, 0.5f, 0.5f));
}

TEST(EllipsoidColumns, TheGlyphOptionChoosesOverTheData)
{
    std::string error;
    GlyphMappingOptions options;
    ASSERT_TRUE(setGlyphMappingOption(options, "glyph", "sphere", error)) << error;
    osg::ref_ptr<osgGlyphs::GlyphCloud> cloud =
        mapCsv("x,y,z,shapex,shapey,shapez\n0,0,0,2,1,1\n", options, error);
    ASSERT_TRUE(cloud.valid()) << error;
    EXPECT_EQ(cloud->getShape(), osgGlyphs::GlyphShape::Sphere);
    EXPECT_EQ(cloud->getSemiAxes(), nullptr);
}

TEST(EllipsoidColumns, AnEllipsoidOfDataWithoutShapesIsOneError)
{
    std::string error;
    GlyphMappingOptions options;
    options.optionPrefix = "--";
    ASSERT_TRUE(setGlyphMappingOption(options, "glyph", "ellipsoid", error)) << error;
    EXPECT_FALSE(mapCsv("x,y,z\n0,0,0\n", options, error).valid());
    EXPECT_NE(error.find("--glyph ellipsoid needs semi-axes: no shapex,shapey,shapez in ellipsoids.csv"),
              std::string::npos)
        << error;
}

// OVITO's Superquadric Roundness (Phi, Theta) beside Aspherical Shape: superquadrics by default, of
// exponents e1 = Phi (along the body z axis) and e2 = Theta; roundness 0 (OVITO's box) is the
// sharpest exponent drawn; --glyph ellipsoid leaves the roundness out.
TEST(EllipsoidColumns, OvitoRoundnessMakesSuperquadrics)
{
    const std::string csv = "x,y,z,Aspherical Shape.X,Aspherical Shape.Y,Aspherical Shape.Z,"
                            "Superquadric Roundness.Phi,Superquadric Roundness.Theta\n"
                            "0,0,0,2,1,0.5,0.3,1.5\n3,0,0,1,1,1,0,1\n";
    std::string error;
    osg::ref_ptr<osgGlyphs::GlyphCloud> cloud = mapCsv(csv, GlyphMappingOptions(), error);
    ASSERT_TRUE(cloud.valid()) << error;
    EXPECT_EQ(cloud->getShape(), osgGlyphs::GlyphShape::Superquadric);
    ASSERT_NE(cloud->getExponents(), nullptr);
    EXPECT_EQ((*cloud->getExponents())[0], osg::Vec2(0.3f, 1.5f));
    EXPECT_EQ((*cloud->getExponents())[1], osg::Vec2(0.1f, 1.0f));
    EXPECT_EQ((*cloud->getSemiAxes())[0], osg::Vec3(2.0f, 1.0f, 0.5f));
    EXPECT_EQ(cloud->getNumSkippedGlyphs(), 0u);

    GlyphMappingOptions ellipsoids;
    ASSERT_TRUE(setGlyphMappingOption(ellipsoids, "glyph", "ellipsoid", error)) << error;
    cloud = mapCsv(csv, ellipsoids, error);
    ASSERT_TRUE(cloud.valid()) << error;
    EXPECT_EQ(cloud->getShape(), osgGlyphs::GlyphShape::Ellipsoid);
    EXPECT_EQ(cloud->getExponents(), nullptr);

    GlyphMappingOptions superquadrics;
    superquadrics.optionPrefix = "--";
    ASSERT_TRUE(setGlyphMappingOption(superquadrics, "glyph", "superquadric", error)) << error;
    EXPECT_FALSE(mapCsv("x,y,z,shapex,shapey,shapez\n0,0,0,2,1,1\n", superquadrics, error).valid());
    EXPECT_NE(error.find("--glyph superquadric draws tensors (--tensor, Kindlmann's glyphs) or shapes with a "
                         "roundness"),
              std::string::npos)
        << error;
}
