// OSG's clip planes on glyph clouds: glyphs are cut along their true surface per fragment, open
// or capped, for every shape and technique, with several planes, against the analytic cut solid
// and side by side with tessellated osg::ShapeDrawables under the same planes.

#include "GlyphTestScenes.h"

#include <osgGlyphs/GlyphCloud>
#include <osgGlyphs/GlyphStateCache>
#include <osgGlyphs/ImpostorTechniques>

#include <osg/ClipNode>
#include <osg/ClipPlane>
#include <osg/LightSource>
#include <osg/ShapeDrawable>

#include <cmath>

using namespace osgGlyphsTest;
using osgGlyphs::GlyphCloud;
using osgGlyphs::GlyphShape;

namespace
{

const osg::Vec4ub RED(255, 0, 0, 255);
const osg::Vec4ub GREEN(0, 255, 0, 255);
const osg::Vec4ub BLUE(0, 0, 255, 255);
const std::vector<osg::Vec4ub> PALETTE = {RED, GREEN, BLUE};
const double HEAD_LENGTH = 0.3, HEAD_RADIUS = 2.0; // GlyphCloud's arrow defaults

/** Depth to a few 24-bit steps; grazing hits (|cos| < 0.15) are not compared. */
const double DEPTH_TOLERANCE = 5e-7;

/** A superquadric's semi-axes are 16-bit fractions of a radius up to sqrt(3) times the largest (the
 * bound of the rounded box here is 1.46 times): their rounding moves its surface by up to 1e-6. */
double depthToleranceOf(GlyphShape shape)
{
    return shape == GlyphShape::Superquadric ? 2.0 * DEPTH_TOLERANCE : DEPTH_TOLERANCE;
}

struct Glyph
{
    osg::Vec3 position;
    osg::Vec3 vector; // unused for spheres
    float radius;
    osg::Vec4ub color;
};

/** Three glyphs apart from each other: one towards the viewer, one across, one oblique. Radii are
 * k/16 of the largest, which half-float radii hold exactly. */
const std::vector<Glyph> GLYPHS = {{osg::Vec3(-2.3f, 0.0f, 0.2f), osg::Vec3(0.3f, -1.6f, 0.9f), 0.64f, RED},
                                   {osg::Vec3(0.0f, 0.3f, -0.3f), osg::Vec3(1.9f, 0.2f, 0.4f), 0.56f, GREEN},
                                   {osg::Vec3(2.3f, -0.2f, 0.4f), osg::Vec3(-0.6f, 1.0f, -1.5f), 0.6f, BLUE}};

/** An ellipsoid glyph's semi-axes (half the vector along body x, the radius, 0.7 of it) and turn
 * (body x along the vector). */
osg::Vec3 semiAxesOf(const Glyph& glyph)
{
    return osg::Vec3(0.5f * glyph.vector.length(), glyph.radius, 0.7f * glyph.radius);
}

/** A superquadric glyph's exponents, with the ellipsoid's semi-axes and turn: a rounded box. */
const osg::Vec2 EXPONENTS(0.3f, 0.6f);

osg::Quat turnOf(const Glyph& glyph)
{
    osg::Quat turn;
    turn.makeRotate(osg::Vec3d(1.0, 0.0, 0.0), osg::Vec3d(glyph.vector));
    return turn;
}

osg::ref_ptr<GlyphCloud> createCloud(GlyphShape shape, const std::vector<Glyph>& glyphs, bool lit = false)
{
    osg::ref_ptr<osg::Vec3Array> positions = new osg::Vec3Array, vectors = new osg::Vec3Array;
    osg::ref_ptr<osg::FloatArray> radii = new osg::FloatArray;
    osg::ref_ptr<osg::Vec4ubArray> colors = new osg::Vec4ubArray;
    osg::ref_ptr<osg::Vec3Array> semiAxes = new osg::Vec3Array;
    osg::ref_ptr<osg::Vec4Array> turns = new osg::Vec4Array;
    osg::ref_ptr<osg::Vec2Array> exponents = new osg::Vec2Array;
    for (const Glyph& glyph : glyphs)
    {
        positions->push_back(glyph.position);
        vectors->push_back(glyph.vector);
        radii->push_back(glyph.radius);
        colors->push_back(glyph.color);
        semiAxes->push_back(semiAxesOf(glyph));
        turns->push_back(turnOf(glyph).asVec4());
        exponents->push_back(EXPONENTS);
    }
    osg::ref_ptr<GlyphCloud> cloud = new GlyphCloud;
    cloud->setShape(shape);
    cloud->setSemiAxes(semiAxes.get());
    cloud->setOrientations(turns.get());
    cloud->setExponents(exponents.get());
    // Float radii: an ellipsoid's radius is its largest semi-axis, which a half float would round.
    cloud->setCompressedAttributes(!osgGlyphs::isAxesShape(shape));
    cloud->setPositions(positions.get());
    cloud->setVectors(vectors.get());
    cloud->setRadii(radii.get());
    cloud->setColors(colors.get());
    cloud->setLit(lit);
    return cloud;
}

/** The glyphs as analytic solids (vector glyphs centred on their points, the default anchor). */
void addGlyphs(AnalyticScene& scene, GlyphShape shape, const std::vector<Glyph>& glyphs)
{
    for (const Glyph& glyph : glyphs)
    {
        osg::Vec3d axis = glyph.vector;
        const double length = axis.normalize();
        const osg::Vec3d tail = osg::Vec3d(glyph.position) - axis * (0.5 * length);
        if (shape == GlyphShape::Sphere)
            scene.addSphere(glyph.position, glyph.radius);
        else if (shape == GlyphShape::Ellipsoid)
            scene.addEllipsoid(glyph.position, semiAxesOf(glyph), turnOf(glyph));
        else if (shape == GlyphShape::Superquadric)
            // The exponents as the GPU holds them, in steps of 1/127.
            scene.addSuperquadric(glyph.position, semiAxesOf(glyph), turnOf(glyph),
                                  std::round(EXPONENTS.x() * 127.0) / 127.0,
                                  std::round(EXPONENTS.y() * 127.0) / 127.0);
        else if (shape == GlyphShape::Cone)
            scene.addCone(tail, axis, length, glyph.radius);
        else if (shape == GlyphShape::Cylinder)
            scene.addCylinder(tail, axis, length, glyph.radius);
        else
            scene.addArrow(tail, axis, length, glyph.radius, HEAD_LENGTH, HEAD_RADIUS);
    }
}

/** The scene under a ClipNode with these planes (world coordinates), capped or not. */
osg::ref_ptr<osg::ClipNode> clipped(osg::Node* scene, const std::vector<osg::Plane>& planes, bool capped)
{
    osg::ref_ptr<osg::ClipNode> clipNode = new osg::ClipNode;
    for (unsigned int i = 0; i < planes.size(); ++i)
        clipNode->addClipPlane(new osg::ClipPlane(i, planes[i]));
    osgGlyphs::setClipCaps(*clipNode->getOrCreateStateSet(), capped);
    clipNode->addChild(scene);
    return clipNode;
}

std::string shapeName(GlyphShape shape)
{
    return osgGlyphs::getShapeName(shape);
}

/** Planes through the glyphs: one slanted cut through all three, one facing the viewer, and one
 * from behind, so that cuts show caps, open insides and nothing. */
const std::vector<osg::Plane> SLANTED = {osg::Plane(0.5, 0.6, -0.62, 0.1)};
const std::vector<osg::Plane> FACING_VIEWER = {osg::Plane(0.0, 1.0, 0.0, 0.05)};
const std::vector<osg::Plane> THREE_PLANES = {
    osg::Plane(0.5, 0.6, -0.62, 0.1), osg::Plane(0.0, 1.0, 0.0, 0.25), osg::Plane(-0.3, 0.2, 1.0, 0.2)};

struct ClipCase
{
    GlyphShape shape;
    bool capped;
};

class ClippedGlyphs : public ::testing::TestWithParam<ClipCase>
{
protected:
    std::string caseName() const
    {
        return shapeName(GetParam().shape) + (GetParam().capped ? "_capped" : "_open");
    }

