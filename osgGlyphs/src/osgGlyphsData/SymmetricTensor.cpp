#include "SymmetricTensor.h"

#include <osg/Matrixd>

#include <algorithm>
#include <cmath>
#include <utility>

using namespace osgGlyphsData::detail;

SymmetricTensor SymmetricTensor::fromRows(const double rows[9])
{
    SymmetricTensor tensor;
    tensor.xx = rows[0];
    tensor.yy = rows[4];
    tensor.zz = rows[8];
    tensor.xy = 0.5 * (rows[1] + rows[3]);
    tensor.xz = 0.5 * (rows[2] + rows[6]);
    tensor.yz = 0.5 * (rows[5] + rows[7]);
    return tensor;
}

bool SymmetricTensor::isFinite() const
{
    return std::isfinite(xx) && std::isfinite(yy) && std::isfinite(zz) && std::isfinite(xy) &&
           std::isfinite(xz) && std::isfinite(yz);
}

TensorEigen osgGlyphsData::detail::decompose(const SymmetricTensor& tensor)
{
    double a[3][3] = {{tensor.xx, tensor.xy, tensor.xz},
                      {tensor.xy, tensor.yy, tensor.yz},
                      {tensor.xz, tensor.yz, tensor.zz}};
    double v[3][3] = {{1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, {0.0, 0.0, 1.0}}; // columns: the eigenvectors
    double norm = 0.0;
    for (const auto& row : a)
        for (double value : row)
            norm += value * value;
    for (int sweep = 0; sweep < 50; ++sweep)
    {
        const double off = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
        if (off <= 1e-30 * norm || off == 0.0)
            break;
        for (int p = 0; p < 2; ++p)
            for (int q = p + 1; q < 3; ++q)
            {
                if (a[p][q] == 0.0)
                    continue;
                // The rotation in the (p, q) plane that zeroes a[p][q] (Golub and Van Loan, 8.4).
                const double theta = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
                const double t =
                    (theta >= 0.0 ? 1.0 : -1.0) / (std::abs(theta) + std::sqrt(theta * theta + 1.0));
                const double c = 1.0 / std::sqrt(t * t + 1.0), s = t * c;
                for (int k = 0; k < 3; ++k)
                {
                    const double akp = a[k][p], akq = a[k][q];
                    a[k][p] = c * akp - s * akq;
                    a[k][q] = s * akp + c * akq;
                }
                for (int k = 0; k < 3; ++k)
                {
                    const double apk = a[p][k], aqk = a[q][k];
                    a[p][k] = c * apk - s * aqk;
                    a[q][k] = s * apk + c * aqk;
                }
                for (int k = 0; k < 3; ++k)
                {
                    const double vkp = v[k][p], vkq = v[k][q];
                    v[k][p] = c * vkp - s * vkq;
                    v[k][q] = s * vkp + c * vkq;
                }
            }
    }
    int order[3] = {0, 1, 2};
    std::sort(order, order + 3, [&](int i, int j) { return a[i][i] > a[j][j]; });
    TensorEigen result;
    osg::Vec3d axes[3];
    for (int k = 0; k < 3; ++k)
    {
        result.values[k] = a[order[k]][order[k]];
        axes[k].set(v[0][order[k]], v[1][order[k]], v[2][order[k]]);
    }
    if ((axes[0] ^ axes[1]) * axes[2] < 0.0)
        axes[2] = -axes[2]; // right-handed: a rotation
    // osg::Matrixd is row-major for row vectors: its rows are the images of the body axes.
    const osg::Matrixd rotation(axes[0].x(), axes[0].y(), axes[0].z(), 0.0, axes[1].x(), axes[1].y(),
                                axes[1].z(), 0.0, axes[2].x(), axes[2].y(), axes[2].z(), 0.0, 0.0, 0.0, 0.0,
                                1.0);
    result.rotation = rotation.getRotate();
    return result;
}

double osgGlyphsData::detail::fractionalAnisotropy(const osg::Vec3d& eigenvalues)
{
    const double length2 = eigenvalues.length2();
    if (!(length2 > 0.0))
        return 0.0;
    const double mean = (eigenvalues.x() + eigenvalues.y() + eigenvalues.z()) / 3.0;
    const osg::Vec3d deviation = eigenvalues - osg::Vec3d(mean, mean, mean);
    return std::min(1.0, std::sqrt(1.5 * deviation.length2() / length2));
}

TensorSuperquadric osgGlyphsData::detail::kindlmannGlyph(const TensorEigen& eigen, double sharpness)
{
    // The eigenvectors by decreasing magnitude of their eigenvalues.
    int order[3] = {0, 1, 2};
    std::sort(order, order + 3,
              [&](int a, int b) { return std::abs(eigen.values[a]) > std::abs(eigen.values[b]); });
    osg::Vec3d vectors[3], magnitudes;
    for (int k = 0; k < 3; ++k)
    {
        osg::Vec3d axis;
        axis[order[k]] = 1.0;
        vectors[k] = eigen.rotation * axis;
        magnitudes[k] = std::abs(eigen.values[order[k]]);
    }
    const double sum = magnitudes[0] + magnitudes[1] + magnitudes[2];
    const double linear = sum > 0.0 ? (magnitudes[0] - magnitudes[1]) / sum : 0.0;
    const double planar = sum > 0.0 ? 2.0 * (magnitudes[1] - magnitudes[2]) / sum : 0.0;
    // Body x, y, z: the two others, then the axis of symmetry.
    const int body[3] = {linear >= planar ? 1 : 0, linear >= planar ? 2 : 1, linear >= planar ? 0 : 2};
    TensorSuperquadric glyph;
    osg::Vec3d columns[3];
    for (int k = 0; k < 3; ++k)
    {
        columns[k] = vectors[body[k]];
        glyph.semiAxes[k] = magnitudes[body[k]];
    }
    if ((columns[0] ^ columns[1]) * columns[2] < 0.0)
        columns[0] = -columns[0]; // right-handed
    // osg::Matrix holds the images of the basis vectors in its rows.
    const osg::Matrixd turn(columns[0].x(), columns[0].y(), columns[0].z(), 0.0, columns[1].x(),
                            columns[1].y(), columns[1].z(), 0.0, columns[2].x(), columns[2].y(),
                            columns[2].z(), 0.0, 0.0, 0.0, 0.0, 1.0);
    glyph.rotation = turn.getRotate();
    // e1 along the axis of symmetry, e2 around it.
    const double fromLinear = std::pow(1.0 - std::min(linear, 1.0), sharpness);
    const double fromPlanar = std::pow(1.0 - std::min(planar, 1.0), sharpness);
    glyph.exponents =
        linear >= planar ? osg::Vec2d(fromLinear, fromPlanar) : osg::Vec2d(fromPlanar, fromLinear);
    return glyph;
}
