// Glyphs far from the world origin (projected and geocentric coordinates): a cloud keeps a
// double-precision origin and float offsets from it, and draws exactly as the same cloud at the
// world origin seen from the same place relative to it.

#include "GlyphTestScenes.h"

#include <osgGlyphs/GlyphCloud>

#include <osg/Geode>

#include <string>

using namespace osgGlyphsTest;
using osgGlyphs::GlyphCloud;
using osgGlyphs::GlyphShape;

namespace
{

const osg::Vec4ub RED(255, 0, 0, 255);
const osg::Vec4ub GREEN(0, 255, 0, 255);
const osg::Vec4ub BLUE(0, 0, 255, 255);
const osg::Vec4ub YELLOW(255, 255, 0, 255);

/** Spheres that intersect each other, of radii k/64 of the largest (exact in half floats). */
const std::vector<SphereSpec> SPHERES = {{osg::Vec3(0.0f, 0.0f, 0.0f), 0.8f, RED},
                                         {osg::Vec3(0.8f, 0.3f, 0.2f), 0.5f, GREEN},
                                         {osg::Vec3(-0.9f, -0.4f, 0.5f), 0.3f, BLUE},
                                         {osg::Vec3(0.3f, -0.7f, 0.9f), 0.05f, YELLOW}};

const osg::Vec3d EYE(1.0, 2.0, 6.0);
const osg::Vec3d UP(0.0, 1.0, 0.0);

/** 24-bit depth steps are 6e-8. */
const double EXACT_DEPTH = 2.5e-7;

/** Cones along x, y and z beside the spheres. */
osg::ref_ptr<GlyphCloud> createCones()
{
    osg::ref_ptr<GlyphCloud> cones = new GlyphCloud;
    cones->setShape(GlyphShape::Cone);
    cones->setPositions(
        makeArray<osg::Vec3Array>({{-1.6f, 1.0f, 0.0f}, {1.6f, -1.0f, 0.0f}, {0.0f, 1.4f, 0.6f}}));
    cones->setVectors(
        makeArray<osg::Vec3Array>({{0.8f, 0.0f, 0.0f}, {0.0f, 0.9f, 0.0f}, {0.0f, 0.0f, 1.0f}}));
    cones->setRadius(0.25f);
    cones->setColor(osg::Vec4(0.9f, 0.6f, 0.2f, 1.0f));
    return cones;
}

/** The spheres (lit or not) and the cones, each cloud at origin. */
osg::ref_ptr<osg::Geode> createScene(const osg::Vec3d& origin, bool lit)
{
    osg::ref_ptr<GlyphCloud> spheres = createSphereCloud(SPHERES, lit);
    osg::ref_ptr<GlyphCloud> cones = createCones();
    cones->setLit(lit);
    for (GlyphCloud* cloud : {spheres.get(), cones.get()})
        cloud->setOrigin(origin);
    return group({spheres.get(), cones.get()});
}

class FarFromOrigin : public ::testing::TestWithParam<osg::Vec3d>
{
protected:
    Frame renderFrom(const osg::Vec3d& origin, osg::Node* scene)
    {
        renderer.setLookAt(origin + EYE, origin, UP);
        return renderer.render(scene);
    }

    Renderer renderer{200, 150};
};

/** Pixels whose colour (any channel by more than 2 levels) or depth (by more than depthTolerance)
 * differ between two frames of the same size. */
int countDifferences(const Frame& a, const Frame& b, double depthTolerance)
{
    int differences = 0;
    for (int y = 0; y < a.height(); ++y)
    {
        for (int x = 0; x < a.width(); ++x)
        {
            const osg::Vec4ub ca = a.colorAt(x, y), cb = b.colorAt(x, y);
            bool differs = std::abs(static_cast<double>(a.depthAt(x, y)) - b.depthAt(x, y)) > depthTolerance;
            for (int c = 0; c < 4; ++c)
                differs = differs || std::abs(int(ca[c]) - int(cb[c])) > 2;
            differences += differs ? 1 : 0;
        }
    }
    return differences;
}

}

