// An application with a window, built against the installed osgGlyphs: it links the core
// library and osgViewer only, glvnd's libGL first, and needs no link-order rule. It opens an
// osgViewer window on $DISPLAY, draws glyph spheres sunk into an osg::ShapeDrawable box, reads
// the frame back from a final draw callback and checks every pixel against a ray cast of the
// same spheres and box: the glyphs' colours, occlusion both ways through depth, the background.
//
//   windowed_consumer [ACTUAL.png]
//
// Prints its checks; exits 0 when they pass, 1 when one fails, 77 (CTest's skip code) without
// $DISPLAY.

#include <osgGlyphs/GlyphCloud>
#include <osgGlyphs/Version>

#include <osg/Camera>
#include <osg/GL>
#include <osg/Geode>
#include <osg/GraphicsContext>
#include <osg/ShapeDrawable>
#include <osgDB/WriteFile>
#include <osgViewer/Viewer>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

namespace
{

const int WIDTH = 320, HEIGHT = 240;
const osg::Vec3d EYE(0.0, -8.0, 3.0);
const double NEAR_PLANE = 2.0, FAR_PLANE = 30.0;
const osg::Vec4 CLEAR_COLOR(0.1f, 0.15f, 0.2f, 1.0f);

// An unlit grey box whose top face is z = 0, and three unlit spheres sunk into it by different
// depths: the box hides their lower parts, they hide parts of the box.
const osg::Vec3d BOX_MIN(-2.6, -0.9, -1.2), BOX_MAX(2.6, 0.9, 0.0);
const osg::Vec4 BOX_COLOR(0.6f, 0.6f, 0.6f, 1.0f);
const double RADIUS = 0.6;
const osg::Vec3d CENTERS[] = {osg::Vec3d(-1.6, 0.0, 0.15), osg::Vec3d(0.0, -0.3, 0.3),
                              osg::Vec3d(1.6, 0.2, 0.0)};
const osg::Vec4ub SPHERE_COLORS[] = {osg::Vec4ub(230, 40, 30, 255), osg::Vec4ub(40, 200, 60, 255),
                                     osg::Vec4ub(50, 80, 240, 255)};
const int NUM_SPHERES = 3;

// A pixel's colour is the surface's to 2 levels (8-bit rounding), its depth the analytic window
// depth to 1e-5 (the window's depth buffer resolves 6e-8; the depth range here spans 0.2).
const int COLOR_TOLERANCE = 2;
const double DEPTH_TOLERANCE = 1.0e-5;

/** What a pixel shows: the background, the box, or sphere 0, 1, 2. */
const int BACKGROUND = -2, BOX = -1;

osg::ref_ptr<osg::Node> createScene()
{
    osg::ref_ptr<osg::Vec3Array> positions = new osg::Vec3Array;
    osg::ref_ptr<osg::Vec4ubArray> colors = new osg::Vec4ubArray;
    for (int i = 0; i < NUM_SPHERES; ++i)
    {
        positions->push_back(CENTERS[i]);
        colors->push_back(SPHERE_COLORS[i]);
    }
    osg::ref_ptr<osgGlyphs::GlyphCloud> cloud = new osgGlyphs::GlyphCloud;
    cloud->setPositions(positions.get());
    cloud->setRadius(RADIUS);
    cloud->setColors(colors.get());
    cloud->setLit(false);

    const osg::Vec3d size = BOX_MAX - BOX_MIN;
    osg::ref_ptr<osg::ShapeDrawable> box =
        new osg::ShapeDrawable(new osg::Box((BOX_MIN + BOX_MAX) * 0.5, size.x(), size.y(), size.z()));
    box->setColor(BOX_COLOR);
    box->getOrCreateStateSet()->setMode(GL_LIGHTING, osg::StateAttribute::OFF);

    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    geode->addDrawable(box.get());
    geode->addDrawable(cloud.get());
    return geode;
}

/** Reads the back buffer after the camera has drawn, before the buffers swap. */
class ReadBack : public osg::Camera::DrawCallback
{
public:
    void operator()(osg::RenderInfo&) const override
    {
        renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
        color = new osg::Image;
        color->readPixels(0, 0, WIDTH, HEIGHT, GL_RGBA, GL_UNSIGNED_BYTE);
        depth = new osg::Image;
        depth->readPixels(0, 0, WIDTH, HEIGHT, GL_DEPTH_COMPONENT, GL_FLOAT);
    }

