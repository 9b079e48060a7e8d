// The ray-surface truth of the picking tests, written apart from the library's ray casts: each
// glyph is a solid with an exact signed distance (a sphere, or a polygon in (radius, height)
// revolved about the glyph's axis), and rays find its surface by sphere tracing.

#ifndef OSGGLYPHS_TESTS_SOLIDTRUTH_H
#define OSGGLYPHS_TESTS_SOLIDTRUTH_H

#include <osg/Vec2d>
#include <osg/Vec3d>

#include <vector>

namespace osgGlyphsTest
{

class Solid
{
public:
    static Solid sphere(const osg::Vec3d& centre, double radius);
    /** A solid of revolution: profile points (distance from the axis, height above tail) in order
     * round the polygon, which runs along the axis from its first point to its last. */
    static Solid revolved(const osg::Vec3d& tail, const osg::Vec3d& unitAxis,
                          const std::vector<osg::Vec2d>& profile);

    static Solid cylinder(const osg::Vec3d& tail, const osg::Vec3d& unitAxis, double length, double radius);
    static Solid cone(const osg::Vec3d& tail, const osg::Vec3d& unitAxis, double length, double radius);
    static Solid arrow(const osg::Vec3d& tail, const osg::Vec3d& unitAxis, double length, double radius,
                       double headLengthRatio, double headRadiusRatio);

    /** Negative inside, the exact distance to the surface. */
    double signedDistance(const osg::Vec3d& point) const;
    /** The outward unit normal, by central differences. */
    osg::Vec3d normal(const osg::Vec3d& point) const;

    /** How a ray from outside meets the surface. */
    struct Trace
    {
        bool hit = false;
        double t = 0.0;
        /** The least distance to the surface along the traced part of the ray. */
        double closest = 1e300;
    };
    /** Sphere tracing from origin along the unit direction up to maxT; converged within epsilon. */
    Trace trace(const osg::Vec3d& origin, const osg::Vec3d& direction, double maxT, double epsilon) const;

    /** A size of the solid: its radius, or its length. */
    double size() const { return _size; }

private:
    bool _isSphere = true;
    osg::Vec3d _point; // centre, or tail
    osg::Vec3d _axis;
    double _radius = 0.0;
    double _size = 0.0;
    std::vector<osg::Vec2d> _profile;
};

}

#endif
