// The drawing techniques against the default: the exact ones (instanced, point sprite) must
// match the geometry-shader technique pixel for pixel; the others must draw what their method
// draws (the paper's billboards, tessellated polygons, textured sprites, single points).
// texture-multi's pre-lit sprites are checked against their analytic circle and colours,
// against texture-blend and against a baseline.

#include "GlyphTestScenes.h"

#include <osgGlyphs/GlyphCloud>
#include <osgGlyphs/GlyphStateCache>
#include <osgGlyphsPaper/Techniques>

#include <osg/GraphicsContext>
#include <osg/Texture2DArray>

#include <algorithm>
#include <cmath>

using namespace osgGlyphsTest;
using osgGlyphs::ColorMap;
using osgGlyphs::GlyphCloud;
using osgGlyphs::GlyphShape;

namespace
{

/** The paper's techniques, by name, beside osgGlyphs' own. */
const bool PAPER_TECHNIQUES_REGISTERED = (osgGlyphsPaper::registerTechniques(), true);

}

namespace
{

/** A few lit glyphs of the shape, crossing each other and a slab. */
osg::ref_ptr<GlyphCloud> createScene(GlyphShape shape)
{
    osg::ref_ptr<osg::Vec3Array> positions = new osg::Vec3Array, vectors = new osg::Vec3Array;
    osg::ref_ptr<osg::FloatArray> scalars = new osg::FloatArray;
    for (int i = 0; i < 9; ++i)
    {
        const float angle = 0.7f * i;
        positions->push_back(
            osg::Vec3(-2.4f + 0.6f * i, 0.4f * std::sin(2.0f * angle), 0.9f * std::cos(angle)));
        vectors->push_back(osg::Vec3(std::cos(angle), std::sin(angle), 0.5f) * 1.4f);
        scalars->push_back(float(i));
    }
    osg::ref_ptr<GlyphCloud> cloud = new GlyphCloud;
    cloud->setShape(shape);
    cloud->setPositions(positions.get());
    cloud->setVectors(vectors.get());
    cloud->setScalars(scalars.get());
    cloud->setRadius(shape == GlyphShape::Sphere ? 0.5f : 0.25f);
    return cloud;
}

struct Comparison
{
    int differingColor = 0;
    int differingDepth = 0;
    int coveredBoth = 0;
    int coveredEither = 0;
};

Comparison compare(const Frame& a, const Frame& b, int colorTolerance, float depthTolerance)
{
    Comparison result;
    for (int y = 0; y < a.height(); ++y)
    {
        for (int x = 0; x < a.width(); ++x)
        {
            const bool inA = a.isCovered(x, y), inB = b.isCovered(x, y);
            result.coveredBoth += inA && inB ? 1 : 0;
            result.coveredEither += inA || inB ? 1 : 0;
            if (!colorNear(a, x, y, b.colorAt(x, y), colorTolerance))
                ++result.differingColor;
            if (std::fabs(a.depthAt(x, y) - b.depthAt(x, y)) > depthTolerance)
                ++result.differingDepth;
        }
    }
    return result;
}

class Techniques : public ::testing::TestWithParam<GlyphShape>
{
protected:
    Frame render(const std::string& technique)
    {
        osg::ref_ptr<GlyphCloud> cloud = createScene(GetParam());
        cloud->setTechnique(osgGlyphs::createTechnique(technique).get());
        const Frame frame = renderer.render(group({cloud.get()}).get());
        saveFrame(frame, std::string("technique_") + technique + "_" + osgGlyphs::getShapeName(GetParam()));
        return frame;
    }

    Renderer renderer{160, 120};
};

}

TEST_P(Techniques, ExactTechniquesDrawTheSamePixels)
{
    const Frame reference = render("geometry-shader");
    for (const std::string technique : {"instanced", "point-sprite"})
    {
        // Rays rebuilt per fragment (point sprites) differ from interpolated ones in the last bits.
        const Comparison comparison = compare(render(technique), reference, 1, 1e-6f);
        EXPECT_GT(comparison.coveredBoth, 800) << technique;
        EXPECT_LE(comparison.differingColor, comparison.coveredBoth / 200) << technique;
        EXPECT_LE(comparison.differingDepth, comparison.coveredBoth / 200) << technique;
    }
}

