// Depth peeling (osgGlyphs::DepthPeeling): transparent glyphs blend as the analytic "over"
// operator of their surfaces sorted by depth, whatever the order of the arrays or children, with
// opaque geometry outside the node hiding what lies behind it.
//
// The truth is composed from renders of each glyph alone, opaque: per pixel, the glyphs' lit
// colours sorted by their depths, then c = a * c_i + (1 - a) * c over the background, back to
// front. The peeled picture keeps its layers in half floats and the single renders are rounded
// to 8 bits, so a channel may differ by COLOR_TOLERANCE.

#include "GlyphTestScenes.h"

#include <osgGlyphs/DepthPeeling>
#include <osgGlyphs/GlyphCloud>
#include <osgGlyphs/ScreenEffects>

#include <osg/Group>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

using namespace osgGlyphsTest;
using osgGlyphs::DepthPeeling;
using osgGlyphs::GlyphCloud;

namespace
{

const int COLOR_TOLERANCE = 2;
const osg::Vec4 BACKGROUND(0.2f, 0.3f, 0.4f, 1.0f);

/** A render of one glyph, drawn alone and opaque, and the alpha it is blended with. */
struct Surface
{
    Frame frame;
    float alpha;
};

/** Each test runs with each of DepthPeeling's methods. */
class DepthPeelingTest : public ::testing::TestWithParam<DepthPeeling::Method>
{
protected:
    DepthPeelingTest() { renderer.setClearColor(BACKGROUND); }

    /** A peeling node of the method under test. */
    osg::ref_ptr<DepthPeeling> createPeeling() const
    {
        osg::ref_ptr<DepthPeeling> peeling = new DepthPeeling;
        peeling->setMethod(GetParam());
        return peeling;
    }

    /** The children under a peeling node. */
    Frame renderPeeled(std::initializer_list<osg::Node*> transparent, osg::Node* opaque = nullptr)
    {
        osg::ref_ptr<osg::Group> root = new osg::Group;
        if (opaque)
            root->addChild(opaque);
        osg::ref_ptr<DepthPeeling> peeling = createPeeling();
        for (osg::Node* child : transparent)
            peeling->addChild(child);
        root->addChild(peeling.get());
        return renderer.render(root.get());
    }

    /** The name of a saved picture ends with the method's. */
    std::string methodSuffix() const { return GetParam() == DepthPeeling::K_BUFFER ? "_kbuffer" : "_passes"; }

    /** A node drawn alone and opaque. */
    Surface renderAlone(osg::Node* node, float alpha) { return {renderer.render(node), alpha}; }

    Renderer renderer{160, 120};
};

/** A sphere cloud of one lit sphere with an opacity. */
osg::ref_ptr<GlyphCloud> sphere(const osg::Vec3& center, float radius, const osg::Vec4ub& color,
                                float opacity)
{
    osg::ref_ptr<GlyphCloud> cloud = createSphereCloud({{center, radius, color}}, true);
    cloud->setOpacity(opacity);
    return cloud;
}

osg::Vec4 toVec4(const osg::Vec4ub& c)
{
    return osg::Vec4(c.r(), c.g(), c.b(), c.a()) / 255.0f;
}

/** The expected pixel: the surfaces that cover it, blended back to front over the background. */
osg::Vec4 composeOver(const std::vector<Surface>& surfaces, int x, int y)
{
    std::vector<const Surface*> covering;
    for (const Surface& surface : surfaces)
        if (surface.frame.isCovered(x, y))
            covering.push_back(&surface);
    std::sort(covering.begin(), covering.end(),
              [x, y](const Surface* a, const Surface* b)
              { return a->frame.depthAt(x, y) > b->frame.depthAt(x, y); });
    osg::Vec4 color = BACKGROUND;
    for (const Surface* surface : covering)
        color = toVec4(surface->frame.colorAt(x, y)) * surface->alpha + color * (1.0f - surface->alpha);
    return color;
}

/** How many pixels differ from the composed truth by more than the tolerance; the pixels where
 * two or more surfaces overlap are counted in overlaps. */
int countMismatches(const Frame& frame, const std::vector<Surface>& surfaces, int& overlaps,
                    int tolerance = COLOR_TOLERANCE)
{
    int mismatches = 0;
    overlaps = 0;
    for (int y = 0; y < frame.height(); ++y)
        for (int x = 0; x < frame.width(); ++x)
        {
            int covering = 0;
            for (const Surface& surface : surfaces)
                covering += surface.frame.isCovered(x, y) ? 1 : 0;
            overlaps += covering >= 2 ? 1 : 0;
            const osg::Vec4 expected = composeOver(surfaces, x, y) * 255.0f;
            const osg::Vec4ub actual = frame.colorAt(x, y);
            for (int c = 0; c < 3; ++c)
                if (std::abs(actual[c] - expected[c]) > tolerance + 0.5f)
                {
                    if (mismatches < 5)
                        ADD_FAILURE() << "pixel (" << x << ", " << y << ") channel " << c << ": "
                                      << int(actual[c]) << ", expected " << expected[c];
                    ++mismatches;
                    break;
                }
        }
    return mismatches;
}

int countDifferentPixels(const Frame& a, const Frame& b)
{
    int different = 0;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x)
        {
            const osg::Vec4ub ca = a.colorAt(x, y), cb = b.colorAt(x, y);
            for (int c = 0; c < 3; ++c)
                if (std::abs(ca[c] - cb[c]) > 1)
                {
                    ++different;
                    break;
                }
        }
    return different;
}