    /** Renders GLYPHS clipped by the planes and compares them with the analytic cut solids. */
    Agreement renderAndCompare(const std::vector<osg::Plane>& planes, const std::string& name)
    {
        const ClipCase clipCase = GetParam();
        AnalyticScene truth;
        addGlyphs(truth, clipCase.shape, GLYPHS);
        for (const osg::Plane& plane : planes)
            truth.addClipPlane(plane);
        truth.setClipCaps(clipCase.capped);
        osg::ref_ptr<osg::Geode> glyphs = group({createCloud(clipCase.shape, GLYPHS).get()});
        const Frame frame = renderer.render(clipped(glyphs.get(), planes, clipCase.capped).get());
        saveFrame(frame, "clip_" + name + "_" + caseName());
        return compareWithTruth(frame, truth, PALETTE, depthToleranceOf(clipCase.shape), 0.15);
    }

    Renderer renderer{240, 160};
};

}

TEST_P(ClippedGlyphs, OnePlaneCutsTheTrueSurface)
{
    for (const std::vector<osg::Plane>* planes : {&SLANTED, &FACING_VIEWER})
    {
        const Agreement agreement = renderAndCompare(*planes, planes == &SLANTED ? "slanted" : "facing");
        EXPECT_GT(agreement.covered, 800);
        // Single precision at rims and tips: at most 1 pixel in 1000 of those compared.
        EXPECT_LE(agreement.wrongLabel, agreement.certain / 1000)
            << "of " << agreement.certain << " certain pixels";
        EXPECT_LE(agreement.wrongDepth, agreement.covered / 1000) << "worst " << agreement.worstDepthError;
    }
}