TEST_P(Techniques, PolygonsApproximateTheExactGlyphs)
{
    const Frame reference = render("geometry-shader");
    osg::ref_ptr<GlyphCloud> cloud = createScene(GetParam());
    osg::ref_ptr<osgGlyphsPaper::PolygonsTechnique> polygons = new osgGlyphsPaper::PolygonsTechnique;
    polygons->setResolution(32, 16);
    cloud->setTechnique(polygons.get());
    const Frame fine = renderer.render(group({cloud.get()}).get());
    const Comparison comparison = compare(fine, reference, 255, 1.0f);
    EXPECT_GT(double(comparison.coveredBoth) / comparison.coveredEither, 0.97);
    // The default 8 x 4 tessellation is visibly coarser.
    const Comparison coarse = compare(render("polygons"), reference, 255, 1.0f);
    EXPECT_LT(coarse.coveredBoth, comparison.coveredBoth);
}

TEST_P(Techniques, SpriteTechniquesCoverRoughlyTheGlyphs)
{
    const Frame reference = render("geometry-shader");
    int referenceCovered = 0;
    for (int y = 0; y < reference.height(); ++y)
        for (int x = 0; x < reference.width(); ++x)
            referenceCovered += reference.isCovered(x, y) ? 1 : 0;
    for (const std::string technique : {"paper-quad", "texture-blend", "texture-multi"})
    {
        if (!osgGlyphs::createTechnique(technique)->supportsShape(GetParam()))
            continue;
        const Comparison comparison = compare(render(technique), reference, 255, 1.0f);
        EXPECT_GT(double(comparison.coveredBoth) / referenceCovered, 0.6) << technique;
    }
}

TEST_P(Techniques, ANewColourRangeReachesEveryTechnique)
{
    // A narrower range re-quantises the scalars; techniques that copy the packed words into
    // their primitives (paper-quad) must copy them again.
    for (const std::string& name : osgGlyphs::getTechniqueNames())
    {
        osg::ref_ptr<GlyphCloud> changed = createScene(GetParam()), fresh = createScene(GetParam());
        changed->setTechnique(osgGlyphs::createTechnique(name).get());
        const Frame first = renderer.render(group({changed.get()}).get());
        changed->setScalarRange(2.0f, 5.0f);
        fresh->setScalarRange(2.0f, 5.0f);
        fresh->setTechnique(osgGlyphs::createTechnique(name).get());
        const Comparison comparison = compare(renderer.render(group({changed.get()}).get()),
                                              renderer.render(group({fresh.get()}).get()), 0, 0.0f);
        EXPECT_GT(comparison.coveredBoth, 0) << name;
        EXPECT_EQ(comparison.differingColor, 0) << name;
        if (name != "points-floor") // the floor draws the cloud's one colour
        {
            EXPECT_GT(compare(first, renderer.render(group({fresh.get()}).get()), 0, 1.0f).differingColor, 0)
                << name << ": the range should change some colours";
        }
    }
}

TEST_P(Techniques, PointsFloorDrawsOnePixelPerGlyph)
{
    const Frame frame = render("points-floor");
    int covered = 0;
    for (int y = 0; y < frame.height(); ++y)
        for (int x = 0; x < frame.width(); ++x)
            covered += frame.isCovered(x, y) ? 1 : 0;
    EXPECT_GE(covered, 7); // nine glyphs, some may share a pixel
    EXPECT_LE(covered, 9);
}

