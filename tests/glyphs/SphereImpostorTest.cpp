// Sphere impostors against analytic truth: exact depth and silhouettes under perspective and
// orthographic projections, intersections with each other and with fixed-function geometry,
// the near-plane cut, lighting, colour mapping, updates, culling and bad input.

#include "GlyphTestScenes.h"

#include <osgGlyphs/GlyphCloud>
#include <osgGlyphs/GlyphStateCache>
#include <osgGlyphsHeadless/DepthImage>

#include <osg/Group>
#include <osg/LightSource>
#include <osg/ShapeDrawable>
#include <osgDB/FileUtils>

#include <cmath>
#include <fstream>

using namespace osgGlyphsTest;
using osgGlyphs::GlyphCloud;

namespace
{

const osg::Vec4ub RED(255, 0, 0, 255);
const osg::Vec4ub GREEN(0, 255, 0, 255);
const osg::Vec4ub BLUE(0, 0, 255, 255);

/** 24-bit depth steps are 6e-8; the impostor's float arithmetic stays well inside 4 steps. */
const double EXACT_DEPTH = 2.5e-7;

class SphereImpostor : public ::testing::Test
{
protected:
    Renderer renderer{160, 120};
};

}

TEST_F(SphereImpostor, DepthAndSilhouetteAreTheExactSphere)
{
    const std::vector<SphereSpec> spheres = {{osg::Vec3(0.4f, 0.0f, 0.3f), 1.2f, RED}};
    AnalyticScene truth;
    addSpheres(truth, spheres);
    const Frame frame = renderer.render(group({createSphereCloud(spheres).get()}).get());

    const Agreement agreement = compareWithTruth(frame, truth, {RED}, EXACT_DEPTH);
    EXPECT_GT(agreement.covered, 1000); // pi * (1.2 * 164.8 / 10)^2 = 1230 pixels
    EXPECT_EQ(agreement.wrongLabel, 0) << "of " << agreement.certain << " certain pixels";
    EXPECT_EQ(agreement.wrongDepth, 0) << "worst depth error " << agreement.worstDepthError;
}

TEST_F(SphereImpostor, SmallSpheresAreExactToo)
{
    // Radii of 1 to 10 pixels: below 8 pixels a glyph's bound is one triangle, above it a quad.
    // Each radius is k/64 of the largest, which the half-float radius holds exactly.
    std::vector<SphereSpec> spheres;
    std::vector<osg::Vec4ub> palette;
    for (int i = 0; i < 24; ++i)
    {
        const osg::Vec3 center(-4.0f + 1.6f * (i % 6), 0.0f, -2.4f + 1.6f * (i / 6));
        const osg::Vec4ub color(40 + 8 * i, 220 - 8 * i, (60 + 70 * i) % 256, 255);
        spheres.push_back({center, 0.01f * (6 + 58 * i / 23), color});
        palette.push_back(color);
    }
    AnalyticScene truth;
    addSpheres(truth, spheres);
    const Frame frame = renderer.render(group({createSphereCloud(spheres).get()}).get());
    saveFrame(frame, "small_spheres");

    const Agreement agreement = compareWithTruth(frame, truth, palette, EXACT_DEPTH);
    EXPECT_GT(agreement.covered, 1500); // the sum of pi * (radius * 16.48)^2 is 1770 pixels
    EXPECT_EQ(agreement.wrongLabel, 0) << "of " << agreement.certain << " certain pixels";
    EXPECT_EQ(agreement.wrongDepth, 0) << "worst depth error " << agreement.worstDepthError;
}

TEST_F(SphereImpostor, SubPixelSpheresHitExactlyThePixelCentresTheyCover)
{
    // Spheres of 0.2 to 1 pixel, most between pixel centres: those are culled before
    // rasterisation, and the rest must still hit every centre they cover.
    std::vector<SphereSpec> spheres;
    std::vector<osg::Vec4ub> palette;
    for (int i = 0; i < 400; ++i)
    {
        const osg::Vec3 center(-4.5f + 0.4507f * (i % 20), 0.0f, -3.3f + 0.3301f * (i / 20));
        const osg::Vec4ub color(20 + 11 * (i % 20), 20 + 11 * (i / 20), 200, 255);
        spheres.push_back({center, 0.004f * (4 + i % 13), color}); // k/16 of the largest radius
        palette.push_back(color);
    }
    AnalyticScene truth;
    addSpheres(truth, spheres);
    const Frame frame = renderer.render(group({createSphereCloud(spheres).get()}).get());

    // Too small for compareWithTruth's certain pixels: compare every pixel centre's ray.
    const CentreAgreement agreement = compareEveryPixelCentre(frame, truth, palette, EXACT_DEPTH);
    EXPECT_GT(agreement.hits, 300);
    EXPECT_EQ(agreement.wrongCoverage, 0) << "of " << agreement.hits << " pixel centres on a sphere";
    EXPECT_EQ(agreement.wrongLabel, 0);
    EXPECT_EQ(agreement.wrongDepth, 0);
}