    mutable std::string renderer;
    mutable osg::ref_ptr<osg::Image> color, depth;
};

/** What a ray meets: the nearest surface and where, and what that surface hides. */
struct Hit
{
    int surface = BACKGROUND;
    osg::Vec3d point;
    bool hidesBox = false;    // a sphere in front of the box
    bool hidesSphere = false; // the box in front of a sphere
};

const double MISS = std::numeric_limits<double>::infinity();

/** Where a ray (unit direction) enters a sphere, or MISS. */
double sphereEntry(const osg::Vec3d& origin, const osg::Vec3d& direction, const osg::Vec3d& center)
{
    const osg::Vec3d toOrigin = origin - center;
    const double half = toOrigin * direction;
    const double discriminant = half * half - toOrigin.length2() + RADIUS * RADIUS;
    return discriminant < 0.0 ? MISS : -half - std::sqrt(discriminant);
}

/** Where a ray from outside the box enters it, or MISS. */
double boxEntry(const osg::Vec3d& origin, const osg::Vec3d& direction)
{
    double enter = -MISS, leave = MISS;
    for (int axis = 0; axis < 3; ++axis)
    {
        const double a = (BOX_MIN[axis] - origin[axis]) / direction[axis];
        const double b = (BOX_MAX[axis] - origin[axis]) / direction[axis];
        enter = std::max(enter, std::min(a, b));
        leave = std::min(leave, std::max(a, b));
    }
    return enter <= leave && enter > 0.0 ? enter : MISS;
}

/** The frame read back, and the scene ray-cast through its pixels. */
class Frame
{
public:
    Frame(const ReadBack& readBack, const osg::Camera& camera)
        : _color(readBack.color), _depth(readBack.depth),
          _viewProjection(camera.getViewMatrix() * camera.getProjectionMatrix())
    {
        _inverse.invert(_viewProjection);
    }

    /** The ray through window point (wx, wy), from the near plane. */
    Hit cast(double wx, double wy) const
    {
        const double x = 2.0 * wx / WIDTH - 1.0, y = 2.0 * wy / HEIGHT - 1.0;
        const osg::Vec3d origin = osg::Vec3d(x, y, -1.0) * _inverse;
        osg::Vec3d direction = osg::Vec3d(x, y, 1.0) * _inverse - origin;
        direction.normalize();
        const double box = boxEntry(origin, direction);
        double nearest = box, nearestSphere = MISS;
        Hit hit;
        hit.surface = box < MISS ? BOX : BACKGROUND;
        for (int i = 0; i < NUM_SPHERES; ++i)
        {
            const double t = sphereEntry(origin, direction, CENTERS[i]);
            nearestSphere = std::min(nearestSphere, t);
            if (t < nearest)
            {
                nearest = t;
                hit.surface = i;
            }
        }
        hit.point = origin + direction * nearest;
        hit.hidesBox = hit.surface >= 0 && box < MISS;
        hit.hidesSphere = hit.surface == BOX && nearestSphere < MISS;
        return hit;
    }

    /** Whether the pixel centre and four points 0.3 px about it meet the same surface. */
    bool isCertain(int x, int y, const Hit& centre) const
    {
        for (const double dx : {0.2, 0.8})
            for (const double dy : {0.2, 0.8})
                if (cast(x + dx, y + dy).surface != centre.surface)
                    return false;
        return true;
    }

    /** The window depth of a point. */
    double windowDepth(const osg::Vec3d& point) const
    {
        const osg::Vec4d clip = osg::Vec4d(point, 1.0) * _viewProjection;
        return clip.z() / clip.w() * 0.5 + 0.5;
    }