TEST_P(Techniques, DisplayListsDrawWhatBufferObjectsDraw)
{
    for (const std::string& name : osgGlyphs::getTechniqueNames())
    {
        osg::ref_ptr<GlyphCloud> buffers = createScene(GetParam()), lists = createScene(GetParam());
        for (GlyphCloud* cloud : {buffers.get(), lists.get()})
            cloud->setTechnique(osgGlyphs::createTechnique(name).get());
        // GL compiles no instanced draw into a display list: those techniques refuse them and
        // draw from client arrays.
        const bool supported = lists->getEffectiveTechnique()->supportsDisplayLists();
        EXPECT_EQ(lists->getSupportsDisplayList(), supported) << name;
        lists->setUseVertexBufferObjects(false);
        if (supported)
            lists->setUseDisplayList(true);
        const Frame fromBuffers = renderer.render(group({buffers.get()}).get());
        const Comparison comparison =
            compare(renderer.render(group({lists.get()}).get()), fromBuffers, 0, 0.0f);
        EXPECT_GT(comparison.coveredBoth, 0) << name;
        EXPECT_EQ(comparison.coveredBoth, comparison.coveredEither) << name;
        EXPECT_EQ(comparison.differingColor, 0) << name;
        EXPECT_EQ(comparison.differingDepth, 0) << name;
    }
}

// Every technique decodes compressed positions: a cloud drawn from its 16-bit positions draws the
// pixels and depths of one drawn from the same grid points as floats. The glyphs sit far from
// their origin, so that a grid offset left out would move them.
TEST_P(Techniques, CompressedPositionsDrawTheirGridPointsExactly)
{
    const osg::Vec3 shift(30.0f, -12.0f, 5.0f);
    for (const std::string& name : osgGlyphs::getTechniqueNames())
    {
        osg::ref_ptr<GlyphCloud> compressed = createScene(GetParam()), floats = createScene(GetParam());
        for (GlyphCloud* cloud : {compressed.get(), floats.get()})
        {
            osg::ref_ptr<osg::Vec3Array> shifted = new osg::Vec3Array(*cloud->getPositions());
            for (osg::Vec3& p : *shifted)
                p += shift;
            cloud->setPositions(shifted.get());
            cloud->setOrigin(-shift);
            cloud->setTechnique(osgGlyphs::createTechnique(name).get());
        }
        compressed->setCompressedPositions(true);
        floats->setPositions(compressed->computeDrawnPositions().get());
        const Frame expected = renderer.render(group({floats.get()}).get());
        const Comparison comparison =
            compare(renderer.render(group({compressed.get()}).get()), expected, 0, 0.0f);
        EXPECT_GT(comparison.coveredBoth, name == "points-floor" ? 6 : 300) << name;
        EXPECT_EQ(comparison.coveredBoth, comparison.coveredEither) << name;
        EXPECT_EQ(comparison.differingColor, 0) << name;
        EXPECT_EQ(comparison.differingDepth, 0) << name;
    }
}

TEST(TechniqueNames, EveryRegisteredNameCreatesItsTechnique)
{
    const std::vector<std::string> names = osgGlyphs::getTechniqueNames();
    EXPECT_EQ(names,
              std::vector<std::string>({"geometry-shader", "instanced", "point-sprite", "paper-quad",
                                        "polygons", "texture-blend", "texture-multi", "points-floor"}));
    for (const std::string& name : names)
        EXPECT_EQ(osgGlyphs::createTechnique(name)->getTechniqueName(), name);
    EXPECT_STREQ(osgGlyphs::createTechnique("default")->getTechniqueName(),
                 osgGlyphs::DEFAULT_GLYPH_TECHNIQUE);
    EXPECT_FALSE(osgGlyphs::createTechnique("raytrace").valid());
}

INSTANTIATE_TEST_SUITE_P(, Techniques,
                         ::testing::Values(GlyphShape::Sphere, GlyphShape::Cone, GlyphShape::Arrow,
                                           GlyphShape::Cylinder),
                         [](const ::testing::TestParamInfo<GlyphShape>& param)
                         { return std::string(osgGlyphs::getShapeName(param.param)); });

