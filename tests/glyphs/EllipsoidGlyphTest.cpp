// Ellipsoids against analytic truth: a quadric solved in the world frame, which the shaders' unit
// sphere frame must agree with. Silhouettes as the intersection over union of the pixel centres
// covered, depth as the distance along each pixel's ray relative to the largest semi-axis, under
// each exact technique: prolate and oblate, needles (12:1) and discs (1:12), oblique, crossing, at
// the border of a wide field of view, cut by the near plane; picking, the culling box and bad input.

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

struct EllipsoidSpec
{
    osg::Vec3 position;
    osg::Vec3 semiAxes;
    osg::Quat rotation;
    osg::Vec4ub color;
};

osg::ref_ptr<GlyphCloud> createEllipsoidCloud(const std::vector<EllipsoidSpec>& glyphs)
{
    osg::ref_ptr<osg::Vec3Array> positions = new osg::Vec3Array, semiAxes = new osg::Vec3Array;
    osg::ref_ptr<osg::Vec4Array> orientations = new osg::Vec4Array;
    osg::ref_ptr<osg::Vec4ubArray> colors = new osg::Vec4ubArray;
    for (const EllipsoidSpec& glyph : glyphs)
    {
        positions->push_back(glyph.position);
        semiAxes->push_back(glyph.semiAxes);
        orientations->push_back(glyph.rotation.asVec4());
        colors->push_back(glyph.color);
    }
    osg::ref_ptr<GlyphCloud> cloud = new GlyphCloud;
    cloud->setShape(GlyphShape::Ellipsoid);
    cloud->setSemiAxes(semiAxes.get());
    cloud->setOrientations(orientations.get());
    cloud->setColors(colors.get());
    // Float radii: the comparison is of the shapes, not of half-float radii.
    cloud->setCompressedAttributes(false);
    cloud->setLit(false);
    cloud->setPositions(positions.get());
    return cloud;
}

AnalyticScene truthOf(const std::vector<EllipsoidSpec>& glyphs)
{
    AnalyticScene truth;
    for (const EllipsoidSpec& glyph : glyphs)
        truth.addEllipsoid(glyph.position, glyph.semiAxes, glyph.rotation);
    return truth;
}

std::vector<osg::Vec4ub> paletteOf(const std::vector<EllipsoidSpec>& glyphs)
{
    std::vector<osg::Vec4ub> palette;
    for (const EllipsoidSpec& glyph : glyphs)
        palette.push_back(glyph.color);
    return palette;
}

osg::Quat turn(double angle, const osg::Vec3d& axis)
{
    return osg::Quat(angle, axis);
}

const osg::Vec4ub RED(255, 0, 0, 255), GREEN(0, 255, 0, 255), BLUE(0, 0, 255, 255), YELLOW(255, 255, 0, 255),
    CYAN(0, 255, 255, 255), MAGENTA(255, 0, 255, 255);

/** Prolate and oblate, a needle (12:1) and a disc (1:12), each turned obliquely, and two crossing. */
std::vector<EllipsoidSpec> sixEllipsoids()
{
    const osg::Quat oblique = turn(0.7, osg::Vec3d(1.0, 0.4, 0.2)) * turn(0.5, osg::Vec3d(0.0, 0.0, 1.0));
    return {{osg::Vec3(-2.6f, 0.0f, 1.4f), osg::Vec3(1.0f, 0.35f, 0.35f), oblique, RED}, // prolate
            {osg::Vec3(0.0f, 0.5f, 1.5f), osg::Vec3(0.9f, 0.9f, 0.3f), turn(1.1, {1, 0, 0}), GREEN}, // oblate
            {osg::Vec3(2.6f, 0.0f, 1.3f), osg::Vec3(1.2f, 0.1f, 0.1f), oblique.inverse(), BLUE},     // needle
            {osg::Vec3(-2.4f, 0.0f, -1.4f), osg::Vec3(1.2f, 1.2f, 0.1f), turn(0.9, {0.3, 1, 0.5}),
             YELLOW}, // disc
            {osg::Vec3(0.6f, 0.0f, -1.4f), osg::Vec3(1.3f, 0.4f, 0.25f), turn(0.4, {0, 1, 0}), CYAN},
            {osg::Vec3(0.7f, 0.2f, -1.3f), osg::Vec3(0.3f, 0.5f, 1.1f), turn(-0.6, {1, 0, 1}), MAGENTA}};
}