TEST_F(SphereImpostor, DepthMatchesAFinelyTessellatedFixedFunctionSphere)
{
    const osg::Vec3 center(-0.3f, 0.5f, 0.2f);
    const Frame impostor = renderer.render(group({createSphereCloud({{center, 1.0f, RED}}).get()}).get());
    osg::ref_ptr<osg::TessellationHints> hints = new osg::TessellationHints;
    hints->setDetailRatio(8.0f);
    const Frame tessellated =
        renderer.render(group({new osg::ShapeDrawable(new osg::Sphere(center, 1.0f), hints.get())}).get());

    AnalyticScene truth;
    truth.addSphere(center, 1.0);
    int both = 0, differing = 0;
    double worst = 0.0;
    for (int y = 0; y < impostor.height(); ++y)
    {
        for (int x = 0; x < impostor.width(); ++x)
        {
            if (!impostor.isCovered(x, y) || !tessellated.isCovered(x, y))
                continue;
            // Near the silhouette the depth slope magnifies the tessellation's chord error.
            osg::Vec3d origin, direction;
            impostor.pixelRay(x + 0.5, y + 0.5, origin, direction);
            const RayHit hit = truth.cast(origin, direction);
            if (!hit.hit() || -(hit.normal * direction) < 0.3)
                continue;
            ++both;
            // The tessellation's chord error is 2e-4 of the radius: 3e-6 in window depth here.
            const double error = std::fabs(impostor.depthAt(x, y) - tessellated.depthAt(x, y));
            worst = std::max(worst, error);
            differing += error > 5e-6 ? 1 : 0;
        }
    }
    EXPECT_GT(both, 600);
    EXPECT_EQ(differing, 0) << "worst difference " << worst;
}

TEST_F(SphereImpostor, OrthographicProjectionIsExactToo)
{
    renderer.getViewer()->getCamera()->setProjectionMatrixAsOrtho(-4.0, 4.0, -3.0, 3.0, 1.0, 30.0);
    const std::vector<SphereSpec> spheres = {{osg::Vec3(1.5f, -1.0f, 0.5f), 0.75f, RED},
                                             {osg::Vec3(-1.0f, 2.0f, -0.5f), 1.5f, GREEN}};
    AnalyticScene truth;
    addSpheres(truth, spheres);
    const Frame frame = renderer.render(group({createSphereCloud(spheres).get()}).get());
    const Agreement agreement = compareWithTruth(frame, truth, {RED, GREEN}, EXACT_DEPTH);
    EXPECT_GT(agreement.covered, 2500); // 20 pixels per unit
    EXPECT_EQ(agreement.wrongLabel, 0);
    EXPECT_EQ(agreement.wrongDepth, 0) << "worst depth error " << agreement.worstDepthError;
}

TEST_F(SphereImpostor, TwoSpheresIntersectAlongTheAnalyticCurve)
{
    const std::vector<SphereSpec> spheres = {{osg::Vec3(-0.5f, 0.0f, 0.0f), 1.0f, RED},
                                             {osg::Vec3(0.5f, 0.3f, 0.2f), 0.875f, GREEN}};
    AnalyticScene truth;
    addSpheres(truth, spheres);
    const Frame frame = renderer.render(group({createSphereCloud(spheres).get()}).get());
    saveFrame(frame, "sphere_intersection");
    const Agreement agreement = compareWithTruth(frame, truth, {RED, GREEN}, EXACT_DEPTH);

    // The curve exists in the picture: both spheres are visible, and each certain pixel shows
    // the sphere the analytic nearest hit names.
    int curvePixels = 0;
    for (int y = 0; y < frame.height(); ++y)
        for (int x = 1; x < frame.width(); ++x)
            curvePixels += (labelOfColor(frame.colorAt(x - 1, y), {RED}) == 0 &&
                            labelOfColor(frame.colorAt(x, y), {GREEN}) == 0)
                               ? 1
                               : 0;
    EXPECT_GT(curvePixels, 10);
    EXPECT_EQ(agreement.wrongLabel, 0) << "of " << agreement.certain << " certain pixels";
    EXPECT_EQ(agreement.wrongDepth, 0) << "worst depth error " << agreement.worstDepthError;
}

