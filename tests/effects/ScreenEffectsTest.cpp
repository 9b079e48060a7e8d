// Screen-space ambient occlusion and outlines (osgGlyphs::ScreenEffects): outlines ring a lone
// sphere at its exact silhouette under both projections and mark where two spheres meet;
// occlusion darkens a sphere near its contact with others and leaves a lone sphere alone; the
// composite writes the children's depth, so that geometry outside the node intersects them as
// without the node; with both effects off the node draws as a plain group.

#include "RenderHarness.h"

#include <osgGlyphs/GlyphCloud>
#include <osgGlyphs/ScreenEffects>

#include <osg/Geode>
#include <osg/Group>
#include <osg/ShapeDrawable>

#include <cmath>
#include <string>
#include <tuple>
#include <vector>

using namespace osgGlyphsTest;
using osgGlyphs::GlyphCloud;
using osgGlyphs::ScreenEffects;

namespace
{

const int SIZE = 240;
const osg::Vec4 GREY(0.5f, 0.5f, 0.5f, 1.0f);
const osg::Vec4 GREEN(0.1f, 0.9f, 0.1f, 1.0f);
const osg::Vec4 MAGENTA(1.0f, 0.0f, 1.0f, 1.0f);

osg::ref_ptr<GlyphCloud> sphereCloud(const std::vector<osg::Vec3>& centres, float radius)
{
    osg::ref_ptr<GlyphCloud> cloud = new GlyphCloud;
    cloud->setPositions(new osg::Vec3Array(centres.begin(), centres.end()));
    cloud->setRadius(radius);
    cloud->setColor(GREEN);
    return cloud;
}

float luminance(const osg::Vec4ub& c)
{
    return (c.r() + c.g() + c.b()) / 3.0f;
}

/** A pixel the magenta outline colour dominates (the spheres are green, the background grey). */
bool isOutline(const osg::Vec4ub& c)
{
    return c.r() > c.g() + 60 && c.b() > c.g() + 60;
}

/** A renderer looking at the origin from -y, up z, over a grey background. */
Renderer makeRenderer(bool orthographic)
{
    Renderer renderer(SIZE, SIZE);
    renderer.setClearColor(GREY);
    renderer.setLookAt(osg::Vec3d(0.0, -10.0, 0.0), osg::Vec3d(), osg::Vec3d(0.0, 0.0, 1.0));
    if (orthographic)
        renderer.getViewer()->getCamera()->setProjectionMatrixAsOrtho(-2.0, 2.0, -2.0, 2.0, 1.0, 40.0);
    else
        renderer.setPerspective(30.0, 1.0, 40.0);
    return renderer;
}

/** The radius in pixels of the outline of a sphere of radius r at the origin, seen from 10 away. */
double projectedRadius(bool orthographic, double r)
{
    if (orthographic)
        return r * SIZE / 4.0;
    const double angle = std::asin(r / 10.0);
    return 0.5 * SIZE * std::tan(angle) / std::tan(osg::DegreesToRadians(15.0));
}

osg::ref_ptr<ScreenEffects> effectsAround(osg::Node* child)
{
    osg::ref_ptr<ScreenEffects> effects = new ScreenEffects;
    effects->addChild(child);
    return effects;
}

}

class OutlineRing : public ::testing::TestWithParam<bool>
{
};

