// Superquadrics against analytic truth: Barr's implicit function marched densely along each
// pixel's ray and refined by bisection (AnalyticScene), against the shaders' Newton steps on a norm
// from a bracketed minimum. Silhouettes as the intersection over union of the pixel centres covered,
// depth relative to the largest semi-axis, under each exact technique: boxes, cylinders,
// octahedra, pillows and diamonds, turned and crossing; exponents 1 as the ellipsoid; the lit
// normal; picking, the culling box and bad exponents.

#include "GlyphTestScenes.h"

#include <osgGlyphs/GlyphCloud>

#include <osg/LightSource>
#include <osg/Quat>

#include <algorithm>
#include <cmath>
#include <iostream>

using namespace osgGlyphsTest;
using osgGlyphs::GlyphCloud;
using osgGlyphs::GlyphShape;

namespace
{

struct SuperquadricSpec
{
    osg::Vec3 position;
    osg::Vec3 semiAxes;
    osg::Quat rotation;
    osg::Vec2 exponents; // e1, e2
    osg::Vec4ub color;
};

/** An exponent as the GPU holds it: a byte, in steps of 1/127 (GlyphCloud::setExponents()). */
double drawnExponent(float exponent)
{
    return std::round(std::clamp(exponent, 0.1f, 2.0f) * 127.0) / 127.0;
}

osg::ref_ptr<GlyphCloud> createSuperquadricCloud(const std::vector<SuperquadricSpec>& glyphs)
{
    osg::ref_ptr<osg::Vec3Array> positions = new osg::Vec3Array, semiAxes = new osg::Vec3Array;
    osg::ref_ptr<osg::Vec4Array> orientations = new osg::Vec4Array;
    osg::ref_ptr<osg::Vec2Array> exponents = new osg::Vec2Array;
    osg::ref_ptr<osg::Vec4ubArray> colors = new osg::Vec4ubArray;
    for (const SuperquadricSpec& glyph : glyphs)
    {
        positions->push_back(glyph.position);
        semiAxes->push_back(glyph.semiAxes);
        orientations->push_back(glyph.rotation.asVec4());
        exponents->push_back(glyph.exponents);
        colors->push_back(glyph.color);
    }
    osg::ref_ptr<GlyphCloud> cloud = new GlyphCloud;
    cloud->setShape(GlyphShape::Superquadric);
    cloud->setSemiAxes(semiAxes.get());
    cloud->setOrientations(orientations.get());
    cloud->setExponents(exponents.get());
    cloud->setColors(colors.get());
    cloud->setCompressedAttributes(false); // the shapes compared, not half-float radii
    cloud->setLit(false);
    cloud->setPositions(positions.get());
    return cloud;
}

AnalyticScene truthOf(const std::vector<SuperquadricSpec>& glyphs)
{
    AnalyticScene truth;
    for (const SuperquadricSpec& glyph : glyphs)
        truth.addSuperquadric(glyph.position, glyph.semiAxes, glyph.rotation,
                              drawnExponent(glyph.exponents.x()), drawnExponent(glyph.exponents.y()));
    return truth;
}

std::vector<osg::Vec4ub> paletteOf(const std::vector<SuperquadricSpec>& glyphs)
{
    std::vector<osg::Vec4ub> palette;
    for (const SuperquadricSpec& glyph : glyphs)
        palette.push_back(glyph.color);
    return palette;
}

double largestSemiAxis(const std::vector<SuperquadricSpec>& glyphs)
{
    double largest = 0.0;
    for (const SuperquadricSpec& glyph : glyphs)
        largest = std::max<double>(
            largest, std::max(glyph.semiAxes.x(), std::max(glyph.semiAxes.y(), glyph.semiAxes.z())));
    return largest;
}

osg::Quat turn(double angle, const osg::Vec3d& axis)
{
    return osg::Quat(angle, axis);
}

const osg::Vec4ub RED(255, 0, 0, 255), GREEN(0, 255, 0, 255), BLUE(0, 0, 255, 255), YELLOW(255, 255, 0, 255),
    CYAN(0, 255, 255, 255), MAGENTA(255, 0, 255, 255);

/** A rounded box, a cylinder, an octahedron, a pillow and a diamond, turned, and two crossing. */
std::vector<SuperquadricSpec> sixSuperquadrics()
{
    const osg::Quat oblique = turn(0.7, osg::Vec3d(1.0, 0.4, 0.2)) * turn(0.5, osg::Vec3d(0.0, 0.0, 1.0));
    return {
        {osg::Vec3(-2.6f, 0.0f, 1.4f), osg::Vec3(0.8f, 0.5f, 0.4f), oblique, osg::Vec2(0.15f, 0.15f), RED},
        {osg::Vec3(0.0f, 0.5f, 1.5f), osg::Vec3(0.5f, 0.5f, 0.9f), turn(1.1, {1, 0, 0}),
         osg::Vec2(0.2f, 1.0f), GREEN}, // a cylinder
        {osg::Vec3(2.6f, 0.0f, 1.3f), osg::Vec3(0.8f, 0.7f, 0.9f), oblique.inverse(), osg::Vec2(2.0f, 2.0f),
         BLUE}, // an octahedron
        {osg::Vec3(-2.4f, 0.0f, -1.4f), osg::Vec3(1.0f, 0.9f, 0.35f), turn(0.9, {0.3, 1, 0.5}),
         osg::Vec2(1.0f, 0.3f), YELLOW}, // a pillow
        {osg::Vec3(0.6f, 0.0f, -1.4f), osg::Vec3(1.2f, 0.4f, 0.3f), turn(0.4, {0, 1, 0}),
         osg::Vec2(1.5f, 0.6f), CYAN},
        {osg::Vec3(0.7f, 0.2f, -1.3f), osg::Vec3(0.3f, 0.5f, 1.0f), turn(-0.6, {1, 0, 1}),
         osg::Vec2(0.5f, 0.4f), MAGENTA}};
}

class Superquadrics : public ::testing::TestWithParam<const char*>
{
protected:
    Renderer renderer{240, 180};