class Ellipsoids : public ::testing::TestWithParam<const char*>
{
protected:
    Renderer renderer{320, 240};

    Frame render(const std::vector<EllipsoidSpec>& glyphs, const std::string& name)
    {
        osg::ref_ptr<GlyphCloud> cloud = createEllipsoidCloud(glyphs);
        cloud->setTechnique(osgGlyphs::createTechnique(GetParam()).get());
        const Frame frame = renderer.render(group({cloud.get()}).get());
        saveFrame(frame, name + "_" + GetParam());
        return frame;
    }

    void expectExact(const std::vector<EllipsoidSpec>& glyphs, const std::string& name, int minCentres)
    {
        const Frame frame = render(glyphs, name);
        const AnalyticScene truth = truthOf(glyphs);
        double largest = 0.0;
        for (const EllipsoidSpec& glyph : glyphs)
            largest = std::max<double>(
                largest, std::max(glyph.semiAxes.x(), std::max(glyph.semiAxes.y(), glyph.semiAxes.z())));
        CoverageComparison comparison = compareCoveredCentres(frame, truth, largest);
        EXPECT_GT(comparison.truthCentres, minCentres);
        EXPECT_GE(comparison.iou(), 0.998) << comparison.intersection << " of " << comparison.unionCentres;
        EXPECT_LE(comparison.depthPercentile(0.99), 1e-4);
        std::cout << "[ ellipsoids ] " << name << " " << GetParam() << ": IoU " << comparison.iou()
                  << ", depth p99 " << comparison.depthPercentile(0.99) << ", max "
                  << comparison.depthPercentile(1.0) << " (of the largest semi-axis), "
                  << comparison.truthCentres << " centres" << std::endl;
        const Agreement agreement = compareWithTruth(frame, truth, paletteOf(glyphs), 1.0);
        EXPECT_EQ(agreement.wrongLabel, 0) << "of " << agreement.certain << " certain pixels";
    }
};

}

TEST_P(Ellipsoids, ProlateOblateNeedlesDiscsObliqueAndCrossing)
{
    expectExact(sixEllipsoids(), "ellipsoids", 6000);
}

TEST_P(Ellipsoids, SeenAlongEachAxis)
{
    // The camera looks along +y: a needle and a disc end-on and edge-on.
    const std::vector<EllipsoidSpec> glyphs = {
        {osg::Vec3(-2.5f, 0.0f, 1.2f), osg::Vec3(0.1f, 1.2f, 0.1f), osg::Quat(), RED},
        {osg::Vec3(0.0f, 0.0f, 1.2f), osg::Vec3(1.2f, 0.1f, 1.2f), osg::Quat(), GREEN},
        {osg::Vec3(2.5f, 0.0f, 1.2f), osg::Vec3(1.2f, 1.2f, 0.1f), osg::Quat(), BLUE},
        {osg::Vec3(0.0f, 0.0f, -1.5f), osg::Vec3(2.0f, 0.5f, 0.7f), osg::Quat(), YELLOW}};
    expectExact(glyphs, "ellipsoid_axes", 3000);
}

TEST_P(Ellipsoids, AtTheBorderOfAWideFieldOfView)
{
    renderer.setPerspective(100.0, 0.5, 50.0);
    const std::vector<EllipsoidSpec> glyphs = {
        {osg::Vec3(4.6f, -6.0f, 2.6f), osg::Vec3(1.2f, 0.1f, 0.3f), turn(0.8, {0, 0, 1}), RED},
        {osg::Vec3(-4.8f, -6.2f, -2.8f), osg::Vec3(0.6f, 0.9f, 0.2f), turn(1.0, {1, 1, 0}), GREEN},
        {osg::Vec3(-4.0f, -7.0f, 3.0f), osg::Vec3(1.0f, 0.3f, 0.3f), turn(0.3, {1, 0, 0}), BLUE}};
    expectExact(glyphs, "ellipsoid_wide_fov", 1500);
}

