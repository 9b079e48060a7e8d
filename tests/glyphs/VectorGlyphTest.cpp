// Cones, arrows and cylinders against analytic truth: silhouettes and depth along, against and
// across the view axis, occlusion with fixed-function geometry, crossing glyphs, the near
// plane, wide fields of view, lit colours against the analytic normal, how tightly the screen
// bound holds a cone, the paper's cone technique, and degenerate vectors.

#include "GlyphTestScenes.h"

#include <osgGlyphsPaper/Techniques>

#include <osgGlyphs/GlyphCloud>

#include <osg/LightSource>

#include <algorithm>
#include <cmath>
#include <limits>

using namespace osgGlyphsTest;
using osgGlyphs::GlyphAnchor;
using osgGlyphs::GlyphCloud;
using osgGlyphs::GlyphShape;

namespace
{

const osg::Vec4ub RED(255, 0, 0, 255);
const osg::Vec4ub GREEN(0, 255, 0, 255);
const osg::Vec4ub BLUE(0, 0, 255, 255);
const std::vector<osg::Vec4ub> PALETTE = {RED, GREEN, BLUE};
const double HEAD_LENGTH = 0.3, HEAD_RADIUS = 2.0; // GlyphCloud's arrow defaults

struct VectorSpec
{
    osg::Vec3 position;
    osg::Vec3 vector;
    float radius;
    osg::Vec4ub color;
};

osg::ref_ptr<GlyphCloud> createVectorCloud(GlyphShape shape, const std::vector<VectorSpec>& glyphs,
                                           bool lit = false)
{
    osg::ref_ptr<osg::Vec3Array> positions = new osg::Vec3Array, vectors = new osg::Vec3Array;
    osg::ref_ptr<osg::FloatArray> radii = new osg::FloatArray;
    osg::ref_ptr<osg::Vec4ubArray> colors = new osg::Vec4ubArray;
    for (const VectorSpec& glyph : glyphs)
    {
        positions->push_back(glyph.position);
        vectors->push_back(glyph.vector);
        radii->push_back(glyph.radius);
        colors->push_back(glyph.color);
    }
    osg::ref_ptr<GlyphCloud> cloud = new GlyphCloud;
    cloud->setShape(shape);
    cloud->setPositions(positions.get());
    cloud->setVectors(vectors.get());
    cloud->setRadii(radii.get());
    cloud->setColors(colors.get());
    cloud->setLit(lit);
    return cloud;
}

/** The same glyphs, centred on their points (the default anchor), as analytic solids. */
void addVectorGlyphs(AnalyticScene& scene, GlyphShape shape, const std::vector<VectorSpec>& glyphs)
{
    for (const VectorSpec& glyph : glyphs)
    {
        osg::Vec3d axis = glyph.vector;
        const double length = axis.normalize();
        const osg::Vec3d tail = osg::Vec3d(glyph.position) - axis * (0.5 * length);
        if (shape == GlyphShape::Cone)
            scene.addCone(tail, axis, length, glyph.radius);
        else if (shape == GlyphShape::Cylinder)
            scene.addCylinder(tail, axis, length, glyph.radius);
        else
            scene.addArrow(tail, axis, length, glyph.radius, HEAD_LENGTH, HEAD_RADIUS);
    }
}

/** Depth agrees to 5e-7 (a few 24-bit steps) everywhere but at a few tips and rims, where
 * single-precision quadratics lose digits; those may not exceed 0.5% of the pixels. Grazing
 * hits are not compared. */
Agreement compareWithTruth(const Frame& frame, const AnalyticScene& truth,
                           const std::vector<osg::Vec4ub>& palette)
{
    return osgGlyphsTest::compareWithTruth(frame, truth, palette, 5e-7, 0.15);
}

class VectorGlyphs : public ::testing::TestWithParam<GlyphShape>
{
protected:
    Renderer renderer{160, 120};

