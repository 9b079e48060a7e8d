// The ray casts of shaders/osgGlyphs, on the CPU: same names, same steps, doubles for floats.
#include "GlyphRayCast.h"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>

using namespace osgGlyphs;
using namespace osgGlyphs::detail;

namespace
{

const double INFINITE_DISTANCE = 1.0e300;

using glm::dvec2;
using glm::dvec3;

/** sphere.glsl: where the ray enters and leaves the sphere; false if it misses. */
bool intersectSphere(const dvec3& origin, const dvec3& direction, const dvec3& centre, double radius,
                     double& tEnter, double& tLeave)
{
    const dvec3 m = origin - centre;
    const double b = glm::dot(m, direction);
    const dvec3 closest = m - b * direction;
    const double h2 = radius * radius - glm::dot(closest, closest);
    if (h2 < 0.0)
        return false;
    const double h = std::sqrt(h2);
    tEnter = -b - h;
    tLeave = -b + h;
    return true;
}

/** ellipsoid.glsl: where the ray meets the ellipsoid x = centre + A u, |u| <= 1, in the frame where it
 * is the unit sphere (u = A^-1 (x - centre)), and the unit normals there; false if it misses. */
bool intersectEllipsoid(const dvec3& origin, const dvec3& direction, const dvec3& centre,
                        const glm::dmat3& semiAxes, double& tEnter, double& tLeave, dvec3& nEnter,
                        dvec3& nLeave)
{
    const glm::dmat3 inverse = glm::inverse(semiAxes);
    const dvec3 o = inverse * (origin - centre), d = inverse * direction;
    const double a = glm::dot(d, d), b = glm::dot(o, d);
    const dvec3 closest = o - (b / a) * d;
    const double h2 = 1.0 - glm::dot(closest, closest);
    if (h2 < 0.0)
        return false;
    const double h = std::sqrt(h2 / a);
    tEnter = -b / a - h;
    tLeave = -b / a + h;
    nEnter = glm::normalize(glm::transpose(inverse) * (o + d * tEnter));
    nLeave = glm::normalize(glm::transpose(inverse) * (o + d * tLeave));
    return true;
}

/** superquadric.glsl: the norm whose unit ball is the superquadric, and its gradient. */
double superquadricNorm(const dvec3& p, const glm::dvec2& exponents, dvec3& gradient)
{
    dvec3 a = glm::abs(p);
    const double largest = std::max(a.x, std::max(a.y, a.z));
    if (!(largest > 0.0))
    {
        gradient = dvec3(0.0);
        return 0.0;
    }
    a = glm::max(a / largest, dvec3(1e-20));
    const double q = 2.0 / exponents.y, s = 2.0 / exponents.x;
    const double xq = std::pow(a.x, q), yq = std::pow(a.y, q), rq = xq + yq;
    const double rs = std::pow(rq, s / q), zs = std::pow(a.z, s);
    const double ns = rs + zs, n = std::pow(ns, 1.0 / s);
    const double outer = n / ns, across = rq > 0.0 ? outer * rs / rq : 0.0;
    gradient = glm::sign(p) * dvec3(across * xq / a.x, across * yq / a.y, outer * zs / a.z);
    return largest * n;
}

double superquadricAlong(const dvec3& o, const dvec3& d, double t, const glm::dvec2& exponents, double& slope)
{
    dvec3 gradient;
    const double h = superquadricNorm(o + t * d, exponents, gradient) - 1.0;
    slope = glm::dot(gradient, d);
    return h;
}

/** Where the ray meets the superquadric of superquadric.glsl, in double precision and by another
 * route to the same surface: a search for a point inside, which brackets the entry and the exit,
 * then Newton's steps to each (the shaders take Newton's steps from the near end alone). */
bool intersectSuperquadric(const dvec3& origin, const dvec3& direction, const dvec3& centre,
                           const glm::dmat3& semiAxes, const glm::dvec2& exponents, double& tEnter,
                           double& tLeave, dvec3& nEnter)
{
    const glm::dmat3 inverse = glm::inverse(semiAxes);
    const dvec3 o = inverse * (origin - centre), d = inverse * direction;
    double lo = -INFINITE_DISTANCE, hi = INFINITE_DISTANCE;
    for (int axis = 0; axis < 3; ++axis)
    {
        const double safe = std::abs(d[axis]) < 1e-30 ? 1e-30 : d[axis];
        const double tA = (-1.0 - o[axis]) / safe, tB = (1.0 - o[axis]) / safe;
        lo = std::max(lo, std::min(tA, tB));
        hi = std::min(hi, std::max(tA, tB));
    }
    if (!(lo < hi))
        return false;
    double gLo, gHi;
    double hLo = superquadricAlong(o, d, lo, exponents, gLo);
    double hHi = superquadricAlong(o, d, hi, exponents, gHi);
    bool found = hLo <= 0.0 || hHi <= 0.0;
    double inside = hLo <= 0.0 ? lo : hi;
    for (int i = 0; i < 24 && !found; ++i)
    {
        if (!(gLo < 0.0) || !(gHi > 0.0))
            return false;
        const double tx = (hHi - hLo + gLo * lo - gHi * hi) / (gLo - gHi);
        if (hLo + gLo * (tx - lo) > 0.0)
            return false;
        const double t = i % 3 == 2 ? 0.5 * (lo + hi) : std::clamp(tx, lo, hi);
        double g;
        const double h = superquadricAlong(o, d, t, exponents, g);
        if (h <= 0.0)
        {
            found = true;
            inside = t;
        }
        else if (g < 0.0)
        {
            lo = t;
            hLo = h;
            gLo = g;
        }
        else
        {
            hi = t;
            hHi = h;
            gHi = g;
        }
    }
    if (!found)
        return false;
    tEnter = lo;
    tLeave = hi;
    for (int i = 0; i < 16 && hLo > 2e-7 && gLo < 0.0; ++i)
    {
        tEnter = std::min(tEnter - hLo / gLo, inside);
        hLo = superquadricAlong(o, d, tEnter, exponents, gLo);
    }
    for (int i = 0; i < 16 && hHi > 2e-7 && gHi > 0.0; ++i)
    {
        tLeave = std::max(tLeave - hHi / gHi, inside);
        hHi = superquadricAlong(o, d, tLeave, exponents, gHi);
    }
    dvec3 gradient;
    superquadricNorm(o + tEnter * d, exponents, gradient);
    nEnter = glm::normalize(glm::transpose(inverse) * gradient);
    return true;
}

/** vector.glsl: two unit vectors that complete the axis to a right-handed orthonormal frame. */
void axisFrame(const dvec3& axis, dvec3& u, dvec3& v)
{
    const dvec3 helper = std::abs(axis.x) < 0.9 ? dvec3(1.0, 0.0, 0.0) : dvec3(0.0, 1.0, 0.0);
    u = glm::normalize(glm::cross(helper, axis));
    v = glm::cross(axis, u);
}

void hitDisc(const dvec3& o, const dvec3& d, double z, double radius, double facing, double& tBest,
             dvec3& nBest)
{
    if (std::abs(d.z) < 1e-12)
        return;
    const double t = (z - o.z) / d.z;
    const dvec2 p = dvec2(o) + dvec2(d) * t;
    if (t >= 0.0 && t < tBest && glm::dot(p, p) <= radius * radius)
    {
        tBest = t;
        nBest = dvec3(0.0, 0.0, facing);
    }
}

/** The side of a cylinder or truncated cone: radius r0 at z0 shrinking linearly to r1 at z1. */
void hitSide(const dvec3& o, const dvec3& d, double z0, double r0, double z1, double r1, double& tBest,
             dvec3& nBest)
{
    const double slope = (r1 - r0) / (z1 - z0);
    const double radiusAtOrigin = r0 + slope * (o.z - z0);
    const double a = glm::dot(dvec2(d), dvec2(d)) - slope * slope * d.z * d.z;
    const double b = glm::dot(dvec2(o), dvec2(d)) - slope * radiusAtOrigin * d.z;
    const double c = glm::dot(dvec2(o), dvec2(o)) - radiusAtOrigin * radiusAtOrigin;
    double roots[2];
    if (std::abs(a) < 1e-12)
    {
        if (std::abs(b) < 1e-12)
            return;
        roots[0] = roots[1] = -c / (2.0 * b);
    }
    else
    {
        const double discriminant = b * b - a * c;
        if (discriminant < 0.0)
            return;
        const double s = std::sqrt(discriminant);
        roots[0] = std::min((-b - s) / a, (-b + s) / a);
        roots[1] = std::max((-b - s) / a, (-b + s) / a);
    }
    for (double t : roots)
    {
        const double z = o.z + d.z * t;
        const double radiusAtHit = r0 + slope * (z - z0);
        if (t >= 0.0 && t < tBest && z >= z0 && z <= z1 && radiusAtHit >= 0.0)
        {
            const dvec2 p = dvec2(o) + dvec2(d) * t;
            tBest = t;
            nBest = glm::normalize(dvec3(p, -slope * radiusAtHit));
            return;
        }
    }
}

bool insideSide(const dvec3& p, double z0, double r0, double z1, double r1)
{
    const double r = r0 + (r1 - r0) * ((p.z - z0) / (z1 - z0));
    return p.z >= z0 && p.z <= z1 && glm::dot(dvec2(p), dvec2(p)) < r * r;
}

bool insideShape(const GlyphSolid& glyph, const dvec3& p)
{
    const double radius = glyph.radius, len = glyph.length;
    switch (glyph.shape)
    {
    case GlyphShape::Cylinder:
        return insideSide(p, 0.0, radius, len, radius);
    case GlyphShape::Cone:
        return insideSide(p, 0.0, radius, len, 0.0);
    default:
    {
        const double headStart = len * (1.0 - glyph.arrowParams.x);
        return insideSide(p, 0.0, radius, headStart, radius) ||
               insideSide(p, headStart, radius * glyph.arrowParams.y, len, 0.0);
    }
    }
}

/** The nearest hit (t >= 0) of a ray with the shape, and its normal; tBest stays infinite on a miss. */
void intersectShape(const GlyphSolid& glyph, const dvec3& o, const dvec3& d, double& tBest, dvec3& normal)
{
    const double radius = glyph.radius, len = glyph.length;
    tBest = INFINITE_DISTANCE;
    normal = dvec3(0.0, 0.0, 1.0);
    switch (glyph.shape)
    {
    case GlyphShape::Cylinder:
        hitSide(o, d, 0.0, radius, len, radius, tBest, normal);
        hitDisc(o, d, 0.0, radius, -1.0, tBest, normal);
        hitDisc(o, d, len, radius, 1.0, tBest, normal);
        break;
    case GlyphShape::Cone:
        hitSide(o, d, 0.0, radius, len, 0.0, tBest, normal);
        hitDisc(o, d, 0.0, radius, -1.0, tBest, normal);
        break;
    default:
    {
        const double headStart = len * (1.0 - glyph.arrowParams.x);
        const double headRadius = radius * glyph.arrowParams.y;
        hitSide(o, d, 0.0, radius, headStart, radius, tBest, normal);
        hitDisc(o, d, 0.0, radius, -1.0, tBest, normal);
        hitSide(o, d, headStart, headRadius, len, 0.0, tBest, normal);
        hitDisc(o, d, headStart, headRadius, -1.0, tBest, normal);
    }
    }
}

}

