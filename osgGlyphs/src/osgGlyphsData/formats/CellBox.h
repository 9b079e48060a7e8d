/* osgGlyphs - private: simulation cells as binary formats give them, as PointData boxes. */

#ifndef OSGGLYPHS_FORMATS_CELLBOX_H
#define OSGGLYPHS_FORMATS_CELLBOX_H 1

#include <osgGlyphsData/PointData>

namespace osgGlyphsData
{
namespace formats
{

/** Sets the box of a cell given by its edge vectors a, b, c (rows), as XTC, TRR and H5MD give
 * it, with its lower corner at origin. Only cells in LAMMPS' restricted form (a along x, b in the
 * xy plane: a.y = a.z = b.z = 0, lengths positive) are boxes; false for any other cell, which
 * leaves the frame without a box. */
bool setCellVectors(PointData& frame, const osg::Vec3d& a, const osg::Vec3d& b, const osg::Vec3d& c,
                    const osg::Vec3d& origin = osg::Vec3d());

/** Sets the box of a cell given by its edge lengths and angles (degrees: alpha between b and c,
 * beta between a and c, gamma between a and b), as DCD and PDB's CRYST1 give it, turned into the
 * restricted form. False (no box) when the lengths are not positive and finite or the angles make
 * no cell. */
bool setCellLengthsAngles(PointData& frame, double a, double b, double c, double alpha, double beta,
                          double gamma, const osg::Vec3d& origin = osg::Vec3d());

} // namespace formats
}

#endif