const osg::Vec4ub RED(230, 40, 30, 255);
const osg::Vec4ub GREEN(40, 220, 60, 255);
const osg::Vec4ub WHITE(240, 240, 240, 255);

}

TEST_P(DepthPeelingTest, OverlappingSpheresBlendAsSortedInEitherArrayOrder)
{
    // The red sphere is nearer the eye (at y = -10) than the green one.
    const SphereSpec nearSphere = {osg::Vec3(-0.5f, -1.0f, 0.2f), 1.3f, RED};
    const SphereSpec farSphere = {osg::Vec3(0.6f, 1.0f, -0.1f), 1.5f, GREEN};
    auto cloudOf = [](const std::vector<SphereSpec>& spheres)
    {
        osg::ref_ptr<GlyphCloud> cloud = createSphereCloud(spheres, true);
        cloud->setOpacity(0.5f);
        return cloud;
    };
    const Frame frontToBack = renderPeeled({cloudOf({nearSphere, farSphere}).get()});
    const Frame backToFront = renderPeeled({cloudOf({farSphere, nearSphere}).get()});
    saveFrame(frontToBack, "peeling_two_spheres" + methodSuffix());

    EXPECT_EQ(countDifferentPixels(frontToBack, backToFront), 0);
    const std::vector<Surface> surfaces = {renderAlone(createSphereCloud({nearSphere}, true).get(), 0.5f),
                                           renderAlone(createSphereCloud({farSphere}, true).get(), 0.5f)};
    int overlaps = 0;
    EXPECT_EQ(countMismatches(frontToBack, surfaces, overlaps), 0);
    EXPECT_GT(overlaps, 500);
}

TEST_P(DepthPeelingTest, OpaqueGeometryOutsideHidesTheGlyphsBehindIt)
{
    const SphereSpec wall = {osg::Vec3(0.0f, 0.0f, 0.0f), 2.0f, WHITE};
    const SphereSpec behind = {osg::Vec3(-0.3f, 3.0f, 0.2f), 0.8f, RED};
    const SphereSpec inFront = {osg::Vec3(0.8f, -3.0f, -0.2f), 0.5f, GREEN};
    const Frame frame = renderPeeled({sphere(behind.center, behind.radius, behind.color, 0.5f).get(),
                                      sphere(inFront.center, inFront.radius, inFront.color, 0.5f).get()},
                                     createSphereCloud({wall}, true).get());
    saveFrame(frame, "peeling_opaque_wall" + methodSuffix());

    const std::vector<Surface> surfaces = {renderAlone(createSphereCloud({wall}, true).get(), 1.0f),
                                           renderAlone(createSphereCloud({behind}, true).get(), 0.5f),
                                           renderAlone(createSphereCloud({inFront}, true).get(), 0.5f)};
    int overlaps = 0;
    EXPECT_EQ(countMismatches(frame, surfaces, overlaps), 0);
    EXPECT_GT(overlaps, 200);
    // The depth buffer gets the nearest layer's depth: the transparent sphere's in front of the
    // wall, the wall's where the transparent one behind it is hidden.
    const osg::Vec3d front = frame.project(osg::Vec3d(inFront.center));
    EXPECT_TRUE(depthNear(frame, int(front.x()), int(front.y()),
                          surfaces[2].frame.depthAt(int(front.x()), int(front.y())), 1.0e-6));
    const osg::Vec3d hidden = frame.project(osg::Vec3d(behind.center));
    EXPECT_TRUE(depthNear(frame, int(hidden.x()), int(hidden.y()),
                          surfaces[0].frame.depthAt(int(hidden.x()), int(hidden.y())), 1.0e-6));
}