TEST_F(SphereImpostor, FixedFunctionPlaneCutsTheSphere)
{
    renderer.setLookAt(osg::Vec3d(1.0, -9.0, 4.0), osg::Vec3d(), osg::Vec3d(0.0, 0.0, 1.0));
    const std::vector<SphereSpec> spheres = {{osg::Vec3(0.0f, 0.0f, 0.0f), 1.0f, RED}};
    AnalyticScene truth;
    addSpheres(truth, spheres);
    truth.addPlane(osg::Vec3d(0.0, 0.0, 0.25), osg::Vec3d(0.0, 0.0, 1.0), 2.0);
    osg::ref_ptr<osg::Geometry> plane =
        createFlatQuad(osg::Vec3(0.0f, 0.0f, 0.25f), osg::Vec3(2.0f, 0.0f, 0.0f), osg::Vec3(0.0f, 2.0f, 0.0f),
                       osg::Vec4(0.0f, 0.0f, 1.0f, 1.0f));
    const Frame frame = renderer.render(group({createSphereCloud(spheres).get(), plane.get()}).get());
    saveFrame(frame, "sphere_plane_cut");
    const Agreement agreement = compareWithTruth(frame, truth, {RED, BLUE}, EXACT_DEPTH);
    EXPECT_GT(agreement.covered, 1500);
    EXPECT_EQ(agreement.wrongLabel, 0) << "of " << agreement.certain << " certain pixels";
    EXPECT_EQ(agreement.wrongDepth, 0) << "worst depth error " << agreement.worstDepthError;
}

TEST_F(SphereImpostor, WideFieldOfViewSilhouetteIsTheProjectedEllipse)
{
    renderer.setPerspective(90.0, 0.5, 50.0);
    // Near the top-right corner the projection of a sphere is a markedly elongated ellipse.
    const std::vector<SphereSpec> spheres = {{osg::Vec3(3.6f, -7.0f, 2.0f), 0.75f, RED},
                                             {osg::Vec3(-3.9f, -7.3f, -2.1f), 0.5625f, GREEN}};
    AnalyticScene truth;
    addSpheres(truth, spheres);
    const Frame frame = renderer.render(group({createSphereCloud(spheres).get()}).get());
    saveFrame(frame, "sphere_wide_fov");
    const Agreement agreement = compareWithTruth(frame, truth, {RED, GREEN}, EXACT_DEPTH);
    EXPECT_GT(agreement.covered, 300);
    EXPECT_EQ(agreement.wrongLabel, 0) << "of " << agreement.certain << " certain pixels";
    EXPECT_EQ(agreement.wrongDepth, 0) << "worst depth error " << agreement.worstDepthError;
    EXPECT_TRUE(coverageMatches(
        frame, [&](int x, int y) { return truth.castPixel(frame, x, y).hit(); }, 6, "sphere_wide_fov"));
}

TEST_F(SphereImpostor, SphereCrossingTheNearPlaneIsCutNotDropped)
{
    // The near plane is at y = -9; the sphere spans y in [-9.1, -8.1].
    const osg::Vec3 center(0.05f, -8.6f, 0.02f);
    const float radius = 0.5f;
    const Frame frame = renderer.render(group({createSphereCloud({{center, radius, RED}}).get()}).get());
    saveFrame(frame, "sphere_near_plane_cut");

    int cut = 0, surface = 0, wrong = 0;
    for (int y = 0; y < frame.height(); ++y)
    {
        for (int x = 0; x < frame.width(); ++x)
        {
            osg::Vec3d origin, direction; // origin on the near plane
            frame.pixelRay(x + 0.5, y + 0.5, origin, direction);
            const osg::Vec3d m = origin - osg::Vec3d(center);
            const double b = m * direction;
            const double h2 = radius * radius - (m - direction * b).length2();
            if (std::fabs(h2) < 2e-3)
                continue; // too close to the silhouette to call
            const bool hits = h2 > 0.0 && -b + std::sqrt(h2) > 0.0;
            if (!hits)
            {
                wrong += frame.isCovered(x, y) ? 1 : 0;
                continue;
            }
            const double enter = -b - std::sqrt(h2);
            const double expected = enter >= 0.0 ? frame.windowDepth(origin + direction * enter) : 0.0;
            (enter >= 0.0 ? surface : cut) += 1;
            // So close to the eye the depth slope is steep: compare distances along the view axis.
            const double expectedDistance =
                osgGlyphsHeadless::eyeDistanceFromWindowDepth(frame.projection, expected);
            const double distance =
                osgGlyphsHeadless::eyeDistanceFromWindowDepth(frame.projection, frame.depthAt(x, y));
            const bool bad = !frame.isCovered(x, y) || std::fabs(distance - expectedDistance) > 2e-5;
            wrong += bad ? 1 : 0;
        }
    }
    EXPECT_GT(cut, 3000);     // the cut disc, radius 0.3 at distance 1: 7500 pixels
    EXPECT_GT(surface, 2000); // the ring of sphere around it
    EXPECT_EQ(wrong, 0);
}