    Frame render(osg::ref_ptr<GlyphCloud> cloud, const std::string& name)
    {
        cloud->setTechnique(osgGlyphs::createTechnique(GetParam()).get());
        const Frame frame = renderer.render(group({cloud.get()}).get());
        saveFrame(frame, name + "_" + GetParam());
        return frame;
    }

    void expectExact(const Frame& frame, const AnalyticScene& truth, const std::vector<osg::Vec4ub>& palette,
                     double size, const std::string& name, int minCentres)
    {
        CoverageComparison comparison = compareCoveredCentres(frame, truth, size);
        EXPECT_GT(comparison.truthCentres, minCentres);
        EXPECT_GE(comparison.iou(), 0.998) << comparison.intersection << " of " << comparison.unionCentres;
        EXPECT_LE(comparison.depthPercentile(0.99), 1e-4);
        std::cout << "[ superquadrics ] " << name << " " << GetParam() << ": IoU " << comparison.iou()
                  << ", depth p99 " << comparison.depthPercentile(0.99) << ", max "
                  << comparison.depthPercentile(1.0) << " (of the largest semi-axis), "
                  << comparison.truthCentres << " centres" << std::endl;
        const Agreement agreement = compareWithTruth(frame, truth, palette, 1.0);
        EXPECT_EQ(agreement.wrongLabel, 0) << "of " << agreement.certain << " certain pixels";
    }
};

}

TEST_P(Superquadrics, BoxesCylindersOctahedraPillowsAndDiamonds)
{
    const std::vector<SuperquadricSpec> glyphs = sixSuperquadrics();
    const Frame frame = render(createSuperquadricCloud(glyphs), "superquadrics");
    expectExact(frame, truthOf(glyphs), paletteOf(glyphs), largestSemiAxis(glyphs), "superquadrics", 4000);
}

TEST_P(Superquadrics, ExponentsOfOneDrawTheEllipsoid)
{
    std::vector<SuperquadricSpec> glyphs = sixSuperquadrics();
    AnalyticScene ellipsoids;
    for (SuperquadricSpec& glyph : glyphs)
    {
        glyph.exponents.set(1.0f, 1.0f);
        ellipsoids.addEllipsoid(glyph.position, glyph.semiAxes, glyph.rotation);
    }
    const Frame frame = render(createSuperquadricCloud(glyphs), "superquadric_ellipsoids");
    expectExact(frame, ellipsoids, paletteOf(glyphs), largestSemiAxis(glyphs), "as ellipsoids", 4000);
}

