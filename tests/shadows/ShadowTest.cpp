// Glyphs under osgShadow: a sphere glyph casts the shadow a tessellated sphere casts on a ground
// plane, a vector glyph the shadow of a tessellated cylinder, and a sphere glyph receives a box's
// shadow as a tessellated sphere does, with osgShadow::ShadowMap and ViewDependentShadowMap
// (perspective and orthographic shadow maps).

#include "RenderHarness.h"

#include <osgGlyphs/GlyphCloud>
#include <osgGlyphs/GlyphStateCache>

#include <osg/Geode>
#include <osg/LightSource>
#include <osg/ShapeDrawable>
#include <osgShadow/ShadowMap>
#include <osgShadow/ShadowedScene>
#include <osgShadow/ViewDependentShadowMap>

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

using namespace osgGlyphsTest;
using osgGlyphs::GlyphCloud;
using osgGlyphs::GlyphShape;

namespace
{

const int SIZE = 320;
const unsigned int CASTS = 0x1, RECEIVES = 0x2;
const osg::Vec3 SPHERE_CENTRE(0.0f, 0.0f, 1.6f);
const float SPHERE_RADIUS = 0.8f;
const osg::Vec4 RED(1.0f, 0.0f, 0.0f, 1.0f);
/** Towards the light, from above and to the side, so that shadows fall beside their casters. */
const osg::Vec3 TO_LIGHT = osg::Vec3(1.0f, 0.3f, 1.5f) / osg::Vec3(1.0f, 0.3f, 1.5f).length();

enum class Technique
{
    ShadowMap,
    ViewDependent,
    ViewDependentOrthographic
};

std::string techniqueName(Technique technique)
{
    switch (technique)
    {
    case Technique::ShadowMap:
        return "ShadowMap";
    case Technique::ViewDependent:
        return "ViewDependent";
    default:
        return "ViewDependentOrthographic";
    }
}

osg::ref_ptr<osg::Node> shapeNode(osg::Shape* shape, const osg::Vec4& color, unsigned int mask)
{
    osg::ref_ptr<osg::TessellationHints> hints = new osg::TessellationHints;
    hints->setDetailRatio(8.0f);
    osg::ref_ptr<osg::ShapeDrawable> drawable = new osg::ShapeDrawable(shape, hints.get());
    drawable->setColor(color);
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    geode->addDrawable(drawable.get());
    geode->setNodeMask(mask);
    return geode;
}

osg::ref_ptr<osg::Node> groundPlane()
{
    return shapeNode(new osg::Box(osg::Vec3(0.0f, 0.0f, -0.05f), 12.0f, 12.0f, 0.1f),
                     osg::Vec4(0.8f, 0.8f, 0.8f, 1.0f), RECEIVES);
}

osg::ref_ptr<GlyphCloud> glyphCloud(GlyphShape shape, const osg::Vec3& position, const osg::Vec3& vector,
                                    float radius)
{
    osg::ref_ptr<GlyphCloud> cloud = new GlyphCloud;
    cloud->setShape(shape);
    cloud->setPositions(new osg::Vec3Array(1, &position));
    cloud->setVectors(new osg::Vec3Array(1, &vector));
    cloud->setRadii(new osg::FloatArray(1, &radius));
    const osg::Vec4ub red(255, 0, 0, 255);
    cloud->setColors(new osg::Vec4ubArray(1, &red));
    cloud->setLit(true);
    return cloud;
}

osg::ref_ptr<osg::Node> asNode(osg::Drawable* drawable)
{
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    geode->addDrawable(drawable);
    geode->setNodeMask(CASTS | RECEIVES);
    return geode;
}

/** The objects under a ShadowedScene with light 0 shining along TO_LIGHT; glyphs receive. */
osg::ref_ptr<osg::Node> shadowed(Technique technique, const std::vector<osg::ref_ptr<osg::Node>>& objects)
{
    osg::ref_ptr<osgShadow::ShadowedScene> scene = new osgShadow::ShadowedScene;
    scene->setCastsShadowTraversalMask(CASTS);
    scene->setReceivesShadowTraversalMask(RECEIVES);
    // ViewDependentShadowMap's own shaders (ShaderHint) do not compile in core GLSL 1.30+ (a
    // non-constant gl_TexCoord index): tessellated shapes receive through fixed-function texturing.
    osgShadow::ShadowSettings* settings = scene->getShadowSettings();
    if (technique == Technique::ShadowMap)
        scene->setShadowTechnique(new osgShadow::ShadowMap);
    else
    {
        if (technique == Technique::ViewDependentOrthographic)
            settings->setShadowMapProjectionHint(osgShadow::ShadowSettings::ORTHOGRAPHIC_SHADOW_MAP);
        scene->setShadowTechnique(new osgShadow::ViewDependentShadowMap);
    }
    osgGlyphs::setGlyphShadows(*scene->getOrCreateStateSet(), true);

    osg::ref_ptr<osg::LightSource> lightSource = new osg::LightSource;
    osg::Light* light = lightSource->getLight();
    light->setLightNum(0);
    light->setPosition(osg::Vec4(TO_LIGHT, 0.0f));
    light->setAmbient(osg::Vec4(0.2f, 0.2f, 0.2f, 1.0f));
    light->setDiffuse(osg::Vec4(0.8f, 0.8f, 0.8f, 1.0f));
    light->setSpecular(osg::Vec4(0.0f, 0.0f, 0.0f, 1.0f));
    scene->addChild(lightSource.get());
    for (const osg::ref_ptr<osg::Node>& object : objects)
        scene->addChild(object.get());
    return scene;
}

Frame render(osg::Node* scene)
{
    Renderer renderer(SIZE, SIZE);
    renderer.getViewer()->setLightingMode(osg::View::NO_LIGHT);
    renderer.getViewer()->getCamera()->setComputeNearFarMode(
        osg::CullSettings::COMPUTE_NEAR_FAR_USING_BOUNDING_VOLUMES);
    renderer.setClearColor(osg::Vec4(0.0f, 0.0f, 0.3f, 1.0f));
    renderer.setLookAt(osg::Vec3d(0.0, -6.0, 9.0), osg::Vec3d(0.0, 0.0, 0.6), osg::Vec3d(0.0, 0.0, 1.0));
    return renderer.render(scene);
}

using Mask = std::vector<bool>;

Mask maskOf(const Frame& frame, const std::function<bool(const osg::Vec4ub&)>& test)
{
    Mask mask(SIZE * SIZE);
    for (int y = 0; y < SIZE; ++y)
        for (int x = 0; x < SIZE; ++x)
            mask[y * SIZE + x] = test(frame.colorAt(x, y));
    return mask;
}

/** Whether the pixel shows the ground plane's top (z = 0), by its depth. */
bool showsPlane(const Frame& frame, int x, int y)
{
    osg::Vec3d origin, direction;
    frame.pixelRay(x + 0.5, y + 0.5, origin, direction);
    if (direction.z() >= 0.0)
        return false;
    const osg::Vec3d onPlane = origin - direction * (origin.z() / direction.z());
    return std::abs(frame.depthAt(x, y) - frame.windowDepth(onPlane)) < 1e-4;
}

/** The pixels of the plane in shadow: darker than the lit plane. */
Mask planeShadow(const Frame& frame)
{
    Mask plane(SIZE * SIZE);
    int lit = 0;
    for (int y = 0; y < SIZE; ++y)
        for (int x = 0; x < SIZE; ++x)
            if ((plane[y * SIZE + x] = showsPlane(frame, x, y)))
                lit = std::max<int>(lit, frame.colorAt(x, y).g());
    Mask shadow(SIZE * SIZE);
    for (int y = 0; y < SIZE; ++y)
        for (int x = 0; x < SIZE; ++x)
            shadow[y * SIZE + x] = plane[y * SIZE + x] && frame.colorAt(x, y).g() < 0.7 * lit;
    return shadow;
}

/** The pixels of the red sphere that a shadow darkens, among those where light falls steeply
 * (eligible): darker than in the frame without the shadow. */
Mask darkenedSphere(const Frame& shadowedFrame, const Frame& litFrame, const Mask& eligible)
{
    Mask mask(SIZE * SIZE);
    for (int y = 0; y < SIZE; ++y)
        for (int x = 0; x < SIZE; ++x)
            mask[y * SIZE + x] =
                eligible[y * SIZE + x] && shadowedFrame.colorAt(x, y).r() < 0.8 * litFrame.colorAt(x, y).r();
    return mask;
}

/** The pixels of the glyph sphere where light falls steeply: the diffuse term outweighs the
 * ambient, so that a shadow darkens them clearly whether it takes the ambient too
 * (fixed-function texturing) or not (the glyphs, as osgShadow's shaders). */
Mask steeplyLit(const Frame& litGlyph)
{
    return maskOf(litGlyph, [](const osg::Vec4ub& c) { return c.r() > 160 && c.g() < 60; });
}

int count(const Mask& mask)
{
    return static_cast<int>(std::count(mask.begin(), mask.end(), true));
}

double intersectionOverUnion(const Mask& a, const Mask& b)
{
    int both = 0, either = 0;
    for (std::size_t i = 0; i < a.size(); ++i)
    {
        both += a[i] && b[i];
        either += a[i] || b[i];
    }
    return either ? double(both) / either : 1.0;
}

class GlyphShadows : public ::testing::TestWithParam<Technique>
{
protected:
    std::string name(const std::string& what) const
    {
        return "shadows_" + techniqueName(GetParam()) + "_" + what;
    }
};

TEST_P(GlyphShadows, SphereGlyphCastsTheShadowOfATessellatedSphere)
{
    const Frame glyph = render(shadowed(
        GetParam(),
        {groundPlane(), asNode(glyphCloud(GlyphShape::Sphere, SPHERE_CENTRE, osg::Vec3(), SPHERE_RADIUS))}));
    const Frame tessellated =
        render(shadowed(GetParam(), {groundPlane(), shapeNode(new osg::Sphere(SPHERE_CENTRE, SPHERE_RADIUS),
                                                              RED, CASTS | RECEIVES)}));
    saveFrame(glyph, name("sphere_glyph"));
    saveFrame(tessellated, name("sphere_tessellated"));
    const Mask expected = planeShadow(tessellated), actual = planeShadow(glyph);
    ASSERT_GT(count(expected), 2000) << "the tessellated sphere casts no shadow to compare with";
    RecordProperty("iou", std::to_string(intersectionOverUnion(actual, expected)));
    EXPECT_GE(intersectionOverUnion(actual, expected), 0.98)
        << count(actual) << " shadowed pixels, " << count(expected) << " expected";
}

TEST_P(GlyphShadows, CylinderGlyphCastsTheShadowOfATessellatedCylinder)
{
    const osg::Vec3 axis(0.6f, 0.8f, 0.0f);
    const float length = 2.0f, radius = 0.4f;
    const Frame glyph = render(shadowed(
        GetParam(),
        {groundPlane(), asNode(glyphCloud(GlyphShape::Cylinder, SPHERE_CENTRE, axis * length, radius))}));
    osg::ref_ptr<osg::Cylinder> cylinder = new osg::Cylinder(SPHERE_CENTRE, radius, length);
    osg::Quat rotation;
    rotation.makeRotate(osg::Vec3(0.0f, 0.0f, 1.0f), axis);
    cylinder->setRotation(rotation);
    const Frame tessellated =
        render(shadowed(GetParam(), {groundPlane(), shapeNode(cylinder.get(), RED, CASTS | RECEIVES)}));
    saveFrame(glyph, name("cylinder_glyph"));
    saveFrame(tessellated, name("cylinder_tessellated"));
    const Mask expected = planeShadow(tessellated), actual = planeShadow(glyph);
    ASSERT_GT(count(expected), 1000) << "the tessellated cylinder casts no shadow to compare with";
    RecordProperty("iou", std::to_string(intersectionOverUnion(actual, expected)));
    EXPECT_GE(intersectionOverUnion(actual, expected), 0.98)
        << count(actual) << " shadowed pixels, " << count(expected) << " expected";
}

/** A box between the light and the sphere's upper side, casting or not. */
osg::ref_ptr<osg::Node> occluder(bool casts)
{
    const osg::Vec3 centre = SPHERE_CENTRE + TO_LIGHT * 2.2f + osg::Vec3(0.0f, 0.35f, 0.0f);
    return shapeNode(new osg::Box(centre, 0.7f), osg::Vec4(0.2f, 0.9f, 0.2f, 1.0f),
                     casts ? CASTS | RECEIVES : RECEIVES);
}

TEST_P(GlyphShadows, SphereGlyphReceivesABoxShadowLikeATessellatedSphere)
{
    auto glyphScene = [&](bool boxCasts)
    {
        return render(shadowed(
            GetParam(), {groundPlane(), occluder(boxCasts),
                         asNode(glyphCloud(GlyphShape::Sphere, SPHERE_CENTRE, osg::Vec3(), SPHERE_RADIUS))}));
    };
    auto tessellatedScene = [&](bool boxCasts)
    {
        return render(shadowed(
            GetParam(), {groundPlane(), occluder(boxCasts),
                         shapeNode(new osg::Sphere(SPHERE_CENTRE, SPHERE_RADIUS), RED, CASTS | RECEIVES)}));
    };
    const Frame glyph = glyphScene(true), glyphLit = glyphScene(false);
    const Frame tessellated = tessellatedScene(true), tessellatedLit = tessellatedScene(false);
    saveFrame(glyph, name("receive_glyph"));
    saveFrame(glyphLit, name("receive_glyph_unshadowed"));
    saveFrame(tessellated, name("receive_tessellated"));
    const Mask eligible = steeplyLit(glyphLit);
    const Mask expected = darkenedSphere(tessellated, tessellatedLit, eligible),
               actual = darkenedSphere(glyph, glyphLit, eligible);
    ASSERT_GT(count(expected), 150) << "the box shadows no part of the tessellated sphere";
    // Tolerance: the shadow's edge on the sphere is the shadow map's, sampled at slightly
    // different points of a tessellated and an exact surface.
    RecordProperty("iou", std::to_string(intersectionOverUnion(actual, expected)));
    EXPECT_GE(intersectionOverUnion(actual, expected), 0.95)
        << count(actual) << " darkened pixels, " << count(expected) << " expected";
}

TEST_P(GlyphShadows, SphereGlyphDoesNotShadowItsOwnLitSide)
{
    osg::ref_ptr<osg::Node> unshadowedScene =
        asNode(glyphCloud(GlyphShape::Sphere, SPHERE_CENTRE, osg::Vec3(), SPHERE_RADIUS));
    const Frame shadowedFrame = render(shadowed(GetParam(), {groundPlane(), unshadowedScene}));
    osg::ref_ptr<osg::Node> notReceiving = shadowed(GetParam(), {groundPlane(), unshadowedScene});
    osgGlyphs::setGlyphShadows(*notReceiving->getOrCreateStateSet(), false);
    const Frame litFrame = render(notReceiving.get());
    const Mask darkened = darkenedSphere(shadowedFrame, litFrame, steeplyLit(litFrame));
    EXPECT_LE(count(darkened), 10) << "the glyph shadows itself";
}

/** The mean and the largest distance from expected of the green channel over the mask. */
std::pair<double, int> greenOver(const Frame& frame, const Mask& mask, int expected)
{
    double sum = 0.0;
    int worst = 0, n = 0;
    for (int y = 0; y < SIZE; ++y)
        for (int x = 0; x < SIZE; ++x)
            if (mask[y * SIZE + x])
            {
                const int green = frame.colorAt(x, y).g();
                sum += green;
                worst = std::max(worst, std::abs(green - expected));
                ++n;
            }
    return {n ? sum / n : -1.0, worst};
}

TEST_P(GlyphShadows, SurfaceShadingLightsAPlaneAndKeepsTheAmbientInItsShadow)
{
    if (GetParam() == Technique::ShadowMap)
        GTEST_SKIP() << "osgShadow::ShadowMap's own program shades ordinary geometry below it";
    auto scene = [&]
    {
        return shadowed(GetParam(), {groundPlane(), shapeNode(new osg::Sphere(SPHERE_CENTRE, SPHERE_RADIUS),
                                                              RED, CASTS | RECEIVES)});
    };
    const Frame fixedFunction = render(scene().get());
    osg::ref_ptr<osg::Node> shadedScene = scene();
    osgGlyphs::setSurfaceShading(*shadedScene->getOrCreateStateSet());
    const Frame shaded = render(shadedScene.get());
    saveFrame(shaded, name("surface_shading"));

    const Mask expected = planeShadow(fixedFunction), actual = planeShadow(shaded);
    ASSERT_GT(count(expected), 2000) << "the tessellated sphere casts no shadow to compare with";
    EXPECT_GE(intersectionOverUnion(actual, expected), 0.98)
        << count(actual) << " shadowed pixels, " << count(expected) << " expected";

    // The plane's grey 0.8 under the glyph material's ambient 0.2, light 0's ambient 0.2 and
    // diffuse 0.8 (no specular): 0.8 * 0.4 in the shadow, 0.8 * (0.4 + 0.8 N.L) in the light.
    const int TOLERANCE = 3; // rounding to 8 bits, and the shadow map's filtered edge left out
    const int inShadow = int(std::lround(255.0 * 0.8 * 0.4));
    const int inLight = int(std::lround(255.0 * 0.8 * (0.4 + 0.8 * TO_LIGHT.z())));
    Mask shadowInside(SIZE * SIZE), lit(SIZE * SIZE);
    for (int y = 2; y < SIZE - 2; ++y)
        for (int x = 2; x < SIZE - 2; ++x)
        {
            bool allShadow = true, allLit = true;
            for (int dy = -2; dy <= 2; ++dy)
                for (int dx = -2; dx <= 2; ++dx)
                {
                    const int i = (y + dy) * SIZE + x + dx;
                    allShadow = allShadow && actual[i];
                    allLit = allLit && showsPlane(shaded, x + dx, y + dy) && !actual[i];
                }
            shadowInside[y * SIZE + x] = allShadow;
            lit[y * SIZE + x] = allLit;
        }
    ASSERT_GT(count(shadowInside), 1000);
    ASSERT_GT(count(lit), 10000);
    const auto shadowGreen = greenOver(shaded, shadowInside, inShadow);
    const auto litGreen = greenOver(shaded, lit, inLight);
    EXPECT_LE(shadowGreen.second, TOLERANCE) << "mean " << shadowGreen.first << ", expected " << inShadow;
    EXPECT_LE(litGreen.second, TOLERANCE) << "mean " << litGreen.first << ", expected " << inLight;
}

/** The same view through a projection that mixes eye-space axes, as light-space perspective
 * shadow maps (ViewDependentShadowMap's default) do: view * rotation^-1 and rotation *
 * projection. A sphere glyph covers the same pixels at the same depths. */
TEST(GlyphProjection, SphereGlyphIsExactUnderAProjectionThatMixesEyeAxes)
{
    osg::ref_ptr<osg::Node> scene =
        asNode(glyphCloud(GlyphShape::Sphere, SPHERE_CENTRE, osg::Vec3(), SPHERE_RADIUS));
    Renderer renderer(SIZE, SIZE);
    renderer.setLookAt(osg::Vec3d(0.0, -6.0, 9.0), osg::Vec3d(0.0, 0.0, 0.6), osg::Vec3d(0.0, 0.0, 1.0));
    const Frame standard = renderer.render(scene.get());
    osg::Camera* camera = renderer.getViewer()->getCamera();
    const osg::Matrixd mixing = osg::Matrixd::rotate(osg::DegreesToRadians(25.0), osg::Vec3d(1.0, 0.4, 0.2));
    camera->setViewMatrix(camera->getViewMatrix() * osg::Matrixd::inverse(mixing));
    camera->setProjectionMatrix(mixing * camera->getProjectionMatrix());
    const Frame mixed = renderer.render(scene.get());
    saveFrame(mixed, "shadows_mixed_projection");
    int covered = 0, coverageDiffers = 0, depthDiffers = 0;
    for (int y = 0; y < SIZE; ++y)
        for (int x = 0; x < SIZE; ++x)
        {
            covered += standard.isCovered(x, y);
            coverageDiffers += standard.isCovered(x, y) != mixed.isCovered(x, y);
            depthDiffers += standard.isCovered(x, y) && mixed.isCovered(x, y) &&
                            std::abs(standard.depthAt(x, y) - mixed.depthAt(x, y)) > 1e-6;
        }
    ASSERT_GT(covered, 2000);
    EXPECT_LE(coverageDiffers, covered / 200) << "of " << covered << " covered pixels";
    EXPECT_LE(depthDiffers, covered / 200) << "of " << covered << " covered pixels";
}

TEST(GlyphShadowsState, AUnitWithoutTexGenPlanesReceivesNothing)
{
    osg::ref_ptr<osg::StateSet> stateSet = new osg::StateSet;
    osgGlyphs::setGlyphShadows(*stateSet, true, 8);
    const osg::StateSet::DefinePair* define = stateSet->getDefinePair(osgGlyphs::GLYPH_SHADOWS_DEFINE);
    ASSERT_NE(define, nullptr);
    EXPECT_FALSE(define->second & osg::StateAttribute::ON);
    EXPECT_EQ(stateSet->getUniform("osgGlyphs_shadowMap"), nullptr);

    osgGlyphs::setGlyphShadows(*stateSet, true, 3);
    int unit = -1;
    ASSERT_NE(stateSet->getUniform("osgGlyphs_shadowMap"), nullptr);
    stateSet->getUniform("osgGlyphs_shadowMap")->get(unit);
    EXPECT_EQ(unit, 3);
    EXPECT_TRUE(stateSet->getDefinePair(osgGlyphs::GLYPH_SHADOWS_DEFINE)->second & osg::StateAttribute::ON);

    osgGlyphs::setGlyphShadows(*stateSet, false);
    EXPECT_EQ(stateSet->getUniform("osgGlyphs_shadowMap"), nullptr);
    EXPECT_FALSE(stateSet->getDefinePair(osgGlyphs::GLYPH_SHADOWS_DEFINE)->second & osg::StateAttribute::ON);
}

INSTANTIATE_TEST_SUITE_P(Techniques, GlyphShadows,
                         ::testing::Values(Technique::ShadowMap, Technique::ViewDependent,
                                           Technique::ViewDependentOrthographic),
                         [](const ::testing::TestParamInfo<Technique>& instance)
                         { return techniqueName(instance.param); });

} // namespace
