#include <osgGlyphs/GlyphCloud>
#include <osgGlyphs/GlyphDiagnosis>

#include <osg/CullSettings>
#include <osg/NodeVisitor>
#include <osg/Polytope>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

using namespace osgGlyphs;

namespace
{

/** Eye distances beyond this overflow the shaders' float arithmetic, which squares them. */
const double FLOAT_SQUARE_LIMIT = std::sqrt(static_cast<double>(std::numeric_limits<float>::max()));

/** The viewport of osgviewer's default window, for diagnoseGlyphScene(). */
const double DEFAULT_VIEWPORT_WIDTH = 1280.0;
const double DEFAULT_VIEWPORT_HEIGHT = 1024.0;

/** Glyphs all under a pixel wide that cover less than this fraction of the viewport make no
 * picture: a few scattered pixels at most. */
const double SUB_PIXEL_COVERAGE_LIMIT = 0.001;

/** Why GlyphCloud skips a glyph, in the order of its warnings (see GlyphCloud::dirtyGlyphs()). */
enum SkipReason
{
    DRAWN = -1,
    NON_FINITE_POSITION,
    BAD_RADIUS,
    NON_FINITE_SCALAR,
    NON_FINITE_VECTOR,
    ZERO_VECTOR,
    BAD_SEMI_AXES,
    BAD_ORIENTATION,
    BAD_EXPONENTS,
    NUM_SKIP_REASONS
};

const char* const SKIP_DESCRIPTIONS[NUM_SKIP_REASONS] = {
    "a position that is not finite",
    "a radius that is not finite and > 0",
    "a scalar that is not finite",
    "a vector that is not finite",
    "a zero vector, which gives it no direction",
    "semi-axes that are not all finite and > 0",
    "an orientation quaternion that is zero or not finite",
    "superquadric exponents that are not both finite and > 0"};

bool isFinite(const osg::Vec3& v)
{
    return std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z());
}

bool isFinite(const osg::Matrixd& m)
{
    for (int i = 0; i < 16; ++i)
        if (!std::isfinite(m.ptr()[i]))
            return false;
    return true;
}

std::string format(double value)
{
    char text[32];
    std::snprintf(text, sizeof(text), "%.3g", value);
    return text;
}

/** A cloud below the node and its transform to world coordinates. */
struct PlacedCloud
{
    const GlyphCloud* cloud;
    osg::Matrixd toWorld;
};

class CloudCollector : public osg::NodeVisitor
{
public:
    CloudCollector() : osg::NodeVisitor(TRAVERSE_ALL_CHILDREN) {}

    void apply(osg::Drawable& drawable) override
    {
        if (const GlyphCloud* cloud = dynamic_cast<const GlyphCloud*>(&drawable))
            clouds.push_back(PlacedCloud{cloud, osg::computeLocalToWorld(getNodePath())});
    }

    std::vector<PlacedCloud> clouds;
};

float getGlyphRadius(const GlyphCloud& cloud, unsigned int i)
{
    if (isAxesShape(cloud.getShape()))
    {
        const osg::Vec3& semiAxes = (*cloud.getSemiAxes())[i];
        return std::max(semiAxes.x(), std::max(semiAxes.y(), semiAxes.z()));
    }
    return cloud.getRadii() ? (*cloud.getRadii())[i] : cloud.getRadius();
}

/** GlyphCloud's rules for an ellipsoid's semi-axes and orientation. */
SkipReason getEllipsoidSkipReason(const GlyphCloud& cloud, unsigned int i)
{
    const osg::Vec3& semiAxes = (*cloud.getSemiAxes())[i];
    if (!isFinite(semiAxes) || !(semiAxes.x() > 0.0f && semiAxes.y() > 0.0f && semiAxes.z() > 0.0f))
        return BAD_SEMI_AXES;
    const float turn = cloud.getOrientations() ? (*cloud.getOrientations())[i].length() : 1.0f;
    if (!(std::isfinite(turn) && turn > 0.0f))
        return BAD_ORIENTATION;
    if (cloud.getShape() != GlyphShape::Superquadric || !cloud.getExponents())
        return DRAWN;
    const osg::Vec2& e = (*cloud.getExponents())[i];
    return std::isfinite(e.x()) && std::isfinite(e.y()) && e.x() > 0.0f && e.y() > 0.0f ? DRAWN
                                                                                        : BAD_EXPONENTS;
}

