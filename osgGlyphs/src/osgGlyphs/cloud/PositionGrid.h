/* osgGlyphs - private: the grid of 16-bit compressed positions. Not installed. */

#ifndef OSGGLYPHS_POSITIONGRID_H
#define OSGGLYPHS_POSITIONGRID_H 1

#include <osg/Array>
#include <osg/Vec3>
#include <osg/Vec3s>

namespace osgGlyphs
{
namespace detail
{

/** Positions as 16-bit integers q: offset + q * step, computed in float (the product is exact,
 * the sum rounds once, on the CPU as in decode.glsl). The step is the smallest power of two for
 * which MAX_STEPS steps span the positions' box on every axis, and the offset a multiple of it
 * near the box's centre. Positions that are already grid points fit the same grid or a finer
 * one, and quantise to themselves: a cloud re-read from the 16-bit values draws the same. */
struct PositionGrid
{
    static constexpr double MAX_STEPS = 65532.0;

    osg::Vec3 offset;
    float step = 1.0f;

    /** The grid of the finite positions among the first count. */
    static PositionGrid fit(const osg::Vec3Array& positions, unsigned int count);

    /** The nearest grid point's integers (rounding halves up); non-finite positions give 0. */
    osg::Vec3s quantise(const osg::Vec3& position) const;

    osg::Vec3 decode(const osg::Vec3s& q) const
    {
        return osg::Vec3(offset.x() + float(q.x()) * step, offset.y() + float(q.y()) * step,
                         offset.z() + float(q.z()) * step);
    }
};

}
}

#endif
