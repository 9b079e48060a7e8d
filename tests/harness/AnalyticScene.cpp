#include "AnalyticScene.h"

#include <algorithm>
#include <cmath>

namespace osgGlyphsTest
{

int AnalyticScene::addSphere(const osg::Vec3d& center, double radius)
{
    _primitives.push_back({Primitive::SPHERE, center, osg::Vec3d(radius, 0.0, 0.0)});
    return static_cast<int>(_primitives.size()) - 1;
}

int AnalyticScene::addBox(const osg::Vec3d& min, const osg::Vec3d& max)
{
    _primitives.push_back({Primitive::BOX, min, max});
    return static_cast<int>(_primitives.size()) - 1;
}

int AnalyticScene::addPlane(const osg::Vec3d& point, const osg::Vec3d& normal, double halfExtent)
{
    osg::Vec3d unit = normal;
    unit.normalize();
    _primitives.push_back({Primitive::PLANE, point, unit, halfExtent});
    return static_cast<int>(_primitives.size()) - 1;
}

bool AnalyticScene::intersect(const Primitive& p, const osg::Vec3d& origin, const osg::Vec3d& direction,
                              double minDistance, double& distance, osg::Vec3d& normal) const
{
    switch (p.kind)
    {
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
            nearest.label = static_cast<int>(i);
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