TEST_P(Ellipsoids, SmallEllipsoidsAreExactToo)
{
    // A few pixels each: one-triangle bounds, and centres between which the bound falls.
    std::vector<EllipsoidSpec> glyphs;
    for (int i = 0; i < 60; ++i)
    {
        const osg::Vec3 position(-4.0f + 0.8f * (i % 10), 0.0f, -2.6f + 0.9f * (i / 10));
        const float size = 0.02f + 0.004f * (i % 7);
        const osg::Vec3 semiAxes(size * (1.0f + i % 4), size, size * (1.0f + 0.5f * (i % 3)));
        const osg::Vec4ub color(40 + 3 * i, 240 - 3 * i, (60 + 70 * i) % 256, 255);
        glyphs.push_back(
            {position, semiAxes, turn(0.7 * i, osg::Vec3d(std::cos(i), std::sin(1.3 * i), 0.5)), color});
    }
    const Frame frame = render(glyphs, "small_ellipsoids");
    const CentreAgreement agreement =
        compareEveryPixelCentre(frame, truthOf(glyphs), paletteOf(glyphs), 1e-5);
    EXPECT_GT(agreement.hits, 150);
    EXPECT_EQ(agreement.wrongCoverage, 0) << "of " << agreement.hits << " pixel centres on a glyph";
    EXPECT_EQ(agreement.wrongLabel, 0);
}

TEST_P(Ellipsoids, CrossingTheNearPlaneIsCutNotDropped)
{
    if (std::string(GetParam()) == "point-sprite")
        GTEST_SKIP() << "a point sprite covers GL_POINT_SIZE_RANGE at most, not the whole view";
    // The near plane is at y = -9; the needle reaches from y = -10.2 to y = -7.8.
    const std::vector<EllipsoidSpec> glyphs = {
        {osg::Vec3(0.1f, -9.0f, 0.0f), osg::Vec3(0.3f, 1.2f, 0.2f), turn(0.2, {0, 0, 1}), RED}};
    const Frame frame = render(glyphs, "ellipsoid_near_plane");
    // Pixels whose ray from the near plane starts inside the solid show the cut, at depth 0.
    const AnalyticScene truth = truthOf(glyphs);
    int cut = 0, wrong = 0;
    for (int y = 0; y < frame.height(); ++y)
        for (int x = 0; x < frame.width(); ++x)
        {
            osg::Vec3d origin, direction;
            frame.pixelRay(x + 0.5, y + 0.5, origin, direction);
            const RayHit fromBehind = truth.cast(origin - direction * 100.0, direction);
            const RayHit fromNear = truth.cast(origin, direction);
            const bool startsInside = fromBehind.hit() && fromBehind.distance < 100.0 && fromNear.hit() &&
                                      fromNear.normal * direction > 0.0;
            if (!startsInside || truth.certainLabel(frame, x, y) == AnalyticScene::AMBIGUOUS)
                continue;
            ++cut;
            wrong += frame.isCovered(x, y) && frame.depthAt(x, y) < 1e-6f ? 0 : 1;
        }
    EXPECT_GT(cut, 1000);
    EXPECT_EQ(wrong, 0);
}

TEST_P(Ellipsoids, LitColourFollowsTheAnalyticNormal)
{
    // A coloured directional light from the upper left front in place of the headlight: a normal
    // off the quadric's gradient changes the shade.
    renderer.getViewer()->setLightingMode(osg::View::NO_LIGHT);
    osg::ref_ptr<osg::LightSource> source = createColouredLight();
    const osg::Light* light = source->getLight();
    const osg::Vec3d material(0.12, 0.5, 24.0);
    std::vector<EllipsoidSpec> glyphs = sixEllipsoids();
    for (std::size_t i = 0; i < glyphs.size(); ++i)
        glyphs[i].color = osg::Vec4ub(120 + 20 * i, 200 - 15 * i, 110 + 17 * i, 255);
    osg::ref_ptr<GlyphCloud> cloud = createEllipsoidCloud(glyphs);
    cloud->setTechnique(osgGlyphs::createTechnique(GetParam()).get());
    cloud->setLit(true);
    cloud->setMaterial(material.x(), material.y(), material.z());
    source->addChild(group({cloud.get()}));
    osg::ref_ptr<osg::Group> root = new osg::Group;
    root->addChild(source.get());
    const Frame frame = renderer.render(root.get());
    saveFrame(frame, std::string("ellipsoids_lit_") + GetParam());

    // The semi-axes and quaternion in 16 bits tilt the normal by 1e-4 at most: 3 levels per channel.
    const LitAgreement agreement = compareLitWithTruth(frame, truthOf(glyphs), paletteOf(glyphs),
                                                       eyeLightOf(*light, frame), material, 3);
    EXPECT_GT(agreement.checked, 5000);
    EXPECT_LE(agreement.wrong, agreement.checked / 1000) << "of " << agreement.checked << " pixels";
}

