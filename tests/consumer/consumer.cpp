// Renders a GlyphCloud next to fixed-function geometry, headless, through the installed
// osgGlyphs, and checks the frame: at chosen pixels the depth against the analytic scene,
// occlusion both ways and colours; then the whole image against a baseline PNG.
//
//   consumer [BASELINE.png [ACTUAL.png]]
//
// Without BASELINE only the analytic checks run. ACTUAL.png receives the rendered frame, and
// ACTUAL.diff.png the pixels that differ from the baseline (red) when the comparison fails.
// With OSGGLYPHS_BLESS=1 in the environment the frame is written to BASELINE.png instead of
// being compared with it, once the analytic checks pass. Prints every check; exits 1 on failure.

#include <osgGlyphs/ColorMap>
#include <osgGlyphs/GlyphCloud>
#include <osgGlyphs/Version>
#include <osgGlyphsHeadless/DepthImage>
#include <osgGlyphsHeadless/OffscreenViewer>

#include <osg/Geode>
#include <osg/ShapeDrawable>
#include <osgDB/ReadFile>
#include <osgDB/WriteFile>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>

namespace
{

const int WIDTH = 160, HEIGHT = 120;
const osg::Vec3d EYE(0.0, -7.0, 2.5);
// A lit box whose top face is z = 0, and two spheres of radius 0.6 sunk 0.4 deep into it,
// coloured by the two ends of the coolwarm colour map.
const osg::Vec3d BOX_MIN(-2.0, -1.0, -1.0), BOX_MAX(2.0, 1.0, 0.0);
const double RADIUS = 0.6;
const osg::Vec3d CENTERS[2] = {osg::Vec3d(-1.0, 0.0, 0.2), osg::Vec3d(1.0, 0.0, 0.2)};
const float SCALARS[2] = {0.0f, 1.0f};
const char* const COLOR_MAP = "coolwarm";
const osg::Vec4 BACKGROUND(0.1f, 0.1f, 0.1f, 1.0f);

// Eye distances here are about 7; 24-bit depth between near 1 and far 20 resolves 3e-6 there.
const double DEPTH_TOLERANCE = 1.0e-4;
const double HUE_TOLERANCE = 10.0; // degrees
// Baseline: a pixel differs when a channel is more than 4 levels off; 0.5% of them may differ.
const int CHANNEL_TOLERANCE = 4;
const double PIXEL_BUDGET = 0.005;
const double INF = std::numeric_limits<double>::infinity();

/** Which surface a pixel shows. */
enum Surface
{
    BACKGROUND_SURFACE = -2,
    BOX_SURFACE = -1,
    SPHERE_0 = 0,
    SPHERE_1 = 1
};

std::string surfaceName(int surface)
{
    return surface == BACKGROUND_SURFACE ? "background"
           : surface == BOX_SURFACE      ? "box"
                                         : "sphere " + std::to_string(surface);
}

osg::ref_ptr<osg::Node> createScene()
{
    osg::ref_ptr<osg::Vec3Array> positions = new osg::Vec3Array;
    osg::ref_ptr<osg::FloatArray> scalars = new osg::FloatArray;
    for (int i = 0; i < 2; ++i)
    {
        positions->push_back(CENTERS[i]);
        scalars->push_back(SCALARS[i]);
    }
    osg::ref_ptr<osgGlyphs::GlyphCloud> cloud = new osgGlyphs::GlyphCloud;
    cloud->setPositions(positions.get());
    cloud->setRadius(RADIUS);
    cloud->setScalars(scalars.get());
    cloud->setColorMap(osgGlyphs::ColorMap::getBuiltin(COLOR_MAP));
    cloud->setScalarRange(0.0f, 1.0f);

    const osg::Vec3d size = BOX_MAX - BOX_MIN;
    osg::ref_ptr<osg::ShapeDrawable> box =
        new osg::ShapeDrawable(new osg::Box((BOX_MIN + BOX_MAX) * 0.5, size.x(), size.y(), size.z()));
    box->setColor(osg::Vec4(0.8f, 0.8f, 0.8f, 1.0f));

    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    geode->addDrawable(cloud.get());
    geode->addDrawable(box.get());
    return geode;
}

/** The rendered frame: colour (RGBA8), window depth (float), row 0 at the bottom. */
struct Frame
{
    osg::ref_ptr<osg::Image> color;
    osg::ref_ptr<osg::Image> depth;
    osg::Matrixd view;
    osg::Matrixd projection;
    std::string backend;
    std::string renderer;
};

bool render(Frame& frame)
{
    osg::ref_ptr<osgGlyphsHeadless::OffscreenViewer> viewer =
        new osgGlyphsHeadless::OffscreenViewer(WIDTH, HEIGHT);
    if (!viewer->valid())
        return false;
    osg::Camera* camera = viewer->getCamera();
    camera->setClearColor(BACKGROUND);
    camera->setComputeNearFarMode(osg::CullSettings::DO_NOT_COMPUTE_NEAR_FAR);
    camera->setProjectionMatrixAsPerspective(30.0, static_cast<double>(WIDTH) / HEIGHT, 1.0, 20.0);
    camera->setViewMatrixAsLookAt(EYE, osg::Vec3d(), osg::Vec3d(0.0, 0.0, 1.0));
    viewer->setSceneData(createScene().get());
    viewer->frame();

    osgGlyphsHeadless::FrameCapture* capture = viewer->getFrameCapture();
    frame.color = new osg::Image(*capture->getColorImage(), osg::CopyOp::DEEP_COPY_ALL);
    frame.depth = new osg::Image(*capture->getDepthImage(), osg::CopyOp::DEEP_COPY_ALL);
    frame.view = capture->getViewMatrix();
    frame.projection = capture->getProjectionMatrix();
    frame.backend = osgGlyphsHeadless::getHeadlessBackendName(viewer->getContext()->getBackend());
    frame.renderer = capture->getGLRenderer();
    return true;
}

/** Ray parameter where a ray (unit direction) enters a sphere, or INF. */
double raySphere(const osg::Vec3d& origin, const osg::Vec3d& direction, const osg::Vec3d& center)
{
    const osg::Vec3d oc = origin - center;
    const double b = oc * direction;
    const double discriminant = b * b - (oc.length2() - RADIUS * RADIUS);
    return discriminant < 0.0 ? INF : -b - std::sqrt(discriminant);
}

/** Ray parameter where a ray from outside enters the box, or INF. */
double rayBox(const osg::Vec3d& origin, const osg::Vec3d& direction)
{
    double enter = -INF, leave = INF;
    for (int axis = 0; axis < 3; ++axis)
    {
        if (direction[axis] == 0.0)
        {
            if (origin[axis] < BOX_MIN[axis] || origin[axis] > BOX_MAX[axis])
                return INF;
            continue;
        }
        const double t0 = (BOX_MIN[axis] - origin[axis]) / direction[axis];
        const double t1 = (BOX_MAX[axis] - origin[axis]) / direction[axis];
        enter = std::max(enter, std::min(t0, t1));
        leave = std::min(leave, std::max(t0, t1));
    }
    return enter <= leave && enter > 0.0 ? enter : INF;
}

/** The analytic scene along the ray through a pixel centre: the ray parameter of every
 * surface it meets (INF where it misses), and the nearest of them. */
struct RayCast
{
    osg::Vec3d origin, direction;
    double t[2 + 1] = {INF, INF, INF}; // spheres 0 and 1, then the box
    int visible = BACKGROUND_SURFACE;