TEST_F(SphereImpostor, LitShadingIsBlinnPhongUnderTheHeadlight)
{
    const osg::Vec4ub base(200, 120, 60, 255);
    const std::vector<SphereSpec> spheres = {{osg::Vec3(0.2f, 0.0f, 0.1f), 1.3f, base}};
    osg::ref_ptr<GlyphCloud> cloud = createSphereCloud(spheres, true);
    cloud->setMaterial(0.15f, 0.5f, 30.0f);
    AnalyticScene truth;
    addSpheres(truth, spheres);
    const Frame frame = renderer.render(group({cloud.get()}).get());
    saveFrame(frame, "sphere_lit");

    const osg::Light* light = renderer.getViewer()->getLight();
    ASSERT_NE(light, nullptr);
    int checked = 0, wrong = 0;
    for (int y = 0; y < frame.height(); ++y)
    {
        for (int x = 0; x < frame.width(); ++x)
        {
            if (truth.certainLabel(frame, x, y) != 0)
                continue;
            const RayHit hit = truth.castPixel(frame, x, y);
            osg::Vec3d origin, direction;
            frame.pixelRay(x + 0.5, y + 0.5, origin, direction);
            // Eye space: the headlight shines along the view axis from the eye.
            osg::Vec3d normal = osg::Matrixd::transform3x3(hit.normal, frame.view);
            osg::Vec3d toEye = -osg::Matrixd::transform3x3(direction, frame.view);
            normal.normalize();
            toEye.normalize();
            const osg::Vec3d toLight(0.0, 0.0, 1.0);
            const double diffuse = std::max(normal * toLight, 0.0);
            osg::Vec3d halfway = toLight + toEye;
            halfway.normalize();
            const double specular = diffuse > 0.0 ? std::pow(std::max(normal * halfway, 0.0), 30.0) : 0.0;
            osg::Vec4ub expected(0, 0, 0, 255);
            for (int c = 0; c < 3; ++c)
            {
                const double value =
                    base[c] / 255.0 * (0.15 + light->getAmbient()[c] + diffuse * light->getDiffuse()[c]) +
                    0.5 * specular * light->getSpecular()[c];
                expected[c] = static_cast<unsigned char>(std::lround(std::clamp(value, 0.0, 1.0) * 255.0));
            }
            ++checked;
            wrong += colorNear(frame, x, y, expected, 3) ? 0 : 1;
        }
    }
    EXPECT_GT(checked, 1200);
    EXPECT_EQ(wrong, 0) << "of " << checked;
}

TEST_F(SphereImpostor, LightingIsSwitchedPerCloudOrPerSubgraph)
{
    const osg::Vec4ub base(200, 120, 60, 255);
    osg::ref_ptr<GlyphCloud> cloud = createSphereCloud({{osg::Vec3(), 1.5f, base}}, true);
    osg::ref_ptr<osg::Group> root = new osg::Group;
    root->addChild(group({cloud.get()}));

    auto countBase = [&](const Frame& frame)
    {
        int count = 0;
        for (int y = 0; y < frame.height(); ++y)
            for (int x = 0; x < frame.width(); ++x)
                count += frame.isCovered(x, y) && labelOfColor(frame.colorAt(x, y), {base}, 1) == 0 ? 1 : 0;
        return count;
    };
    const int coveredPixels = 1900; // about pi * (1.5 * 164.8 / 10)^2
    EXPECT_LT(countBase(renderer.render(root.get())), coveredPixels / 10) << "lit";
    osgGlyphs::setGlyphLighting(*root->getOrCreateStateSet(), false);
    EXPECT_GT(countBase(renderer.render(root.get())), coveredPixels * 9 / 10) << "unlit subgraph";
    root->getStateSet()->removeDefine(osgGlyphs::GLYPH_LIT_DEFINE);
    cloud->setLit(false);
    EXPECT_GT(countBase(renderer.render(root.get())), coveredPixels * 9 / 10) << "unlit cloud";
    osgGlyphs::setGlyphLighting(*root->getStateSet(), true);
    EXPECT_LT(countBase(renderer.render(root.get())), coveredPixels / 10) << "lit subgraph";
}

