/* osgGlyphs - private: coordinates in a simulation cell of edges a = (lx, 0, 0), b = (xy, ly, 0),
 * c = (xz, yz, lz) (LAMMPS's form: lengths, and tilt = (xy, xz, yz)). Not installed. */

#ifndef OSGGLYPHSDATA_CELLCOORDINATES_H
#define OSGGLYPHSDATA_CELLCOORDINATES_H 1

#include <osg/Vec3d>

namespace osgGlyphsData
{
namespace detail
{

/** The fractional coordinates (in edges) of a displacement; inverse holds 1 / each length. */
inline osg::Vec3d toCellFractional(const osg::Vec3d& d, const osg::Vec3d& tilt, const osg::Vec3d& inverse)
{
    const double sz = d.z() * inverse.z();
    const double sy = (d.y() - tilt.z() * sz) * inverse.y();
    const double sx = (d.x() - tilt.x() * sy - tilt.y() * sz) * inverse.x();
    return osg::Vec3d(sx, sy, sz);
}

/** The displacement of fractional coordinates. */
inline osg::Vec3d toCellCartesian(const osg::Vec3d& s, const osg::Vec3d& length, const osg::Vec3d& tilt)
{
    return osg::Vec3d(length.x() * s.x() + tilt.x() * s.y() + tilt.y() * s.z(),
                      length.y() * s.y() + tilt.z() * s.z(), length.z() * s.z());
}

}
}

#endif