TEST_P(ClippedGlyphs, ThreePlanesCutTogether)
{
    const Agreement agreement = renderAndCompare(THREE_PLANES, "three");
    EXPECT_GT(agreement.covered, 300);
    EXPECT_LE(agreement.wrongLabel, agreement.certain / 1000)
        << "of " << agreement.certain << " certain pixels";
    // Under 1000 pixels compared, one may be off (an ellipsoid's 16-bit semi-axes: 5.3e-7 seen).
    EXPECT_LE(agreement.wrongDepth, std::max(agreement.covered / 1000, 1))
        << "worst " << agreement.worstDepthError;
}

INSTANTIATE_TEST_SUITE_P(
    , ClippedGlyphs,
    ::testing::Values(ClipCase{GlyphShape::Sphere, false}, ClipCase{GlyphShape::Sphere, true},
                      ClipCase{GlyphShape::Cone, false}, ClipCase{GlyphShape::Cone, true},
                      ClipCase{GlyphShape::Arrow, false}, ClipCase{GlyphShape::Arrow, true},
                      ClipCase{GlyphShape::Cylinder, false}, ClipCase{GlyphShape::Cylinder, true},
                      ClipCase{GlyphShape::Ellipsoid, false}, ClipCase{GlyphShape::Ellipsoid, true},
                      ClipCase{GlyphShape::Superquadric, false}, ClipCase{GlyphShape::Superquadric, true}),
    [](const ::testing::TestParamInfo<ClipCase>& param)
    { return shapeName(param.param.shape) + (param.param.capped ? "_capped" : "_open"); });

namespace
{

int countCovered(const Frame& frame, int x0 = 0, int x1 = -1)
{
    int covered = 0;
    for (int y = 0; y < frame.height(); ++y)
        for (int x = x0; x < (x1 < 0 ? frame.width() : x1); ++x)
            covered += frame.isCovered(x, y);
    return covered;
}

}

TEST(ClippedCone, CutThroughItsCentreKeepsTheKeptHalf)
{
    // A cone across the view, centred on the origin, its apex towards +x: x >= 0 keeps the apex half.
    Renderer renderer(240, 160);
    const std::vector<Glyph> cone = {{osg::Vec3(), osg::Vec3(4.0f, 0.0f, 0.0f), 1.0f, RED}};
    for (bool capped : {false, true})
    {
        osg::ref_ptr<osg::Geode> glyphs = group({createCloud(GlyphShape::Cone, cone).get()});
        const Frame frame =
            renderer.render(clipped(glyphs.get(), {osg::Plane(1.0, 0.0, 0.0, 0.0)}, capped).get());
        saveFrame(frame, std::string("clip_cone_half_") + (capped ? "capped" : "open"));
        const int centre = static_cast<int>(frame.project(osg::Vec3d()).x());
        EXPECT_EQ(countCovered(frame, 0, centre - 1), 0) << "the removed half shows";
        // The apex half's outline: a triangle of height 2 on a base of 1, 1 square unit, at
        // 160 / (2 * 10 * tan 20 degrees) pixels a unit.
        const double pixelsPerUnit = 160.0 / (20.0 * std::tan(osg::DegreesToRadians(20.0)));
        const double expected = pixelsPerUnit * pixelsPerUnit;
        EXPECT_NEAR(countCovered(frame, centre - 1), expected, 0.1 * expected);
    }
}