TEST_P(Superquadrics, SmallSuperquadricsAreExactToo)
{
    std::vector<SuperquadricSpec> glyphs;
    for (int i = 0; i < 40; ++i)
    {
        const osg::Vec3 position(-4.0f + 0.9f * (i % 10), 0.0f, -2.4f + 1.2f * (i / 10));
        const float size = 0.03f + 0.005f * (i % 7);
        const osg::Vec4ub color(40 + 4 * i, 240 - 4 * i, (60 + 70 * i) % 256, 255);
        glyphs.push_back({position, osg::Vec3(size * (1.0f + i % 3), size, size * 1.5f),
                          turn(0.7 * i, osg::Vec3d(std::cos(i), std::sin(1.3 * i), 0.5)),
                          osg::Vec2(0.1f + 0.05f * (i % 9), 0.1f + 0.2f * (i % 5)), color});
    }
    const Frame frame = render(createSuperquadricCloud(glyphs), "small_superquadrics");
    const CentreAgreement agreement =
        compareEveryPixelCentre(frame, truthOf(glyphs), paletteOf(glyphs), 1e-5);
    EXPECT_GT(agreement.hits, 100);
    EXPECT_EQ(agreement.wrongCoverage, 0) << "of " << agreement.hits << " pixel centres on a glyph";
    EXPECT_EQ(agreement.wrongLabel, 0);
}

TEST_P(Superquadrics, CrossingTheNearPlaneIsCutNotDropped)
{
    if (std::string(GetParam()) == "point-sprite")
        GTEST_SKIP() << "a point sprite covers GL_POINT_SIZE_RANGE at most, not the whole view";
    // The near plane is at y = -9; the rounded bar reaches from y = -10.2 to y = -7.8. Pixels whose
    // ray from the near plane starts inside show the cut at depth 0; the others the surface beyond.
    const std::vector<SuperquadricSpec> glyphs = {{osg::Vec3(0.1f, -9.0f, 0.0f), osg::Vec3(0.3f, 1.2f, 0.2f),
                                                   turn(0.2, {0, 0, 1}), osg::Vec2(0.3f, 0.5f), RED}};
    const Frame frame = render(createSuperquadricCloud(glyphs), "superquadric_near_plane");
    const AnalyticScene truth = truthOf(glyphs);
    int cut = 0, wrong = 0, beyond = 0;
    for (int y = 0; y < frame.height(); ++y)
        for (int x = 0; x < frame.width(); ++x)
        {
            if (truth.certainLabel(frame, x, y) == AnalyticScene::AMBIGUOUS)
                continue;
            osg::Vec3d origin, direction;
            frame.pixelRay(x + 0.5, y + 0.5, origin, direction);
            const RayHit fromNear = truth.cast(origin, direction);
            const bool startsInside = fromNear.hit() && fromNear.normal * direction > 0.0;
            if (startsInside)
            {
                ++cut;
                wrong += frame.isCovered(x, y) && frame.depthAt(x, y) < 1e-6f ? 0 : 1;
            }
            else if (fromNear.hit())
            {
                ++beyond;
                wrong += frame.isCovered(x, y) &&
                                 std::fabs(frame.depthAt(x, y) - frame.windowDepth(fromNear.point)) < 1e-5
                             ? 0
                             : 1;
            }
            else
                wrong += frame.isCovered(x, y) ? 1 : 0;
        }
    EXPECT_GT(cut, 1000);
    EXPECT_EQ(wrong, 0) << "of " << cut << " cut and " << beyond << " beyond";
}

TEST_P(Superquadrics, LitColourFollowsTheAnalyticNormal)
{
    renderer.getViewer()->setLightingMode(osg::View::NO_LIGHT);
    osg::ref_ptr<osg::LightSource> source = createColouredLight();
    const osg::Vec3d material(0.12, 0.5, 24.0);
    std::vector<SuperquadricSpec> glyphs = sixSuperquadrics();
    for (std::size_t i = 0; i < glyphs.size(); ++i)
        glyphs[i].color = osg::Vec4ub(120 + 20 * i, 200 - 15 * i, 110 + 17 * i, 255);
    osg::ref_ptr<GlyphCloud> cloud = createSuperquadricCloud(glyphs);
    cloud->setTechnique(osgGlyphs::createTechnique(GetParam()).get());
    cloud->setLit(true);
    cloud->setMaterial(material.x(), material.y(), material.z());
    source->addChild(group({cloud.get()}));
    osg::ref_ptr<osg::Group> root = new osg::Group;
    root->addChild(source.get());
    const Frame frame = renderer.render(root.get());
    saveFrame(frame, std::string("superquadrics_lit_") + GetParam());
    const LitAgreement agreement = compareLitWithTruth(frame, truthOf(glyphs), paletteOf(glyphs),
                                                       eyeLightOf(*source->getLight(), frame), material, 3);
    EXPECT_GT(agreement.checked, 3000);
    // The sharp edges of the boxes turn the normal fast: a pixel or two there may round otherwise.
    EXPECT_LE(agreement.wrong, agreement.checked / 500) << "of " << agreement.checked << " pixels";
}