    /** Renders the glyphs as the test's shape and compares them with the analytic solids. */
    Agreement renderAndCompare(const std::vector<VectorSpec>& glyphs, const std::string& name,
                               osg::Drawable* extra = nullptr, const AnalyticScene* withExtra = nullptr)
    {
        AnalyticScene truth = withExtra ? *withExtra : AnalyticScene();
        addVectorGlyphs(truth, GetParam(), glyphs);
        osg::ref_ptr<osg::Geode> scene = group({createVectorCloud(GetParam(), glyphs).get()});
        if (extra)
            scene->addDrawable(extra);
        const Frame frame = renderer.render(scene.get());
        saveFrame(frame, name + "_" + shapeName());
        std::vector<osg::Vec4ub> palette = PALETTE;
        return compareWithTruth(frame, truth, palette);
    }

    std::string shapeName() const
    {
        return GetParam() == GlyphShape::Cone    ? "cone"
               : GetParam() == GlyphShape::Arrow ? "arrow"
                                                 : "cylinder";
    }
};

}

TEST_P(VectorGlyphs, AlongAgainstAndAcrossTheViewAxis)
{
    // The camera looks along +y: towards the viewer, away from it, and oblique.
    const std::vector<VectorSpec> glyphs = {
        {osg::Vec3(-2.2f, 0.0f, 0.6f), osg::Vec3(0.0f, -2.0f, 0.0f), 0.5f, RED},
        {osg::Vec3(0.0f, 0.0f, 0.6f), osg::Vec3(0.0f, 2.0f, 0.0f), 0.5f, GREEN},
        {osg::Vec3(2.0f, 0.5f, -0.8f), osg::Vec3(1.2f, -1.0f, 1.5f), 0.5f, BLUE}};
    const Agreement agreement = renderAndCompare(glyphs, "vector_axes");
    EXPECT_GT(agreement.covered, 500);
    EXPECT_EQ(agreement.wrongLabel, 0) << "of " << agreement.certain << " certain pixels";
    EXPECT_LE(agreement.wrongDepth, agreement.covered / 200)
        << "worst depth error " << agreement.worstDepthError;
}

TEST_P(VectorGlyphs, SmallGlyphsAreExactToo)
{
    // Glyphs a few pixels long get a one-triangle bound, larger ones a quad. Radii are k/64 of
    // the largest, which the half-float radius holds exactly.
    std::vector<VectorSpec> glyphs;
    std::vector<osg::Vec4ub> palette;
    for (int i = 0; i < 24; ++i)
    {
        const osg::Vec3 position(-4.0f + 1.6f * (i % 6), 0.0f, -2.4f + 1.6f * (i / 6));
        const float radius = 0.005f * (6 + 58 * i / 23);
        const osg::Vec3 direction(std::cos(0.9f * i), std::sin(1.7f * i), std::sin(0.9f * i));
        const osg::Vec4ub color(40 + 8 * i, 220 - 8 * i, (60 + 70 * i) % 256, 255);
        glyphs.push_back({position, direction * (5.0f * radius / direction.length()), radius, color});
        palette.push_back(color);
    }
    AnalyticScene truth;
    addVectorGlyphs(truth, GetParam(), glyphs);
    const Frame frame = renderer.render(group({createVectorCloud(GetParam(), glyphs).get()}).get());
    saveFrame(frame, "small_vectors_" + shapeName());

    const Agreement agreement = compareWithTruth(frame, truth, palette);
    EXPECT_GT(agreement.covered, 300);
    EXPECT_EQ(agreement.wrongLabel, 0) << "of " << agreement.certain << " certain pixels";
    EXPECT_LE(agreement.wrongDepth, agreement.covered / 200)
        << "worst depth error " << agreement.worstDepthError;
}

