#include "AnalyticScene.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <variant>

// The truth is ray-cast in double precision with the math of the shaders it checks
// (shaders/osgGlyphs/sphere.glsl, vector.glsl and lighting.glsl), in GLM's GLSL-like types; osg types at the
// boundary of the class only.

namespace
{

using glm::dvec2;
using glm::dvec3;
using glm::dvec4;

const double INFINITE_DISTANCE = std::numeric_limits<double>::infinity();

dvec3 toGlm(const osg::Vec3d& v)
{
    return dvec3(v.x(), v.y(), v.z());
}

osg::Vec3d toOsg(const dvec3& v)
{
    return osg::Vec3d(v.x, v.y, v.z);
}

/** GLSL's v.xy. */
dvec2 xy(const dvec3& v)
{
    return dvec2(v.x, v.y);
}

/** The nearest surface met so far along a ray. */
struct Hit
{
    double t = INFINITE_DISTANCE;
    dvec3 normal = dvec3(0.0);
};

struct Sphere
{
    dvec4 sphere; // centre, radius
};

struct Box
{
    dvec3 min, max;
};

/** A square of the given half extent about point, facing both ways. */
struct Plane
{
    dvec3 point, normal;
    double halfExtent;
};

/** The quadric (x - centre)^T form (x - centre) <= 1: an ellipsoid. */
struct Ellipsoid
{
    dvec3 centre;
    glm::dmat3 form;
};

/** Barr's superellipsoid: in the body frame scaled by the semi-axes,
 * (|x|^(2/e2) + |y|^(2/e2))^(e2/e1) + |z|^(2/e1) <= 1. toBody maps x - centre there. */
struct Superquadric
{
    dvec3 centre;
    glm::dmat3 toBody;
    double e1, e2, reach; // reach: a radius about centre that holds it