TEST_F(SphereImpostor, LitByAnOsgLightSource)
{
    // A directional light from +x, in place of the view's headlight: the +x side is brightest.
    renderer.getViewer()->setLightingMode(osg::View::NO_LIGHT);
    osg::ref_ptr<osg::LightSource> source = new osg::LightSource;
    source->getLight()->setLightNum(0);
    source->getLight()->setPosition(osg::Vec4(1.0f, 0.0f, 0.0f, 0.0f));
    source->getLight()->setDiffuse(osg::Vec4(1.0f, 1.0f, 1.0f, 1.0f));
    source->getLight()->setSpecular(osg::Vec4(0.0f, 0.0f, 0.0f, 1.0f));
    source->getLight()->setAmbient(osg::Vec4(0.0f, 0.0f, 0.0f, 1.0f));
    source->addChild(
        group({createSphereCloud({{osg::Vec3(), 2.0f, osg::Vec4ub(255, 255, 255, 255)}}, true).get()}));
    osg::ref_ptr<osg::Group> root = new osg::Group;
    root->addChild(source.get());
    const Frame frame = renderer.render(root.get());

    const osg::Vec3d right = frame.project(osg::Vec3d(1.9, -0.6, 0.0));
    const osg::Vec3d left = frame.project(osg::Vec3d(-1.9, -0.6, 0.0));
    const osg::Vec3d centre = frame.project(osg::Vec3d(0.0, -2.0, 0.0));
    const int bright = frame.colorAt(int(right.x()), int(right.y())).r();
    const int dark = frame.colorAt(int(left.x()), int(left.y())).r();
    const int middle = frame.colorAt(int(centre.x()), int(centre.y())).r();
    EXPECT_GT(bright, 200);
    // Unlit sides get only the ambient term: 0.2 of the base colour.
    EXPECT_NEAR(dark, 51, 2);
    EXPECT_NEAR(middle, 51, 4); // the pixel centre faces the light by a degree or so
}

TEST_F(SphereImpostor, CopiesRenderLikeTheOriginal)
{
    osg::ref_ptr<GlyphCloud> original = createSphereCloud(
        {{osg::Vec3(-1.0f, 0.0f, 0.0f), 1.0f, RED}, {osg::Vec3(1.2f, 0.0f, 0.5f), 0.75f, GREEN}});
    original->setMaterial(0.3f, 0.1f, 20.0f);
    osg::ref_ptr<GlyphCloud> deep = osg::clone(original.get(), osg::CopyOp::DEEP_COPY_ALL);
    osg::ref_ptr<GlyphCloud> shallow = osg::clone(original.get(), osg::CopyOp::SHALLOW_COPY);
    EXPECT_NE(deep->getPositions(), original->getPositions());
    EXPECT_EQ(shallow->getPositions(), original->getPositions());
    EXPECT_EQ(deep->getNumGlyphs(), 2u);
    EXPECT_FLOAT_EQ(deep->getShininess(), 20.0f);

    const Frame expected = renderer.render(group({original.get()}).get());
    for (GlyphCloud* copy : {deep.get(), shallow.get()})
    {
        const Frame frame = renderer.render(group({copy}).get());
        int differing = 0;
        for (int y = 0; y < frame.height(); ++y)
            for (int x = 0; x < frame.width(); ++x)
                differing += (frame.colorAt(x, y) != expected.colorAt(x, y) ||
                              frame.depthAt(x, y) != expected.depthAt(x, y))
                                 ? 1
                                 : 0;
        EXPECT_EQ(differing, 0);
    }
    // A deep copy's arrays are its own: editing it leaves the original alone.
    (*deep->getPositions())[0].x() = 3.0f;
    deep->getPositions()->dirty();
    deep->dirtyGlyphs();
    EXPECT_FLOAT_EQ((*original->getPositions())[0].x(), -1.0f);
}
