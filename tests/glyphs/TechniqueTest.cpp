// The drawing techniques against the default: the exact ones (instanced, point sprite) must
// match the geometry-shader technique pixel for pixel; the others must draw what their method
// draws (the paper's billboards, tessellated polygons, textured sprites, single points).

#include "GlyphTestScenes.h"

#include <osgGlyphs/GlyphCloud>

#include <cmath>

using namespace osgGlyphsTest;
using osgGlyphs::GlyphCloud;
using osgGlyphs::GlyphShape;
using osgGlyphs::GlyphTechnique;

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
    Frame render(GlyphTechnique technique)
    {
        osg::ref_ptr<GlyphCloud> cloud = createScene(GetParam());
        cloud->setTechnique(technique);
        const Frame frame = renderer.render(group({cloud.get()}).get());
        saveFrame(frame, std::string("technique_") + osgGlyphs::getTechniqueName(technique) + "_" +
                             osgGlyphs::getShapeName(GetParam()));
        return frame;
    }

    Renderer renderer{160, 120};
};

}

TEST_P(Techniques, ExactTechniquesDrawTheSamePixels)
{
    const Frame reference = render(GlyphTechnique::GeometryShader);
    for (GlyphTechnique technique : {GlyphTechnique::Instanced, GlyphTechnique::PointSprite})
    {
        // Rays rebuilt per fragment (point sprites) differ from interpolated ones in the last bits.
        const Comparison comparison = compare(render(technique), reference, 1, 1e-6f);
        EXPECT_GT(comparison.coveredBoth, 800) << osgGlyphs::getTechniqueName(technique);
        EXPECT_LE(comparison.differingColor, comparison.coveredBoth / 200)
            << osgGlyphs::getTechniqueName(technique);
        EXPECT_LE(comparison.differingDepth, comparison.coveredBoth / 200)
            << osgGlyphs::getTechniqueName(technique);
    }
}

TEST_P(Techniques, PolygonsApproximateTheExactGlyphs)
{
    const Frame reference = render(GlyphTechnique::GeometryShader);
    osg::ref_ptr<GlyphCloud> cloud = createScene(GetParam());
    cloud->setTechnique(GlyphTechnique::Polygons);
    cloud->setPolygonResolution(32, 16);
    const Frame fine = renderer.render(group({cloud.get()}).get());
    const Comparison comparison = compare(fine, reference, 255, 1.0f);
    EXPECT_GT(double(comparison.coveredBoth) / comparison.coveredEither, 0.97);
    // The default 8 x 4 tessellation is visibly coarser.
    const Comparison coarse = compare(render(GlyphTechnique::Polygons), reference, 255, 1.0f);
    EXPECT_LT(coarse.coveredBoth, comparison.coveredBoth);
}

TEST_P(Techniques, SpriteTechniquesCoverRoughlyTheGlyphs)
{
    const Frame reference = render(GlyphTechnique::GeometryShader);
    int referenceCovered = 0;
    for (int y = 0; y < reference.height(); ++y)
        for (int x = 0; x < reference.width(); ++x)
            referenceCovered += reference.isCovered(x, y) ? 1 : 0;
    for (GlyphTechnique technique : {GlyphTechnique::PaperQuad, GlyphTechnique::TextureBlend})
    {
        if (!osgGlyphs::isTechniqueSupported(technique, GetParam()))
            continue;
        const Comparison comparison = compare(render(technique), reference, 255, 1.0f);
        EXPECT_GT(double(comparison.coveredBoth) / referenceCovered, 0.6)
            << osgGlyphs::getTechniqueName(technique);
    }
}

TEST_P(Techniques, PointsFloorDrawsOnePixelPerGlyph)
{
    const Frame frame = render(GlyphTechnique::PointsFloor);
    int covered = 0;
    for (int y = 0; y < frame.height(); ++y)
        for (int x = 0; x < frame.width(); ++x)
            covered += frame.isCovered(x, y) ? 1 : 0;
    EXPECT_GE(covered, 7); // nine glyphs, some may share a pixel
    EXPECT_LE(covered, 9);
}

TEST(TechniqueNames, RoundTrip)
{
    for (GlyphTechnique technique : osgGlyphs::getTechniques())
    {
        GlyphTechnique parsed = GlyphTechnique::PointsFloor;
        EXPECT_TRUE(osgGlyphs::parseTechnique(osgGlyphs::getTechniqueName(technique), parsed));
        EXPECT_EQ(parsed, technique);
    }
    GlyphTechnique parsed;
    EXPECT_TRUE(osgGlyphs::parseTechnique("default", parsed));
    EXPECT_EQ(parsed, osgGlyphs::DEFAULT_GLYPH_TECHNIQUE);
    EXPECT_FALSE(osgGlyphs::parseTechnique("raytrace", parsed));
}

INSTANTIATE_TEST_SUITE_P(, Techniques,
                         ::testing::Values(GlyphShape::Sphere, GlyphShape::Cone, GlyphShape::Arrow,
                                           GlyphShape::Cylinder),
                         [](const ::testing::TestParamInfo<GlyphShape>& param)
                         { return std::string(osgGlyphs::getShapeName(param.param)); });