TEST_P(VectorGlyphs, SubPixelGlyphsHitExactlyThePixelCentresTheyCover)
{
    // Glyphs 0.25 to 1 pixel wide and 1 to 3 long, slanted every way: a glyph is culled before
    // rasterisation when its slanted bound holds no pixel centre, and the rest must still hit
    // every centre they cover. Radii are k/8 of the largest.
    std::vector<VectorSpec> glyphs;
    std::vector<osg::Vec4ub> palette;
    for (int i = 0; i < 400; ++i)
    {
        const osg::Vec3 position(-4.5f + 0.4507f * (i % 20), 0.0f, -3.3f + 0.3301f * (i / 20));
        const float radius = 0.004f * (2 + i % 7);
        const osg::Vec3 direction(std::cos(0.9f * i), std::sin(1.7f * i), std::sin(0.9f * i));
        const osg::Vec4ub color(20 + 11 * (i % 20), 20 + 11 * (i / 20), 200, 255);
        glyphs.push_back(
            {position, direction * ((4.0f + i % 3) * radius / direction.length()), radius, color});
        palette.push_back(color);
    }
    AnalyticScene truth;
    addVectorGlyphs(truth, GetParam(), glyphs);
    const Frame frame = renderer.render(group({createVectorCloud(GetParam(), glyphs).get()}).get());
    saveFrame(frame, "subpixel_vectors_" + shapeName());

    // Depth is compared on larger glyphs (SmallGlyphsAreExactToo); here coverage and colour.
    const CentreAgreement agreement = compareEveryPixelCentre(frame, truth, palette, 1.0);
    EXPECT_GT(agreement.hits, 200);
    EXPECT_EQ(agreement.wrongCoverage, 0) << "of " << agreement.hits << " pixel centres on a glyph";
    EXPECT_EQ(agreement.wrongLabel, 0);
}

TEST_P(VectorGlyphs, OccludedByAndPiercingFixedFunctionGeometry)
{
    renderer.setLookAt(osg::Vec3d(2.0, -9.0, 3.0), osg::Vec3d(), osg::Vec3d(0.0, 0.0, 1.0));
    AnalyticScene plane;
    plane.addPlane(osg::Vec3d(0.0, 0.0, 0.0), osg::Vec3d(0.0, 0.0, 1.0), 2.5);
    osg::ref_ptr<osg::Geometry> quad =
        createFlatQuad(osg::Vec3(), osg::Vec3(2.5f, 0.0f, 0.0f), osg::Vec3(0.0f, 2.5f, 0.0f),
                       osg::Vec4(0.0f, 0.0f, 1.0f, 1.0f));
    const std::vector<VectorSpec> glyphs = {
        {osg::Vec3(-0.8f, 0.0f, 0.2f), osg::Vec3(0.3f, 0.4f, 2.5f), 0.5f, RED},
        {osg::Vec3(1.0f, 0.5f, -0.1f), osg::Vec3(2.0f, -0.5f, 0.6f), 0.375f, GREEN}};
    // Labels: the plane is 0 (blue), the glyphs 1 and 2 (red, green).
    const std::vector<VectorSpec> relabelled = glyphs;
    AnalyticScene truth = plane;
    addVectorGlyphs(truth, GetParam(), relabelled);
    const Frame frame =
        renderer.render(group({createVectorCloud(GetParam(), glyphs).get(), quad.get()}).get());
    saveFrame(frame, "vector_plane_" + shapeName());
    const Agreement agreement = compareWithTruth(frame, truth, {BLUE, RED, GREEN});
    EXPECT_GT(agreement.covered, 2000);
    EXPECT_EQ(agreement.wrongLabel, 0) << "of " << agreement.certain << " certain pixels";
    EXPECT_LE(agreement.wrongDepth, agreement.covered / 200)
        << "worst depth error " << agreement.worstDepthError;
}

TEST_P(VectorGlyphs, CrossingGlyphsIntersectThroughDepth)
{
    const std::vector<VectorSpec> glyphs = {
        {osg::Vec3(0.0f, 0.0f, 0.0f), osg::Vec3(3.0f, 0.5f, 1.0f), 0.6f, RED},
        {osg::Vec3(0.2f, 0.1f, 0.1f), osg::Vec3(-1.0f, -0.8f, 3.0f), 0.6f, GREEN}};
    const Agreement agreement = renderAndCompare(glyphs, "vector_crossing");
    EXPECT_GT(agreement.covered, 700);
    EXPECT_EQ(agreement.wrongLabel, 0) << "of " << agreement.certain << " certain pixels";
    EXPECT_LE(agreement.wrongDepth, agreement.covered / 200)
        << "worst depth error " << agreement.worstDepthError;
}