TEST(TechniqueSupport, UnsupportedShapesFallBackToTheDefault)
{
    for (GlyphShape shape : {GlyphShape::Sphere, GlyphShape::Cone, GlyphShape::Arrow, GlyphShape::Cylinder})
    {
        for (const std::string& technique : osgGlyphs::getTechniqueNames())
        {
            osg::ref_ptr<GlyphCloud> cloud = createScene(shape);
            cloud->setTechnique(osgGlyphs::createTechnique(technique).get());
            const bool supported = osgGlyphs::createTechnique(technique)->supportsShape(shape);
            EXPECT_EQ(cloud->getEffectiveTechnique()->getTechniqueName(),
                      supported ? technique : std::string(osgGlyphs::DEFAULT_GLYPH_TECHNIQUE))
                << technique << " " << osgGlyphs::getShapeName(shape);
        }
    }
    // The paper's textures are of spheres.
    for (const std::string technique : {"texture-blend", "texture-multi"})
    {
        EXPECT_TRUE(osgGlyphs::createTechnique(technique)->supportsShape(GlyphShape::Sphere));
        EXPECT_FALSE(osgGlyphs::createTechnique(technique)->supportsShape(GlyphShape::Cone));
    }
}

// ---------------------------------------------------------------------------------------------
// texture-multi: one pre-lit sprite per colour

namespace
{

/** texture-blend's lit sphere at r radii from the sprite's centre: Blinn-Phong under a
 * headlight with GlyphCloud's default material, saturated (1) near the centre. */
double spriteShade(double r)
{
    const double nz = std::sqrt(std::max(1.0 - r * r, 0.0));
    const double halfway = (nz + 1.0) / std::sqrt(2.0 * (1.0 + nz));
    return std::min(0.2 + nz + 0.4 * std::pow(halfway, 48.0), 1.0);
}

osg::Vec4ub toColor(const osg::Vec4& color)
{
    auto channel = [](float value) { return static_cast<unsigned char>(std::lround(value * 255.0f)); };
    return osg::Vec4ub(channel(color.r()), channel(color.g()), channel(color.b()), 255);
}

/** Where a texture technique draws a sphere: a circle about its projected centre, of its
 * radius projected at its depth, in window pixels; and the colour of its sprite. */
struct ExpectedSprite
{
    osg::Vec2d center;
    double radius;
    osg::Vec4 color;

    double distance(int x, int y) const { return (osg::Vec2d(x + 0.5, y + 0.5) - center).length(); }
    int centerX() const { return static_cast<int>(std::floor(center.x())); }
    int centerY() const { return static_cast<int>(std::floor(center.y())); }
};

ExpectedSprite expectSprite(const Frame& frame, const osg::Vec3& center, float radius, const osg::Vec4& color)
{
    const osg::Vec3d window = frame.project(center);
    const double depth = -(osg::Vec3d(center) * frame.view).z();
    const double pixels = radius * frame.projection(1, 1) / depth * 0.5 * frame.height();
    return {osg::Vec2d(window.x(), window.y()), pixels, color};
}

struct ScalarSphere
{
    osg::Vec3 center;
    float radius;
    float scalar; // in [0, 63]
};

/** Apart, at different depths and off the axis; scalars on levels of the colour map. */
const std::vector<ScalarSphere> SCALAR_SPHERES = {{osg::Vec3(-3.0f, 1.5f, 0.9f), 0.6f, 0.0f},
                                                  {osg::Vec3(-1.5f, -1.0f, -0.7f), 0.5f, 9.0f},
                                                  {osg::Vec3(0.1f, 0.0f, 0.4f), 0.7f, 27.0f},
                                                  {osg::Vec3(1.7f, 2.0f, -1.0f), 0.6f, 45.0f},
                                                  {osg::Vec3(3.1f, -1.5f, 0.6f), 0.5f, 63.0f}};

/** The colour-map colour of texture-multi's layer for a scalar of [0, 63]. */
osg::Vec4 layerColor(const ColorMap& colorMap, float scalar)
{
    const float last = static_cast<float>(osgGlyphsPaper::TEXTURE_MULTI_COLORMAP_LEVELS - 1);
    return colorMap.getColor(std::round(scalar / 63.0f * last) / last);
}

class TextureMulti : public ::testing::Test
{
protected:
    osg::ref_ptr<GlyphCloud> createScalarSpheres(const std::string& technique = "texture-multi")
    {
        osg::ref_ptr<osg::Vec3Array> positions = new osg::Vec3Array;
        osg::ref_ptr<osg::FloatArray> radii = new osg::FloatArray, scalars = new osg::FloatArray;
        for (const ScalarSphere& sphere : SCALAR_SPHERES)
        {
            positions->push_back(sphere.center);
            radii->push_back(sphere.radius);
            scalars->push_back(sphere.scalar);
        }
        osg::ref_ptr<GlyphCloud> cloud = new GlyphCloud;
        cloud->setPositions(positions.get());
        cloud->setRadii(radii.get());
        cloud->setScalars(scalars.get());
        cloud->setScalarRange(0.0f, 63.0f);
        cloud->setTechnique(osgGlyphs::createTechnique(technique).get());
        return cloud;
    }

