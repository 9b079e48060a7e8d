#include "RenderHarness.h"

#include <iostream>
#include <osgGlyphsHeadless/DepthImage>

#include <OpenThreads/Thread>
#include <osgDB/DatabasePager>
#include <osgDB/FileUtils>
#include <osgDB/ReadFile>
#include <osgDB/WriteFile>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace osgGlyphsTest
{

namespace
{

bool blessing()
{
    const char* value = std::getenv("OSGGLYPHS_BLESS");
    return value && std::string(value) == "1";
}

std::string baselinePath(const std::string& fileName)
{
    return std::string(OSGGLYPHS_BASELINE_DIR) + "/" + fileName;
}

osg::ref_ptr<osg::Image> newRGBA(int width, int height)
{
    osg::ref_ptr<osg::Image> image = new osg::Image;
    image->allocateImage(width, height, 1, GL_RGBA, GL_UNSIGNED_BYTE);
    return image;
}

void setPixel(osg::Image& image, int x, int y, const osg::Vec4ub& color)
{
    unsigned char* p = image.data(x, y);
    for (int c = 0; c < 4; ++c)
        p[c] = color[c];
}

/** A greyscale picture of window depth, stretched over the covered range; background black. */
osg::ref_ptr<osg::Image> visualizeDepth(const osg::Image& depth)
{
    const float* values = reinterpret_cast<const float*>(depth.data());
    const int count = depth.s() * depth.t();
    float lo = 1.0f, hi = 0.0f;
    for (int i = 0; i < count; ++i)
    {
        if (values[i] < 1.0f)
        {
            lo = std::min(lo, values[i]);
            hi = std::max(hi, values[i]);
        }
    }
    osg::ref_ptr<osg::Image> picture = newRGBA(depth.s(), depth.t());
    for (int y = 0; y < depth.t(); ++y)
    {
        for (int x = 0; x < depth.s(); ++x)
        {
            const float d = values[y * depth.s() + x];
            const float shade = d < 1.0f ? 1.0f - 0.8f * (d - lo) / std::max(hi - lo, 1e-9f) : 0.0f;
            const auto g = static_cast<unsigned char>(255.0f * shade);
            setPixel(*picture, x, y, osg::Vec4ub(g, g, g, 255));
        }
    }
    return picture;
}

bool save(const osg::Image& image, const std::string& path, std::ostringstream& report)
{
    if (!osgDB::writeImageFile(image, path))
    {
        report << "\n  (could not write " << path << ")";
        return false;
    }
    report << "\n  " << path;
    return true;
}

int countColorDifferences(const osg::Image& actual, const osg::Image& expected, int tolerance,
                          osg::Image& diff)
{
    int differing = 0;
    for (int y = 0; y < actual.t(); ++y)
    {
        for (int x = 0; x < actual.s(); ++x)
        {
            const unsigned char* a = actual.data(x, y);
            const unsigned char* e = expected.data(x, y);
            int worst = 0;
            for (int c = 0; c < 4; ++c)
                worst = std::max(worst, std::abs(int(a[c]) - int(e[c])));
            const bool differs = worst > tolerance;
            differing += differs ? 1 : 0;
            const auto faint = static_cast<unsigned char>(e[0] / 4 + e[1] / 4 + e[2] / 4);
            setPixel(diff, x, y,
                     differs ? osg::Vec4ub(255, 0, 0, 255) : osg::Vec4ub(faint, faint, faint, 255));
        }
    }
    return differing;
}

int countDepthDifferences(const osg::Image& actual, const osg::Image& expected, float tolerance,
                          osg::Image& diff)
{
    const float* a = reinterpret_cast<const float*>(actual.data());
    const float* e = reinterpret_cast<const float*>(expected.data());
    int differing = 0;
    for (int y = 0; y < actual.t(); ++y)
    {
        for (int x = 0; x < actual.s(); ++x)
        {
            const int i = y * actual.s() + x;
            const bool differs = !(std::fabs(a[i] - e[i]) <= tolerance);
            differing += differs ? 1 : 0;
            const unsigned char g = e[i] < 1.0f ? 64 : 0;
            setPixel(diff, x, y, differs ? osg::Vec4ub(255, 0, 0, 255) : osg::Vec4ub(g, g, g, 255));
        }
    }
    return differing;
}

} // namespace

osg::Vec4ub Frame::colorAt(int x, int y) const
{
    const unsigned char* p = color->data(x, y);
    return osg::Vec4ub(p[0], p[1], p[2], p[3]);
}

float Frame::depthAt(int x, int y) const
{
    return *reinterpret_cast<const float*>(depth->data(x, y));
}

osg::Vec3d Frame::project(const osg::Vec3d& world) const
{
    const osg::Vec4d clip = osg::Vec4d(world, 1.0) * view * projection;
    const osg::Vec3d ndc(clip.x() / clip.w(), clip.y() / clip.w(), clip.z() / clip.w());
    return osg::Vec3d((ndc.x() * 0.5 + 0.5) * width(), (ndc.y() * 0.5 + 0.5) * height(), ndc.z() * 0.5 + 0.5);
}

void Frame::pixelRay(double wx, double wy, osg::Vec3d& origin, osg::Vec3d& direction) const
{
    const osg::Matrixd inverse = osg::Matrixd::inverse(view * projection);
    const double x = 2.0 * wx / width() - 1.0, y = 2.0 * wy / height() - 1.0;
    origin = osg::Vec3d(x, y, -1.0) * inverse;
    direction = osg::Vec3d(x, y, 1.0) * inverse - origin;
    direction.normalize();
}

Renderer::Renderer(int width, int height, osgGlyphsHeadless::HeadlessBackend backend)
    : _viewer(new osgGlyphsHeadless::OffscreenViewer(width, height, backend))
{
    if (!_viewer->valid())
        std::cerr << "no headless context: " << _viewer->getContextError() << std::endl;
    osg::Camera* camera = _viewer->getCamera();
    camera->setComputeNearFarMode(osg::CullSettings::DO_NOT_COMPUTE_NEAR_FAR);
    camera->setClearColor(osg::Vec4(0.0f, 0.0f, 0.0f, 1.0f));
    setPerspective(40.0, 1.0, 100.0);
    setLookAt(osg::Vec3d(0.0, -10.0, 0.0), osg::Vec3d(), osg::Vec3d(0.0, 0.0, 1.0));
}

void Renderer::setLookAt(const osg::Vec3d& eye, const osg::Vec3d& center, const osg::Vec3d& up)
{
    _viewer->getCamera()->setViewMatrixAsLookAt(eye, center, up);
}

void Renderer::setPerspective(double fovyDegrees, double zNear, double zFar)
{
    const osg::Viewport* viewport = _viewer->getCamera()->getViewport();
    _viewer->getCamera()->setProjectionMatrixAsPerspective(
        fovyDegrees, viewport->width() / viewport->height(), zNear, zFar);
}

void Renderer::setClearColor(const osg::Vec4& color)
{
    _viewer->getCamera()->setClearColor(color);
}

Frame Renderer::render(osg::Node* scene)
{
    _viewer->setSceneData(scene);
    _viewer->frame();
    return capture();
}

Frame Renderer::capture() const
{
    Frame frame;
    frame.color = new osg::Image(*_viewer->getColorImage(), osg::CopyOp::DEEP_COPY_ALL);
    frame.depth = new osg::Image(*_viewer->getDepthImage(), osg::CopyOp::DEEP_COPY_ALL);
    frame.view = _viewer->getFrameCapture()->getViewMatrix();
    frame.projection = _viewer->getFrameCapture()->getProjectionMatrix();
    return frame;
}

int countDifferingPixels(const Frame& a, const Frame& b)
{
    int differing = 0;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x)
            differing += a.colorAt(x, y) != b.colorAt(x, y) || a.depthAt(x, y) != b.depthAt(x, y);
    return differing;
}