/** Whether and why the cloud skips glyph i, by GlyphCloud's rules. */
SkipReason getSkipReason(const GlyphCloud& cloud, unsigned int i)
{
    if (!isFinite((*cloud.getPositions())[i]))
        return NON_FINITE_POSITION;
    const bool ellipsoid = isAxesShape(cloud.getShape());
    const float radius = ellipsoid ? 1.0f : getGlyphRadius(cloud, i);
    if (!(std::isfinite(radius) && radius > 0.0f))
        return BAD_RADIUS;
    if (cloud.getScalars() && !std::isfinite((*cloud.getScalars())[i]))
        return NON_FINITE_SCALAR;
    if (ellipsoid)
        return getEllipsoidSkipReason(cloud, i);
    if (!isVectorShape(cloud.getShape()))
        return DRAWN;
    const osg::Vec3& vector = (*cloud.getVectors())[i];
    if (!isFinite(vector))
        return NON_FINITE_VECTOR;
    return vector.length2() == 0.0f ? ZERO_VECTOR : DRAWN;
}

/** "every glyph is skipped: ..." when no cloud draws a glyph, else empty. */
std::string diagnoseSkipped(const std::vector<PlacedCloud>& clouds)
{
    unsigned int glyphs = 0;
    unsigned int counts[NUM_SKIP_REASONS] = {};
    bool vectorShape = false;
    for (const PlacedCloud& placed : clouds)
    {
        const GlyphCloud& cloud = *placed.cloud;
        vectorShape = vectorShape || isVectorShape(cloud.getShape());
        for (unsigned int i = 0; i < cloud.getNumGlyphs(); ++i)
        {
            const SkipReason reason = getSkipReason(cloud, i);
            if (reason == DRAWN)
                return std::string();
            ++counts[reason];
        }
        glyphs += cloud.getNumGlyphs();
    }
    if (glyphs == 0)
        return vectorShape ? "no glyph is drawn: no cloud has a glyph (vector glyphs need vectors)"
                           : "no glyph is drawn: no cloud has a glyph";
    const unsigned int* commonest = std::max_element(counts, counts + NUM_SKIP_REASONS);
    return "no glyph is drawn: every glyph is skipped (" + std::to_string(*commonest) + " of " +
           std::to_string(glyphs) + " have " + SKIP_DESCRIPTIONS[commonest - counts] + ")";
}

/** The bounds of the glyphs in world coordinates; false when they are not finite. */
bool getWorldBounds(const std::vector<PlacedCloud>& clouds, osg::BoundingBoxd& bounds)
{
    for (const PlacedCloud& placed : clouds)
    {
        const osg::BoundingBox& box = placed.cloud->getBoundingBox();
        if (!box.valid())
            continue;
        for (unsigned int corner = 0; corner < 8; ++corner)
        {
            const osg::Vec3d world = osg::Vec3d(box.corner(corner)) * placed.toWorld;
            if (!(std::isfinite(world.x()) && std::isfinite(world.y()) && std::isfinite(world.z())))
                return false;
            bounds.expandBy(world);
        }
    }
    return true;
}

/** The depth of a point in front of the eye at distance d, after the projection, in [-1, 1]
 * when it is between the near and far planes. */
double projectDepth(const osg::Matrixd& projection, double distance)
{
    const osg::Vec4d clip = osg::Vec4d(0.0, 0.0, -distance, 1.0) * projection;
    return clip.z() / clip.w();
}

/** Whether the projection, clamped to the depth range as OSG's cull traversal does, maps some of
 * the glyphs' depths, from nearest to farthest, into its depth range (rounding makes the clamped
 * projection of a range far deeper than its near plane clip part of it, or all, or give NaN). */