TEST_P(DepthPeelingTest, ConeThroughSpherePeelsInEitherChildOrder)
{
    const SphereSpec ball = {osg::Vec3(0.0f, 0.0f, 0.0f), 1.2f, GREEN};
    auto cone = []
    {
        osg::ref_ptr<GlyphCloud> cloud = new GlyphCloud;
        cloud->setShape(osgGlyphs::GlyphShape::Cone);
        cloud->setPositions(makeArray<osg::Vec3Array>({osg::Vec3(0.0f, -0.6f, 0.0f)}));
        // Across the view and slanted in depth: it enters the ball's front and leaves its back.
        cloud->setVectors(makeArray<osg::Vec3Array>({osg::Vec3(3.5f, 2.0f, 0.4f)}));
        cloud->setAnchor(osgGlyphs::GlyphAnchor::Center);
        cloud->setRadius(0.5f);
        cloud->setColor(toVec4(RED));
        return cloud;
    };
    auto transparent = [](osg::ref_ptr<GlyphCloud> cloud)
    {
        cloud->setOpacity(0.5f);
        return cloud;
    };
    const Frame coneFirst =
        renderPeeled({transparent(cone()).get(), sphere(ball.center, ball.radius, ball.color, 0.5f).get()});
    const Frame ballFirst =
        renderPeeled({sphere(ball.center, ball.radius, ball.color, 0.5f).get(), transparent(cone()).get()});
    saveFrame(coneFirst, "peeling_cone_through_sphere" + methodSuffix());

    EXPECT_EQ(countDifferentPixels(coneFirst, ballFirst), 0);
    const std::vector<Surface> surfaces = {renderAlone(cone().get(), 0.5f),
                                           renderAlone(createSphereCloud({ball}, true).get(), 0.5f)};
    int overlaps = 0;
    EXPECT_EQ(countMismatches(coneFirst, surfaces, overlaps), 0);
    EXPECT_GT(overlaps, 300);
}

TEST_P(DepthPeelingTest, UnderScreenEffectsTheLayersBlendOverTheBackgroundToo)
{
    // ScreenEffects with the opaque wall and the peeled spheres as children; one sphere lies over
    // the background alone. Occlusion of strength 0 runs the effects' composite without changing
    // a colour: the picture is the analytic blend, as without the effects (the composite's 8-bit
    // premultiplied colour may round one level more).
    const SphereSpec wall = {osg::Vec3(0.0f, 0.0f, 0.0f), 2.0f, WHITE};
    const SphereSpec behind = {osg::Vec3(-0.3f, 3.0f, 0.2f), 0.8f, RED};
    const SphereSpec inFront = {osg::Vec3(0.8f, -3.0f, -0.2f), 0.5f, GREEN};
    const SphereSpec aside = {osg::Vec3(-2.9f, -1.0f, 1.2f), 0.6f, RED};
    osg::ref_ptr<DepthPeeling> peeling = createPeeling();
    for (const SphereSpec& spec : {behind, inFront, aside})
        peeling->addChild(sphere(spec.center, spec.radius, spec.color, 0.5f).get());
    osg::ref_ptr<osgGlyphs::ScreenEffects> effects = new osgGlyphs::ScreenEffects;
    effects->addChild(createSphereCloud({wall}, true).get());
    effects->addChild(peeling.get());
    effects->setAmbientOcclusion(true);
    effects->setOcclusionStrength(0.0f);
    const Frame frame = renderer.render(effects.get());
    saveFrame(frame, "peeling_under_screen_effects" + methodSuffix());

    const std::vector<Surface> surfaces = {renderAlone(createSphereCloud({wall}, true).get(), 1.0f),
                                           renderAlone(createSphereCloud({behind}, true).get(), 0.5f),
                                           renderAlone(createSphereCloud({inFront}, true).get(), 0.5f),
                                           renderAlone(createSphereCloud({aside}, true).get(), 0.5f)};
    int overlaps = 0;
    EXPECT_EQ(countMismatches(frame, surfaces, overlaps, COLOR_TOLERANCE + 1), 0);
    int asideAlone = 0;
    for (int y = 0; y < frame.height(); ++y)
        for (int x = 0; x < frame.width(); ++x)
            asideAlone += surfaces[3].frame.isCovered(x, y) && !surfaces[0].frame.isCovered(x, y) ? 1 : 0;
    EXPECT_GT(asideAlone, 100); // the case the effects used to lose

    // With outlines too, the sphere over the background stays: its centre keeps its colour.
    effects->setOutlines(true);
    const Frame outlined = renderer.render(effects.get());
    const osg::Vec3d centre = outlined.project(osg::Vec3d(aside.center));
    const osg::Vec4ub expected = frame.colorAt(int(centre.x()), int(centre.y()));
    const osg::Vec4ub actual = outlined.colorAt(int(centre.x()), int(centre.y()));
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(actual[c], expected[c], 1) << "channel " << c;
}

