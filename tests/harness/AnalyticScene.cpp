#include "AnalyticScene.h"

#include <algorithm>
#include <cmath>

namespace osgGlyphsTest
{

int AnalyticScene::add(const Primitive& primitive)
{
    _primitives.push_back(primitive);
    if (_primitives.back().label < 0)
        _primitives.back().label = _numLabels++;
    return _primitives.back().label;
}

int AnalyticScene::addSphere(const osg::Vec3d& center, double radius)
{
    Primitive p{Primitive::SPHERE, center, osg::Vec3d(radius, 0.0, 0.0)};
    p.label = -1;
    return add(p);
}

int AnalyticScene::addBox(const osg::Vec3d& min, const osg::Vec3d& max)
{
    Primitive p{Primitive::BOX, min, max};
    p.label = -1;
    return add(p);
}

int AnalyticScene::addPlane(const osg::Vec3d& point, const osg::Vec3d& normal, double halfExtent)
{
    osg::Vec3d unit = normal;
    unit.normalize();
    Primitive p{Primitive::PLANE, point, unit, halfExtent};
    p.label = -1;
    return add(p);
}

int AnalyticScene::addSegment(const osg::Vec3d& base, const osg::Vec3d& axis, double z0, double r0, double z1,
                              double r1, bool capAtZ0, bool capAtZ1, int label)
{
    osg::Vec3d unit = axis;
    unit.normalize();
    Primitive p{Primitive::SEGMENT, base, unit};
    p.label = label;
    p.z0 = z0;
    p.r0 = r0;
    p.z1 = z1;
    p.r1 = r1;
    p.cap0 = capAtZ0;
    p.cap1 = capAtZ1;
    return add(p);
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

bool AnalyticScene::intersectSegment(const Primitive& p, const osg::Vec3d& origin,
                                     const osg::Vec3d& direction, double minDistance, double& distance,
                                     osg::Vec3d& normal) const
{
    // A frame with the axis along z.
    const osg::Vec3d helper = std::fabs(p.b.x()) < 0.9 ? osg::Vec3d(1, 0, 0) : osg::Vec3d(0, 1, 0);
    osg::Vec3d u = helper ^ p.b;
    u.normalize();
    const osg::Vec3d v = p.b ^ u;
    const osg::Vec3d rel = origin - p.a;
    const osg::Vec3d o(rel * u, rel * v, rel * p.b), d(direction * u, direction * v, direction * p.b);
    distance = std::numeric_limits<double>::infinity();
    osg::Vec3d local;
    auto consider = [&](double t, const osg::Vec3d& n)
    {
        if (t >= minDistance && t < distance)
        {
            distance = t;
            local = n;
        }
    };
    // The side: x^2 + y^2 = (r0 + slope (z - z0))^2.
    const double slope = (p.r1 - p.r0) / (p.z1 - p.z0);
    const double rho = p.r0 + slope * (o.z() - p.z0);
    const double a = d.x() * d.x() + d.y() * d.y() - slope * slope * d.z() * d.z();
    const double b = o.x() * d.x() + o.y() * d.y() - slope * rho * d.z();
    const double c = o.x() * o.x() + o.y() * o.y() - rho * rho;
    const double discriminant = b * b - a * c;
    if (std::fabs(a) > 1e-15 && discriminant >= 0.0)
    {
        for (double sign : {-1.0, 1.0})
        {
            const double t = (-b + sign * std::sqrt(discriminant)) / a;
            const osg::Vec3d hit = o + d * t;
            const double radius = p.r0 + slope * (hit.z() - p.z0);
            if (hit.z() >= p.z0 && hit.z() <= p.z1 && radius >= 0.0)
            {
                osg::Vec3d n(hit.x(), hit.y(), -slope * radius);
                n.normalize();
                consider(t, n);
            }
        }
    }
    auto cap = [&](bool present, double z, double radius, double facing)
    {
        if (!present || std::fabs(d.z()) < 1e-15)
            return;
        const double t = (z - o.z()) / d.z();
        const osg::Vec3d hit = o + d * t;
        if (hit.x() * hit.x() + hit.y() * hit.y() <= radius * radius)
            consider(t, osg::Vec3d(0.0, 0.0, facing));
    };
    cap(p.cap0, p.z0, p.r0, -1.0);
    cap(p.cap1, p.z1, p.r1, 1.0);
    if (distance == std::numeric_limits<double>::infinity())
        return false;
    normal = u * local.x() + v * local.y() + p.b * local.z();
    return true;
}

bool AnalyticScene::intersect(const Primitive& p, const osg::Vec3d& origin, const osg::Vec3d& direction,
                              double minDistance, double& distance, osg::Vec3d& normal) const
{
    switch (p.kind)
    {
    case Primitive::SEGMENT:
        return intersectSegment(p, origin, direction, minDistance, distance, normal);
    case Primitive::SPHERE:
    {
        const double radius = p.b.x();
        const osg::Vec3d m = origin - p.a;
        const double b = m * direction;
        const osg::Vec3d closest = m - direction * b;
        const double h2 = radius * radius - closest * closest;
        if (h2 < 0.0)
            return false;
        const double h = std::sqrt(h2);
        distance = -b - h >= minDistance ? -b - h : -b + h;
        if (distance < minDistance)
            return false;
        normal = (origin + direction * distance - p.a) / radius;
        return true;
    }
    case Primitive::BOX:
    {
        double tNear = -1e300, tFar = 1e300;
        int nearAxis = 0;
        for (int axis = 0; axis < 3; ++axis)
        {
            if (std::fabs(direction[axis]) < 1e-300)
            {
                if (origin[axis] < p.a[axis] || origin[axis] > p.b[axis])
                    return false;
                continue;
            }
            double t0 = (p.a[axis] - origin[axis]) / direction[axis];
            double t1 = (p.b[axis] - origin[axis]) / direction[axis];
            if (t0 > t1)
                std::swap(t0, t1);
            if (t0 > tNear)
            {
                tNear = t0;
                nearAxis = axis;
            }
            tFar = std::min(tFar, t1);
        }
        if (tNear > tFar || tNear < minDistance)
            return false;
        distance = tNear;
        normal = osg::Vec3d();
        normal[nearAxis] = direction[nearAxis] > 0.0 ? -1.0 : 1.0;
        return true;
    }
    case Primitive::PLANE:
    {
        const double denominator = p.b * direction;
        if (std::fabs(denominator) < 1e-300)
            return false;
        distance = ((p.a - origin) * p.b) / denominator;
        const osg::Vec3d offset = origin + direction * distance - p.a;
        if (distance < minDistance || std::fabs(offset.x()) > p.extent || std::fabs(offset.y()) > p.extent ||
            std::fabs(offset.z()) > p.extent)
            return false;
        normal = denominator < 0.0 ? p.b : -p.b;
        return true;
    }
    }
    return false;
}

RayHit AnalyticScene::cast(const osg::Vec3d& origin, const osg::Vec3d& direction, double minDistance) const
{
    RayHit nearest;
    for (size_t i = 0; i < _primitives.size(); ++i)
    {
        double distance = 0.0;
        osg::Vec3d normal;
        if (intersect(_primitives[i], origin, direction, minDistance, distance, normal) &&
            distance < nearest.distance)
        {
            nearest.label = _primitives[i].label;
            nearest.distance = distance;
            nearest.normal = normal;
        }
    }
    if (nearest.hit())
        nearest.point = origin + direction * nearest.distance;
    return nearest;
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
