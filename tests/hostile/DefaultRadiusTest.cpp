// The default glyph radius (the median nearest-neighbour distance) of point layouts that made its
// search hang or overflow. Each case runs under ctest's TIMEOUT: a hang fails it.

#include "NeighbourDistance.h"

#include <osgGlyphsData/GlyphMapping>
#include <osgGlyphsData/PointReader>

#include <osg/Vec3d>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
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

double bruteForceNearestDistance(const std::vector<osg::Vec3f>& points, std::size_t point)
{
    double nearest = std::numeric_limits<double>::infinity();
    for (const osg::Vec3f& p : points)
    {
        const double d2 = (osg::Vec3d(p) - osg::Vec3d(points[point])).length2();
        if (d2 > 0.0)
            nearest = std::min(nearest, d2);
    }
    return std::sqrt(nearest);
}

/** The distance from each of the first count points to its nearest neighbour against brute force:
 * with one sample, the first point, the estimate is that distance. */
void expectNearestDistances(std::vector<osg::Vec3f> points, std::size_t count)
{
    for (std::size_t point = 0; point < count; ++point)
    {
        std::swap(points[0], points[point]);
        EXPECT_EQ(osgGlyphsData::detail::estimateNeighbourDistance(points, 1),
                  bruteForceNearestDistance(points, 0))
            << "point " << point;
        std::swap(points[0], points[point]);
    }
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

// Scattered points among tight clusters, which make the grid's cells small for the points' spacing:
// the nearest neighbours of the scattered points are several cells away.
TEST(DefaultRadius, NearestNeighboursOfPointsScatteredAmongClusters)
{
    std::mt19937 random(1);
    std::uniform_real_distribution<float> place(0.0f, 100.0f);
    std::normal_distribution<float> spread(0.0f, 0.01f);
    std::vector<osg::Vec3f> points;
    for (int i = 0; i < 1000; ++i)
        points.emplace_back(place(random), place(random), place(random));
    for (int cluster = 0; cluster < 16; ++cluster)
    {
        const osg::Vec3f centre(place(random), place(random), place(random));
        for (int i = 0; i < 2000; ++i)
            points.push_back(centre + osg::Vec3f(spread(random), spread(random), spread(random)));
    }
    expectNearestDistances(points, 200);
}

// Each position 50 times, a quarter of them next to another: crowded cells keep one point of each
// position, and the positions are several cells apart.
TEST(DefaultRadius, NearestNeighboursOfRepeatedPositions)
{
    std::mt19937 random(2);
    std::uniform_real_distribution<float> place(0.0f, 10.0f);
    std::vector<osg::Vec3f> positions;
    for (int i = 0; i < 1000; ++i)
    {
        positions.emplace_back(place(random), place(random), place(random));
        if (i % 4 == 0)
            positions.push_back(positions.back() + osg::Vec3f(0.01f, 0.0f, 0.0f));
    }
    std::vector<osg::Vec3f> points;
    for (int copy = 0; copy < 50; ++copy)
        points.insert(points.end(), positions.begin(), positions.end());
    std::shuffle(points.begin(), points.end(), random);
    expectNearestDistances(points, 200);
}