TEST_P(DepthPeelingTest, StacksOfSmallSpheresPeelAsSortedInEitherArrayOrder)
{
    // Spheres of about a pixel, stacked three deep along rays from the eye (at y = -10) and moved
    // by a third of a pixel within a stack, so that they cover each other's pixels in part: the
    // vertex stage ray-casts small spheres against the previous layer (bound.glsl) and must keep
    // every one that still shows at some pixel.
    const float RADIUS = 0.04f; // about 0.7 pixels
    const osg::Vec3 eye(0.0f, -10.0f, 0.0f);
    const float depths[3] = {-1.0f, 0.0f, 1.0f};
    const osg::Vec3 shifts[3] = {osg::Vec3(), osg::Vec3(0.02f, 0.0f, 0.01f), osg::Vec3(-0.015f, 0.0f, 0.02f)};
    const osg::Vec4ub colors[3] = {RED, GREEN, WHITE};
    std::vector<SphereSpec> layers[3];
    for (float x = -4.0f; x <= 4.0f; x += 0.3f)
        for (float z = -3.0f; z <= 3.0f; z += 0.3f)
            for (int k = 0; k < 3; ++k)
            {
                const osg::Vec3 onPlane(x, 0.0f, z);
                const osg::Vec3 center = eye + (onPlane - eye) * ((10.0f + depths[k]) / 10.0f) + shifts[k];
                layers[k].push_back({center, RADIUS, colors[k]});
            }
    std::vector<SphereSpec> nearFirst, farFirst;
    for (int k = 0; k < 3; ++k)
    {
        nearFirst.insert(nearFirst.end(), layers[k].begin(), layers[k].end());
        farFirst.insert(farFirst.end(), layers[2 - k].begin(), layers[2 - k].end());
    }
    auto cloudOf = [](const std::vector<SphereSpec>& spheres)
    {
        osg::ref_ptr<GlyphCloud> cloud = createSphereCloud(spheres, true);
        cloud->setOpacity(0.5f);
        return cloud;
    };
    const Frame frontToBack = renderPeeled({cloudOf(nearFirst).get()});
    const Frame backToFront = renderPeeled({cloudOf(farFirst).get()});
    saveFrame(frontToBack, "peeling_small_spheres" + methodSuffix());

    EXPECT_EQ(countDifferentPixels(frontToBack, backToFront), 0);
    std::vector<Surface> surfaces;
    for (const auto& layer : layers)
        surfaces.push_back(renderAlone(createSphereCloud(layer, true).get(), 0.5f));
    int overlaps = 0;
    EXPECT_EQ(countMismatches(frontToBack, surfaces, overlaps), 0);
    EXPECT_GT(overlaps, 500);
}

