// Analytic ground truth for regression renders: a scene of exact primitives, ray-cast
// through the same pixels the renderer draws.

#ifndef OSGGLYPHS_TESTS_ANALYTICSCENE_H
#define OSGGLYPHS_TESTS_ANALYTICSCENE_H

#include "RenderHarness.h"

#include <osg/Plane>
#include <osg/Quat>

#include <limits>
#include <string>
#include <vector>

namespace osgGlyphsTest
{

/** The nearest surface a ray meets. label is the primitive's index, -1 for none. */
struct RayHit
{
    int label = -1;
    double distance = std::numeric_limits<double>::infinity();
    osg::Vec3d point;
    osg::Vec3d normal;

    bool hit() const { return label >= 0; }
};

/** OSG's light 0 as the glyph shaders read it (gl_LightSource[0]): its position in eye space
 * (w = 0: the direction towards the light) and its colours. */
struct EyeLight
{
    osg::Vec4d position;
    osg::Vec3d ambient, diffuse, specular;
};

/** The lit colour of shaders/osgGlyphs/lighting.glsl, unclamped: a base colour at an eye-space
 * point with a unit normal and the unit direction to the eye, under the light, with a
 * GlyphCloud's material (ambient, specular strength, shininess). */
osg::Vec3d shadeLikeGlyphs(const osg::Vec3d& base, const osg::Vec3d& position, const osg::Vec3d& normal,
                           const osg::Vec3d& toEye, const EyeLight& light, const osg::Vec3d& material);

class AnalyticScene
{
public:
    AnalyticScene();
    AnalyticScene(const AnalyticScene& other);
    AnalyticScene& operator=(const AnalyticScene& other);
    ~AnalyticScene();

    /** Each add returns the primitive's label. */
    int addSphere(const osg::Vec3d& center, double radius);
    /** The ellipsoid of semi-axes along its body x, y, z axes, turned by rotation (a body vector v
     * lies at rotation * v from center). */
    int addEllipsoid(const osg::Vec3d& center, const osg::Vec3d& semiAxes, const osg::Quat& rotation);
    /** Barr's superellipsoid of exponents e1 (along the body z axis) and e2 (around it), with the
     * semi-axes and turn of addEllipsoid(). */
    int addSuperquadric(const osg::Vec3d& center, const osg::Vec3d& semiAxes, const osg::Quat& rotation,
                        double e1, double e2);
    int addBox(const osg::Vec3d& min, const osg::Vec3d& max);
    /** A plane through point with the given normal; only rays hitting it within the
     * given distance of point count (a finite square quad when used for a plane drawable). */
    int addPlane(const osg::Vec3d& point, const osg::Vec3d& normal, double halfExtent);

    /** A solid of revolution about the axis from base (unit axis): radius r0 at z0 changing
     * linearly to r1 at z1 (distances along the axis), with flat caps where asked.
     * Cylinders, cones and arrows are made of these. Returns the label given (or, for -1,
     * the next label: labels count the solids in the order they were added). */
    int addSegment(const osg::Vec3d& base, const osg::Vec3d& axis, double z0, double r0, double z1, double r1,
                   bool capAtZ0, bool capAtZ1, int label = -1);

    /** The vector glyphs with osgGlyphs' convention: tail at base, unit axis, given length and
     * radius; arrows with the head's length ratio and radius ratio. All parts share one label. */
    int addCylinder(const osg::Vec3d& tail, const osg::Vec3d& axis, double length, double radius);
    int addCone(const osg::Vec3d& tail, const osg::Vec3d& axis, double length, double radius);
    int addArrow(const osg::Vec3d& tail, const osg::Vec3d& axis, double length, double radius,
                 double headLength, double headRadius);

    /** Keeps the half-space plane(p) >= 0 only (world coordinates, osg::ClipPlane's convention):
     * surfaces beyond it are cut away. */
    void addClipPlane(const osg::Plane& plane);
    /** Capped, a cut shows the solid's cross-section in the plane, facing the viewer; open (the
     * default), the surfaces behind the cut show. */
    void setClipCaps(bool capped) { _clipCaps = capped; }

    /** The nearest hit at least minDistance along the ray. With clip planes, the normal faces
     * the ray's origin (the inside of a cut solid, a cap). */
    RayHit cast(const osg::Vec3d& origin, const osg::Vec3d& direction, double minDistance = 0.0) const;

    /** The hit through window point (x + dx, y + dy), between the frame's near and far planes. */
    RayHit castPixel(const Frame& frame, int x, int y, double dx = 0.5, double dy = 0.5) const;

    /** The label at pixel (x, y) when the centre and four samples 0.3 px around it agree;
     * AMBIGUOUS for pixels on a silhouette or an intersection curve. */
    int certainLabel(const Frame& frame, int x, int y) const;
    static const int AMBIGUOUS = -2;

private:
    /** A solid in GLM's double-precision types, as the shaders' math has it (AnalyticScene.cpp). */
    struct Primitive;
    int add(const Primitive& primitive);

    /** The nearest surface hit, clip planes ignored. */
    RayHit castSurfaces(const osg::Vec3d& origin, const osg::Vec3d& direction, double minDistance) const;
    /** The nearest surface hit with clip planes; see cast. */
    RayHit castClipped(const osg::Vec3d& origin, const osg::Vec3d& direction, double minDistance) const;
    bool isKept(const osg::Vec3d& point) const;
    /** The label of a solid (of the given label, or any for -1) the point lies inside; -1 for none. */
    int labelInside(const osg::Vec3d& point, int label = -1) const;

    std::vector<Primitive> _primitives;
    int _numLabels = 0;
    std::vector<osg::Plane> _clipPlanes;
    bool _clipCaps = false;
};

}

#endif