    osg::Vec4ub colorAt(int x, int y) const
    {
        const unsigned char* p = _color->data(x, y);
        return osg::Vec4ub(p[0], p[1], p[2], p[3]);
    }
    float depthAt(int x, int y) const { return *reinterpret_cast<const float*>(_depth->data(x, y)); }

private:
    osg::ref_ptr<osg::Image> _color, _depth;
    osg::Matrixd _viewProjection, _inverse;
};

osg::Vec4ub expectedColor(int surface)
{
    auto byte = [](float value) { return static_cast<unsigned char>(std::lround(value * 255.0f)); };
    if (surface >= 0)
        return SPHERE_COLORS[surface];
    const osg::Vec4& color = surface == BOX ? BOX_COLOR : CLEAR_COLOR;
    return osg::Vec4ub(byte(color.r()), byte(color.g()), byte(color.b()), 255);
}

bool colorsNear(const osg::Vec4ub& actual, const osg::Vec4ub& expected)
{
    for (int c = 0; c < 3; ++c)
        if (std::abs(int(actual[c]) - int(expected[c])) > COLOR_TOLERANCE)
            return false;
    return true;
}

int failures = 0;

void expect(bool ok, const std::string& what)
{
    std::cout << (ok ? "  ok    " : "  FAIL  ") << what << std::endl;
    failures += ok ? 0 : 1;
}

}

/** A window of WIDTH x HEIGHT on the display, or nullptr. */
osg::ref_ptr<osg::GraphicsContext> openWindow()
{
    osg::ref_ptr<osg::GraphicsContext::Traits> traits = new osg::GraphicsContext::Traits;
    traits->readDISPLAY();
    traits->setUndefinedScreenDetailsToDefaultScreen();
    traits->x = 0;
    traits->y = 0;
    traits->width = WIDTH;
    traits->height = HEIGHT;
    traits->windowDecoration = false;
    traits->doubleBuffer = true;
    traits->depth = 24;
    traits->windowName = "osgGlyphs windowed consumer";
    osg::ref_ptr<osg::GraphicsContext> window = osg::GraphicsContext::createGraphicsContext(traits.get());
    if (!window || !window->valid())
    {
        std::cerr << "windowed_consumer: FAILED: no window on " << traits->displayName() << std::endl;
        return nullptr;
    }
    return window;
}

/** Looks at the scene through the window; the final draw reads the frame back. */
void setUpCamera(osg::Camera& camera, osg::GraphicsContext* window, ReadBack* readBack)
{
    camera.setGraphicsContext(window);
    camera.setViewport(0, 0, WIDTH, HEIGHT);
    camera.setDrawBuffer(GL_BACK);
    camera.setReadBuffer(GL_BACK);
    camera.setClearColor(CLEAR_COLOR);
    camera.setComputeNearFarMode(osg::CullSettings::DO_NOT_COMPUTE_NEAR_FAR);
    camera.setProjectionMatrixAsPerspective(30.0, double(WIDTH) / HEIGHT, NEAR_PLANE, FAR_PLANE);
    camera.setViewMatrixAsLookAt(EYE, osg::Vec3d(), osg::Vec3d(0.0, 0.0, 1.0));
    camera.setFinalDrawCallback(readBack);
}

/** What the certain pixels of a frame show. */
struct Tally
{
    std::vector<int> shown = std::vector<int>(NUM_SPHERES, 0);
    int background = 0, box = 0, boxHidesSphere = 0, sphereHidesBox = 0, wrongColor = 0, wrongDepth = 0;
};

/** Every pixel whose surface is certain (not on a silhouette, nor on the curve where a sphere
 * enters the box) must show that surface's colour, and a sphere or the box its analytic depth. */
