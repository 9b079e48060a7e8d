// The default glyph radius (the median nearest-neighbour distance) of point layouts that made its
// search hang or overflow. Each case runs under ctest's TIMEOUT: a hang fails it.

#include <osgGlyphsData/GlyphMapping>
#include <osgGlyphsData/PointReader>

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>

namespace
{

/** The radius GlyphMapper gives every glyph of a CSV text by default. */
float defaultRadius(const std::string& csv)
{
    std::istringstream stream(csv);
    std::string error;
    osg::ref_ptr<osgGlyphsData::PointDataset> dataset =
        osgGlyphsData::readPointStream(stream, "csv", "points.csv", osgGlyphsData::PointReadOptions(), error);
    EXPECT_TRUE(dataset.valid()) << error;
    if (!dataset.valid())
        return 0.0f;
    osgGlyphsData::GlyphMapper mapper{osgGlyphsData::GlyphMappingOptions()};
    EXPECT_TRUE(mapper.prepare(*dataset, 0, error)) << error;
    osg::ref_ptr<osgGlyphs::GlyphCloud> cloud = mapper.createCloud(*dataset->getFrame(0), error);
    EXPECT_TRUE(cloud.valid()) << error;
    return cloud.valid() ? cloud->getRadius() : 0.0f;
}

std::string row(double x, double y, double z)
{
    std::ostringstream text;
    text.precision(17);
    text << x << ',' << y << ',' << z << '\n';
    return text.str();
}

} // namespace

// Ten probes 10 m apart down a borehole, each read at 100 times: every position 100 times, on a line.
TEST(DefaultRadius, BoreholeProbesAtRepeatedPositions)
{
    std::string csv = "time,x,y,z\n";
    for (int time = 0; time < 100; ++time)
    {
        for (int probe = 0; probe < 10; ++probe)
            csv += std::to_string(time) + "," + row(0.0, 0.0, -10.0 * probe);
    }
    EXPECT_FLOAT_EQ(defaultRadius(csv), 4.0f); // 0.4 of the probes' spacing
}

TEST(DefaultRadius, ManyCoincidentPointsAndOneOther)
{
    std::string csv = "x,y,z\n";
    for (int i = 0; i < 5000; ++i)
        csv += row(1.0, 2.0, 3.0);
    csv += row(4.0, 2.0, 3.0);
    EXPECT_FLOAT_EQ(defaultRadius(csv), 1.2f);
}

// A plane of 5 x 5 positions 20 apart, each 3200 times.
TEST(DefaultRadius, FlatLayerOfRepeatedPositions)
{
    std::string csv = "x,y,z\n";
    for (int copy = 0; copy < 3200; ++copy)
    {
        for (int i = 0; i < 5; ++i)
        {
            for (int j = 0; j < 5; ++j)
                csv += row(20.0 * i, 20.0 * j, 7.0);
        }
    }
    EXPECT_FLOAT_EQ(defaultRadius(csv), 8.0f);
}

// A tight cluster and one point far away: the cluster fills one cell of the grid.
TEST(DefaultRadius, ClusterAndOneFarPoint)
{
    std::string csv = "x,y,z\n";
    for (int i = 0; i < 20000; ++i)
        csv += row(1e-6 * (i % 31), 1e-6 * (i % 37), 1e-6 * (i % 41));
    csv += row(1000.0, 1000.0, 1000.0);
    const float radius = defaultRadius(csv);
    EXPECT_TRUE(std::isfinite(radius) && radius > 0.0f) << radius;
}

// The spread of positions near the float limit: no cast of NaN or infinity to an integer (UBSan).
TEST(DefaultRadius, SpreadBeyondTheRangeOfAFloat)
{
    const float radius = defaultRadius("x,y,z\n" + row(-3e38, -3e38, -3e38) + row(3e38, 3e38, 3e38) +
                                       row(0.0, 0.0, 0.0) + row(1.0, 1.0, 1.0));
    EXPECT_TRUE(std::isfinite(radius) && radius > 0.0f) << radius;
}

// A box diagonal of 3.5e19, whose square overflows a float.
TEST(DefaultRadius, SpreadOf1e19)
{
    const float radius = defaultRadius("x,y,z\n" + row(-1e19, -1e19, -1e19) + row(1e19, 1e19, 1e19) +
                                       row(0.0, 0.0, 0.0) + row(1e18, 0.0, 0.0));
    // The median nearest distance: from (1e19, 1e19, 1e19) to (1e18, 0, 0).
    EXPECT_FLOAT_EQ(radius, static_cast<float>(0.4 * std::sqrt(81e36 + 1e38 + 1e38)));
}