TEST(ClippedGlyphsSideBySide, CoverageMatchesTessellatedShapesUnderTheSamePlane)
{
    // Open cuts: a tessellated solid without back-face culling shows its inside where the plane
    // cuts it open, as an open cut glyph does.
    Renderer renderer(240, 160);
    const std::vector<osg::Plane> planes = SLANTED;
    osg::ref_ptr<osg::TessellationHints> hints = new osg::TessellationHints;
    hints->setDetailRatio(4.0f);
    hints->setCreateBackFace(false);
    for (GlyphShape shape : {GlyphShape::Sphere, GlyphShape::Cone})
    {
        osg::ref_ptr<osg::Geode> tessellated = new osg::Geode;
        for (const Glyph& glyph : GLYPHS)
        {
            osg::ref_ptr<osg::Shape> solid;
            if (shape == GlyphShape::Sphere)
                solid = new osg::Sphere(glyph.position, glyph.radius);
            else
            {
                // osg::Cone: its origin is a quarter of the height above the base.
                const float length = glyph.vector.length();
                osg::Vec3 axis = glyph.vector / length;
                osg::ref_ptr<osg::Cone> cone =
                    new osg::Cone(glyph.position - axis * (0.25f * length), glyph.radius, length);
                osg::Quat rotation;
                rotation.makeRotate(osg::Vec3(0.0f, 0.0f, 1.0f), axis);
                cone->setRotation(rotation);
                solid = cone;
            }
            tessellated->addDrawable(new osg::ShapeDrawable(solid.get(), hints.get()));
        }
        tessellated->getOrCreateStateSet()->setMode(GL_LIGHTING, osg::StateAttribute::OFF);
        const Frame shapes = renderer.render(clipped(tessellated.get(), planes, false).get());
        osg::ref_ptr<osg::Geode> glyphs = group({createCloud(shape, GLYPHS).get()});
        const Frame impostors = renderer.render(clipped(glyphs.get(), planes, false).get());
        saveFrame(shapes, "clip_tessellated_" + shapeName(shape));
        saveFrame(impostors, "clip_impostors_" + shapeName(shape));
        int differing = 0;
        for (int y = 0; y < shapes.height(); ++y)
            for (int x = 0; x < shapes.width(); ++x)
                differing += shapes.isCovered(x, y) != impostors.isCovered(x, y);
        // The tessellation's polygonal silhouettes and cut edges: under 3% of the covered pixels.
        const int covered = countCovered(impostors);
        EXPECT_GT(covered, 800);
        EXPECT_LT(differing, covered * 3 / 100) << shapeName(shape);
    }
}

TEST(ClippedGlyphsTechniques, PointSpritesAndInstancingCutAsTheGeometryShaderDoes)
{
    Renderer renderer(240, 160);
    for (GlyphShape shape : {GlyphShape::Sphere, GlyphShape::Arrow})
    {
        osg::ref_ptr<GlyphCloud> cloud = createCloud(shape, GLYPHS, true);
        osg::ref_ptr<osg::ClipNode> scene = clipped(group({cloud.get()}).get(), THREE_PLANES, true);
        const Frame reference = renderer.render(scene.get());
        for (osgGlyphs::GlyphTechnique* technique :
             {static_cast<osgGlyphs::GlyphTechnique*>(new osgGlyphs::PointSpriteTechnique),
              static_cast<osgGlyphs::GlyphTechnique*>(new osgGlyphs::InstancedTechnique)})
        {
            cloud->setTechnique(technique);
            if (cloud->getEffectiveTechnique() != technique)
                continue; // point sprites draw spheres only
            const Frame frame = renderer.render(scene.get());
            int differing = 0;
            for (int y = 0; y < frame.height(); ++y)
                for (int x = 0; x < frame.width(); ++x)
                    differing += frame.colorAt(x, y) != reference.colorAt(x, y) ||
                                 frame.depthAt(x, y) != reference.depthAt(x, y);
            EXPECT_EQ(differing, 0) << technique->getTechniqueName() << " " << shapeName(shape);
        }
        EXPECT_GT(countCovered(reference), 300);
    }
}