    std::vector<ExpectedSprite> expectScalarSprites(const Frame& frame, const ColorMap& colorMap) const
    {
        std::vector<ExpectedSprite> sprites;
        for (const ScalarSphere& sphere : SCALAR_SPHERES)
            sprites.push_back(
                expectSprite(frame, sphere.center, sphere.radius, layerColor(colorMap, sphere.scalar)));
        return sprites;
    }

    Renderer renderer{320, 240};
};

/** The colour under a sprite's centre, where its pre-lit shade is 1: the layer's colour. */
::testing::AssertionResult centerColorNear(const Frame& frame, const ExpectedSprite& sprite, int tolerance)
{
    return colorNear(frame, sprite.centerX(), sprite.centerY(), toColor(sprite.color), tolerance);
}

}

TEST_F(TextureMulti, ScalarSpheresAreLitCirclesInTheirLevelsColour)
{
    const Frame frame = renderer.render(group({createScalarSpheres().get()}).get());
    saveFrame(frame, "texture_multi_scalars");
    const std::vector<ExpectedSprite> sprites = expectScalarSprites(frame, *ColorMap::getBuiltin("viridis"));

    // Coverage: the analytic circles, but for pixels within 1 px of an edge (the mipmapped
    // circle mask is thresholded at half coverage).
    int uncoveredInside = 0, coveredOutside = 0, edge = 0;
    for (int y = 0; y < frame.height(); ++y)
    {
        for (int x = 0; x < frame.width(); ++x)
        {
            bool inside = false, outside = true;
            for (const ExpectedSprite& sprite : sprites)
            {
                inside = inside || sprite.distance(x, y) < sprite.radius - 1.0;
                outside = outside && sprite.distance(x, y) > sprite.radius + 1.0;
            }
            uncoveredInside += inside && !frame.isCovered(x, y) ? 1 : 0;
            coveredOutside += outside && frame.isCovered(x, y) ? 1 : 0;
            edge += !inside && !outside ? 1 : 0;
        }
    }
    EXPECT_EQ(uncoveredInside, 0);
    EXPECT_EQ(coveredOutside, 0);
    EXPECT_GT(edge, 300);

    for (const ExpectedSprite& sprite : sprites)
    {
        // The centre: the colour map's colour at the glyph's level (8-bit rounding, filtering).
        EXPECT_TRUE(centerColorNear(frame, sprite, 2));
        // Inside: that colour, pre-lit (8-bit texels, blurred by the mipmaps; 3 levels seen).
        int wrong = 0, checked = 0;
        for (int y = sprite.centerY() - 30; y <= sprite.centerY() + 30; ++y)
        {
            for (int x = sprite.centerX() - 30; x <= sprite.centerX() + 30; ++x)
            {
                const double r = sprite.distance(x, y) / sprite.radius;
                if (r > 0.85)
                    continue;
                ++checked;
                const osg::Vec4 lit = sprite.color * static_cast<float>(spriteShade(r));
                wrong += colorNear(frame, x, y, toColor(lit), 4) ? 0 : 1;
            }
        }
        EXPECT_GT(checked, 300);
        EXPECT_EQ(wrong, 0) << "of " << checked << " pixels of the sprite at " << sprite.center.x() << ", "
                            << sprite.center.y();
    }
}