INSTANTIATE_TEST_SUITE_P(Methods, DepthPeelingTest,
                         ::testing::Values(DepthPeeling::K_BUFFER, DepthPeeling::PEEL_PASSES),
                         [](const ::testing::TestParamInfo<DepthPeeling::Method>& method)
                         { return method.param == DepthPeeling::K_BUFFER ? "KBuffer" : "PeelPasses"; });

TEST(DepthPeelingMethods, KBufferKeepsTheLayersPeelPassesKeepInADenseCloud)
{
    // 3000 spheres in a cube, about ten deep at a pixel: beyond the 4 layers kept, so both methods
    // drop the same fragments. The k-buffer keeps each layer's colour in 8 bits, the passes in
    // half floats: a channel may differ by 2; the depth left behind is the same nearest layer.
    // Occlusion culling (chunks of 32) skips what lies behind the farthest layer of full lists,
    // which the k-buffer pass writes as depth: the picture must be that of the unculled cloud.
    std::mt19937 random(7);
    std::uniform_real_distribution<float> coordinate(-1.8f, 1.8f);
    std::uniform_int_distribution<int> channel(30, 240);
    std::vector<SphereSpec> spheres;
    for (int i = 0; i < 3000; ++i)
        spheres.push_back({osg::Vec3(coordinate(random), coordinate(random), coordinate(random)), 0.16f,
                           osg::Vec4ub(channel(random), channel(random), channel(random), 255)});
    Renderer renderer{160, 120};
    renderer.setClearColor(BACKGROUND);
    osgGlyphs::GlyphCullingStatistics culled;
    auto render = [&](DepthPeeling::Method method, unsigned int layers,
                      osgGlyphs::GlyphCulling culling = osgGlyphs::GlyphCulling::Occlusion)
    {
        osg::ref_ptr<GlyphCloud> cloud = createSphereCloud(spheres, true);
        cloud->setOpacity(0.5f);
        cloud->setCulling(culling);
        cloud->setCullingChunkSize(32);
        osg::ref_ptr<DepthPeeling> peeling = new DepthPeeling;
        peeling->setMethod(method);
        peeling->setNumLayers(layers);
        peeling->addChild(cloud.get());
        const Frame frame = renderer.render(peeling.get());
        culled = cloud->getCullingStatistics(0);
        return frame;
    };
    const Frame kBuffer = render(DepthPeeling::K_BUFFER, 4);
    const osgGlyphs::GlyphCullingStatistics kBufferCulled = culled;
    const Frame unculled = render(DepthPeeling::K_BUFFER, 4, osgGlyphs::GlyphCulling::Off);
    const Frame passes = render(DepthPeeling::PEEL_PASSES, 4);
    saveFrame(kBuffer, "peeling_dense_kbuffer");

    int covered = 0, colorMismatches = 0, depthMismatches = 0;
    for (int y = 0; y < kBuffer.height(); ++y)
        for (int x = 0; x < kBuffer.width(); ++x)
        {
            covered += kBuffer.isCovered(x, y) ? 1 : 0;
            const osg::Vec4ub a = kBuffer.colorAt(x, y), b = passes.colorAt(x, y);
            for (int c = 0; c < 3; ++c)
                if (std::abs(a[c] - b[c]) > COLOR_TOLERANCE)
                {
                    if (colorMismatches++ < 5)
                        ADD_FAILURE() << "pixel (" << x << ", " << y << ") channel " << c << ": k-buffer "
                                      << int(a[c]) << ", passes " << int(b[c]);
                    break;
                }
            if (std::abs(kBuffer.depthAt(x, y) - passes.depthAt(x, y)) > 1.0e-6f ||
                kBuffer.depthAt(x, y) != unculled.depthAt(x, y))
                ++depthMismatches;
        }
    EXPECT_EQ(colorMismatches, 0);
    EXPECT_EQ(depthMismatches, 0);
    EXPECT_EQ(countDifferentPixels(kBuffer, unculled), 0);
    EXPECT_GT(covered, kBuffer.width() * kBuffer.height() / 5);
    EXPECT_LT(kBufferCulled.glyphsSubmitted, spheres.size() * 9 / 10) << "culling skipped nothing";
    // The fifth and later layers show with 8 kept: the cloud is deeper than 4 layers.
    EXPECT_GT(countDifferentPixels(kBuffer, render(DepthPeeling::K_BUFFER, 8)), covered / 4);
}
