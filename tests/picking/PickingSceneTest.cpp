// Picking in scenes: through osgViewer on a rendered headless view, under transforms and far
// from the world origin, next to a tessellated osg::Sphere; polytopes; limits; edits; threads.

#include "RenderHarness.h"
#include "SolidTruth.h"

#include <osgGlyphs/GlyphCloud>

#include <gtest/gtest.h>
#include <osg/MatrixTransform>
#include <osg/ShapeDrawable>
#include <osgUtil/IntersectionVisitor>
#include <osgUtil/LineSegmentIntersector>
#include <osgUtil/PolytopeIntersector>

#include <random>
#include <set>
#include <thread>

using namespace osgGlyphsTest;
using osgGlyphs::GlyphCloud;
using osgGlyphs::GlyphCulling;
using osgGlyphs::GlyphShape;

namespace
{

osg::ref_ptr<GlyphCloud> createSpheres(const std::vector<osg::Vec3>& positions, float radius)
{
    osg::ref_ptr<GlyphCloud> cloud = new GlyphCloud;
    cloud->setPositions(new osg::Vec3Array(positions.begin(), positions.end()));
    cloud->setRadius(radius);
    cloud->setColor(osg::Vec4(0.9f, 0.5f, 0.2f, 1.0f));
    return cloud;
}

osgUtil::LineSegmentIntersector::Intersections
pick(osg::Node& node, const osg::Vec3d& start, const osg::Vec3d& end,
     osgUtil::Intersector::IntersectionLimit limit = osgUtil::Intersector::NO_LIMIT)
{
    osg::ref_ptr<osgUtil::LineSegmentIntersector> picker = new osgUtil::LineSegmentIntersector(start, end);
    picker->setIntersectionLimit(limit);
    osgUtil::IntersectionVisitor visitor(picker.get());
    node.accept(visitor);
    return picker->getIntersections();
}

/** The world point picked under window point (x, y) of the viewer's camera, and the glyph index. */
bool pickWindow(osgViewer::View& view, double x, double y, osg::Vec3d& world, unsigned int& index,
                osg::Drawable** drawable = nullptr)
{
    osgUtil::LineSegmentIntersector::Intersections hits;
    if (!view.computeIntersections(view.getCamera(), osgUtil::Intersector::WINDOW, float(x), float(y), hits))
        return false;
    world = hits.begin()->getWorldIntersectPoint();
    index = hits.begin()->primitiveIndex;
    if (drawable)
        *drawable = hits.begin()->drawable.get();
    return true;
}

}

TEST(Picking, RayThroughBoundingSquareMissesTheSurface)
{
    osg::ref_ptr<GlyphCloud> spheres = createSpheres({osg::Vec3()}, 1.0f);
    EXPECT_TRUE(pick(*spheres, osg::Vec3d(0.8, -5.0, 0.8), osg::Vec3d(0.8, 5.0, 0.8)).empty());
    const auto through = pick(*spheres, osg::Vec3d(0.5, -5.0, 0.5), osg::Vec3d(0.5, 5.0, 0.5));
    ASSERT_EQ(through.size(), 1u);
    EXPECT_NEAR(through.begin()->localIntersectionPoint.y(), -std::sqrt(0.5), 1e-12);
    EXPECT_NEAR(through.begin()->localIntersectionNormal.y(), -std::sqrt(0.5), 1e-6);

    // A cone along +z from (0,0,-1) to its apex at (0,0,1), base radius 1: its box holds (0.9, 0, 0.9).
    osg::ref_ptr<GlyphCloud> cone = createSpheres({osg::Vec3()}, 1.0f);
    cone->setShape(GlyphShape::Cone);
    osg::ref_ptr<osg::Vec3Array> vectors = new osg::Vec3Array;
    vectors->push_back(osg::Vec3(0.0f, 0.0f, 2.0f));
    cone->setVectors(vectors.get());
    EXPECT_TRUE(pick(*cone, osg::Vec3d(0.9, -5.0, 0.9), osg::Vec3d(0.9, 5.0, 0.9)).empty());
    const auto base = pick(*cone, osg::Vec3d(0.2, 0.3, -5.0), osg::Vec3d(0.2, 0.3, 5.0));
    ASSERT_EQ(base.size(), 1u);
    EXPECT_NEAR(base.begin()->localIntersectionPoint.z(), -1.0, 1e-12);
    EXPECT_NEAR(base.begin()->localIntersectionNormal.z(), -1.0, 1e-6);
}

