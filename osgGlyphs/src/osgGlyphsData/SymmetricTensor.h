/* osgGlyphsData - private: symmetric 3x3 tensors (stress per atom, diffusion) as glyphs. Not installed. */

#ifndef OSGGLYPHSDATA_SYMMETRICTENSOR_H
#define OSGGLYPHSDATA_SYMMETRICTENSOR_H 1

#include <osg/Quat>
#include <osg/Vec2d>
#include <osg/Vec3d>

namespace osgGlyphsData
{
namespace detail
{

/** A symmetric tensor's eigen-decomposition: eigenvalues from the largest to the smallest (signed),
 * and the rotation whose columns are their unit eigenvectors, right-handed. */
struct TensorEigen
{
    osg::Vec3d values;
    osg::Quat rotation;
};

/** The components xx, yy, zz, xy, xz, yz (the order of LAMMPS's compute stress/atom). */
struct SymmetricTensor
{
    double xx = 0.0, yy = 0.0, zz = 0.0, xy = 0.0, xz = 0.0, yz = 0.0;

    /** From 9 components in rows (xx xy xz yx yy yz zx zy zz): the symmetric part. */
    static SymmetricTensor fromRows(const double rows[9]);

    bool isFinite() const;
    double trace() const { return xx + yy + zz; }
};

/** Jacobi's rotations until the off-diagonal part is below 1e-15 of the tensor's norm (at most 50
 * sweeps; 3x3 tensors take 4 to 6). */
TensorEigen decompose(const SymmetricTensor& tensor);

/** Kindlmann's superquadric tensor glyph ("Superquadric Tensor Glyphs", 2004) for a GlyphCloud
 * superquadric: semi-axes |eigenvalue| (signs show in the colours; the glyph is of the magnitudes)
 * along the eigenvectors, the body z axis the glyph's axis of symmetry (the largest magnitude's
 * eigenvector where the tensor is more linear than planar, c_l >= c_p, the smallest's where it is
 * more planar), and the exponents (e1 along it, e2 around it) from Westin's c_l and c_p of the
 * magnitudes: (1 - c_l)^sharpness and (1 - c_p)^sharpness. Linear tensors are cylinders, planar
 * ones discs, isotropic ones spheres, and those between rounded boxes. */
struct TensorSuperquadric
{
    osg::Vec3d semiAxes;
    osg::Quat rotation;
    osg::Vec2d exponents;
};
TensorSuperquadric kindlmannGlyph(const TensorEigen& eigen, double sharpness = 3.0);

/** Fractional anisotropy in [0, 1]: sqrt(3/2) |lambda - mean| / |lambda|; 0 for the zero tensor. */
double fractionalAnisotropy(const osg::Vec3d& eigenvalues);

}
}

#endif