TEST_F(TextureMulti, DrawsWhatTextureBlendDraws)
{
    // Same sprites, same circle, same lighting: only how the colour gets there differs (a
    // product of 8-bit texels against an 8-bit product, each mipmapped; 3 levels at most seen).
    const Frame multi = renderer.render(group({createScalarSpheres().get()}).get());
    const Frame blend = renderer.render(group({createScalarSpheres("texture-blend").get()}).get());
    saveFrame(blend, "texture_blend_scalars");
    const Comparison comparison = compare(multi, blend, 3, 0.0f);
    EXPECT_GT(comparison.coveredBoth, 4000);
    EXPECT_EQ(comparison.coveredBoth, comparison.coveredEither);
    EXPECT_EQ(comparison.differingColor, 0);
    EXPECT_EQ(comparison.differingDepth, 0);
}

TEST_F(TextureMulti, MatchesBaseline)
{
    const Frame frame = renderer.render(group({createScalarSpheres().get()}).get());
    Tolerance tolerance;
    tolerance.colorChannel = 2;
    tolerance.colorPixelBudget = 8;
    tolerance.depth = 1e-6f;
    tolerance.depthPixelBudget = 8;
    EXPECT_TRUE(matchesBaseline(frame, "technique_texture_multi", tolerance));
}

TEST_F(TextureMulti, RgbaColoursTakeTheNearestColourOfTheCube)
{
    // Four levels per channel: 0, 85, 170, 255.
    const std::vector<std::pair<osg::Vec4ub, osg::Vec4ub>> colors = {
        {osg::Vec4ub(255, 0, 0, 255), osg::Vec4ub(255, 0, 0, 255)},
        {osg::Vec4ub(0, 85, 170, 255), osg::Vec4ub(0, 85, 170, 255)},
        {osg::Vec4ub(200, 100, 30, 255), osg::Vec4ub(170, 85, 0, 255)},
        {osg::Vec4ub(40, 130, 220, 128), osg::Vec4ub(0, 170, 255, 255)},
        {osg::Vec4ub(250, 250, 250, 255), osg::Vec4ub(255, 255, 255, 255)}};
    std::vector<SphereSpec> spheres;
    for (size_t i = 0; i < colors.size(); ++i)
        spheres.push_back({SCALAR_SPHERES[i].center, SCALAR_SPHERES[i].radius, colors[i].first});
    osg::ref_ptr<GlyphCloud> cloud = createSphereCloud(spheres, true);
    cloud->setTechnique(new osgGlyphsPaper::TextureMultiTechnique);
    const Frame frame = renderer.render(group({cloud.get()}).get());
    saveFrame(frame, "texture_multi_rgba");
    for (size_t i = 0; i < colors.size(); ++i)
    {
        const osg::Vec4 expected =
            osg::Vec4(colors[i].second.r(), colors[i].second.g(), colors[i].second.b(), 255) / 255.0f;
        EXPECT_TRUE(
            centerColorNear(frame, expectSprite(frame, spheres[i].center, spheres[i].radius, expected), 2));
    }
}

TEST_F(TextureMulti, OneColourCloudsAreDrawnInExactlyTheirColour)
{
    const osg::Vec4 orange(0.9f, 0.4f, 0.1f, 1.0f), sky(0.2f, 0.6f, 0.9f, 1.0f), plum(0.5f, 0.1f, 0.4f, 1.0f);
    std::vector<osg::ref_ptr<GlyphCloud>> clouds;
    for (size_t i = 0; i < 3; ++i)
    {
        osg::ref_ptr<GlyphCloud> cloud = new GlyphCloud;
        cloud->setPositions(new osg::Vec3Array(1, &SCALAR_SPHERES[i].center));
        cloud->setRadius(SCALAR_SPHERES[i].radius);
        cloud->setColor(i == 1 ? sky : orange);
        cloud->setTechnique(new osgGlyphsPaper::TextureMultiTechnique);
        clouds.push_back(cloud);
    }
    EXPECT_EQ(clouds[0]->getVariantStateSet(), clouds[2]->getVariantStateSet()); // one texture per colour
    EXPECT_NE(clouds[0]->getVariantStateSet(), clouds[1]->getVariantStateSet());
    osg::ref_ptr<osg::Node> scene = group({clouds[0].get(), clouds[1].get(), clouds[2].get()});
    auto expectColors = [&](const Frame& frame, const std::vector<osg::Vec4>& expected)
    {
        for (size_t i = 0; i < 3; ++i)
            EXPECT_TRUE(centerColorNear(
                frame, expectSprite(frame, SCALAR_SPHERES[i].center, SCALAR_SPHERES[i].radius, expected[i]),
                2));
    };
    expectColors(renderer.render(scene.get()), {orange, sky, orange});
    clouds[2]->setColor(plum);
    expectColors(renderer.render(scene.get()), {orange, sky, plum});
}

