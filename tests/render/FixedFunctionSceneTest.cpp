// A lit fixed-function scene (an osg::ShapeDrawable box and sphere under OSG's headlight),
// checked against ray-cast analytic coverage and depth, and against its baseline.

#include "AnalyticScene.h"

#include <osg/Geode>
#include <osg/ShapeDrawable>

#include <algorithm>
#include <cmath>
#include <limits>

using namespace osgGlyphsTest;

namespace
{

const osg::Vec3d BOX_CENTER(1.5, 0.0, 0.0);
const double BOX_HALF = 1.0;
const osg::Vec3d SPHERE_CENTER(-1.5, 0.0, 0.0);
const double SPHERE_RADIUS = 1.0;

osg::ref_ptr<osg::Node> createScene()
{
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    osg::ref_ptr<osg::ShapeDrawable> box = new osg::ShapeDrawable(new osg::Box(BOX_CENTER, 2.0f * BOX_HALF));
    box->setColor(osg::Vec4(0.9f, 0.6f, 0.2f, 1.0f));
    osg::ref_ptr<osg::TessellationHints> fine = new osg::TessellationHints;
    fine->setDetailRatio(4.0f);
    osg::ref_ptr<osg::ShapeDrawable> sphere =
        new osg::ShapeDrawable(new osg::Sphere(SPHERE_CENTER, SPHERE_RADIUS), fine);
    sphere->setColor(osg::Vec4(0.3f, 0.5f, 0.8f, 1.0f));
    geode->addDrawable(box.get());
    geode->addDrawable(sphere.get());
    return geode;
}

AnalyticScene createAnalyticScene()
{
    AnalyticScene scene;
    scene.addBox(BOX_CENTER - osg::Vec3d(BOX_HALF, BOX_HALF, BOX_HALF),
                 BOX_CENTER + osg::Vec3d(BOX_HALF, BOX_HALF, BOX_HALF));
    scene.addSphere(SPHERE_CENTER, SPHERE_RADIUS);
    return scene;
}

const int BOX = 0;

float luminance(const osg::Vec4ub& c)
{
    return 0.2126f * c.r() + 0.7152f * c.g() + 0.0722f * c.b();
}

class FixedFunctionScene : public ::testing::Test
{
protected:
    void SetUp() override
    {
        Renderer renderer(160, 120);
        renderer.setLookAt(osg::Vec3d(-3.0, -10.0, 4.0), osg::Vec3d(), osg::Vec3d(0.0, 0.0, 1.0));
        renderer.setPerspective(40.0, 1.0, 100.0);
        frame = renderer.render(createScene());
    }

    Frame frame;
    AnalyticScene truth = createAnalyticScene();
};

} // namespace

TEST_F(FixedFunctionScene, CoverageMatchesRayCastScene)
{
    // Pixel centres within a fraction of a pixel of a silhouette may fall either way.
    EXPECT_TRUE(coverageMatches(
        frame, [&](int x, int y) { return truth.castPixel(frame, x, y).hit(); }, 12, "fixed_function_scene"));
}

TEST_F(FixedFunctionScene, DepthMatchesRayCastScene)
{
    int boxPixels = 0, spherePixels = 0, boxWrong = 0, sphereWrong = 0;
    for (int y = 0; y < frame.height(); ++y)
    {
        for (int x = 0; x < frame.width(); ++x)
        {
            const RayHit hit = truth.castPixel(frame, x, y);
            if (!hit.hit() || !frame.isCovered(x, y))
                continue;
            const double expected = frame.windowDepth(hit.point);
            const double error = std::fabs(frame.depthAt(x, y) - expected);
            // Planar faces are exact up to 24-bit depth quantisation; the tessellated sphere
            // deviates from the true sphere by its chord error (about 1e-3 of the radius here).
            if (hit.label == BOX)
            {
                ++boxPixels;
                boxWrong += error > 2e-6 ? 1 : 0;
            }
            else
            {
                ++spherePixels;
                sphereWrong += error > 5e-5 ? 1 : 0;
            }
        }
    }
    EXPECT_GT(boxPixels, 800);
    EXPECT_GT(spherePixels, 600);
    EXPECT_LE(boxWrong, 10) << "of " << boxPixels << " box pixels";
    EXPECT_LE(sphereWrong, 10) << "of " << spherePixels << " sphere pixels";
}

TEST_F(FixedFunctionScene, HeadlightLightsFacesByTheirAngleToTheView)
{
    // The headlight shines along the view axis: the face most turned to the eye is brightest.
    const osg::Vec3d faceCenters[] = {BOX_CENTER + osg::Vec3d(0.0, -BOX_HALF, 0.0),  // front, normal -y
                                      BOX_CENTER + osg::Vec3d(0.0, 0.0, BOX_HALF),   // top, normal +z
                                      BOX_CENTER + osg::Vec3d(-BOX_HALF, 0.0, 0.0)}; // left, normal -x
    float brightness[3];
    for (int i = 0; i < 3; ++i)
    {
        const osg::Vec3d window = frame.project(faceCenters[i]);
        brightness[i] = luminance(frame.colorAt(int(window.x()), int(window.y())));
    }
    EXPECT_GT(brightness[0], brightness[1] + 20.0f);
    EXPECT_GT(brightness[1], brightness[2] + 5.0f);
}

TEST_F(FixedFunctionScene, BackgroundIsTheClearColourAtFarDepth)
{
    EXPECT_TRUE(colorNear(frame, 0, 0, osg::Vec4ub(0, 0, 0, 255), 0));
    EXPECT_TRUE(depthNear(frame, 0, 0, 1.0, 0.0));
}

TEST_F(FixedFunctionScene, MatchesBaseline)
{
    Tolerance tolerance;
    tolerance.colorChannel = 2;
    tolerance.colorPixelBudget = 4;
    tolerance.depth = 2e-6f;
    tolerance.depthPixelBudget = 4;
    EXPECT_TRUE(matchesBaseline(frame, "fixed_function_scene", tolerance));
}