TEST_P(OutlineRing, LoneSphereIsRingedAtItsSilhouette)
{
    const bool orthographic = GetParam();
    const std::string name = orthographic ? "orthographic" : "perspective";
    osg::ref_ptr<ScreenEffects> effects = effectsAround(sphereCloud({osg::Vec3()}, 1.0f).get());
    effects->setOutlines(true);
    effects->setOutlineWidth(2.0f);
    effects->setOutlineColor(MAGENTA);
    Renderer renderer = makeRenderer(orthographic);
    const Frame frame = renderer.render(effects.get());
    saveFrame(frame, "screen_effects_ring_" + name);

    const double radius = projectedRadius(orthographic, 1.0);
    const double width = effects->getOutlineWidth();
    int ring = 0, inside = 0, outside = 0;
    std::vector<int> sectors(16, 0);
    for (int y = 0; y < SIZE; ++y)
    {
        for (int x = 0; x < SIZE; ++x)
        {
            const double dx = x + 0.5 - 0.5 * SIZE, dy = y + 0.5 - 0.5 * SIZE;
            const double rho = std::sqrt(dx * dx + dy * dy);
            const bool outline = isOutline(frame.colorAt(x, y));
            if (!outline)
                continue;
            if (rho > radius + 1.0)
                ++outside;
            else if (rho < radius - width - 2.0)
                ++inside;
            else
            {
                ++ring;
                const double angle = std::atan2(dy, dx) + M_PI;
                ++sectors[std::min(15, int(angle / (2.0 * M_PI) * 16.0))];
            }
        }
    }
    EXPECT_EQ(outside, 0) << "outline pixels beyond the silhouette";
    EXPECT_EQ(inside, 0) << "outline pixels well inside the silhouette";
    EXPECT_GT(ring, int(2.0 * M_PI * radius * (width - 0.5)))
        << "the ring is closed and " << width << " px wide";
    for (int sector = 0; sector < 16; ++sector)
        EXPECT_GT(sectors[sector], int(2.0 * M_PI * radius / 16.0)) << "sector " << sector;
}

INSTANTIATE_TEST_SUITE_P(Projections, OutlineRing, ::testing::Values(false, true),
                         [](const ::testing::TestParamInfo<bool>& param)
                         { return param.param ? std::string("Orthographic") : std::string("Perspective"); });

TEST(ScreenEffects, TouchingSpheresGetALineWhereTheyMeet)
{
    // Two spheres of radius 1 whose centres are 1.6 apart along x meet on a circle of radius
    // 0.6 in the plane x = 0: seen from -y, a vertical segment through the image centre.
    osg::ref_ptr<GlyphCloud> cloud =
        sphereCloud({osg::Vec3(-0.8f, 0.0f, 0.0f), osg::Vec3(0.8f, 0.0f, 0.0f)}, 1.0f);
    osg::ref_ptr<ScreenEffects> effects = effectsAround(cloud.get());
    Renderer renderer = makeRenderer(false);
    const Frame plain = renderer.render(effects.get());
    effects->setOutlines(true);
    const Frame outlined = renderer.render(effects.get());
    saveFrame(outlined, "screen_effects_crease");

    const int centre = SIZE / 2;
    const int half = int(0.45 * projectedRadius(false, 1.0));
    for (int y = centre - half; y < centre + half; y += 4)
    {
        const float darkest =
            std::min(luminance(outlined.colorAt(centre - 1, y)), luminance(outlined.colorAt(centre, y)));
        EXPECT_LT(darkest, 0.3f * luminance(plain.colorAt(centre, y))) << "row " << y;
    }
    // Away from the line and the silhouettes, the spheres are as without outlines.
    const int side = int(0.4 * projectedRadius(false, 1.0));
    for (int x : {centre - side, centre + side})
        EXPECT_TRUE(colorNear(outlined, x, centre, plain.colorAt(x, centre), 2));
}

TEST(ScreenEffects, OcclusionDarkensNearTheContact)
{
    // A sphere lying on a plane of touching spheres, seen from above at an angle: on the plane
    // sphere next to it, the point whose normal leans 30 degrees towards it is darkened, the same
    // point of a plane sphere far from it is not (its neighbours lie on that point's horizon). Both are
    // compared with the render without occlusion, so that the headlight's shading cancels.
    const float r = 0.5f;
    std::vector<osg::Vec3> centres{osg::Vec3()};
    for (int y = -6; y <= 6; ++y)
        for (int x = -6; x <= 8; ++x)
            centres.emplace_back(x * 2.0f * r, y * 2.0f * r, -2.0f * r);
    osg::ref_ptr<ScreenEffects> effects = effectsAround(sphereCloud(centres, r).get());
    Renderer renderer = makeRenderer(false);
    renderer.setLookAt(osg::Vec3d(2.25, -7.0, 6.0), osg::Vec3d(2.25, 0.0, -1.0), osg::Vec3d(0.0, 0.0, 1.0));
    const Frame plain = renderer.render(effects.get());
    effects->setAmbientOcclusion(true);
    const Frame occluded = renderer.render(effects.get());
    saveFrame(occluded, "screen_effects_occlusion");

    const osg::Vec3d leaning = osg::Vec3d(-0.5, 0.0, std::sqrt(0.75)) * r;
    auto darkening = [&](const osg::Vec3d& centre)
    {
        // Over 3x3 pixels, which the sample pattern varies over.
        const osg::Vec3d p = plain.project(centre + leaning);
        float before = 0.0f, after = 0.0f;
        for (int dy = -1; dy <= 1; ++dy)
        {
            for (int dx = -1; dx <= 1; ++dx)
            {
                before += luminance(plain.colorAt(int(p.x()) + dx, int(p.y()) + dy));
                after += luminance(occluded.colorAt(int(p.x()) + dx, int(p.y()) + dy));
            }
        }
        return after / before;
    };
    const float near = darkening(osg::Vec3d(1.0, 0.0, -1.0)), far = darkening(osg::Vec3d(4.0, 0.0, -1.0));
    EXPECT_GT(far, 0.9f) << "the far sphere keeps (almost all) its light";
    EXPECT_LT(near, 0.85f) << "the sphere next to the one lying on the plane is darker towards it";
    EXPECT_LT(near, far - 0.1f);
}

