// osgGlyphs::diagnoseGlyphView and diagnoseGlyphScene: a view that shows no glyph, or next to none,
// has one line that says why, and a view that shows glyphs has none. Each case is rendered too:
// the diagnosis must agree with the picture.

#include "GlyphTestScenes.h"

#include <osgGlyphs/GlyphCloud>
#include <osgGlyphs/GlyphDiagnosis>

#include <osg/Sequence>

#include <limits>
#include <random>

using namespace osgGlyphsTest;
using osgGlyphs::GlyphCloud;

namespace
{

const int WIDTH = 160, HEIGHT = 120;

int countCovered(const Frame& frame)
{
    int covered = 0;
    for (int y = 0; y < frame.height(); ++y)
        for (int x = 0; x < frame.width(); ++x)
            covered += frame.isCovered(x, y) ? 1 : 0;
    return covered;
}

/** Spheres of one radius at the points, unlit. */
osg::ref_ptr<GlyphCloud> createCloud(const std::vector<osg::Vec3>& points, float radius)
{
    osg::ref_ptr<GlyphCloud> cloud = new GlyphCloud;
    cloud->setPositions(new osg::Vec3Array(points.begin(), points.end()));
    cloud->setRadius(radius);
    cloud->setLit(false);
    return cloud;
}

const std::vector<osg::Vec3> THREE_POINTS = {osg::Vec3(-1.0f, 0.0f, 0.0f), osg::Vec3(1.0f, 0.0f, 0.0f),
                                             osg::Vec3(0.0f, 0.0f, 1.0f)};

class GlyphDiagnosis : public ::testing::Test
{
protected:
    /** The diagnosis of the renderer's camera, and what the render covers. */
    std::string diagnoseAndRender(osg::Node* scene, int& covered)
    {
        const std::string reason = osgGlyphs::diagnoseGlyphView(*scene, *renderer.getViewer()->getCamera());
        covered = countCovered(renderer.render(scene));
        return reason;
    }

    /** Expects a diagnosis that starts with prefix and a render that covers at most maxCovered pixels. */
    void expectHidden(osg::Node* scene, const std::string& prefix, int maxCovered = 0)
    {
        int covered = 0;
        const std::string reason = diagnoseAndRender(scene, covered);
        EXPECT_EQ(reason.compare(0, prefix.size(), prefix), 0) << reason;
        EXPECT_EQ(reason.find('\n'), std::string::npos) << reason;
        EXPECT_LE(covered, maxCovered) << reason;
    }

    /** Expects no diagnosis and a render that covers at least minCovered pixels. */
    void expectSeen(osg::Node* scene, int minCovered)
    {
        int covered = 0;
        EXPECT_EQ(diagnoseAndRender(scene, covered), "");
        EXPECT_GE(covered, minCovered);
    }

    /** A camera whose cull traversal fits near and far to the scene, as osgViewer's does. */
    void computeNearFar(double zNear, double zFar)
    {
        renderer.getViewer()->getCamera()->setComputeNearFarMode(
            osg::CullSettings::COMPUTE_NEAR_FAR_USING_BOUNDING_VOLUMES);
        renderer.setPerspective(40.0, zNear, zFar);
    }

    Renderer renderer{WIDTH, HEIGHT};
};

}

TEST_F(GlyphDiagnosis, GlyphsInViewHaveNone)
{
    osg::ref_ptr<GlyphCloud> cloud = createCloud(THREE_POINTS, 0.5f);
    expectSeen(group({cloud.get()}).get(), 300);
    computeNearFar(1.0, 1000.0);
    expectSeen(group({cloud.get()}).get(), 300);
}

// A cloud far from zero (LAS, UTM coordinates) keeps its positions relative to its origin.
TEST_F(GlyphDiagnosis, GlyphsRelativeToAFarOriginInViewHaveNone)
{
    const osg::Vec3d origin(3000.0, -4000.0, -5000.0);
    std::vector<osg::Vec3> relative;
    for (const osg::Vec3& point : THREE_POINTS)
        relative.push_back(osg::Vec3(osg::Vec3d(point) - origin));
    osg::ref_ptr<GlyphCloud> cloud = createCloud(relative, 0.5f);
    cloud->setOrigin(origin);
    computeNearFar(1.0, 1000.0);
    expectSeen(group({cloud.get()}).get(), 300);
}