    double at(int surface) const
    {
        return surface == BACKGROUND_SURFACE ? INF : t[surface == BOX_SURFACE ? 2 : surface];
    }
};

RayCast castPixel(const Frame& frame, int x, int y)
{
    const osg::Matrixd inverse = osg::Matrixd::inverse(frame.view * frame.projection);
    const double nx = 2.0 * (x + 0.5) / WIDTH - 1.0, ny = 2.0 * (y + 0.5) / HEIGHT - 1.0;
    RayCast ray;
    ray.origin = osg::Vec3d(nx, ny, -1.0) * inverse;
    ray.direction = osg::Vec3d(nx, ny, 1.0) * inverse - ray.origin;
    ray.direction.normalize();
    ray.t[0] = raySphere(ray.origin, ray.direction, CENTERS[0]);
    ray.t[1] = raySphere(ray.origin, ray.direction, CENTERS[1]);
    ray.t[2] = rayBox(ray.origin, ray.direction);
    for (int surface : {SPHERE_0, SPHERE_1, BOX_SURFACE})
    {
        if (ray.at(surface) < ray.at(ray.visible))
            ray.visible = surface;
    }
    return ray;
}

/** Distance from the eye plane (-z in eye space) of the surface the ray meets at t. */
double eyeDistance(const Frame& frame, const RayCast& ray, double t)
{
    return std::isinf(t) ? INF : -((ray.origin + ray.direction * t) * frame.view).z();
}

double renderedEyeDistance(const Frame& frame, int x, int y)
{
    const float depth = *reinterpret_cast<const float*>(frame.depth->data(x, y));
    return osgGlyphsHeadless::eyeDistanceFromWindowDepth(frame.projection, depth);
}

double hue(const osg::Vec4& c)
{
    const double hi = std::max({c.r(), c.g(), c.b()}), lo = std::min({c.r(), c.g(), c.b()});
    if (hi - lo <= 0.0)
        return 0.0;
    const double h = hi == c.r()   ? (c.g() - c.b()) / (hi - lo)
                     : hi == c.g() ? 2.0 + (c.b() - c.r()) / (hi - lo)
                                   : 4.0 + (c.r() - c.g()) / (hi - lo);
    return std::fmod(h * 60.0 + 360.0, 360.0);
}

double saturation(const osg::Vec4& c)
{
    const double hi = std::max({c.r(), c.g(), c.b()}), lo = std::min({c.r(), c.g(), c.b()});
    return hi > 0.0 ? (hi - lo) / hi : 0.0;
}

std::string describe(const osg::Vec4& c)
{
    std::ostringstream text;
    text << "rgb " << std::lround(c.r() * 255) << " " << std::lround(c.g() * 255) << " "
         << std::lround(c.b() * 255);
    return text.str();
}

class Checks
{
public:
    void expect(bool ok, const std::string& what)
    {
        std::cout << (ok ? "  ok    " : "  FAIL  ") << what << std::endl;
        ++_count;
        _failures += ok ? 0 : 1;
    }
    int count() const { return _count; }
    int failures() const { return _failures; }

private:
    int _count = 0;
    int _failures = 0;
};

/** A pixel to check: where a world point projects, and the surface it must show. */
struct Probe
{
    const char* name;
    osg::Vec3d world;
    int expected;
};

void checkColor(const Frame& frame, int x, int y, int surface, Checks& checks)
{
    const osg::Vec4 color = frame.color->getColor(x, y);
    std::ostringstream what;
    what << "  colour " << describe(color);
    if (surface == BACKGROUND_SURFACE)
    {
        const osg::Vec4 d = color - BACKGROUND;
        const float worst = std::max({std::fabs(d.r()), std::fabs(d.g()), std::fabs(d.b())});
        what << " is the clear colour " << describe(BACKGROUND) << " (+-1)";
        checks.expect(worst <= 1.0f / 255.0f, what.str());
    }
    else if (surface == BOX_SURFACE)
    {
        what << " is the grey box: saturation " << saturation(color) << " <= 0.05";
        checks.expect(saturation(color) <= 0.05, what.str());
    }
    else
    {
        const osg::Vec4 mapped = osgGlyphs::ColorMap::getBuiltin(COLOR_MAP)->getColor(SCALARS[surface]);
        const double error = std::fabs(std::remainder(hue(color) - hue(mapped), 360.0));
        what << ": hue " << hue(color) << " deg, saturation " << saturation(color) << ", " << COLOR_MAP << "("
             << SCALARS[surface] << ") = " << describe(mapped) << ", hue " << hue(mapped) << " (+-"
             << HUE_TOLERANCE << ", saturation at least 0.2)";
        checks.expect(error <= HUE_TOLERANCE && saturation(color) >= 0.2, what.str());
    }
}

void checkProbe(const Frame& frame, const Probe& probe, Checks& checks)
{
    const osg::Vec4d clip = osg::Vec4d(probe.world, 1.0) * frame.view * frame.projection;
    const int x = static_cast<int>(std::floor((clip.x() / clip.w() * 0.5 + 0.5) * WIDTH));
    const int y = static_cast<int>(std::floor((clip.y() / clip.w() * 0.5 + 0.5) * HEIGHT));
    const RayCast ray = castPixel(frame, x, y);
    std::ostringstream where;
    where << probe.name << ", pixel (" << x << ", " << y << "): ";
    if (ray.visible != probe.expected)
    {
        checks.expect(false, where.str() + "the analytic scene shows the " + surfaceName(ray.visible) +
                                 ", not the " + surfaceName(probe.expected) + " (the probe is misplaced)");
        return;
    }

    const double expected = eyeDistance(frame, ray, ray.at(ray.visible));
    const double actual = renderedEyeDistance(frame, x, y);
    std::ostringstream what;
    what << where.str() << surfaceName(ray.visible) << ": eye distance " << actual << ", analytic "
         << expected;
    if (!std::isinf(expected))
        what << ", error " << std::fabs(actual - expected) << " (at most " << DEPTH_TOLERANCE << ")";
    for (int hidden : {SPHERE_0, SPHERE_1, BOX_SURFACE})
    {
        if (hidden != ray.visible && !std::isinf(ray.at(hidden)))
            what << ", hides the " << surfaceName(hidden) << " at "
                 << eyeDistance(frame, ray, ray.at(hidden));
    }
    const bool ok = std::isinf(expected) ? std::isinf(actual) && actual > 0.0
                                         : std::fabs(actual - expected) <= DEPTH_TOLERANCE;
    checks.expect(ok, what.str());
    checkColor(frame, x, y, ray.visible, checks);
}

bool blessing()
{
    const char* value = std::getenv("OSGGLYPHS_BLESS");
    return value && std::string(value) == "1";
}

std::string diffPath(const std::string& actualPath)
{
    const std::string png = ".png";
    const bool hasPng = actualPath.size() > png.size() &&
                        actualPath.compare(actualPath.size() - png.size(), png.size(), png) == 0;
    return (hasPng ? actualPath.substr(0, actualPath.size() - png.size()) : actualPath) + ".diff.png";
}

void compareWithBaseline(const osg::Image& actual, const std::string& baselinePath,
                         const std::string& actualPath, Checks& checks)
{
    osg::ref_ptr<osg::Image> baseline = osgDB::readRefImageFile(baselinePath);
    if (!baseline || baseline->s() != actual.s() || baseline->t() != actual.t())
    {
        checks.expect(false, "baseline " + baselinePath +
                                 (baseline ? " differs in size" : " cannot be read") +
                                 " (OSGGLYPHS_BLESS=1 writes it)");
        return;
    }
    osg::ref_ptr<osg::Image> diff = new osg::Image;
    diff->allocateImage(actual.s(), actual.t(), 1, GL_RGBA, GL_UNSIGNED_BYTE);
    int differing = 0;
    for (int y = 0; y < actual.t(); ++y)
    {
        for (int x = 0; x < actual.s(); ++x)
        {
            const osg::Vec4 d = actual.getColor(x, y) - baseline->getColor(x, y);
            const float worst =
                std::max({std::fabs(d.r()), std::fabs(d.g()), std::fabs(d.b()), std::fabs(d.a())});
            const bool differs = std::lround(worst * 255.0f) > CHANNEL_TOLERANCE;
            differing += differs ? 1 : 0;
            const float grey = baseline->getColor(x, y).r() * 0.25f;
            diff->setColor(differs ? osg::Vec4(1.0f, 0.0f, 0.0f, 1.0f) : osg::Vec4(grey, grey, grey, 1.0f), x,
                           y);
        }
    }
    const int budget = static_cast<int>(PIXEL_BUDGET * actual.s() * actual.t());
    std::ostringstream what;
    what << "baseline " << baselinePath << ": " << differing << " pixels differ by more than "
         << CHANNEL_TOLERANCE << " levels (budget " << budget << ")";
    if (differing > budget && !actualPath.empty() && osgDB::writeImageFile(*diff, diffPath(actualPath)))
        what << ", differing pixels in red: " << diffPath(actualPath);
    checks.expect(differing <= budget, what.str());
}

void blessBaseline(const osg::Image& actual, const std::string& baselinePath, Checks& checks)
{
    if (checks.failures() > 0)
        checks.expect(false, "not blessing " + baselinePath + ": the analytic checks failed");
    else if (osgDB::writeImageFile(actual, baselinePath))
        std::cout << "[ BLESSED  ] " << baselinePath << std::endl;
    else
        checks.expect(false, "cannot write " + baselinePath);
}

}