Frame renderPaged(Renderer& renderer, osg::Node* scene, int& frames, std::vector<Frame>* during)
{
    osgViewer::Viewer* viewer = renderer.getViewer();
    viewer->setSceneData(scene);
    osgDB::DatabasePager* pager = viewer->getDatabasePager();
    frames = 0;
    do
    {
        viewer->frame();
        ++frames;
        if (during)
            during->push_back(renderer.capture());
        if (pager->getDataToMergeListSize() == 0)
            OpenThreads::Thread::microSleep(2000);
    } while ((pager->getRequestsInProgress() || pager->getFileRequestListSize() > 0 ||
              pager->getDataToMergeListSize() > 0) &&
             frames < 2000);
    viewer->frame(); // what the last merge brought in
    return renderer.capture();
}

std::string outputPath(const std::string& fileName)
{
    const std::string directory = OSGGLYPHS_TEST_OUTPUT_DIR;
    osgDB::makeDirectory(directory);
    return directory + "/" + fileName;
}

void saveFrame(const Frame& frame, const std::string& name)
{
    osgDB::writeImageFile(*frame.color, outputPath(name + ".png"));
}

::testing::AssertionResult matchesBaseline(const Frame& frame, const std::string& name,
                                           const Tolerance& tolerance)
{
    const std::string colorFile = baselinePath(name + ".png");
    const std::string depthFile = baselinePath(name + ".depth.pfm");
    std::string error;
    if (blessing())
    {
        if (!osgDB::writeImageFile(*frame.color, colorFile) ||
            !osgGlyphsHeadless::writePFM(*frame.depth, depthFile, error))
            return ::testing::AssertionFailure() << "could not bless " << name << ": " << error;
        std::cout << "[ BLESSED  ] " << colorFile << " and " << depthFile << std::endl;
        return ::testing::AssertionSuccess();
    }

    osg::ref_ptr<osg::Image> expectedColor = osgDB::readRefImageFile(colorFile);
    osg::ref_ptr<osg::Image> expectedDepth = osgGlyphsHeadless::readPFM(depthFile, error);
    if (!expectedColor || !expectedDepth)
        return ::testing::AssertionFailure() << "missing baseline " << (expectedColor ? depthFile : colorFile)
                                             << " " << error << "; run with OSGGLYPHS_BLESS=1 to create it";
    if (expectedColor->s() != frame.width() || expectedColor->t() != frame.height() ||
        expectedDepth->s() != frame.width() || expectedDepth->t() != frame.height())
        return ::testing::AssertionFailure()
               << "baseline " << name << " is " << expectedColor->s() << "x" << expectedColor->t()
               << ", the render " << frame.width() << "x" << frame.height();
    if (expectedColor->getPixelFormat() != GL_RGBA || expectedColor->getDataType() != GL_UNSIGNED_BYTE)
        return ::testing::AssertionFailure() << colorFile << " is not an RGBA8 image";

    osg::ref_ptr<osg::Image> colorDiff = newRGBA(frame.width(), frame.height());
    osg::ref_ptr<osg::Image> depthDiff = newRGBA(frame.width(), frame.height());
    const int colorDiffering =
        countColorDifferences(*frame.color, *expectedColor, tolerance.colorChannel, *colorDiff);
    const int depthDiffering =
        countDepthDifferences(*frame.depth, *expectedDepth, tolerance.depth, *depthDiff);
    if (colorDiffering <= tolerance.colorPixelBudget && depthDiffering <= tolerance.depthPixelBudget)
        return ::testing::AssertionSuccess();

    std::ostringstream report;
    report << name << ": " << colorDiffering << " pixels differ in colour by more than "
           << tolerance.colorChannel << " (budget " << tolerance.colorPixelBudget << "), " << depthDiffering
           << " in depth by more than " << tolerance.depth << " (budget " << tolerance.depthPixelBudget
           << "). Images:";
    save(*frame.color, outputPath(name + "_actual.png"), report);
    save(*expectedColor, outputPath(name + "_expected.png"), report);
    save(*colorDiff, outputPath(name + "_diff.png"), report);
    save(*visualizeDepth(*frame.depth), outputPath(name + "_depth_actual.png"), report);
    save(*visualizeDepth(*expectedDepth), outputPath(name + "_depth_expected.png"), report);
    save(*depthDiff, outputPath(name + "_depth_diff.png"), report);
    return ::testing::AssertionFailure() << report.str();
}