TEST_P(VectorGlyphs, WideFieldOfViewNearTheBorder)
{
    renderer.setPerspective(90.0, 0.5, 50.0);
    const std::vector<VectorSpec> glyphs = {
        {osg::Vec3(3.4f, -6.5f, 2.0f), osg::Vec3(0.0f, -1.5f, 0.3f), 0.4f, RED},
        {osg::Vec3(-3.6f, -6.8f, -2.0f), osg::Vec3(1.0f, 0.0f, 1.0f), 0.3f, GREEN}};
    const Agreement agreement = renderAndCompare(glyphs, "vector_wide_fov");
    EXPECT_GT(agreement.covered, 300);
    EXPECT_EQ(agreement.wrongLabel, 0) << "of " << agreement.certain << " certain pixels";
    EXPECT_LE(agreement.wrongDepth, agreement.covered / 200)
        << "worst depth error " << agreement.worstDepthError;
}

TEST_P(VectorGlyphs, CrossingTheNearPlaneIsCut)
{
    // The near plane is at y = -9: the glyph reaches from y = -9.8 to y = -8.2.
    const std::vector<VectorSpec> glyphs = {
        {osg::Vec3(0.1f, -9.0f, 0.0f), osg::Vec3(0.0f, 1.6f, 0.3f), 0.4f, RED}};
    const Frame frame = renderer.render(group({createVectorCloud(GetParam(), glyphs).get()}).get());
    saveFrame(frame, "vector_near_plane_" + shapeName());
    // Pixels whose ray from the near plane starts inside the solid show the cut, at depth 0.
    AnalyticScene truth;
    addVectorGlyphs(truth, GetParam(), glyphs);
    int cut = 0, wrong = 0;
    for (int y = 0; y < frame.height(); ++y)
    {
        for (int x = 0; x < frame.width(); ++x)
        {
            osg::Vec3d origin, direction;
            frame.pixelRay(x + 0.5, y + 0.5, origin, direction);
            const RayHit behind = truth.cast(origin - direction * 100.0, direction); // from outside
            const bool startsInside = behind.hit() && behind.distance < 100.0 &&
                                      truth.cast(origin, direction).hit() &&
                                      truth.cast(origin, direction).normal * direction > 0.0;
            if (!startsInside || truth.certainLabel(frame, x, y) == AnalyticScene::AMBIGUOUS)
                continue;
            ++cut;
            wrong += (frame.isCovered(x, y) && frame.depthAt(x, y) < 1e-6) ? 0 : 1;
        }
    }
    EXPECT_GT(cut, 100);
    EXPECT_EQ(wrong, 0);
}

TEST_P(VectorGlyphs, ZeroVectorsAreNotDrawnAndNonFiniteOnesWarn)
{
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const std::vector<VectorSpec> glyphs = {
        {osg::Vec3(-2.0f, 0.0f, 0.0f), osg::Vec3(0.0f, 0.0f, 1.5f), 0.4f, RED},
        {osg::Vec3(0.0f, 0.0f, 0.0f), osg::Vec3(0.0f, 0.0f, 0.0f), 0.4f, GREEN},
        {osg::Vec3(2.0f, 0.0f, 0.0f), osg::Vec3(nan, 0.0f, 1.0f), 0.4f, BLUE}};
    osg::ref_ptr<NotifyCapture> capture = new NotifyCapture;
    osg::ref_ptr<GlyphCloud> cloud = createVectorCloud(GetParam(), glyphs);
    const std::string warnings = capture->stop();
    EXPECT_NE(warnings.find("1 of 3 glyphs have a non-finite vector"), std::string::npos) << warnings;
    EXPECT_EQ(warnings.find("zero vector"), std::string::npos) << "a zero vector is not an error";
    EXPECT_EQ(cloud->getNumSkippedGlyphs(), 2u);

    AnalyticScene truth;
    addVectorGlyphs(truth, GetParam(), {glyphs[0]});
    const Frame frame = renderer.render(group({cloud.get()}).get());
    EXPECT_TRUE(coverageMatches(
        frame, [&](int x, int y) { return truth.castPixel(frame, x, y).hit(); }, 4, "vector_degenerate"));
}