TEST_P(FarFromOrigin, DrawsAsTheSameSceneAtTheOrigin)
{
    const osg::Vec3d far = GetParam();
    const Frame atOrigin = renderFrom(osg::Vec3d(), createScene(osg::Vec3d(), true).get());
    const Frame translated = renderFrom(far, createScene(far, true).get());
    saveFrame(translated, "far_from_origin");

    int covered = 0;
    for (int y = 0; y < atOrigin.height(); ++y)
        for (int x = 0; x < atOrigin.width(); ++x)
            covered += atOrigin.isCovered(x, y) ? 1 : 0;
    EXPECT_GT(covered, 3000);
    // The model-view matrices differ by double rounding only: a few silhouette pixels at most.
    EXPECT_LE(countDifferences(atOrigin, translated, EXACT_DEPTH), 4);
}

TEST_P(FarFromOrigin, SpheresAreTheExactSpheresThere)
{
    const osg::Vec3d far = GetParam();
    osg::ref_ptr<GlyphCloud> spheres = createSphereCloud(SPHERES);
    spheres->setOrigin(far);
    AnalyticScene truth;
    for (const SphereSpec& sphere : SPHERES)
        truth.addSphere(far + osg::Vec3d(sphere.center), sphere.radius);
    const Frame frame = renderFrom(far, group({spheres.get()}).get());

    const Agreement agreement = compareWithTruth(frame, truth, {RED, GREEN, BLUE, YELLOW}, EXACT_DEPTH);
    EXPECT_GT(agreement.covered, 2500); // 2875 at 200x150
    EXPECT_EQ(agreement.wrongLabel, 0) << "of " << agreement.certain << " certain pixels";
    EXPECT_EQ(agreement.wrongDepth, 0) << "worst depth error " << agreement.worstDepthError;

    // The bound the parent sees holds the glyphs where they are.
    const osg::BoundingBox box = spheres->getBoundingBox();
    EXPECT_TRUE(box.contains(osg::Vec3(far + osg::Vec3d(0.8, 0.0, 0.0))));
    EXPECT_TRUE(box.contains(osg::Vec3(far - osg::Vec3d(1.2, 0.7, 0.0))));
}

TEST_P(FarFromOrigin, FloatPositionsThereWouldNotBe)
{
    // The same spheres as float positions from the world origin: the failure the origin avoids,
    // and the proof that the comparison above sees it.
    const osg::Vec3d far = GetParam();
    std::vector<SphereSpec> spheres = SPHERES;
    for (SphereSpec& sphere : spheres)
        sphere.center = osg::Vec3(far + osg::Vec3d(sphere.center));
    AnalyticScene truth;
    for (const SphereSpec& sphere : SPHERES)
        truth.addSphere(far + osg::Vec3d(sphere.center), sphere.radius);
    const Frame frame = renderFrom(far, group({createSphereCloud(spheres).get()}).get());

    const Agreement agreement = compareWithTruth(frame, truth, {RED, GREEN, BLUE, YELLOW}, EXACT_DEPTH);
    EXPECT_GT(agreement.wrongLabel + agreement.wrongDepth, 100);
}

std::string farName(const ::testing::TestParamInfo<osg::Vec3d>& info)
{
    static const char* const names[] = {"Utm1e7", "GeocentricEquator", "GeocentricNorth37"};
    return names[info.index];
}

// UTM-like coordinates 1e7 from the origin on each axis; geocentric points on the equator and at
// 37 degrees north (6.4e6 from the centre of the Earth).
INSTANTIATE_TEST_SUITE_P(, FarFromOrigin,
                         ::testing::Values(osg::Vec3d(1.0e7, 1.0e7, 1.0e7), osg::Vec3d(6378137.0, 0.0, 0.0),
                                           osg::Vec3d(-2694044.4, -4293642.5, 3857878.9)),
                         farName);
