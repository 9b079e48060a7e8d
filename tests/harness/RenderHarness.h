// The regression-render harness: renders OSG scenes headless, reads back colour and depth,
// and compares them with baselines in tests/baselines and with analytic expectations.
//
// Re-bless the baselines after an intended change of the rendering:
//     OSGGLYPHS_BLESS=1 ctest --test-dir build -L render
// then review the changed PNG/PFM files with git before committing them.

#ifndef OSGGLYPHS_TESTS_RENDERHARNESS_H
#define OSGGLYPHS_TESTS_RENDERHARNESS_H

#include <osgGlyphsHeadless/OffscreenViewer>

#include <gtest/gtest.h>
#include <osg/Image>
#include <osg/Matrixd>
#include <osg/Node>

#include <functional>
#include <string>
#include <vector>

namespace osgGlyphsTest
{

/** One rendered frame: colour (RGBA8) and window depth (float), row 0 at the bottom. */
struct Frame
{
    osg::ref_ptr<osg::Image> color;
    osg::ref_ptr<osg::Image> depth;
    osg::Matrixd view;
    osg::Matrixd projection;

    int width() const { return color->s(); }
    int height() const { return color->t(); }
    osg::Vec4ub colorAt(int x, int y) const;
    float depthAt(int x, int y) const;
    bool isCovered(int x, int y) const { return depthAt(x, y) < 1.0f; }

    /** Window coordinates (pixels, depth) of a world-space point. */
    osg::Vec3d project(const osg::Vec3d& world) const;
    /** The ray through window point (wx, wy): its world-space point on the near plane and its
     * unit direction, for perspective and orthographic projections alike. */
    void pixelRay(double wx, double wy, osg::Vec3d& origin, osg::Vec3d& direction) const;
    /** Window depth of a world-space point, as fixed-function geometry would write it. */
    double windowDepth(const osg::Vec3d& world) const { return project(world).z(); }
};

/** How many pixels of two frames of one size differ at all, in colour or depth. */
int countDifferingPixels(const Frame& a, const Frame& b);

/** Renders scenes through osgGlyphsHeadless::OffscreenViewer with a fixed camera: no automatic
 * near/far, no camera manipulator, so that analytic expectations hold exactly. */
class Renderer
{
public:
    Renderer(int width, int height,
             osgGlyphsHeadless::HeadlessBackend backend = osgGlyphsHeadless::HeadlessBackend::Default);

    void setLookAt(const osg::Vec3d& eye, const osg::Vec3d& center, const osg::Vec3d& up);
    void setPerspective(double fovyDegrees, double zNear, double zFar);
    void setClearColor(const osg::Vec4& color);

    Frame render(osg::Node* scene);
    /** The last frame rendered (after getViewer()->frame()). */
    Frame capture() const;
    osgGlyphsHeadless::OffscreenViewer* getViewer() { return _viewer.get(); }

private:
    osg::ref_ptr<osgGlyphsHeadless::OffscreenViewer> _viewer;
};

/** Renders the scene, paged (a tile archive's root), until the viewer's DatabasePager has nothing
 * left to load, then once more; frames: how many it took; during: the frames until then. */
Frame renderPaged(Renderer& renderer, osg::Node* scene, int& frames, std::vector<Frame>* during = nullptr);

/** Tolerances for a baseline comparison. A pixel differs when one colour channel differs by
 * more than colorChannel, or its depth by more than depth; the check fails when more than
 * the budget of pixels differ. */
struct Tolerance
{
    int colorChannel = 2;
    int colorPixelBudget = 0;
    float depth = 1.0e-5f;
    int depthPixelBudget = 0;
};

/** Compares with tests/baselines/<name>.png and <name>.depth.pfm. On failure writes
 * <name>_{actual,expected,diff}.png (and the same for depth) into the build tree and names them.
 * With OSGGLYPHS_BLESS=1 in the environment it rewrites the baselines instead. */
::testing::AssertionResult matchesBaseline(const Frame& frame, const std::string& name,
                                           const Tolerance& tolerance = Tolerance());

/** Colour at a pixel within a per-channel tolerance. */
::testing::AssertionResult colorNear(const Frame& frame, int x, int y, const osg::Vec4ub& expected,
                                     int tolerance);

/** Window depth at a pixel within an absolute tolerance. */
::testing::AssertionResult depthNear(const Frame& frame, int x, int y, double expected, double tolerance);

/** Compares which pixels are covered (depth < 1) with an expected mask, allowing a budget of
 * mismatched pixels. On failure writes <name>_coverage.png: expected-only pixels red,
 * actual-only blue. */
::testing::AssertionResult coverageMatches(const Frame& frame, const std::function<bool(int, int)>& expected,
                                           int mismatchBudget, const std::string& name);

/** Writes the frame's colour as <name>.png into the output folder, for people to look at. */
void saveFrame(const Frame& frame, const std::string& name);

/** Where failure images go: the build tree's tests/output folder. */
std::string outputPath(const std::string& fileName);

} // namespace osgGlyphsTest

#endif
