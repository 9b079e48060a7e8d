// Random rays through clouds of random glyphs, picked through osgUtil, against the independent
// truth of SolidTruth: every glyph a ray meets or misses, and where.

#include "SolidTruth.h"

#include <osgGlyphs/GlyphCloud>

#include <gtest/gtest.h>
#include <osgUtil/IntersectionVisitor>
#include <osgUtil/LineSegmentIntersector>

#include <cmath>
#include <map>
#include <random>

using namespace osgGlyphsTest;
using osgGlyphs::GlyphAnchor;
using osgGlyphs::GlyphCloud;
using osgGlyphs::GlyphShape;

namespace
{

const int RAYS_PER_SHAPE = 10000;
const int GLYPHS = 40;

struct Configuration
{
    GlyphAnchor anchor = GlyphAnchor::Center;
    bool uniformLength = false;
};

/** A cloud of random glyphs and, for each, its solid. */
struct RandomGlyphs
{
    osg::ref_ptr<GlyphCloud> cloud;
    std::vector<Solid> solids;
    std::vector<double> reach; // a radius about the data point that holds the glyph
};

osg::Vec3d randomUnitVector(std::mt19937& random)
{
    std::normal_distribution<double> normal;
    osg::Vec3d v(normal(random), normal(random), normal(random));
    v.normalize();
    return v;
}

RandomGlyphs createRandomGlyphs(GlyphShape shape, const Configuration& configuration, std::mt19937& random)
{
    std::uniform_real_distribution<float> coordinate(-5.0f, 5.0f), radius(0.2f, 1.0f), magnitude(0.5f, 3.0f);
    const float lengthScale = configuration.uniformLength ? 2.5f : 1.3f;
    const double headLength = 0.35, headRadius = 1.8;
    osg::ref_ptr<osg::Vec3Array> positions = new osg::Vec3Array, vectors = new osg::Vec3Array;
    osg::ref_ptr<osg::FloatArray> radii = new osg::FloatArray;
    RandomGlyphs glyphs;
    for (int i = 0; i < GLYPHS; ++i)
    {
        const osg::Vec3 p(coordinate(random), coordinate(random), coordinate(random));
        const osg::Vec3 v = osg::Vec3(randomUnitVector(random)) * magnitude(random);
        const float r = radius(random);
        positions->push_back(p);
        vectors->push_back(v);
        radii->push_back(r);
        // The glyph convention of GlyphCloud's documentation, in double precision.
        const osg::Vec3d vd(v);
        const osg::Vec3d axis = vd / vd.length();
        const double length = configuration.uniformLength ? lengthScale : lengthScale * vd.length();
        const double fraction = osgGlyphs::getAnchorFraction(configuration.anchor);
        const osg::Vec3d tail = osg::Vec3d(p) - axis * (length * fraction);
        switch (shape)
        {
        case GlyphShape::Sphere:
            glyphs.solids.push_back(Solid::sphere(osg::Vec3d(p), r));
            break;
        case GlyphShape::Cone:
            glyphs.solids.push_back(Solid::cone(tail, axis, length, r));
            break;
        case GlyphShape::Cylinder:
            glyphs.solids.push_back(Solid::cylinder(tail, axis, length, r));
            break;
        case GlyphShape::Arrow:
            glyphs.solids.push_back(Solid::arrow(tail, axis, length, r, headLength, headRadius));
            break;
        case GlyphShape::Ellipsoid:    // picked against their truth in EllipsoidGlyphTest
        case GlyphShape::Superquadric: // and SuperquadricGlyphTest
            break;
        }
        glyphs.reach.push_back(shape == GlyphShape::Sphere ? r : length + r * headRadius);
    }
    glyphs.cloud = new GlyphCloud;
    glyphs.cloud->setShape(shape);
    glyphs.cloud->setCompressedAttributes(false); // radii as given, not rounded to half floats
    glyphs.cloud->setPositions(positions.get());
    glyphs.cloud->setRadii(radii.get());
    glyphs.cloud->setVectors(vectors.get());
    glyphs.cloud->setAnchor(configuration.anchor);
    glyphs.cloud->setUniformLength(configuration.uniformLength);
    glyphs.cloud->setLengthScale(lengthScale);
    glyphs.cloud->setArrowHead(float(headLength), float(headRadius));
    return glyphs;
}

/** What a ray through the cloud meets, glyph by glyph: the distance along the segment. */
std::map<unsigned int, double> pick(GlyphCloud& cloud, const osg::Vec3d& start, const osg::Vec3d& end)
{
    osg::ref_ptr<osgUtil::LineSegmentIntersector> picker = new osgUtil::LineSegmentIntersector(start, end);
    osgUtil::IntersectionVisitor visitor(picker.get());
    cloud.accept(visitor);
    std::map<unsigned int, double> hits;
    for (const auto& hit : picker->getIntersections())
    {
        EXPECT_EQ(hit.drawable.get(), &cloud);
        EXPECT_EQ(hits.count(hit.primitiveIndex), 0u) << "glyph " << hit.primitiveIndex << " reported twice";
        hits[hit.primitiveIndex] = hit.ratio * (end - start).length();
    }
    return hits;
}

struct Tally
{
    int hits = 0, misses = 0, grazing = 0; // misses: of rays that pass within the glyph's reach
};

/** Casts rays through random clouds of the shape in each configuration, and compares. */
Tally checkShape(GlyphShape shape, const std::vector<Configuration>& configurations)
{
    Tally tally;
    std::mt19937 random(1234 + int(shape));
    std::uniform_real_distribution<double> target(-6.0, 6.0);
    const int raysPerConfiguration = RAYS_PER_SHAPE / int(configurations.size());
    for (const Configuration& configuration : configurations)
    {
        RandomGlyphs glyphs = createRandomGlyphs(shape, configuration, random);
        for (int ray = 0; ray < raysPerConfiguration; ++ray)
        {
            const osg::Vec3d start = randomUnitVector(random) * 25.0;
            osg::Vec3d direction = osg::Vec3d(target(random), target(random), target(random)) - start;
            direction.normalize();
            const double length = 60.0;
            const std::map<unsigned int, double> picked =
                pick(*glyphs.cloud, start, start + direction * length);
            for (unsigned int i = 0; i < glyphs.solids.size(); ++i)
            {
                const Solid& solid = glyphs.solids[i];
                // A ray that passes farther from the data point than the glyph reaches misses it.
                const osg::Vec3d toPoint = osg::Vec3d((*glyphs.cloud->getPositions())[i]) - start;
                const double passes = (toPoint - direction * (toPoint * direction)).length();
                const bool pickedIt = picked.count(i) > 0;
                if (passes > glyphs.reach[i] * 2.0)
                {
                    EXPECT_FALSE(pickedIt) << "glyph " << i << " picked by a ray that passes far from it";
                    continue;
                }
                const Solid::Trace truth = solid.trace(start, direction, length, 1e-10 * solid.size());
                // Rays that graze the surface within float rounding of the glyph's own inputs
                // (positions, radii and vectors are floats) may fall either way.
                const bool grazing =
                    truth.hit ? std::abs(solid.normal(start + direction * truth.t) * direction) < 1e-4
                              : truth.closest < 1e-6 * solid.size();
                if (grazing)
                {
                    ++tally.grazing;
                    continue;
                }
                EXPECT_EQ(pickedIt, truth.hit)
                    << "glyph " << i << ", ray from " << start.x() << " " << start.y() << " " << start.z()
                    << " along " << direction.x() << " " << direction.y() << " " << direction.z()
                    << ", closest approach " << truth.closest;
                if (!truth.hit || !pickedIt)
                {
                    ++tally.misses;
                    continue;
                }
                ++tally.hits;
                const double t = picked.at(i);
                EXPECT_NEAR(t, truth.t, 1e-5 * truth.t) << "glyph " << i;
                EXPECT_NEAR(solid.signedDistance(start + direction * t), 0.0, 1e-5 * solid.size());
            }
        }
    }
    return tally;
}

std::vector<Configuration> vectorConfigurations()
{
    std::vector<Configuration> configurations;
    for (GlyphAnchor anchor : {GlyphAnchor::Tail, GlyphAnchor::Center, GlyphAnchor::Head})
        for (bool uniformLength : {false, true})
            configurations.push_back({anchor, uniformLength});
    return configurations;
}

void expectEnoughOfEach(const Tally& tally)
{
    // Enough hits and near misses to mean something, and few rays too close to call.
    EXPECT_GT(tally.hits, 1000);
    EXPECT_GT(tally.misses, 1000);
    EXPECT_LT(tally.grazing, tally.hits / 1000 + 5);
}

}

TEST(PickingRayTruth, Spheres)
{
    expectEnoughOfEach(checkShape(GlyphShape::Sphere, {Configuration()}));
}

TEST(PickingRayTruth, Cones)
{
    expectEnoughOfEach(checkShape(GlyphShape::Cone, vectorConfigurations()));
}

TEST(PickingRayTruth, Arrows)
{
    expectEnoughOfEach(checkShape(GlyphShape::Arrow, vectorConfigurations()));
}

TEST(PickingRayTruth, Cylinders)
{
    expectEnoughOfEach(checkShape(GlyphShape::Cylinder, vectorConfigurations()));
}