TEST_P(VectorGlyphs, LengthScaleUniformLengthAndAnchor)
{
    const std::vector<VectorSpec> glyphs = {
        {osg::Vec3(-1.0f, 0.0f, 0.0f), osg::Vec3(0.0f, 0.0f, 4.0f), 0.3f, RED},
        {osg::Vec3(1.0f, 0.0f, 0.0f), osg::Vec3(0.0f, 0.0f, 0.5f), 0.3f, GREEN}};
    osg::ref_ptr<GlyphCloud> cloud = createVectorCloud(GetParam(), glyphs);
    cloud->setUniformLength(true);
    cloud->setLengthScale(2.0f);
    cloud->setAnchor(GlyphAnchor::Tail);
    // Both glyphs are 2 long and start on their points.
    EXPECT_NEAR(cloud->getBoundingBox().zMin(), -0.3f * (GetParam() == GlyphShape::Arrow ? 2.0f : 1.0f),
                1e-3f);
    EXPECT_NEAR(cloud->getBoundingBox().zMax(), 2.0f + 0.3f * (GetParam() == GlyphShape::Arrow ? 2.0f : 1.0f),
                1e-3f);

    AnalyticScene truth;
    for (const VectorSpec& glyph : glyphs)
    {
        const osg::Vec3d tail = glyph.position, axis(0.0, 0.0, 1.0);
        if (GetParam() == GlyphShape::Cone)
            truth.addCone(tail, axis, 2.0, 0.3);
        else if (GetParam() == GlyphShape::Cylinder)
            truth.addCylinder(tail, axis, 2.0, 0.3);
        else
            truth.addArrow(tail, axis, 2.0, 0.3, HEAD_LENGTH, HEAD_RADIUS);
    }
    const Frame frame = renderer.render(group({cloud.get()}).get());
    const Agreement agreement = compareWithTruth(frame, truth, PALETTE);
    EXPECT_GT(agreement.covered, 200);
    EXPECT_EQ(agreement.wrongLabel, 0);
    EXPECT_LE(agreement.wrongDepth, agreement.covered / 200)
        << "worst depth error " << agreement.worstDepthError;
}

TEST_P(VectorGlyphs, LitMatchesBaseline)
{
    renderer.setLookAt(osg::Vec3d(2.0, -8.0, 3.0), osg::Vec3d(), osg::Vec3d(0.0, 0.0, 1.0));
    std::vector<VectorSpec> glyphs;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 3; ++j)
        {
            const float angle = 0.9f * float(i * 3 + j);
            glyphs.push_back({osg::Vec3(-2.4f + 1.6f * i, 0.0f, -1.6f + 1.6f * j),
                              osg::Vec3(std::cos(angle), std::sin(angle), 0.6f) * 1.2f, 0.22f,
                              osg::Vec4ub(220, 120 + 40 * j, 60 + 50 * i, 255)});
        }
    const Frame frame = renderer.render(group({createVectorCloud(GetParam(), glyphs, true).get()}).get());
    Tolerance tolerance;
    tolerance.colorChannel = 3;
    tolerance.colorPixelBudget = 8;
    tolerance.depth = 1e-6f;
    tolerance.depthPixelBudget = 8;
    EXPECT_TRUE(matchesBaseline(frame, "vector_lit_" + shapeName(), tolerance));
}

