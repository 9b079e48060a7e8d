// Not a test: measures picking in a large cloud on the CPU: the spatial index built by the first
// pick, and then picks through osgUtil::LineSegmentIntersector (nearest glyph, and every glyph
// along the ray) and a PolytopeIntersector box.
//
//   pick_cost [N=1000000] [PICKS=1000]
#include <osgGlyphs/GlyphCloud>

#include <osgUtil/IntersectionVisitor>
#include <osgUtil/LineSegmentIntersector>
#include <osgUtil/PolytopeIntersector>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <iostream>
#include <random>
#include <vector>

using osgGlyphs::GlyphCloud;
using osgGlyphs::GlyphCulling;
using osgGlyphs::GlyphShape;

namespace
{

double millisecondsSince(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

/** N glyphs uniformly in a cube of side 100, radii such that a ray through it meets ~50 glyphs. */
osg::ref_ptr<GlyphCloud> createCloud(unsigned int n, GlyphShape shape, GlyphCulling culling)
{
    std::mt19937 random(3);
    std::uniform_real_distribution<float> coordinate(-50.0f, 50.0f), unit(-1.0f, 1.0f);
    osg::ref_ptr<osg::Vec3Array> positions = new osg::Vec3Array(n), vectors = new osg::Vec3Array(n);
    for (unsigned int i = 0; i < n; ++i)
    {
        (*positions)[i].set(coordinate(random), coordinate(random), coordinate(random));
        (*vectors)[i].set(unit(random), unit(random), 0.5f + unit(random));
    }
    osg::ref_ptr<GlyphCloud> cloud = new GlyphCloud;
    cloud->setCulling(culling);
    cloud->setShape(shape);
    cloud->setRadius(0.4f * std::cbrt(1.0e6f / float(n)));
    cloud->setVectors(vectors.get());
    cloud->setPositions(positions.get());
    return cloud;
}

struct Timing
{
    double first = 0.0, median = 0.0, max = 0.0;
    size_t hits = 0;
};

Timing measure(GlyphCloud& cloud, unsigned int picks, osgUtil::Intersector::IntersectionLimit limit)
{
    std::mt19937 random(5);
    std::uniform_real_distribution<double> coordinate(-45.0, 45.0);
    std::vector<double> times;
    Timing timing;
    for (unsigned int k = 0; k <= picks; ++k)
    {
        const osg::Vec3d start(coordinate(random), -80.0, coordinate(random));
        const osg::Vec3d end(coordinate(random), 80.0, coordinate(random));
        osg::ref_ptr<osgUtil::LineSegmentIntersector> picker =
            new osgUtil::LineSegmentIntersector(start, end);
        picker->setIntersectionLimit(limit);
        osgUtil::IntersectionVisitor visitor(picker.get());
        const auto begin = std::chrono::steady_clock::now();
        cloud.accept(visitor);
        const double ms = millisecondsSince(begin);
        timing.hits += picker->getIntersections().size();
        if (k == 0)
            timing.first = ms; // builds the index where the cloud has none
        else
            times.push_back(ms);
    }
    std::sort(times.begin(), times.end());
    timing.median = times[times.size() / 2];
    timing.max = times.back();
    timing.hits /= picks + 1;
    return timing;
}

}

int main(int argc, char** argv)
{
    const unsigned int n = argc > 1 ? unsigned(std::atoi(argv[1])) : 1000000u;
    const unsigned int picks = argc > 2 ? unsigned(std::max(1, std::atoi(argv[2]))) : 1000u;
    std::cout << "pick_cost: " << n << " glyphs in a cube of side 100, " << picks << " random rays across it"
              << std::endl;
    for (GlyphShape shape : {GlyphShape::Sphere, GlyphShape::Arrow})
        for (GlyphCulling culling : {GlyphCulling::Off, GlyphCulling::Occlusion})
        {
            const auto begin = std::chrono::steady_clock::now();
            osg::ref_ptr<GlyphCloud> cloud = createCloud(n, shape, culling);
            const double created = millisecondsSince(begin);
            const Timing nearest = measure(*cloud, picks, osgUtil::Intersector::LIMIT_NEAREST);
            const Timing all = measure(*cloud, picks, osgUtil::Intersector::NO_LIMIT);
            std::cout << (shape == GlyphShape::Sphere ? "spheres" : "arrows ") << ", culling "
                      << (culling == GlyphCulling::Off ? "off (index built by the first pick)"
                                                       : "on (index = the culling chunks)    ")
                      << ": cloud set up " << created << " ms; first pick " << nearest.first
                      << " ms; nearest: median " << nearest.median << " ms, max " << nearest.max
                      << " ms; all along the ray (" << all.hits << " glyphs): median " << all.median
                      << " ms, max " << all.max << " ms" << std::endl;
        }
    osg::ref_ptr<GlyphCloud> cloud = createCloud(n, GlyphShape::Sphere, GlyphCulling::Occlusion);
    osg::Polytope box;
    box.setToBoundingBox(osg::BoundingBox(-5, -5, -5, 5, 5, 5));
    osg::ref_ptr<osgUtil::PolytopeIntersector> picker = new osgUtil::PolytopeIntersector(box);
    osgUtil::IntersectionVisitor visitor(picker.get());
    const auto begin = std::chrono::steady_clock::now();
    cloud->accept(visitor);
    std::cout << "polytope (a box of side 10): " << picker->getIntersections().size() << " glyphs in "
              << millisecondsSince(begin) << " ms" << std::endl;
    return 0;
}