INSTANTIATE_TEST_SUITE_P(, Ellipsoids, ::testing::Values("geometry-shader", "point-sprite", "instanced"),
                         [](const ::testing::TestParamInfo<const char*>& technique)
                         {
                             std::string name = technique.param;
                             name.erase(std::remove(name.begin(), name.end(), '-'), name.end());
                             return name;
                         });

TEST(EllipsoidCloud, PicksTheSurfaceTheShadersDraw)
{
    const std::vector<EllipsoidSpec> glyphs = sixEllipsoids();
    osg::ref_ptr<osg::Group> root = new osg::Group;
    root->addChild(createEllipsoidCloud(glyphs).get());
    const PickingAgreement agreement = comparePicksWithTruth(*root, truthOf(glyphs));
    EXPECT_GT(agreement.hits, 40);
    EXPECT_EQ(agreement.wrongHit, 0);
    EXPECT_EQ(agreement.wrongLabel, 0);
    // The semi-axes and quaternion in 16 bits, as drawn, move the surface by up to 1e-4 (more
    // along grazing rays).
    EXPECT_LT(agreement.worstDistance, 5e-4);
    EXPECT_GT(agreement.worstNormalCosine, 0.9999);
}

TEST(EllipsoidCloud, CullingBoxesHoldEachEllipsoidExactly)
{
    const std::vector<EllipsoidSpec> glyphs = sixEllipsoids();
    osg::ref_ptr<GlyphCloud> cloud = createEllipsoidCloud(glyphs);
    for (unsigned int i = 0; i < glyphs.size(); ++i)
    {
        // The extent along world axis k: max over unit u of e_k . R S u = |S R^T e_k|.
        const osg::BoundingBox box = cloud->computeGlyphBox(i);
        for (int k = 0; k < 3; ++k)
        {
            osg::Vec3d world;
            world[k] = 1.0;
            const osg::Vec3d body = glyphs[i].rotation.inverse() * world;
            const double extent =
                osg::Vec3d(body.x() * glyphs[i].semiAxes.x(), body.y() * glyphs[i].semiAxes.y(),
                           body.z() * glyphs[i].semiAxes.z())
                    .length();
            EXPECT_NEAR(box._max[k] - glyphs[i].position[k], extent, 2e-4 * extent)
                << "glyph " << i << " axis " << k;
            EXPECT_NEAR(glyphs[i].position[k] - box._min[k], extent, 2e-4 * extent)
                << "glyph " << i << " axis " << k;
        }
    }
}

TEST(EllipsoidCloud, TakeEightBytesMoreThanASphereAndEightForTheirTurn)
{
    osg::ref_ptr<GlyphCloud> cloud = createEllipsoidCloud(sixEllipsoids());
    cloud->setCompressedAttributes(true);
    // Position 12, radius and scalar word 4 (RGBA colours 4 more), semi-axes 8, quaternion 8.
    EXPECT_DOUBLE_EQ(cloud->getGPUBytesPerGlyph(), 12.0 + 4.0 + 4.0 + 8.0 + 8.0);
}

TEST(EllipsoidCloud, BadSemiAxesAndRotationsAreSkippedWithAWarning)
{
    std::vector<EllipsoidSpec> glyphs = sixEllipsoids();
    glyphs[0].semiAxes.y() = 0.0f;
    glyphs[1].semiAxes.z() = std::nanf("");
    osg::ref_ptr<NotifyCapture> capture = new NotifyCapture;
    osg::ref_ptr<GlyphCloud> cloud = createEllipsoidCloud(glyphs);
    osg::Vec4Array& orientations = *cloud->getOrientations();
    orientations[2] = osg::Vec4();
    orientations[3] = osg::Vec4(0.0f, std::numeric_limits<float>::infinity(), 0.0f, 1.0f);
    orientations[4] = orientations[4] * 7.0f; // not unit: normalised, drawn
    orientations.dirty();
    cloud->dirtyGlyphs();
    const std::string warnings = capture->stop();
    EXPECT_EQ(cloud->getNumSkippedGlyphs(), 4u);
    EXPECT_NE(warnings.find("2 of 6 glyphs have semi-axes that are not all finite and > 0"),
              std::string::npos)
        << warnings;
    EXPECT_NE(warnings.find("2 of 6 glyphs have an orientation quaternion that is zero or not finite"),
              std::string::npos)
        << warnings;
    EXPECT_FALSE(cloud->computeGlyphBox(0).valid());
    EXPECT_TRUE(cloud->computeGlyphBox(4).valid());
}
