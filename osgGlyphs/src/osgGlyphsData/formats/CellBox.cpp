#include "CellBox.h"

#include <cmath>

using namespace osgGlyphsData;

namespace
{

bool finitePositive(double value)
{
    return std::isfinite(value) && value > 0.0;
}

}

bool formats::setCellVectors(PointData& frame, const osg::Vec3d& a, const osg::Vec3d& b, const osg::Vec3d& c,
                             const osg::Vec3d& origin)
{
    const bool restricted = a.y() == 0.0 && a.z() == 0.0 && b.z() == 0.0;
    if (!restricted || !finitePositive(a.x()) || !finitePositive(b.y()) || !finitePositive(c.z()) ||
        !std::isfinite(b.x()) || !std::isfinite(c.x()) || !std::isfinite(c.y()))
        return false;
    frame.setBox(osg::BoundingBoxd(origin, origin + osg::Vec3d(a.x(), b.y(), c.z())),
                 osg::Vec3d(b.x(), c.x(), c.y()));
    return true;
}

bool formats::setCellLengthsAngles(PointData& frame, double a, double b, double c, double alpha, double beta,
                                   double gamma, const osg::Vec3d& origin)
{
    if (!finitePositive(a) || !finitePositive(b) || !finitePositive(c) || !finitePositive(alpha) ||
        !finitePositive(beta) || !finitePositive(gamma) || alpha >= 180.0 || beta >= 180.0 || gamma >= 180.0)
        return false;
    const double toRadians = std::acos(-1.0) / 180.0;
    // Right angles exactly, so that an orthogonal cell has no tilt from rounding.
    auto cosine = [toRadians](double degrees)
    { return degrees == 90.0 ? 0.0 : std::cos(degrees * toRadians); };
    const double xy = b * cosine(gamma);
    const double xz = c * cosine(beta);
    const double ly = std::sqrt(b * b - xy * xy);
    if (!finitePositive(ly))
        return false;
    const double yz = (b * c * cosine(alpha) - xy * xz) / ly;
    const double lz2 = c * c - xz * xz - yz * yz;
    if (!(lz2 > 0.0))
        return false;
    return setCellVectors(frame, osg::Vec3d(a, 0.0, 0.0), osg::Vec3d(xy, ly, 0.0),
                          osg::Vec3d(xz, yz, std::sqrt(lz2)), origin);
}