TEST_F(TextureMulti, FollowsChangesOfTheColourMap)
{
    osg::ref_ptr<ColorMap> colorMap =
        new ColorMap("test", {osg::Vec4(1.0f, 0.0f, 0.0f, 1.0f), osg::Vec4(0.0f, 0.0f, 1.0f, 1.0f)});
    osg::ref_ptr<GlyphCloud> cloud = createScalarSpheres();
    cloud->setColorMap(colorMap.get());
    osg::ref_ptr<osg::Node> scene = group({cloud.get()});
    auto expectColors = [&](const Frame& frame)
    {
        for (const ExpectedSprite& sprite : expectScalarSprites(frame, *colorMap))
            EXPECT_TRUE(centerColorNear(frame, sprite, 2));
    };
    expectColors(renderer.render(scene.get()));
    colorMap->setColors({osg::Vec4(0.0f, 1.0f, 0.0f, 1.0f), osg::Vec4(1.0f, 1.0f, 0.0f, 1.0f)});
    expectColors(renderer.render(scene.get()));
}

TEST_F(TextureMulti, SpritesAreSharedPerColourMapAndReleasedWithTheSharedState)
{
    osg::ref_ptr<GlyphCloud> a = createScalarSpheres(), unlit = createScalarSpheres(),
                             magma = createScalarSpheres();
    unlit->setLit(false);
    magma->setColorMap(ColorMap::getBuiltin("magma"));
    auto sprites = [](GlyphCloud* cloud)
    {
        return dynamic_cast<const osg::Texture2DArray*>(cloud->getVariantStateSet()->getTextureAttribute(
            osgGlyphsPaper::LIT_SPRITES_TEXTURE_UNIT, osg::StateAttribute::TEXTURE));
    };
    ASSERT_NE(sprites(a), nullptr);
    EXPECT_EQ(sprites(a)->getTextureDepth(), static_cast<int>(osgGlyphsPaper::TEXTURE_MULTI_COLORMAP_LEVELS));
    // Lighting is baked into the sprites: lit and unlit clouds share one state.
    EXPECT_EQ(a->getVariantStateSet(), unlit->getVariantStateSet());
    EXPECT_EQ(sprites(a), sprites(unlit));
    EXPECT_NE(sprites(a), sprites(magma));

    // Drawn twice, the layers are filled once.
    osg::ref_ptr<osg::Node> scene = group({a.get(), unlit.get()});
    renderer.render(scene.get());
    const unsigned int filled = sprites(a)->getImage(0)->getModifiedCount();
    renderer.render(scene.get());
    EXPECT_EQ(sprites(a)->getImage(0)->getModifiedCount(), filled);

    osg::State* state = renderer.getViewer()->getCamera()->getGraphicsContext()->getState();
    EXPECT_NE(sprites(a)->getTextureObject(state->getContextID()), nullptr);
    osgGlyphs::GlyphStateCache::instance()->releaseGLObjects(state);
    EXPECT_EQ(sprites(a)->getTextureObject(state->getContextID()), nullptr);

    // Loaded again into the context, as into a new context that reuses its ID.
    const Frame frame = renderer.render(scene.get());
    for (const ExpectedSprite& sprite : expectScalarSprites(frame, *ColorMap::getBuiltin("viridis")))
        EXPECT_TRUE(centerColorNear(frame, sprite, 2));
}