TEST_F(GlyphDiagnosis, ConesOfZeroVectorsAreEverySkipped)
{
    osg::ref_ptr<GlyphCloud> cloud = createCloud(THREE_POINTS, 0.5f);
    cloud->setShape(osgGlyphs::GlyphShape::Cone);
    cloud->setVectors(new osg::Vec3Array(THREE_POINTS.size()));
    expectHidden(
        group({cloud.get()}).get(),
        "no glyph is drawn: every glyph is skipped (3 of 3 have a zero vector, which gives it no direction)");
}

TEST_F(GlyphDiagnosis, GlyphsOfARadiusThatIsNotFiniteAreEverySkipped)
{
    osg::ref_ptr<GlyphCloud> cloud = createCloud(THREE_POINTS, 0.5f);
    cloud->setRadii(makeArray<osg::FloatArray>({std::numeric_limits<float>::infinity(), -1.0f, 0.0f}));
    expectHidden(group({cloud.get()}).get(),
                 "no glyph is drawn: every glyph is skipped (3 of 3 have a radius "
                 "that is not finite and > 0)");
}

TEST_F(GlyphDiagnosis, EllipsoidsOfFlatSemiAxesAreEverySkippedAndOthersAreSeen)
{
    osg::ref_ptr<GlyphCloud> cloud = createCloud(THREE_POINTS, 0.5f);
    cloud->setShape(osgGlyphs::GlyphShape::Ellipsoid);
    cloud->setSemiAxes(makeArray<osg::Vec3Array>(
        {osg::Vec3(0.5f, 0.0f, 0.2f), osg::Vec3(0.5f, 0.3f, -0.2f), osg::Vec3(0.5f, 0.3f, 0.0f)}));
    expectHidden(group({cloud.get()}).get(), "no glyph is drawn: every glyph is skipped (3 of 3 have "
                                             "semi-axes that are not all finite and > 0)");
    cloud->setSemiAxes(makeArray<osg::Vec3Array>(
        {osg::Vec3(0.5f, 0.1f, 0.2f), osg::Vec3(0.5f, 0.3f, 0.2f), osg::Vec3(0.5f, 0.3f, 0.4f)}));
    expectSeen(group({cloud.get()}).get(), 100);
}

TEST_F(GlyphDiagnosis, BoundsBeyondFloatAreNotFinite)
{
    // Centres that float holds, padded by radii that take them past its largest value.
    osg::ref_ptr<GlyphCloud> cloud =
        createCloud({osg::Vec3(3e38f, 0.0f, 0.0f), osg::Vec3(-3e38f, 0.0f, 0.0f)}, 1e38f);
    expectHidden(group({cloud.get()}).get(), "no glyph is drawn: the glyphs' bounds are not finite");
}

TEST_F(GlyphDiagnosis, AViewThatIsNotFiniteShowsNothing)
{
    osg::ref_ptr<GlyphCloud> cloud = createCloud(THREE_POINTS, 0.5f);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    renderer.setLookAt(osg::Vec3d(0.0, nan, 0.0), osg::Vec3d(), osg::Vec3d(0.0, 0.0, 1.0));
    expectHidden(group({cloud.get()}).get(),
                 "no glyph is seen: the camera's view or projection is not finite");
}

TEST_F(GlyphDiagnosis, GlyphsBehindOrBesideTheCameraAreNotSeen)
{
    osg::ref_ptr<GlyphCloud> cloud = createCloud(THREE_POINTS, 0.5f);
    renderer.setLookAt(osg::Vec3d(0.0, -10.0, 0.0), osg::Vec3d(0.0, -20.0, 0.0), osg::Vec3d(0.0, 0.0, 1.0));
    expectHidden(group({cloud.get()}).get(), "no glyph is seen: every glyph is behind the camera");
    renderer.setLookAt(osg::Vec3d(0.0, -10.0, 0.0), osg::Vec3d(20.0, -10.0, 0.0), osg::Vec3d(0.0, 0.0, 1.0));
    expectHidden(group({cloud.get()}).get(),
                 "no glyph is seen: the glyphs are outside the camera's field of view");
}