TEST(ClippedGlyphsPlanes, EightPlanesAtOnce)
{
    // Eight planes around the middle sphere's centre, each 0.4 from it: a capped octagonal prism
    // cut from the sphere, its caps kept by the seven other planes.
    Renderer renderer(240, 160);
    std::vector<osg::Plane> planes;
    const osg::Vec3d centre = GLYPHS[1].position;
    for (int i = 0; i < 8; ++i)
    {
        const double angle = osg::PI / 4.0 * i + 0.3;
        const osg::Vec3d normal(-std::cos(angle), 0.6, -std::sin(angle));
        planes.emplace_back(normal, centre - normal / normal.length() * 0.4);
    }
    AnalyticScene truth;
    addGlyphs(truth, GlyphShape::Sphere, GLYPHS);
    for (const osg::Plane& plane : planes)
        truth.addClipPlane(plane);
    truth.setClipCaps(true);
    osg::ref_ptr<osg::Geode> glyphs = group({createCloud(GlyphShape::Sphere, GLYPHS).get()});
    const Frame frame = renderer.render(clipped(glyphs.get(), planes, true).get());
    saveFrame(frame, "clip_eight_planes");
    const Agreement agreement = compareWithTruth(frame, truth, PALETTE, DEPTH_TOLERANCE, 0.15);
    EXPECT_GT(agreement.covered, 150);
    EXPECT_EQ(agreement.wrongLabel, 0) << "of " << agreement.certain << " certain pixels";
    EXPECT_EQ(agreement.wrongDepth, 0) << "worst " << agreement.worstDepthError;
}

TEST(ClippedGlyphsPlanes, AnOverriddenPlaneModeIsRespected)
{
    // A parent turns plane 0 off with OVERRIDE: the ClipNode below cannot turn it on.
    Renderer renderer(240, 160);
    osg::ref_ptr<osg::Geode> glyphs = group({createCloud(GlyphShape::Sphere, GLYPHS).get()});
    const Frame whole = renderer.render(glyphs.get());
    osg::ref_ptr<osg::Group> root = new osg::Group;
    root->addChild(clipped(glyphs.get(), SLANTED, true).get());
    const Frame cut = renderer.render(root.get());
    root->getOrCreateStateSet()->setMode(GL_CLIP_PLANE0,
                                         osg::StateAttribute::OFF | osg::StateAttribute::OVERRIDE);
    const Frame overridden = renderer.render(root.get());
    EXPECT_LT(countCovered(cut), countCovered(whole) * 9 / 10);
    EXPECT_EQ(countCovered(overridden), countCovered(whole));
}

TEST(ClippedGlyphsLighting, CapsAreLitWithThePlaneNormal)
{
    Renderer renderer(240, 160);
    renderer.getViewer()->setLightingMode(osg::View::NO_LIGHT);
    osg::ref_ptr<osg::LightSource> source = createColouredLight();
    const osg::Light* light = source->getLight();
    osg::ref_ptr<GlyphCloud> cloud = createCloud(GlyphShape::Sphere, GLYPHS, true);
    const osg::Vec3d material(cloud->getAmbient(), cloud->getSpecular(), cloud->getShininess());
    source->addChild(clipped(group({cloud.get()}).get(), SLANTED, true).get());
    const Frame frame = renderer.render(source.get());
    saveFrame(frame, "clip_lit_caps");

    AnalyticScene truth;
    addGlyphs(truth, GlyphShape::Sphere, GLYPHS);
    truth.addClipPlane(SLANTED[0]);
    truth.setClipCaps(true);
    const osg::Vec3d capNormal = -SLANTED[0].getNormal() / SLANTED[0].getNormal().length();
    std::vector<osg::Vec4ub> colors;
    for (const Glyph& glyph : GLYPHS)
        colors.push_back(glyph.color);
    const LitAgreement caps =
        compareLitWithTruth(frame, truth, colors, eyeLightOf(*light, frame), material, 3,
                            [&](const RayHit& hit) { return (hit.normal - capNormal).length() <= 1e-9; });
    EXPECT_GT(caps.checked, 50);
    EXPECT_EQ(caps.wrong, 0) << "of " << caps.checked << " cap pixels";
}