::testing::AssertionResult colorNear(const Frame& frame, int x, int y, const osg::Vec4ub& expected,
                                     int tolerance)
{
    const osg::Vec4ub actual = frame.colorAt(x, y);
    for (int c = 0; c < 4; ++c)
    {
        if (std::abs(int(actual[c]) - int(expected[c])) > tolerance)
            return ::testing::AssertionFailure()
                   << "colour at (" << x << ", " << y << ") is " << int(actual[0]) << " " << int(actual[1])
                   << " " << int(actual[2]) << " " << int(actual[3]) << ", expected " << int(expected[0])
                   << " " << int(expected[1]) << " " << int(expected[2]) << " " << int(expected[3]) << " ± "
                   << tolerance;
    }
    return ::testing::AssertionSuccess();
}

::testing::AssertionResult depthNear(const Frame& frame, int x, int y, double expected, double tolerance)
{
    const double actual = frame.depthAt(x, y);
    if (std::fabs(actual - expected) <= tolerance)
        return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure()
           << "depth at (" << x << ", " << y << ") is " << actual << ", expected " << expected << " ± "
           << tolerance << " (off by " << actual - expected << ")";
}

::testing::AssertionResult coverageMatches(const Frame& frame, const std::function<bool(int, int)>& expected,
                                           int mismatchBudget, const std::string& name)
{
    osg::ref_ptr<osg::Image> picture = newRGBA(frame.width(), frame.height());
    int expectedOnly = 0, actualOnly = 0, covered = 0;
    for (int y = 0; y < frame.height(); ++y)
    {
        for (int x = 0; x < frame.width(); ++x)
        {
            const bool want = expected(x, y);
            const bool have = frame.isCovered(x, y);
            covered += want ? 1 : 0;
            expectedOnly += (want && !have) ? 1 : 0;
            actualOnly += (have && !want) ? 1 : 0;
            osg::Vec4ub color = want ? osg::Vec4ub(90, 90, 90, 255) : osg::Vec4ub(0, 0, 0, 255);
            if (want != have)
                color = want ? osg::Vec4ub(255, 0, 0, 255) : osg::Vec4ub(0, 128, 255, 255);
            setPixel(*picture, x, y, color);
        }
    }
    if (expectedOnly + actualOnly <= mismatchBudget)
        return ::testing::AssertionSuccess();
    std::ostringstream report;
    report << name << ": coverage differs from the expected mask of " << covered
           << " pixels: " << expectedOnly << " expected but not covered, " << actualOnly
           << " covered but not expected (budget " << mismatchBudget << "). Image:";
    save(*picture, outputPath(name + "_coverage.png"), report);
    return ::testing::AssertionFailure() << report.str();
}

}