    double inside(dvec3 p) const
    {
        const dvec3 u = glm::abs(toBody * (p - centre));
        return std::pow(std::pow(u.x, 2.0 / e2) + std::pow(u.y, 2.0 / e2), e2 / e1) +
               std::pow(u.z, 2.0 / e1) - 1.0;
    }
};

/** A solid of revolution about the unit axis from base: radius r0 at z0 to r1 at z1. */
struct Segment
{
    dvec3 base, axis;
    double z0, r0, z1, r1;
    bool cap0, cap1;
};

// sphere.glsl

/** Where the ray origin + t * direction (unit) enters and leaves the sphere; false if it misses. */
bool intersectSphere(dvec3 origin, dvec3 direction, dvec4 sphere, double& tEnter, double& tLeave)
{
    dvec3 m = origin - dvec3(sphere);
    double b = dot(m, direction);
    dvec3 closest = m - b * direction;
    double h2 = sphere.w * sphere.w - dot(closest, closest);
    if (h2 < 0.0)
        return false;
    double h = std::sqrt(h2);
    tEnter = -b - h;
    tLeave = -b + h;
    return true;
}

// vector.glsl

/** Two unit vectors that complete the axis to a right-handed orthonormal frame. */
void axisFrame(dvec3 axis, dvec3& u, dvec3& v)
{
    dvec3 helper = std::abs(axis.x) < 0.9 ? dvec3(1.0, 0.0, 0.0) : dvec3(0.0, 1.0, 0.0);
    u = normalize(cross(helper, axis));
    v = cross(axis, u);
}

void hitDisc(dvec3 o, dvec3 d, double z, double radius, double facing, double tMin, Hit& best)
{
    if (std::abs(d.z) < 1e-15)
        return;
    double t = (z - o.z) / d.z;
    dvec2 p = xy(o) + xy(d) * t;
    if (t >= tMin && t < best.t && dot(p, p) <= radius * radius)
    {
        best.t = t;
        best.normal = dvec3(0.0, 0.0, facing);
    }
}

/** The side of a cylinder or truncated cone: radius r0 at z0 changing linearly to r1 at z1. */
void hitSide(dvec3 o, dvec3 d, double z0, double r0, double z1, double r1, double tMin, Hit& best)
{
    // x^2 + y^2 = (r0 + slope (z - z0))^2, with slope = (r1 - r0) / (z1 - z0).
    double slope = (r1 - r0) / (z1 - z0);
    double radiusAtOrigin = r0 + slope * (o.z - z0);
    double a = dot(xy(d), xy(d)) - slope * slope * d.z * d.z;
    double b = dot(xy(o), xy(d)) - slope * radiusAtOrigin * d.z;
    double c = dot(xy(o), xy(o)) - radiusAtOrigin * radiusAtOrigin;
    double roots[2];
    if (std::abs(a) < 1e-15)
    {
        if (std::abs(b) < 1e-15)
            return;
        roots[0] = roots[1] = -c / (2.0 * b);
    }
    else
    {
        double discriminant = b * b - a * c;
        if (discriminant < 0.0)
            return;
        double s = std::sqrt(discriminant);
        roots[0] = std::min((-b - s) / a, (-b + s) / a);
        roots[1] = std::max((-b - s) / a, (-b + s) / a);
    }
    for (double t : roots)
    {
        double z = o.z + d.z * t;
        double radiusAtHit = r0 + slope * (z - z0);
        if (t >= tMin && t < best.t && z >= z0 && z <= z1 && radiusAtHit >= 0.0)
        {
            dvec2 p = xy(o) + xy(d) * t;
            best.t = t;
            best.normal = normalize(dvec3(p, -slope * radiusAtHit));
            return;
        }
    }
}

// lighting.glsl, lit

dvec3 shade(dvec3 base, dvec3 position, dvec3 normal, dvec3 toEye, dvec4 light, dvec3 lightAmbient,
            dvec3 lightDiffuse, dvec3 lightSpecular, dvec3 material)
{
    dvec3 toLight = light.w == 0.0 ? normalize(dvec3(light)) : normalize(dvec3(light) - position);
    double diffuse = std::max(dot(normal, toLight), 0.0);
    double specular = 0.0;
    if (diffuse > 0.0)
        specular = std::pow(std::max(dot(normal, normalize(toLight + toEye)), 0.0), material.z);
    dvec3 ambient = dvec3(material.x) + lightAmbient;
    return base * (ambient + diffuse * lightDiffuse) + material.y * specular * lightSpecular;
}

// Each solid: whether the ray meets it at tMin or beyond and nearer than nearest, which it updates.

bool hitSolid(const Sphere& solid, dvec3 origin, dvec3 direction, double tMin, Hit& nearest)
{
    double tEnter, tLeave;
    if (!intersectSphere(origin, direction, solid.sphere, tEnter, tLeave))
        return false;
    double t = tEnter >= tMin ? tEnter : tLeave;
    if (t < tMin || t >= nearest.t)
        return false;
    nearest.t = t;
    nearest.normal = (origin + direction * t - dvec3(solid.sphere)) / solid.sphere.w;
    return true;
}

bool hitSolid(const Segment& solid, dvec3 origin, dvec3 direction, double tMin, Hit& nearest)
{
    dvec3 u, v;
    axisFrame(solid.axis, u, v);
    dvec3 relative = origin - solid.base;
    dvec3 o = dvec3(dot(relative, u), dot(relative, v), dot(relative, solid.axis));
    dvec3 d = dvec3(dot(direction, u), dot(direction, v), dot(direction, solid.axis));
    Hit local;
    local.t = nearest.t;
    hitSide(o, d, solid.z0, solid.r0, solid.z1, solid.r1, tMin, local);
    if (solid.cap0)
        hitDisc(o, d, solid.z0, solid.r0, -1.0, tMin, local);
    if (solid.cap1)
        hitDisc(o, d, solid.z1, solid.r1, 1.0, tMin, local);
    if (local.t >= nearest.t)
        return false;
    nearest.t = local.t;
    nearest.normal = local.normal.x * u + local.normal.y * v + local.normal.z * solid.axis;
    return true;
}

/** The quadratic in t of the quadric along the ray, in the world frame: not the shaders' way (which
 * maps the ellipsoid to the unit sphere), so that the two can disagree. */
bool hitSolid(const Ellipsoid& solid, dvec3 origin, dvec3 direction, double tMin, Hit& nearest)
{
    const dvec3 m = origin - solid.centre;
    const double a = dot(direction, solid.form * direction);
    const double b = dot(m, solid.form * direction);
    const double c = dot(m, solid.form * m) - 1.0;
    const double discriminant = b * b - a * c;
    if (discriminant < 0.0)
        return false;
    const double root = std::sqrt(discriminant);
    const double q = b > 0.0 ? -(b + root) : -(b - root); // the roots are q / a and c / q
    double t0 = q / a, t1 = c / q;
    if (t0 > t1)
        std::swap(t0, t1);
    const double t = t0 >= tMin ? t0 : t1;
    if (t < tMin || t >= nearest.t)
        return false;
    nearest.t = t;
    nearest.normal = normalize(solid.form * (m + direction * t));
    return true;
}

/** Sphere tracing within the superquadric's box: N = (Barr's function + 1)^(e1/2) is a norm no
 * larger than the L1 norm, so a point where N > 1 lies at least (N - 1) / sqrt(3) from the surface in
 * the unit frame, and each step goes that far; the normal (outward) by central differences of
 * Barr's function. A ray that starts inside meets the surface where it leaves, as for the quadric. Not the
 * shaders' way (Newton's steps from a bracketed minimum), so that the two can disagree. */
bool hitSolid(const Superquadric& solid, dvec3 origin, dvec3 direction, double tMin, Hit& nearest)
{
    const dvec3 o = solid.toBody * (origin - solid.centre), d = solid.toBody * direction;
    double lo = tMin, hi = INFINITE_DISTANCE;
    for (int axis = 0; axis < 3; ++axis)
    {
        if (std::abs(d[axis]) < 1e-300)
        {
            if (std::abs(o[axis]) > 1.0)
                return false;
            continue;
        }
        const double tA = (-1.0 - o[axis]) / d[axis], tB = (1.0 - o[axis]) / d[axis];
        lo = std::max(lo, std::min(tA, tB));
        hi = std::min(hi, std::max(tA, tB));
    }
    if (lo >= hi || lo >= nearest.t)
        return false;
    const double speed = glm::length(d), sqrt3 = std::sqrt(3.0);
    // From outside, forward from the box's entry; from inside (the ray starts in the solid), the
    // way out: backward from the box's exit.
    const bool fromInside = lo == tMin && solid.inside(origin + direction * lo) < 0.0;
    const double way = fromInside ? -1.0 : 1.0;
    double t = fromInside ? hi : lo;
    for (int i = 0; i < 100000 && t >= lo && t <= hi; ++i)
    {
        const double excess = std::pow(solid.inside(origin + direction * t) + 1.0, 0.5 * solid.e1) - 1.0;
        if (excess <= 1e-11)
        {
            if (t >= nearest.t)
                return false;
            nearest.t = t;
            const dvec3 p = origin + direction * t;
            const double e = 1e-7 * solid.reach;
            dvec3 gradient;
            for (int axis = 0; axis < 3; ++axis)
            {
                dvec3 offset(0.0);
                offset[axis] = e;
                gradient[axis] = solid.inside(p + offset) - solid.inside(p - offset);
            }
            nearest.normal = normalize(gradient);
            return true;
        }
        t += way * excess / (sqrt3 * speed);
    }
    return false;
}

/** The slabs of the box; the normal is that of the face the ray enters. */
bool hitSolid(const Box& solid, dvec3 origin, dvec3 direction, double tMin, Hit& nearest)
{
    double tNear = -INFINITE_DISTANCE, tFar = INFINITE_DISTANCE;
    int nearAxis = 0;
    for (int axis = 0; axis < 3; ++axis)
    {
        if (std::abs(direction[axis]) < 1e-300)
        {
            if (origin[axis] < solid.min[axis] || origin[axis] > solid.max[axis])
                return false;
            continue;
        }
        double t0 = (solid.min[axis] - origin[axis]) / direction[axis];
        double t1 = (solid.max[axis] - origin[axis]) / direction[axis];
        if (t0 > t1)
            std::swap(t0, t1);
        if (t0 > tNear)
        {
            tNear = t0;
            nearAxis = axis;
        }
        tFar = std::min(tFar, t1);
    }
    if (tNear > tFar || tNear < tMin || tNear >= nearest.t)
        return false;
    nearest.t = tNear;
    nearest.normal = dvec3(0.0);
    nearest.normal[nearAxis] = direction[nearAxis] > 0.0 ? -1.0 : 1.0;
    return true;
}

bool hitSolid(const Plane& solid, dvec3 origin, dvec3 direction, double tMin, Hit& nearest)
{
    double denominator = dot(solid.normal, direction);
    if (std::abs(denominator) < 1e-300)
        return false;
    double t = dot(solid.point - origin, solid.normal) / denominator;
    dvec3 offset = origin + direction * t - solid.point;
    if (t < tMin || t >= nearest.t || any(greaterThan(abs(offset), dvec3(solid.halfExtent))))
        return false;
    nearest.t = t;
    nearest.normal = denominator < 0.0 ? solid.normal : -solid.normal;
    return true;
}

// Whether a point lies inside each solid (planes have no inside).

bool isInside(const Sphere& solid, dvec3 p)
{
    return glm::length(p - dvec3(solid.sphere)) < solid.sphere.w;
}

bool isInside(const Segment& solid, dvec3 p)
{
    dvec3 u, v;
    axisFrame(solid.axis, u, v);
    dvec3 relative = p - solid.base;
    double z = dot(relative, solid.axis);
    double radius = solid.r0 + (solid.r1 - solid.r0) * (z - solid.z0) / (solid.z1 - solid.z0);
    dvec2 across(dot(relative, u), dot(relative, v));
    return z > solid.z0 && z < solid.z1 && glm::length(across) < radius;
}

bool isInside(const Ellipsoid& solid, dvec3 p)
{
    return dot(p - solid.centre, solid.form * (p - solid.centre)) < 1.0;
}

bool isInside(const Superquadric& solid, dvec3 p)
{
    return solid.inside(p) < 0.0;
}

bool isInside(const Box& solid, dvec3 p)
{
    return all(greaterThan(p, solid.min)) && all(lessThan(p, solid.max));
}

bool isInside(const Plane&, dvec3)
{
    return false;
}

}