TEST(ScreenEffects, OcclusionLeavesALoneSphereAlone)
{
    osg::ref_ptr<ScreenEffects> effects = effectsAround(sphereCloud({osg::Vec3()}, 1.0f).get());
    Renderer renderer = makeRenderer(false);
    const Frame plain = renderer.render(effects.get());
    effects->setAmbientOcclusion(true);
    const Frame occluded = renderer.render(effects.get());
    saveFrame(occluded, "screen_effects_lone_sphere");
    int covered = 0, changed = 0;
    double difference = 0.0;
    for (int y = 0; y < SIZE; ++y)
    {
        for (int x = 0; x < SIZE; ++x)
        {
            if (!plain.isCovered(x, y))
                continue;
            ++covered;
            const float d = luminance(plain.colorAt(x, y)) - luminance(occluded.colorAt(x, y));
            difference += d;
            changed += std::fabs(d) > 4.0f ? 1 : 0;
        }
    }
    ASSERT_GT(covered, 1000);
    EXPECT_LT(difference / covered, 0.5) << "mean darkening";
    EXPECT_LT(changed, covered / 100) << "pixels changed by more than 4 levels";
}

namespace
{

/** The eye-space distance along -z of a pixel's depth: frames whose near and far planes differ
 * compare in it. */
double eyeDepth(const Frame& frame, int x, int y)
{
    const osg::Vec4d ndc(2.0 * (x + 0.5) / frame.width() - 1.0, 2.0 * (y + 0.5) / frame.height() - 1.0,
                         2.0 * frame.depthAt(x, y) - 1.0, 1.0);
    const osg::Vec4d eye = ndc * osg::Matrixd::inverse(frame.projection);
    return -eye.z() / eye.w();
}

bool isRed(const osg::Vec4ub& c)
{
    return c.r() > c.g() + 40;
}

}

/** Whether the view computes its near and far planes, and whether the sphere inside the node is
 * a glyph or ordinary OSG geometry. */
class DepthPassThrough : public ::testing::TestWithParam<std::tuple<bool, bool>>
{
};