TEST(Picking, NearestFirstAndLimits)
{
    osg::ref_ptr<GlyphCloud> spheres =
        createSpheres({osg::Vec3(0, 4, 0), osg::Vec3(0, 0, 0), osg::Vec3(0, 8, 0)}, 1.0f);
    const osg::Vec3d start(0.0, -10.0, 0.0), end(0.0, 20.0, 0.0);
    const auto all = pick(*spheres, start, end);
    ASSERT_EQ(all.size(), 3u);
    std::vector<unsigned int> order;
    for (const auto& hit : all)
        order.push_back(hit.primitiveIndex);
    EXPECT_EQ(order, (std::vector<unsigned int>{1, 0, 2}));
    EXPECT_NEAR(all.begin()->ratio, 9.0 / 30.0, 1e-12);
    for (auto limit : {osgUtil::Intersector::LIMIT_NEAREST, osgUtil::Intersector::LIMIT_ONE,
                       osgUtil::Intersector::LIMIT_ONE_PER_DRAWABLE})
    {
        const auto limited = pick(*spheres, start, end, limit);
        ASSERT_EQ(limited.size(), 1u);
        EXPECT_EQ(limited.begin()->primitiveIndex, 1u);
    }
    // A segment that starts inside a glyph meets it at its start, as the near plane cuts it.
    const auto inside = pick(*spheres, osg::Vec3d(0.0, 4.5, 0.0), osg::Vec3d(0.0, 20.0, 0.0));
    ASSERT_EQ(inside.size(), 2u);
    EXPECT_EQ(inside.begin()->primitiveIndex, 0u);
    EXPECT_EQ(inside.begin()->ratio, 0.0);
    // A segment that ends before the glyph meets nothing.
    EXPECT_TRUE(pick(*spheres, start, osg::Vec3d(0.0, -1.5, 0.0)).empty());
}

TEST(Picking, IndexFollowsEdits)
{
    for (GlyphCulling culling : {GlyphCulling::Off, GlyphCulling::Occlusion})
    {
        osg::ref_ptr<GlyphCloud> spheres = createSpheres({osg::Vec3(0, 0, 0), osg::Vec3(3, 0, 0)}, 1.0f);
        spheres->setCulling(culling);
        ASSERT_EQ(pick(*spheres, osg::Vec3d(0, -5, 0), osg::Vec3d(0, 5, 0)).size(), 1u);
        (*spheres->getPositions())[0].x() = 10.0f;
        spheres->getPositions()->dirty();
        spheres->dirtyGlyphs();
        EXPECT_TRUE(pick(*spheres, osg::Vec3d(0, -5, 0), osg::Vec3d(0, 5, 0)).empty());
        const auto moved = pick(*spheres, osg::Vec3d(10, -5, 0), osg::Vec3d(10, 5, 0));
        ASSERT_EQ(moved.size(), 1u);
        EXPECT_EQ(moved.begin()->primitiveIndex, 0u);
        spheres->setRadius(0.5f);
        EXPECT_TRUE(pick(*spheres, osg::Vec3d(10.7, -5, 0), osg::Vec3d(10.7, 5, 0)).empty());
    }
}

TEST(Picking, ConcurrentPicksAgree)
{
    std::mt19937 random(7);
    std::uniform_real_distribution<float> coordinate(-50.0f, 50.0f);
    std::vector<osg::Vec3> positions(20000);
    for (osg::Vec3& p : positions)
        p.set(coordinate(random), coordinate(random), coordinate(random));
    osg::ref_ptr<GlyphCloud> spheres = createSpheres(positions, 1.5f);
    spheres->setCulling(GlyphCulling::Off); // the index is built by the first pick
    std::vector<osg::Vec3d> starts;
    for (int i = 0; i < 200; ++i)
        starts.emplace_back(coordinate(random), -100.0, coordinate(random));
    auto pickAll = [&](std::vector<int>& found)
    {
        for (const osg::Vec3d& start : starts)
        {
            const auto hits =
                pick(*spheres, start, start + osg::Vec3d(0, 200, 0), osgUtil::Intersector::LIMIT_NEAREST);
            found.push_back(hits.empty() ? -1 : int(hits.begin()->primitiveIndex));
        }
    };
    std::vector<std::vector<int>> found(4);
    std::vector<std::thread> threads;
    for (std::vector<int>& result : found)
        threads.emplace_back(pickAll, std::ref(result));
    for (std::thread& thread : threads)
        thread.join();
    std::vector<int> expected;
    for (const osg::Vec3d& start : starts)
    {
        // Brute force: the sphere whose entry point along +y is nearest.
        int nearest = -1;
        double best = 1e300;
        for (unsigned int i = 0; i < positions.size(); ++i)
        {
            const osg::Vec3d& p = positions[i];
            const double dx = p.x() - start.x(), dz = p.z() - start.z();
            const double h2 = 1.5 * 1.5 - dx * dx - dz * dz;
            if (h2 >= 0.0 && p.y() - std::sqrt(h2) - start.y() < best)
            {
                best = p.y() - std::sqrt(h2) - start.y();
                nearest = int(i);
            }
        }
        expected.push_back(nearest);
    }
    for (const std::vector<int>& result : found)
        EXPECT_EQ(result, expected);
}