TEST_F(GlyphDiagnosis, ADepthRangeTheClampedProjectionLosesIsNotSeen)
{
    // A radius of 1e30 seen from 1e31, with the near plane at 1: OSG's near/far clamping rounds
    // the depth range away. The same scene at 1e12 still shows.
    computeNearFar(1.0, 1000.0);
    for (const double scale : {1e12, 1e30})
    {
        osg::ref_ptr<GlyphCloud> cloud = createCloud({osg::Vec3()}, static_cast<float>(scale));
        renderer.setLookAt(osg::Vec3d(0.0, -10.0 * scale, 0.0), osg::Vec3d(), osg::Vec3d(0.0, 0.0, 1.0));
        if (scale < 1e15)
            expectSeen(group({cloud.get()}).get(), 200);
        else
            expectHidden(group({cloud.get()}).get(),
                         "no glyph is seen: the glyphs' depths, 9e+30 to 1.1e+31 from "
                         "the eye, are lost to rounding when OSG fits the projection");
    }
}

TEST_F(GlyphDiagnosis, EyeDistancesBeyondTheShadersFloatsAreNotSeen)
{
    // A projection that holds the depth range; the shaders square distances of 1e20.
    renderer.setPerspective(40.0, 1e19, 1e21);
    renderer.setLookAt(osg::Vec3d(0.0, -1e20, 0.0), osg::Vec3d(), osg::Vec3d(0.0, 0.0, 1.0));
    osg::ref_ptr<GlyphCloud> cloud = createCloud({osg::Vec3()}, 1e19f);
    expectHidden(group({cloud.get()}).get(),
                 "no glyph is seen: the glyphs lie up to 1.11e+20 from the eye; beyond");
}

TEST_F(GlyphDiagnosis, AFewGlyphsUnderAPixelHardlyShowAndManyDo)
{
    osg::ref_ptr<GlyphCloud> tiny = createCloud(THREE_POINTS, 1e-4f);
    expectHidden(group({tiny.get()}).get(), "the glyphs hardly show: every glyph is under a pixel wide", 3);

    // 20000 glyphs of a third of a pixel fill about a tenth of the picture.
    std::mt19937 random(7);
    std::uniform_real_distribution<float> coordinate(-2.0f, 2.0f);
    std::vector<osg::Vec3> points;
    for (int i = 0; i < 20000; ++i)
        points.push_back(osg::Vec3(coordinate(random), coordinate(random), coordinate(random)));
    osg::ref_ptr<GlyphCloud> many = createCloud(points, 0.008f);
    expectSeen(group({many.get()}).get(), 500);
}

TEST(GlyphSceneDiagnosis, LooksAtEveryFrameAsOsgviewerFramesTheScene)
{
    osg::ref_ptr<osg::Sequence> frames = new osg::Sequence;
    for (int frame = 0; frame < 2; ++frame)
    {
        osg::ref_ptr<GlyphCloud> cloud = createCloud(THREE_POINTS, 0.5f);
        cloud->setShape(osgGlyphs::GlyphShape::Arrow);
        cloud->setVectors(new osg::Vec3Array(THREE_POINTS.size()));
        frames->addChild(group({cloud.get()}), 0.1);
    }
    EXPECT_EQ(
        osgGlyphs::diagnoseGlyphScene(*frames),
        "no glyph is drawn: every glyph is skipped (6 of 6 have a zero vector, which gives it no direction)");

    osg::ref_ptr<GlyphCloud> visible = createCloud(THREE_POINTS, 0.5f);
    frames->addChild(group({visible.get()}), 0.1);
    EXPECT_EQ(osgGlyphs::diagnoseGlyphScene(*frames), "");
    EXPECT_EQ(osgGlyphs::diagnoseGlyphScene(*group({createCloud(THREE_POINTS, 1e-6f).get()}))
                  .compare(0, 49, "the glyphs hardly show: every glyph is under a pi"),
              0);
    osg::ref_ptr<osg::Group> empty = new osg::Group;
    EXPECT_EQ(osgGlyphs::diagnoseGlyphScene(*empty), "");
}