int main(int argc, char** argv)
{
    const std::string baselinePath = argc > 1 ? argv[1] : "";
    const std::string actualPath = argc > 2 ? argv[2] : "";
    Frame frame;
    if (!render(frame))
    {
        std::cerr << "consumer: FAILED: no headless OpenGL context" << std::endl;
        return 1;
    }
    std::cout << std::setprecision(6) << "osgGlyphs " << osgGlyphsGetVersion() << " consumer: rendered "
              << WIDTH << "x" << HEIGHT << " through " << frame.backend << " (" << frame.renderer << ")"
              << std::endl;

    const Probe probes[] = {
        {"sphere 0 centre", CENTERS[0], SPHERE_0},
        {"sphere 1 centre", CENTERS[1], SPHERE_1},
        {"box top between the spheres", osg::Vec3d(0.0, 0.3, 0.0), BOX_SURFACE},
        {"box front face", osg::Vec3d(0.0, -1.0, -0.5), BOX_SURFACE},
        {"sphere 0 sunk into the box", CENTERS[0] - osg::Vec3d(0.0, 0.0, 0.5), BOX_SURFACE},
        {"sphere 1 sunk into the box", CENTERS[1] - osg::Vec3d(0.0, 0.0, 0.5), BOX_SURFACE},
        {"background above the box", osg::Vec3d(0.0, 0.0, 1.5), BACKGROUND_SURFACE}};
    Checks checks;
    for (const Probe& probe : probes)
        checkProbe(frame, probe, checks);

    if (!actualPath.empty() && !osgDB::writeImageFile(*frame.color, actualPath))
        checks.expect(false, "cannot write " + actualPath);
    if (!baselinePath.empty() && blessing())
        blessBaseline(*frame.color, baselinePath, checks);
    else if (!baselinePath.empty())
        compareWithBaseline(*frame.color, baselinePath, actualPath, checks);

    if (checks.failures() > 0)
    {
        std::cerr << "consumer: FAILED: " << checks.failures() << " of " << checks.count() << " checks"
                  << std::endl;
        return 1;
    }
    std::cout << "consumer: ok: " << checks.count() << " checks" << std::endl;
    return 0;
}