/** A cloud of two spheres 1e7 from the world origin, under a rotating and scaling transform, and
 * the same spheres tessellated by osg::ShapeDrawable: picking either through a rendered headless
 * view meets the same point. */
TEST(Picking, ViewPicksGlyphUnderPixelLikeTessellatedSphere)
{
    const osg::Vec3d origin(1.0e7, 1.0e7, 0.0);
    const osg::Matrixd transform = osg::Matrixd::scale(2.0, 2.0, 2.0) *
                                   osg::Matrixd::rotate(osg::DegreesToRadians(30.0), osg::Vec3d(0, 0, 1));
    const std::vector<osg::Vec3> offsets = {osg::Vec3(-1.5f, 0.0f, 0.0f), osg::Vec3(1.5f, 0.0f, 0.3f)};
    const float radius = 1.0f;
    osg::ref_ptr<GlyphCloud> cloud = createSpheres(offsets, radius);
    cloud->setOrigin(origin);
    osg::ref_ptr<osg::MatrixTransform> glyphs = new osg::MatrixTransform(transform);
    glyphs->addChild(cloud.get());

    osg::ref_ptr<osg::Geode> tessellated = new osg::Geode;
    osg::ref_ptr<osg::TessellationHints> hints = new osg::TessellationHints;
    hints->setDetailRatio(8.0f);
    for (const osg::Vec3& offset : offsets)
        tessellated->addDrawable(new osg::ShapeDrawable(new osg::Sphere(offset, radius), hints.get()));
    // Float vertices 1e7 from the origin would be off by a unit: the origin goes in a transform.
    osg::ref_ptr<osg::MatrixTransform> shapes = new osg::MatrixTransform(transform);
    osg::ref_ptr<osg::MatrixTransform> shapeOrigin =
        new osg::MatrixTransform(osg::Matrixd::translate(origin));
    shapeOrigin->addChild(tessellated.get());
    shapes->addChild(shapeOrigin.get());

    const osg::Vec3d centre = origin * transform;
    Renderer renderer(200, 200);
    renderer.setLookAt(centre + osg::Vec3d(-3.0, -14.0, 4.0), centre, osg::Vec3d(0, 0, 1));
    renderer.setPerspective(40.0, 1.0, 100.0);
    for (int glyph = 0; glyph < 2; ++glyph)
    {
        const osg::Vec3d world = (origin + osg::Vec3d(offsets[glyph])) * transform;
        const Frame frame = renderer.render(glyphs.get());
        const osg::Vec3d projected = frame.project(world);
        // A pixel off the centre, where the front surface slopes.
        const int px = int(projected.x()) + 9, py = int(projected.y()) + 5;
        ASSERT_TRUE(frame.isCovered(px, py));
        osg::Vec3d glyphPoint;
        unsigned int index = 99;
        osg::Drawable* drawable = nullptr;
        ASSERT_TRUE(pickWindow(*renderer.getViewer(), px + 0.5, py + 0.5, glyphPoint, index, &drawable));
        EXPECT_EQ(index, unsigned(glyph));
        EXPECT_EQ(drawable, cloud.get());
        // The analytic sphere, in world coordinates (radius scaled by 2), along the pixel's ray.
        osg::Vec3d rayOrigin, rayDirection;
        frame.pixelRay(px + 0.5, py + 0.5, rayOrigin, rayDirection);
        const Solid::Trace truth =
            Solid::sphere(world, 2.0 * radius).trace(rayOrigin, rayDirection, 100.0, 1e-9);
        ASSERT_TRUE(truth.hit);
        EXPECT_LT((glyphPoint - (rayOrigin + rayDirection * truth.t)).length(), 1e-5);
        // The depth the glyph was drawn with at that pixel.
        EXPECT_NEAR(frame.windowDepth(glyphPoint), frame.depthAt(px, py), 2e-6);

        const Frame shapeFrame = renderer.render(shapes.get());
        osg::Vec3d shapePoint;
        ASSERT_TRUE(pickWindow(*renderer.getViewer(), px + 0.5, py + 0.5, shapePoint, index));
        EXPECT_LT((glyphPoint - shapePoint).length(), 0.01 * 2.0 * radius)
            << "tessellated hit " << shapePoint.x() - centre.x() << " " << shapePoint.y() - centre.y() << " "
            << shapePoint.z() - centre.z();
        if (glyph == 0)
        {
            saveFrame(frame, "picking_glyphs");
            saveFrame(shapeFrame, "picking_tessellated");
        }
    }
}