TEST_P(VectorGlyphs, LitColourFollowsTheAnalyticNormal)
{
    // A directional light from the upper left front, coloured, in place of the headlight: every
    // part of a normal (across and along the axis) changes the shade, whichever way the glyph points.
    Renderer large(320, 240);
    large.getViewer()->setLightingMode(osg::View::NO_LIGHT);
    osg::ref_ptr<osg::LightSource> source = createColouredLight();
    const osg::Light* light = source->getLight();
    const osg::Vec3d material(0.12, 0.5, 24.0);

    // Towards the viewer, away from it, across, up and down, oblique.
    const std::vector<VectorSpec> glyphs = {
        {osg::Vec3(-2.4f, 0.0f, 1.1f), osg::Vec3(0.0f, -2.0f, 0.0f), 0.45f, osg::Vec4ub(200, 160, 110, 255)},
        {osg::Vec3(0.0f, 0.0f, 1.1f), osg::Vec3(0.6f, 1.6f, 0.8f), 0.45f, osg::Vec4ub(110, 190, 150, 255)},
        {osg::Vec3(2.4f, 0.0f, 1.1f), osg::Vec3(2.0f, 0.0f, 0.3f), 0.45f, osg::Vec4ub(150, 130, 220, 255)},
        {osg::Vec3(-2.4f, 0.0f, -1.2f), osg::Vec3(-1.2f, -1.0f, 1.5f), 0.45f,
         osg::Vec4ub(210, 110, 140, 255)},
        {osg::Vec3(0.0f, 0.0f, -1.2f), osg::Vec3(0.0f, 0.5f, -2.0f), 0.45f, osg::Vec4ub(120, 170, 210, 255)},
        {osg::Vec3(2.4f, 0.0f, -1.2f), osg::Vec3(-1.0f, 0.7f, 1.4f), 0.45f, osg::Vec4ub(180, 180, 90, 255)}};
    osg::ref_ptr<GlyphCloud> cloud = createVectorCloud(GetParam(), glyphs, true);
    cloud->setMaterial(material.x(), material.y(), material.z());
    source->addChild(group({cloud.get()}));
    osg::ref_ptr<osg::Group> root = new osg::Group;
    root->addChild(source.get());
    const Frame frame = large.render(root.get());
    saveFrame(frame, "vector_lit_normals_" + shapeName());

    AnalyticScene truth;
    addVectorGlyphs(truth, GetParam(), glyphs);
    // Every pixel whose centre and neighbourhood show one glyph gets that glyph's colour, lit at
    // the analytic hit with the analytic normal, to 3 levels per channel: the shader's single
    // precision against double precision (1 level seen). A pixel centre on a rim or crease may fall
    // on the other side of it in single precision: 1 in 1000 pixels may differ.
    std::vector<osg::Vec4ub> colors;
    for (const VectorSpec& glyph : glyphs)
        colors.push_back(glyph.color);
    const LitAgreement agreement =
        compareLitWithTruth(frame, truth, colors, eyeLightOf(*light, frame), material, 3);
    EXPECT_GT(agreement.checked, 4000);
    EXPECT_LE(agreement.wrong, agreement.checked / 1000) << "of " << agreement.checked << " pixels";
}

INSTANTIATE_TEST_SUITE_P(, VectorGlyphs,
                         ::testing::Values(GlyphShape::Cone, GlyphShape::Arrow, GlyphShape::Cylinder),
                         [](const ::testing::TestParamInfo<GlyphShape>& param)
                         {
                             return param.param == GlyphShape::Cone    ? std::string("Cone")
                                    : param.param == GlyphShape::Arrow ? std::string("Arrow")
                                                                       : std::string("Cylinder");
                         });