bool osgGlyphs::detail::castRay(const GlyphSolid& glyph, const dvec3& origin, const dvec3& direction,
                                double& t, dvec3& normal)
{
    if (glyph.shape == GlyphShape::Sphere)
    {
        double tEnter, tLeave;
        if (!intersectSphere(origin, direction, glyph.base, glyph.radius, tEnter, tLeave) || tLeave < 0.0)
            return false;
        t = std::max(tEnter, 0.0);
        normal = tEnter >= 0.0 ? (origin + direction * t - glyph.base) / glyph.radius : -direction;
        return true;
    }
    if (glyph.shape == GlyphShape::Superquadric)
    {
        double tEnter, tLeave;
        dvec3 nEnter;
        if (!intersectSuperquadric(origin, direction, glyph.base, glyph.semiAxes, glyph.exponents, tEnter,
                                   tLeave, nEnter) ||
            tLeave < 0.0)
            return false;
        t = std::max(tEnter, 0.0);
        normal = tEnter >= 0.0 ? nEnter : -direction;
        return true;
    }
    if (glyph.shape == GlyphShape::Ellipsoid)
    {
        double tEnter, tLeave;
        dvec3 nEnter, nLeave;
        if (!intersectEllipsoid(origin, direction, glyph.base, glyph.semiAxes, tEnter, tLeave, nEnter,
                                nLeave) ||
            tLeave < 0.0)
            return false;
        t = std::max(tEnter, 0.0);
        normal = tEnter >= 0.0 ? nEnter : -direction;
        return true;
    }
    dvec3 u, v;
    axisFrame(glyph.axis, u, v);
    dvec3 relative = origin - glyph.base;
    if (insideShape(glyph,
                    dvec3(glm::dot(relative, u), glm::dot(relative, v), glm::dot(relative, glyph.axis))))
    {
        t = 0.0;
        normal = -direction;
        return true;
    }
    // Solve from a point just before the glyph, where the quadratics are well conditioned.
    const double reach = glyph.length + 2.0 * glyph.radius * std::max(glyph.arrowParams.y, 1.0);
    const double start = std::max(glm::dot(-relative, direction) - reach, 0.0);
    relative += direction * start;
    const dvec3 o(glm::dot(relative, u), glm::dot(relative, v), glm::dot(relative, glyph.axis));
    const dvec3 d(glm::dot(direction, u), glm::dot(direction, v), glm::dot(direction, glyph.axis));
    dvec3 local;
    intersectShape(glyph, o, d, t, local);
    t += start;
    normal = local.x * u + local.y * v + local.z * glyph.axis;
    return t < INFINITE_DISTANCE;
}