bool holdsDepthRange(const osg::Camera& camera, double nearest, double farthest)
{
    osg::Matrixd projection = camera.getProjectionMatrix();
    if (camera.getComputeNearFarMode() != osg::CullSettings::DO_NOT_COMPUTE_NEAR_FAR)
    {
        double zNear = std::max(nearest, 0.0), zFar = farthest;
        if (!osg::clampProjectionMatrix(projection, zNear, zFar, camera.getNearFarRatio()))
            return false;
        nearest = std::max(nearest, zNear);
    }
    if (!isFinite(projection))
        return false;
    const double front = projectDepth(projection, nearest), back = projectDepth(projection, farthest);
    return front < back && back > -1.0 && front < 1.0;
}

/** "near plane 1, far plane 1000" of a perspective or orthographic projection. */
std::string describeDepthRange(const osg::Matrixd& projection)
{
    double left, right, bottom, top, zNear, zFar;
    if (!projection.getFrustum(left, right, bottom, top, zNear, zFar) &&
        !projection.getOrtho(left, right, bottom, top, zNear, zFar))
        return "an unusual projection";
    return "from a near plane at " + format(zNear) + " and a far plane at " + format(zFar);
}

/** What the glyphs cover on screen: the widest glyph's width and the area of them all, in pixels. */
struct Footprint
{
    double widest = 0.0;
    double area = 0.0;
};

/** The glyphs' footprint in a viewport of height pixels, through the projection's vertical scale. */
Footprint measureFootprint(const std::vector<PlacedCloud>& clouds, const osg::Matrixd& view,
                           const osg::Matrixd& projection, double height)
{
    const bool perspective = projection(3, 3) == 0.0;
    const double pixelsPerUnit = 0.5 * height * std::fabs(projection(1, 1));
    Footprint footprint;
    for (const PlacedCloud& placed : clouds)
    {
        const GlyphCloud& cloud = *placed.cloud;
        const osg::Matrixd toEye = placed.toWorld * view;
        const double scale = toEye.getScale().length() / std::sqrt(3.0) * pixelsPerUnit;
        const bool vector = isVectorShape(cloud.getShape());
        const double widthFactor = cloud.getShape() == GlyphShape::Arrow
                                       ? 2.0 * std::max(1.0f, cloud.getArrowHeadRadiusRatio())
                                       : 2.0;
        for (unsigned int i = 0; i < cloud.getNumGlyphs(); ++i)
        {
            if (getSkipReason(cloud, i) != DRAWN)
                continue;
            const double distance =
                -((osg::Vec3d((*cloud.getPositions())[i]) + cloud.getOrigin()) * toEye).z();
            if (perspective && distance <= 0.0)
                continue;
            const double perUnit = perspective ? scale / distance : scale;
            const double width = widthFactor * getGlyphRadius(cloud, i) * perUnit;
            const double length =
                vector ? cloud.getLengthScale() * perUnit *
                             (cloud.getUniformLength() ? 1.0 : (*cloud.getVectors())[i].length())
                       : 0.0;
            footprint.widest = std::max(footprint.widest, width);
            footprint.area += vector ? width * std::max(width, length) : 0.25 * osg::PI * width * width;
        }
    }
    return footprint;
}