TEST(Picking, PolytopeSelectsGlyphsWhosePointsAreInside)
{
    std::vector<osg::Vec3> positions;
    for (int i = 0; i < 10; ++i)
        for (int j = 0; j < 10; ++j)
            positions.emplace_back(i - 4.5f, 0.3f * ((i * 7 + j * 3) % 5), j - 4.5f);
    osg::ref_ptr<GlyphCloud> cloud = createSpheres(positions, 0.3f);
    cloud->setOrigin(osg::Vec3d(5.0e6, 0.0, 0.0));
    osg::ref_ptr<osg::MatrixTransform> scene =
        new osg::MatrixTransform(osg::Matrixd::translate(-5.0e6, 0.0, 0.0));
    scene->addChild(cloud.get());
    Renderer renderer(200, 200);
    renderer.setLookAt(osg::Vec3d(1.0, -25.0, 2.0), osg::Vec3d(), osg::Vec3d(0, 0, 1));
    const Frame frame = renderer.render(scene.get());
    const double xMin = 61.3, yMin = 47.7, xMax = 133.2, yMax = 150.6;
    osg::ref_ptr<osgUtil::PolytopeIntersector> picker =
        new osgUtil::PolytopeIntersector(osgUtil::Intersector::WINDOW, xMin, yMin, xMax, yMax);
    osgUtil::IntersectionVisitor visitor(picker.get());
    renderer.getViewer()->getCamera()->accept(visitor);
    std::set<unsigned int> selected;
    for (const auto& hit : picker->getIntersections())
    {
        EXPECT_TRUE(selected.insert(hit.primitiveIndex).second) << "glyph " << hit.primitiveIndex << " twice";
        EXPECT_EQ(hit.numIntersectionPoints, 1u);
        const osg::Vec3d world = hit.localIntersectionPoint * *hit.matrix;
        EXPECT_LT((world - osg::Vec3d(positions[hit.primitiveIndex])).length(), 1e-6);
    }
    std::set<unsigned int> expected;
    for (unsigned int i = 0; i < positions.size(); ++i)
    {
        const osg::Vec3d window = frame.project(osg::Vec3d(positions[i]));
        if (window.x() > xMin && window.x() < xMax && window.y() > yMin && window.y() < yMax)
            expected.insert(i);
    }
    EXPECT_EQ(selected, expected);
    EXPECT_GT(expected.size(), 10u);
    EXPECT_LT(expected.size(), 90u);

    // Lines only: glyphs are neither.
    picker = new osgUtil::PolytopeIntersector(osgUtil::Intersector::WINDOW, xMin, yMin, xMax, yMax);
    picker->setPrimitiveMask(osgUtil::PolytopeIntersector::LINE_PRIMITIVES);
    osgUtil::IntersectionVisitor linesOnly(picker.get());
    renderer.getViewer()->getCamera()->accept(linesOnly);
    EXPECT_TRUE(picker->getIntersections().empty());
}

TEST(Picking, IntersectorGroupPicksWithEach)
{
    osg::ref_ptr<GlyphCloud> spheres = createSpheres({osg::Vec3(0, 0, 0), osg::Vec3(3, 0, 0)}, 1.0f);
    osg::ref_ptr<osgUtil::LineSegmentIntersector> segment =
        new osgUtil::LineSegmentIntersector(osg::Vec3d(3, -5, 0), osg::Vec3d(3, 5, 0));
    osg::Polytope box;
    box.setToBoundingBox(osg::BoundingBox(-1, -1, -1, 1, 1, 1));
    osg::ref_ptr<osgUtil::PolytopeIntersector> polytope = new osgUtil::PolytopeIntersector(box);
    osg::ref_ptr<osgUtil::IntersectorGroup> group = new osgUtil::IntersectorGroup;
    group->addIntersector(segment.get());
    group->addIntersector(polytope.get());
    osgUtil::IntersectionVisitor visitor(group.get());
    spheres->accept(visitor);
    ASSERT_EQ(segment->getIntersections().size(), 1u);
    EXPECT_EQ(segment->getIntersections().begin()->primitiveIndex, 1u);
    ASSERT_EQ(polytope->getIntersections().size(), 1u);
    EXPECT_EQ(polytope->getIntersections().begin()->primitiveIndex, 0u);
}