Tally checkPixels(const Frame& frame)
{
    Tally tally;
    for (int y = 0; y < HEIGHT; ++y)
    {
        for (int x = 0; x < WIDTH; ++x)
        {
            const Hit hit = frame.cast(x + 0.5, y + 0.5);
            if (!frame.isCertain(x, y, hit))
                continue;
            if (hit.surface >= 0)
                ++tally.shown[hit.surface];
            tally.background += hit.surface == BACKGROUND ? 1 : 0;
            tally.box += hit.surface == BOX ? 1 : 0;
            tally.boxHidesSphere += hit.hidesSphere ? 1 : 0;
            tally.sphereHidesBox += hit.hidesBox ? 1 : 0;
            const bool colorOk = colorsNear(frame.colorAt(x, y), expectedColor(hit.surface));
            const double expected = hit.surface == BACKGROUND ? 1.0 : frame.windowDepth(hit.point);
            const bool depthOk = std::fabs(frame.depthAt(x, y) - expected) <= DEPTH_TOLERANCE;
            if ((!colorOk || !depthOk) && tally.wrongColor + tally.wrongDepth < 10)
            {
                const osg::Vec4ub c = frame.colorAt(x, y);
                std::cout << "  pixel (" << x << ", " << y << ") shows " << int(c.r()) << " " << int(c.g())
                          << " " << int(c.b()) << " at depth " << frame.depthAt(x, y) << ", expected surface "
                          << hit.surface << " at depth " << expected << std::endl;
            }
            tally.wrongColor += colorOk ? 0 : 1;
            tally.wrongDepth += depthOk ? 0 : 1;
        }
    }
    return tally;
}

void expectTally(const Tally& tally)
{
    for (int i = 0; i < NUM_SPHERES; ++i)
        expect(tally.shown[i] > 300, "sphere " + std::to_string(i) + " shows on " +
                                         std::to_string(tally.shown[i]) + " certain pixels (more than 300)");
    expect(tally.box > 5000,
           "the box shows on " + std::to_string(tally.box) + " certain pixels (more than 5000)");
    expect(tally.background > 5000, "the background shows on " + std::to_string(tally.background) +
                                        " certain pixels (more than 5000)");
    expect(tally.boxHidesSphere > 200, "the box hides a sphere on " + std::to_string(tally.boxHidesSphere) +
                                           " certain pixels (more than 200)");
    expect(tally.sphereHidesBox > 200, "a sphere hides the box on " + std::to_string(tally.sphereHidesBox) +
                                           " certain pixels (more than 200)");
    expect(tally.wrongColor == 0, std::to_string(tally.wrongColor) +
                                      " certain pixels differ from their surface's colour by more than " +
                                      std::to_string(COLOR_TOLERANCE) + " levels");
    expect(tally.wrongDepth == 0, std::to_string(tally.wrongDepth) +
                                      " certain pixels differ from the analytic depth by more than " +
                                      std::to_string(DEPTH_TOLERANCE));
}

int main(int argc, char** argv)
{
    if (!std::getenv("DISPLAY"))
    {
        std::cout << "windowed_consumer: SKIP: no DISPLAY" << std::endl;
        return 77;
    }
    osg::ref_ptr<osg::GraphicsContext> window = openWindow();
    if (!window)
        return 1;
    osgViewer::Viewer viewer;
    viewer.setThreadingModel(osgViewer::Viewer::SingleThreaded);
    osg::ref_ptr<ReadBack> readBack = new ReadBack;
    setUpCamera(*viewer.getCamera(), window.get(), readBack.get());
    viewer.setSceneData(createScene().get());
    viewer.realize();
    if (!viewer.isRealized())
    {
        std::cerr << "windowed_consumer: FAILED: the viewer did not realize its window" << std::endl;
        return 1;
    }
    for (int i = 0; i < 3; ++i)
        viewer.frame();
    if (!readBack->color || !readBack->color->data() || !readBack->depth || !readBack->depth->data())
    {
        std::cerr << "windowed_consumer: FAILED: no frame was read back" << std::endl;
        return 1;
    }
    std::cout << "osgGlyphs " << osgGlyphsGetVersion() << " windowed consumer: " << WIDTH << "x" << HEIGHT
              << " window on " << window->getTraits()->displayName() << ", " << readBack->renderer
              << std::endl;
    if (argc > 1)
        osgDB::writeImageFile(*readBack->color, argv[1]);
    expectTally(checkPixels(Frame(*readBack, *viewer.getCamera())));
    if (failures > 0)
    {
        std::cerr << "windowed_consumer: FAILED: " << failures << " checks" << std::endl;
        return 1;
    }
    std::cout << "windowed_consumer: ok" << std::endl;
    return 0;
}