std::string diagnose(osg::Node& node, const osg::Camera& camera, const osg::Matrixd& view,
                     const osg::Viewport& viewport)
{
    CloudCollector collector;
    node.accept(collector);
    if (collector.clouds.empty())
        return std::string();
    const std::string skipped = diagnoseSkipped(collector.clouds);
    if (!skipped.empty())
        return skipped;
    osg::BoundingBoxd bounds;
    if (!getWorldBounds(collector.clouds, bounds))
        return "no glyph is drawn: the glyphs' bounds are not finite (coordinates or radii beyond float "
               "range)";
    const osg::Matrixd& projection = camera.getProjectionMatrix();
    if (!isFinite(view) || !isFinite(projection))
        return "no glyph is seen: the camera's view or projection is not finite (framing glyphs within " +
               format(bounds.xMin()) + " .. " + format(bounds.xMax()) + " in x)";

    double nearest = std::numeric_limits<double>::max(), farthest = std::numeric_limits<double>::lowest();
    double farthestCorner = 0.0;
    for (unsigned int corner = 0; corner < 8; ++corner)
    {
        const osg::Vec3d eye = bounds.corner(corner) * view;
        nearest = std::min(nearest, -eye.z());
        farthest = std::max(farthest, -eye.z());
        farthestCorner = std::max(farthestCorner, eye.length());
    }
    const bool perspective = projection(3, 3) == 0.0;
    if (perspective && farthest <= 0.0)
        return "no glyph is seen: every glyph is behind the camera";
    osg::Polytope sides;
    sides.setToUnitFrustum(false, false);
    sides.transformProvidingInverse(view * projection);
    if (!sides.contains(osg::BoundingBox(bounds._min, bounds._max)))
        return "no glyph is seen: the glyphs are outside the camera's field of view";
    if (!holdsDepthRange(camera, nearest, farthest))
        return "no glyph is seen: the glyphs' depths, " + format(std::max(nearest, 0.0)) + " to " +
               format(farthest) +
               " from the eye, are lost to rounding when OSG fits the projection's near and " +
               "far planes to them (" + describeDepthRange(projection) + ")";
    if (farthestCorner > FLOAT_SQUARE_LIMIT)
        return "no glyph is seen: the glyphs lie up to " + format(farthestCorner) + " from the eye; beyond " +
               format(FLOAT_SQUARE_LIMIT) + " the shaders' float arithmetic overflows";
    // Glyphs under a pixel are drawn where they hold a pixel centre: many still make a picture.
    const Footprint footprint = measureFootprint(collector.clouds, view, projection, viewport.height());
    const double pixels = viewport.width() * viewport.height();
    if (footprint.widest < 1.0 && footprint.area < SUB_PIXEL_COVERAGE_LIMIT * pixels)
        return "the glyphs hardly show: every glyph is under a pixel wide (the widest " +
               format(footprint.widest) + " pixels), and together they cover about " +
               format(footprint.area) + " of the " + std::to_string(static_cast<long long>(pixels)) +
               " pixels";
    return std::string();
}

/** The camera's viewport, or osgviewer's default window. */
osg::ref_ptr<const osg::Viewport> getViewport(const osg::Camera& camera)
{
    const osg::Viewport* viewport = camera.getViewport();
    if (viewport && viewport->width() > 0.0 && viewport->height() > 0.0)
        return viewport;
    return new osg::Viewport(0.0, 0.0, DEFAULT_VIEWPORT_WIDTH, DEFAULT_VIEWPORT_HEIGHT);
}

}

std::string osgGlyphs::diagnoseGlyphView(osg::Node& node, const osg::Camera& camera)
{
    return diagnose(node, camera, camera.getViewMatrix(), *getViewport(camera));
}

std::string osgGlyphs::diagnoseGlyphView(osg::Node& node, const osg::Camera& camera, const osg::Matrixd& view)
{
    return diagnose(node, camera, view, *getViewport(camera));
}

std::string osgGlyphs::diagnoseGlyphScene(osg::Node& node)
{
    // osgViewer's default camera, and osgGA::CameraManipulator::computeHomePosition().
    const double fovY = 30.0, aspect = DEFAULT_VIEWPORT_WIDTH / DEFAULT_VIEWPORT_HEIGHT;
    osg::ref_ptr<osg::Camera> camera = new osg::Camera;
    camera->setProjectionMatrixAsPerspective(fovY, aspect, 1.0, 10000.0);
    camera->setViewport(0, 0, DEFAULT_VIEWPORT_WIDTH, DEFAULT_VIEWPORT_HEIGHT);
    const osg::BoundingSphere& bound = node.getBound();
    const double radius = std::max(static_cast<double>(bound.radius()), 1e-6);
    const double halfAngle = std::atan(std::min(std::tan(osg::DegreesToRadians(fovY / 2.0)) * aspect,
                                                std::tan(osg::DegreesToRadians(fovY / 2.0))));
    const double distance = radius / std::sin(halfAngle);
    const osg::Vec3d center = bound.center();
    const osg::Matrixd view =
        osg::Matrixd::lookAt(center + osg::Vec3d(0.0, -distance, 0.0), center, osg::Vec3d(0.0, 0.0, 1.0));
    return diagnose(node, *camera, view, *camera->getViewport());
}