INSTANTIATE_TEST_SUITE_P(, Superquadrics, ::testing::Values("geometry-shader", "point-sprite", "instanced"),
                         [](const ::testing::TestParamInfo<const char*>& technique)
                         {
                             std::string name = technique.param;
                             name.erase(std::remove(name.begin(), name.end(), '-'), name.end());
                             return name;
                         });

TEST(SuperquadricCloud, PicksTheSurfaceTheShadersDraw)
{
    const std::vector<SuperquadricSpec> glyphs = sixSuperquadrics();
    osg::ref_ptr<osg::Group> root = new osg::Group;
    root->addChild(createSuperquadricCloud(glyphs).get());
    const PickingAgreement agreement = comparePicksWithTruth(*root, truthOf(glyphs));
    EXPECT_GT(agreement.hits, 40);
    EXPECT_EQ(agreement.wrongHit, 0);
    EXPECT_EQ(agreement.wrongLabel, 0);
    // The semi-axes and quaternion in 16 bits, as drawn, move the surface by up to 1e-4 (more
    // along grazing rays).
    EXPECT_LT(agreement.worstDistance, 5e-4);
    EXPECT_GT(agreement.worstNormalCosine, 0.999);
}

TEST(SuperquadricCloud, CullingBoxesHoldEachSuperquadric)
{
    const std::vector<SuperquadricSpec> glyphs = sixSuperquadrics();
    osg::ref_ptr<GlyphCloud> cloud = createSuperquadricCloud(glyphs);
    for (unsigned int i = 0; i < glyphs.size(); ++i)
    {
        AnalyticScene one;
        const SuperquadricSpec& glyph = glyphs[i];
        one.addSuperquadric(glyph.position, glyph.semiAxes, glyph.rotation,
                            drawnExponent(glyph.exponents.x()), drawnExponent(glyph.exponents.y()));
        // Surface points from rays toward the centre from all around: inside the box, and some near
        // each of its faces (the box is the shape's own, from the support function of its norm). The
        // point-sprite scenes above check the radius, which sizes the sprites.
        const osg::BoundingBox box = cloud->computeGlyphBox(i);
        osg::BoundingBox reached;
        for (int k = 0; k < 2000; ++k)
        {
            const double polar = std::acos(1.0 - 2.0 * (k + 0.5) / 2000.0), azimuth = 2.399963 * k;
            const osg::Vec3d out(std::sin(polar) * std::cos(azimuth), std::sin(polar) * std::sin(azimuth),
                                 std::cos(polar));
            const RayHit hit = one.cast(osg::Vec3d(glyph.position) + out * 5.0, -out);
            ASSERT_TRUE(hit.hit());
            reached.expandBy(hit.point);
        }
        for (int k = 0; k < 3; ++k)
        {
            EXPECT_LE(box._min[k], reached._min[k] + 1e-5) << i;
            EXPECT_GE(box._max[k], reached._max[k] - 1e-5) << i;
            const double extent = reached._max[k] - reached._min[k];
            // Rays toward the centre sample the corners of the box-like ones a few percent short.
            EXPECT_LE(box._max[k] - box._min[k], 1.06 * extent + 1e-4) << i << " axis " << k;
        }
    }
}

TEST(SuperquadricCloud, BadExponentsSkipTheirGlyphsAndOthersAreClamped)
{
    std::vector<SuperquadricSpec> glyphs = sixSuperquadrics();
    glyphs[1].exponents.set(std::nanf(""), 1.0f);
    glyphs[2].exponents.set(0.0f, 1.0f);
    glyphs[3].exponents.set(7.0f, 0.01f); // clamped to 2 and 0.1
    osg::ref_ptr<GlyphCloud> cloud = createSuperquadricCloud(glyphs);
    EXPECT_EQ(cloud->getNumSkippedGlyphs(), 2u);
    EXPECT_EQ(cloud->computeGlyphBox(1).valid(), false);
    EXPECT_TRUE(cloud->computeGlyphBox(3).valid());
    EXPECT_EQ(drawnExponent(7.0f), 2.0);
    EXPECT_NEAR(drawnExponent(0.01f), 0.1, 0.004);
}