TEST(VectorBound, HoldsAConeInATrapezoidNotItsRectangle)
{
    // impostor.frag replaced by one that fills every fragment it gets: the frame shows the
    // primitives themselves. Cones seen from the side and obliquely, 4 radii long.
    const std::string folder = writeShaderOverride(
        "bound-shader", "impostor.frag",
        "#version 330 compatibility\n#include \"glyph.glsl\"\n#include \"varyings.glsl\"\n"
        "out vec4 color;\nvoid main() { gl_FragDepth = gl_FragCoord.z; color = vec4(1.0); }\n");
    const std::vector<VectorSpec> glyphs = {
        {osg::Vec3(-2.6f, 0.0f, 0.0f), osg::Vec3(0.0f, 0.0f, 2.0f), 0.5f, RED},
        {osg::Vec3(0.0f, 0.0f, 0.0f), osg::Vec3(1.4f, 0.0f, -1.4f), 0.5f, GREEN},
        {osg::Vec3(2.6f, 0.0f, 0.0f), osg::Vec3(0.6f, -1.2f, 1.5f), 0.5f, BLUE}};
    AnalyticScene truth;
    addVectorGlyphs(truth, GlyphShape::Cone, glyphs);
    Renderer renderer(160, 120);
    const Frame frame = renderWithShaderFolder(
        renderer, group({createVectorCloud(GlyphShape::Cone, glyphs).get()}).get(), folder);
    saveFrame(frame, "cone_bounds");

    int onCone = 0, bound = 0, missed = 0;
    for (int y = 0; y < frame.height(); ++y)
        for (int x = 0; x < frame.width(); ++x)
        {
            const bool hit = truth.castPixel(frame, x, y).hit();
            onCone += hit ? 1 : 0;
            bound += frame.isCovered(x, y) ? 1 : 0;
            missed += hit && !frame.isCovered(x, y) ? 1 : 0;
        }
    EXPECT_GT(onCone, 600);
    EXPECT_EQ(missed, 0) << "pixel centres on a cone outside its bound";
    // Side on, a cone fills half of its rectangle; the trapezoid leaves it about one pixel all round.
    EXPECT_LT(bound, 1.3 * onCone) << "the bounds cover " << bound << " pixels for " << onCone
                                   << " on the cones";
}

TEST(PaperCone, DiffersFromTheExactConeWhereThePaperSaysItDoes)
{
    // The paper's cone (TPCG 2010, section 4): a billboard with a base ellipse and two
    // tangents, and the billboard's flat depth. Same cones, both techniques.
    Renderer renderer(160, 120);
    const std::vector<VectorSpec> glyphs = {
        {osg::Vec3(-1.8f, 0.0f, 0.0f), osg::Vec3(0.8f, -0.6f, 1.8f), 0.6f, RED},
        {osg::Vec3(1.5f, 0.0f, 0.2f), osg::Vec3(1.8f, 1.0f, -0.5f), 0.5f, GREEN}};
    osg::ref_ptr<GlyphCloud> exact = createVectorCloud(GlyphShape::Cone, glyphs);
    osg::ref_ptr<GlyphCloud> paper = createVectorCloud(GlyphShape::Cone, glyphs);
    paper->setTechnique(new osgGlyphsPaper::PaperQuadTechnique);
    const Frame exactFrame = renderer.render(group({exact.get()}).get());
    const Frame paperFrame = renderer.render(group({paper.get()}).get());
    saveFrame(exactFrame, "paper_cone_vs_exact_exact");
    saveFrame(paperFrame, "paper_cone_vs_exact_paper");

    // The silhouettes roughly agree: the paper's 2D construction is an orthographic sketch.
    int both = 0, either = 0;
    for (int y = 0; y < exactFrame.height(); ++y)
        for (int x = 0; x < exactFrame.width(); ++x)
        {
            both += exactFrame.isCovered(x, y) && paperFrame.isCovered(x, y) ? 1 : 0;
            either += exactFrame.isCovered(x, y) || paperFrame.isCovered(x, y) ? 1 : 0;
        }
    EXPECT_GT(either, 400);
    EXPECT_GT(double(both) / either, 0.6) << "overlap of the two silhouettes";
    EXPECT_LT(both, either) << "the paper's silhouette is only an approximation";

    // The paper writes the billboard's flat depth: nearly one depth per cone, where the exact
    // cone's depth spans its length.
    auto depthSpan = [](const Frame& frame, int xFrom, int xTo)
    {
        float lo = 1.0f, hi = 0.0f;
        for (int y = 0; y < frame.height(); ++y)
            for (int x = xFrom; x < xTo; ++x)
                if (frame.isCovered(x, y))
                {
                    lo = std::min(lo, frame.depthAt(x, y));
                    hi = std::max(hi, frame.depthAt(x, y));
                }
        return hi - lo;
    };
    EXPECT_GT(depthSpan(exactFrame, 0, 80), 5.0f * depthSpan(paperFrame, 0, 80));
    EXPECT_GT(depthSpan(exactFrame, 80, 160), 5.0f * depthSpan(paperFrame, 80, 160));
}