TEST_P(DepthPassThrough, BoxOutsideIntersectsSphereInside)
{
    const bool computeNearFar = std::get<0>(GetParam()), geometry = std::get<1>(GetParam());
    const std::string name =
        std::string(computeNearFar ? "computed" : "fixed") + (geometry ? "_geometry" : "_glyph");
    // A red box outside the node cuts through the sphere inside it; its front lies behind the
    // sphere's, so that computed near and far planes hold the sphere only if the node says so.
    const osg::Vec3 centre(0.0f, -0.5f, 0.0f);
    osg::ref_ptr<osg::ShapeDrawable> box =
        new osg::ShapeDrawable(new osg::Box(osg::Vec3(0.8f, -0.3f, 0.2f), 1.2f));
    box->setColor(osg::Vec4(0.9f, 0.1f, 0.1f, 1.0f));
    osg::ref_ptr<osg::Geode> boxGeode = new osg::Geode;
    boxGeode->addDrawable(box.get());
    osg::ref_ptr<osg::Node> sphere = sphereCloud({centre}, 1.0f);
    if (geometry)
    {
        osg::ref_ptr<osg::ShapeDrawable> drawable = new osg::ShapeDrawable(new osg::Sphere(centre, 1.0f));
        drawable->setColor(GREEN);
        osg::ref_ptr<osg::Geode> geode = new osg::Geode;
        geode->addDrawable(drawable.get());
        sphere = geode;
    }
    osg::ref_ptr<ScreenEffects> effects = effectsAround(sphere.get());
    osg::ref_ptr<osg::Group> scene = new osg::Group;
    scene->addChild(effects.get());
    scene->addChild(boxGeode.get());

    Renderer renderer = makeRenderer(false);
    if (computeNearFar)
        renderer.getViewer()->getCamera()->setComputeNearFarMode(
            osg::CullSettings::COMPUTE_NEAR_FAR_USING_BOUNDING_VOLUMES);
    const Frame plain = renderer.render(scene.get());
    effects->setAmbientOcclusion(true);
    const Frame composited = renderer.render(scene.get());
    saveFrame(composited, "screen_effects_depth_" + name);

    int red = 0, mismatched = 0, depthMismatched = 0;
    for (int y = 0; y < SIZE; ++y)
    {
        for (int x = 0; x < SIZE; ++x)
        {
            ASSERT_EQ(plain.isCovered(x, y), composited.isCovered(x, y)) << x << ", " << y;
            if (!plain.isCovered(x, y))
                continue;
            red += isRed(plain.colorAt(x, y)) ? 1 : 0;
            mismatched += isRed(plain.colorAt(x, y)) != isRed(composited.colorAt(x, y)) ? 1 : 0;
            depthMismatched += std::fabs(eyeDepth(plain, x, y) - eyeDepth(composited, x, y)) > 1e-3 ? 1 : 0;
        }
    }
    ASSERT_GT(red, 1000) << "the box shows";
    EXPECT_LE(mismatched, 2) << "pixels where box and sphere swap";
    EXPECT_EQ(depthMismatched, 0) << "pixels whose depth moves";
}

INSTANTIATE_TEST_SUITE_P(NearFarAndSphere, DepthPassThrough,
                         ::testing::Combine(::testing::Bool(), ::testing::Bool()),
                         [](const ::testing::TestParamInfo<std::tuple<bool, bool>>& param)
                         {
                             return std::string(std::get<0>(param.param) ? "Computed" : "Fixed") +
                                    (std::get<1>(param.param) ? "Geometry" : "Glyph");
                         });

TEST(ScreenEffects, EffectsOffDrawsAsAGroup)
{
    osg::ref_ptr<osg::ShapeDrawable> box =
        new osg::ShapeDrawable(new osg::Box(osg::Vec3(0.8f, -0.3f, 0.2f), 1.2f));
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    geode->addDrawable(box.get());
    osg::ref_ptr<osg::Group> plainScene = new osg::Group;
    plainScene->addChild(sphereCloud({osg::Vec3(), osg::Vec3(1.5f, 0.0f, 0.5f)}, 1.0f).get());
    plainScene->addChild(geode.get());
    osg::ref_ptr<ScreenEffects> effects = new ScreenEffects;
    effects->addChild(plainScene->getChild(0));
    effects->addChild(geode.get());

    Renderer renderer = makeRenderer(false);
    const Frame plain = renderer.render(plainScene.get());
    const Frame off = renderer.render(effects.get());
    int differing = 0;
    for (int y = 0; y < SIZE; ++y)
        for (int x = 0; x < SIZE; ++x)
            differing += plain.colorAt(x, y) != off.colorAt(x, y) || plain.depthAt(x, y) != off.depthAt(x, y);
    EXPECT_EQ(differing, 0);
}

TEST(ScreenEffects, AutomaticRadiusFollowsTheGlyphs)
{
    osg::ref_ptr<ScreenEffects> effects =
        effectsAround(sphereCloud({osg::Vec3(), osg::Vec3(5.0f, 0.0f, 0.0f)}, 0.25f).get());
    EXPECT_FLOAT_EQ(effects->computeOcclusionRadius(), 0.5f);
    effects->setOcclusionRadius(3.0f);
    EXPECT_FLOAT_EQ(effects->computeOcclusionRadius(), 3.0f);
    effects->setOutlineWidth(0.2f);
    EXPECT_FLOAT_EQ(effects->getOutlineWidth(), 1.0f);
    effects->setOcclusionSamples(1000);
    EXPECT_EQ(effects->getOcclusionSamples(), ScreenEffects::MAX_OCCLUSION_SAMPLES);
}
