#include "SolidTruth.h"

#include <algorithm>
#include <cmath>

using namespace osgGlyphsTest;

namespace
{

/** Distance from q to the segment ab in the plane. */
double segmentDistance(const osg::Vec2d& q, const osg::Vec2d& a, const osg::Vec2d& b)
{
    const osg::Vec2d ab = b - a;
    const double along = std::clamp(((q - a) * ab) / (ab * ab), 0.0, 1.0);
    return (q - (a + ab * along)).length();
}

/** Even-odd rule: whether a horizontal ray from q crosses the polygon's edges an odd number of times. */
bool insidePolygon(const osg::Vec2d& q, const std::vector<osg::Vec2d>& polygon)
{
    bool inside = false;
    for (size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++)
    {
        const osg::Vec2d& a = polygon[i];
        const osg::Vec2d& b = polygon[j];
        if ((a.y() > q.y()) != (b.y() > q.y()) &&
            q.x() < a.x() + (q.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y()))
            inside = !inside;
    }
    return inside;
}

}

Solid Solid::sphere(const osg::Vec3d& centre, double radius)
{
    Solid solid;
    solid._point = centre;
    solid._radius = radius;
    solid._size = radius;
    return solid;
}

Solid Solid::revolved(const osg::Vec3d& tail, const osg::Vec3d& unitAxis,
                      const std::vector<osg::Vec2d>& profile)
{
    Solid solid;
    solid._isSphere = false;
    solid._point = tail;
    solid._axis = unitAxis;
    solid._profile = profile;
    for (const osg::Vec2d& p : profile)
        solid._size = std::max({solid._size, p.x(), p.y()});
    return solid;
}

Solid Solid::cylinder(const osg::Vec3d& tail, const osg::Vec3d& unitAxis, double length, double radius)
{
    return revolved(tail, unitAxis, {{0.0, 0.0}, {radius, 0.0}, {radius, length}, {0.0, length}});
}

Solid Solid::cone(const osg::Vec3d& tail, const osg::Vec3d& unitAxis, double length, double radius)
{
    return revolved(tail, unitAxis, {{0.0, 0.0}, {radius, 0.0}, {0.0, length}});
}

Solid Solid::arrow(const osg::Vec3d& tail, const osg::Vec3d& unitAxis, double length, double radius,
                   double headLengthRatio, double headRadiusRatio)
{
    const double shaft = length * (1.0 - headLengthRatio);
    return revolved(
        tail, unitAxis,
        {{0.0, 0.0}, {radius, 0.0}, {radius, shaft}, {radius * headRadiusRatio, shaft}, {0.0, length}});
}

double Solid::signedDistance(const osg::Vec3d& point) const
{
    const osg::Vec3d relative = point - _point;
    if (_isSphere)
        return relative.length() - _radius;
    const double height = relative * _axis;
    const double fromAxis = (relative - _axis * height).length();
    const osg::Vec2d q(fromAxis, height);
    // The closing edge runs along the axis: inside the solid, not on its surface.
    double distance = 1e300;
    for (size_t i = 0; i + 1 < _profile.size(); ++i)
        distance = std::min(distance, segmentDistance(q, _profile[i], _profile[i + 1]));
    return insidePolygon(q, _profile) ? -distance : distance;
}

osg::Vec3d Solid::normal(const osg::Vec3d& point) const
{
    const double h = 1e-7 * _size;
    osg::Vec3d gradient;
    for (int axis = 0; axis < 3; ++axis)
    {
        osg::Vec3d step;
        step[axis] = h;
        gradient[axis] = signedDistance(point + step) - signedDistance(point - step);
    }
    gradient.normalize();
    return gradient;
}

Solid::Trace Solid::trace(const osg::Vec3d& origin, const osg::Vec3d& direction, double maxT,
                          double epsilon) const
{
    Trace trace;
    double t = 0.0;
    for (int step = 0; step < 10000000 && t <= maxT; ++step)
    {
        const double distance = signedDistance(origin + direction * t);
        trace.closest = std::min(trace.closest, distance);
        if (distance < epsilon)
        {
            trace.hit = true;
            trace.t = t;
            return trace;
        }
        t += distance;
    }
    return trace;
}
