// Coordinates far from zero (UTM metres, geocentric metres, LiDAR): every reader keeps their
// decimals through a column origin, and positions come out relative to an exact origin.

#include "ReaderTestUtil.h"

#include <osgGlyphsData/GlyphMapping>

#include <osgGlyphs/GlyphCloud>

using namespace osgGlyphsData;
using namespace readertest;

namespace
{

// Exactly representable in double, not in float (floats step by 1 at 1e7, by 0.5 at 6.4e6).
const double X[2] = {10000000.125, 10000001.0625};
const double Y[2] = {-6400000.25, -6400000.5};
const double Z[2] = {0.375, 2.5};

/** The two points as text rows, each after prefix. */
std::string rows(const char* separator, const std::string& prefix = std::string())
{
    std::ostringstream text;
    text.precision(17);
    for (int i = 0; i < 2; ++i)
        text << prefix << X[i] << separator << Y[i] << separator << Z[i] << "\n";
    return text.str();
}

/** The frame's positions are the file's values: origin + offset, to the float's precision near
 * zero (1e-7 of the offsets). */
void expectExactPositions(const PointData& frame)
{
    std::vector<osg::Vec3f> positions;
    osg::Vec3d origin;
    std::string error;
    ASSERT_TRUE(getPositions(frame, {}, positions, origin, error)) << error;
    ASSERT_EQ(positions.size(), 2u);
    for (int i = 0; i < 2; ++i)
    {
        const osg::Vec3d p = origin + osg::Vec3d(positions[i]);
        EXPECT_NEAR(p.x(), X[i], 1e-6) << "point " << i;
        EXPECT_NEAR(p.y(), Y[i], 1e-6) << "point " << i;
        EXPECT_NEAR(p.z(), Z[i], 1e-6) << "point " << i;
        EXPECT_DOUBLE_EQ(frame.getValue(frame.findColumn("x"), i), X[i]);
    }
    // Columns near zero have no origin and keep their plain values.
    EXPECT_EQ(frame.getColumnOrigin("z"), 0.0);
    EXPECT_EQ((*frame.getColumn("z"))[1], 2.5f);
}

osg::ref_ptr<PointData> readFirstFrame(const std::string& text, const std::string& format)
{
    std::string error;
    osg::ref_ptr<PointDataset> dataset = readString(text, format, error, "far." + format);
    EXPECT_TRUE(dataset.valid()) << error;
    return dataset.valid() ? dataset->getFrame(0) : new PointData;
}

} // namespace

TEST(FarCoordinates, CsvKeepsTheirDecimals)
{
    expectExactPositions(*readFirstFrame("x,y,z\n" + rows(","), "csv"));
}

TEST(FarCoordinates, XyzAndLammpsKeepTheirDecimals)
{
    expectExactPositions(*readFirstFrame("2\ncomment\n" + rows(" ", "C "), "xyz"));
    expectExactPositions(
        *readFirstFrame("ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n2\nITEM: BOX BOUNDS pp pp pp\n"
                        "0 1\n0 1\n0 1\nITEM: ATOMS x y z\n" +
                            rows(" "),
                        "lammps"));
}

TEST(FarCoordinates, BinaryPlyDoublesKeepTheirDecimals)
{
    Bytes bytes(false);
    bytes.text("ply\nformat binary_little_endian 1.0\nelement vertex 2\nproperty double x\n"
               "property double y\nproperty double z\nend_header\n");
    for (int i = 0; i < 2; ++i)
        bytes.put<double>(X[i]).put<double>(Y[i]).put<double>(Z[i]);
    expectExactPositions(*readFirstFrame(bytes.str(), "ply"));
}

TEST(FarCoordinates, ColumnsOfOtherUsesSeeTheFileValues)
{
    // A colour column far from zero colours by its values, not by the offsets.
    osg::ref_ptr<PointDataset> dataset;
    std::string error;
    dataset = readString("x,y,z,time\n0,0,0,1700000000\n1,0,0,1700000512\n", "csv", error, "t.csv");
    ASSERT_TRUE(dataset.valid()) << error;
    GlyphMappingOptions options;
    options.colorBy = "time";
    options.radius = 0.1f;
    GlyphMapper mapper(options);
    ASSERT_TRUE(mapper.prepare(*dataset, 0, error)) << error;
    EXPECT_FLOAT_EQ(mapper.getColorKey().min, 1700000000.0f);
    EXPECT_FLOAT_EQ(mapper.getColorKey().max, 1700000512.0f);
}

TEST(FarCoordinates, TheCloudTakesTheOrigin)
{
    osg::ref_ptr<PointDataset> dataset;
    std::string error;
    dataset = readString("x,y,z\n" + rows(","), "csv", error, "far.csv");
    ASSERT_TRUE(dataset.valid()) << error;
    GlyphMappingOptions options;
    options.radius = 0.1f;
    GlyphMapper mapper(options);
    ASSERT_TRUE(mapper.prepare(*dataset, 0, error)) << error;
    osg::ref_ptr<osgGlyphs::GlyphCloud> cloud = mapper.createCloud(*dataset->getFrame(0), error);
    ASSERT_TRUE(cloud.valid()) << error;
    for (int i = 0; i < 2; ++i)
    {
        const osg::Vec3d p = cloud->getOrigin() + osg::Vec3d((*cloud->getPositions())[i]);
        EXPECT_NEAR(p.x(), X[i], 1e-6);
        EXPECT_NEAR(p.y(), Y[i], 1e-6);
        EXPECT_NEAR(p.z(), Z[i], 1e-6);
    }
}