namespace osgGlyphsTest
{

osg::Vec3d shadeLikeGlyphs(const osg::Vec3d& base, const osg::Vec3d& position, const osg::Vec3d& normal,
                           const osg::Vec3d& toEye, const EyeLight& light, const osg::Vec3d& material)
{
    const dvec4 lightPosition(light.position.x(), light.position.y(), light.position.z(), light.position.w());
    return toOsg(shade(toGlm(base), toGlm(position), toGlm(normal), toGlm(toEye), lightPosition,
                       toGlm(light.ambient), toGlm(light.diffuse), toGlm(light.specular), toGlm(material)));
}

struct AnalyticScene::Primitive
{
    std::variant<Sphere, Box, Plane, Segment, Ellipsoid, Superquadric> solid;
    int label;
};

AnalyticScene::AnalyticScene() = default;
AnalyticScene::AnalyticScene(const AnalyticScene& other) = default;
AnalyticScene& AnalyticScene::operator=(const AnalyticScene& other) = default;
AnalyticScene::~AnalyticScene() = default;

int AnalyticScene::add(const Primitive& primitive)
{
    _primitives.push_back(primitive);
    if (_primitives.back().label < 0)
        _primitives.back().label = _numLabels++;
    return _primitives.back().label;
}

int AnalyticScene::addSphere(const osg::Vec3d& center, double radius)
{
    return add(Primitive{Sphere{dvec4(toGlm(center), radius)}, -1});
}

int AnalyticScene::addEllipsoid(const osg::Vec3d& center, const osg::Vec3d& semiAxes,
                                const osg::Quat& rotation)
{
    // form = R diag(1 / a^2) R^T, R's columns the rotated body axes.
    glm::dmat3 form(0.0);
    for (int k = 0; k < 3; ++k)
    {
        osg::Vec3d body;
        body[k] = 1.0;
        const dvec3 axis = toGlm(rotation * body);
        form += glm::outerProduct(axis, axis) / (semiAxes[k] * semiAxes[k]);
    }
    return add(Primitive{Ellipsoid{toGlm(center), form}, -1});
}

int AnalyticScene::addSuperquadric(const osg::Vec3d& center, const osg::Vec3d& semiAxes,
                                   const osg::Quat& rotation, double e1, double e2)
{
    // toBody: the rows of R^T over the semi-axes.
    glm::dmat3 toBody(0.0);
    for (int k = 0; k < 3; ++k)
    {
        osg::Vec3d body;
        body[k] = 1.0;
        const dvec3 axis = toGlm(rotation * body) / semiAxes[k];
        for (int column = 0; column < 3; ++column)
            toBody[column][k] = axis[column];
    }
    const double reach = 1.7320508075688772 * std::max(semiAxes.x(), std::max(semiAxes.y(), semiAxes.z()));
    return add(Primitive{Superquadric{toGlm(center), toBody, e1, e2, reach}, -1});
}

int AnalyticScene::addBox(const osg::Vec3d& min, const osg::Vec3d& max)
{
    return add(Primitive{Box{toGlm(min), toGlm(max)}, -1});
}

int AnalyticScene::addPlane(const osg::Vec3d& point, const osg::Vec3d& normal, double halfExtent)
{
    return add(Primitive{Plane{toGlm(point), glm::normalize(toGlm(normal)), halfExtent}, -1});
}

int AnalyticScene::addSegment(const osg::Vec3d& base, const osg::Vec3d& axis, double z0, double r0, double z1,
                              double r1, bool capAtZ0, bool capAtZ1, int label)
{
    const Segment segment{toGlm(base), glm::normalize(toGlm(axis)), z0, r0, z1, r1, capAtZ0, capAtZ1};
    return add(Primitive{segment, label});
}

int AnalyticScene::addCylinder(const osg::Vec3d& tail, const osg::Vec3d& axis, double length, double radius)
{
    return addSegment(tail, axis, 0.0, radius, length, radius, true, true);
}

int AnalyticScene::addCone(const osg::Vec3d& tail, const osg::Vec3d& axis, double length, double radius)
{
    return addSegment(tail, axis, 0.0, radius, length, 0.0, true, false);
}

int AnalyticScene::addArrow(const osg::Vec3d& tail, const osg::Vec3d& axis, double length, double radius,
                            double headLength, double headRadius)
{
    const double headStart = length * (1.0 - headLength);
    const int label = addSegment(tail, axis, 0.0, radius, headStart, radius, true, false);
    return addSegment(tail, axis, headStart, radius * headRadius, length, 0.0, true, false, label);
}

void AnalyticScene::addClipPlane(const osg::Plane& plane)
{
    _clipPlanes.push_back(plane);
}

int AnalyticScene::labelInside(const osg::Vec3d& point, int label) const
{
    for (const Primitive& primitive : _primitives)
    {
        const auto inside = [&](const auto& solid) { return isInside(solid, toGlm(point)); };
        if ((label < 0 || primitive.label == label) && std::visit(inside, primitive.solid))
            return primitive.label;
    }
    return -1;
}

bool AnalyticScene::isKept(const osg::Vec3d& point) const
{
    for (const osg::Plane& plane : _clipPlanes)
        if (plane.distance(point) < 0.0)
            return false;
    return true;
}

RayHit AnalyticScene::castClipped(const osg::Vec3d& origin, const osg::Vec3d& direction,
                                  double minDistance) const
{
    // The nearest surface point the planes keep: step from surface to surface along the ray.
    RayHit nearest;
    double from = minDistance;
    for (int surface = 0; surface < 64; ++surface)
    {
        const RayHit hit = castSurfaces(origin, direction, from);
        if (!hit.hit())
            break;
        const osg::Vec3d before = hit.point - direction * 1e-7, after = hit.point + direction * 1e-7;
        if (isKept(hit.point) && !(labelInside(before, hit.label) >= 0 && labelInside(after, hit.label) >= 0))
        {
            nearest = hit;
            break;
        }
        from = hit.distance + 1e-9;
    }
    // Capped: where a plane crosses the ray inside a solid and the other planes keep the point.
    for (std::size_t i = 0; _clipCaps && i < _clipPlanes.size(); ++i)
    {
        const osg::Vec3d normal = _clipPlanes[i].getNormal();
        const double rate = normal * direction;
        if (rate <= 0.0)
            continue; // the ray leaves the kept side here: no cap faces it
        const double t = -_clipPlanes[i].distance(origin) / rate;
        const osg::Vec3d point = origin + direction * t;
        if (t < minDistance || t >= nearest.distance)
            continue;
        bool kept = true;
        for (std::size_t j = 0; j < _clipPlanes.size(); ++j)
            kept = kept && (j == i || _clipPlanes[j].distance(point) >= 0.0);
        const int label = kept ? labelInside(point) : -1;
        if (label >= 0)
        {
            nearest.label = label;
            nearest.distance = t;
            nearest.point = point;
            nearest.normal = -normal / normal.length();
        }
    }
    if (nearest.hit() && nearest.normal * direction > 0.0)
        nearest.normal = -nearest.normal;
    return nearest;
}

RayHit AnalyticScene::cast(const osg::Vec3d& origin, const osg::Vec3d& direction, double minDistance) const
{
    return _clipPlanes.empty() ? castSurfaces(origin, direction, minDistance)
                               : castClipped(origin, direction, minDistance);
}

RayHit AnalyticScene::castSurfaces(const osg::Vec3d& origin, const osg::Vec3d& direction,
                                   double minDistance) const
{
    const dvec3 o = toGlm(origin), d = toGlm(direction);
    Hit nearest;
    RayHit result;
    for (const Primitive& primitive : _primitives)
    {
        const auto hit = [&](const auto& solid) { return hitSolid(solid, o, d, minDistance, nearest); };
        if (std::visit(hit, primitive.solid))
            result.label = primitive.label;
    }
    if (result.hit())
    {
        result.distance = nearest.t;
        result.point = toOsg(o + d * nearest.t);
        result.normal = toOsg(nearest.normal);
    }
    return result;
}

RayHit AnalyticScene::castPixel(const Frame& frame, int x, int y, double dx, double dy) const
{
    osg::Vec3d origin, direction;
    frame.pixelRay(x + dx, y + dy, origin, direction);
    return cast(origin, direction);
}

int AnalyticScene::certainLabel(const Frame& frame, int x, int y) const
{
    const int label = castPixel(frame, x, y).label;
    const double offsets[4][2] = {{0.2, 0.2}, {0.8, 0.2}, {0.2, 0.8}, {0.8, 0.8}};
    for (const auto& offset : offsets)
    {
        if (castPixel(frame, x, y, offset[0], offset[1]).label != label)
            return AMBIGUOUS;
    }
    return label;
}

}
