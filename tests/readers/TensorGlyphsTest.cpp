// Symmetric tensors as ellipsoids (--tensor): tensors made as R diag(l) R^T from known rotations and
// eigenvalues must come back as semi-axes |l| x scale along R's columns, largest first, whatever the
// signs; 9 columns give the symmetric part; colours by trace, anisotropy and signed eigenvalues over a
// range even about zero; the real LAMMPS stress/atom field maps; a zero tensor is a small sphere; a
// wrong column count, a missing column or another glyph shape is one error.

#include "ReaderTestUtil.h"

#include <osgGlyphsData/GlyphMapping>

#include <osgGlyphs/GlyphCloud>

#include <osg/Matrixd>
#include <osg/Quat>

#include <cmath>
#include <sstream>

using namespace osgGlyphsData;
using namespace readertest;

namespace
{

struct KnownTensor
{
    osg::Vec3d eigenvalues; // largest first
    osg::Quat rotation;     // its columns the eigenvectors
};

/** R diag(l) R^T as xx yy zz xy xz yz. */
std::vector<double> componentsOf(const KnownTensor& known)
{
    double t[3][3] = {};
    for (int k = 0; k < 3; ++k)
    {
        osg::Vec3d body;
        body[k] = 1.0;
        const osg::Vec3d axis = known.rotation * body;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                t[i][j] += known.eigenvalues[k] * axis[i] * axis[j];
    }
    return {t[0][0], t[1][1], t[2][2], t[0][1], t[0][2], t[1][2]};
}

const std::vector<KnownTensor> KNOWN = {
    {osg::Vec3d(3.0, 1.0, 0.5), osg::Quat(0.7, osg::Vec3d(1.0, 0.4, 0.2))},
    {osg::Vec3d(2.0, -1.0, -4.0), osg::Quat(1.9, osg::Vec3d(0.1, 1.0, -0.3))},
    {osg::Vec3d(-0.5, -2.0, -6.0), osg::Quat(-0.4, osg::Vec3d(0.0, 0.0, 1.0))},
    {osg::Vec3d(5.0, 5.0, 1.0), osg::Quat(1.1, osg::Vec3d(1.0, 1.0, 1.0))}}; // two equal: any axes between

std::string csvOf(const std::vector<KnownTensor>& tensors)
{
    std::ostringstream csv;
    csv.precision(17);
    csv << "x,y,z,sxx,syy,szz,sxy,sxz,syz\n";
    for (std::size_t i = 0; i < tensors.size(); ++i)
    {
        csv << 3 * i << ",0,0";
        for (double c : componentsOf(tensors[i]))
            csv << "," << c;
        csv << "\n";
    }
    return csv.str();
}

osg::ref_ptr<osgGlyphs::GlyphCloud> mapTensors(const std::string& csv, GlyphMappingOptions options,
                                               std::string& error, GlyphMapper* keep = nullptr)
{
    osg::ref_ptr<PointDataset> dataset = readString(csv, "csv", error, "tensors.csv");
    if (!dataset)
        return nullptr;
    GlyphMapper mapper(options);
    if (!mapper.prepare(*dataset, 0, error))
        return nullptr;
    if (keep)
        *keep = mapper;
    return mapper.createCloud(*dataset->getFrame(0), error);
}

GlyphMappingOptions tensorOptions(const std::string& columns = "sxx,syy,szz,sxy,sxz,syz")
{
    GlyphMappingOptions options;
    std::string error;
    EXPECT_TRUE(setGlyphMappingOption(options, "tensor", columns, error)) << error;
    EXPECT_TRUE(setGlyphMappingOption(options, "tensor-scale", "0.5", error)) << error;
    options.radius = 0.2f;
    return options;
}

}

TEST(TensorGlyphs, AreEllipsoidsAlongTheEigenvectorsOfSemiAxesTheEigenvalues)
{
    std::string error;
    osg::ref_ptr<osgGlyphs::GlyphCloud> cloud = mapTensors(csvOf(KNOWN), tensorOptions(), error);
    ASSERT_TRUE(cloud.valid()) << error;
    EXPECT_EQ(cloud->getShape(), osgGlyphs::GlyphShape::Ellipsoid);
    ASSERT_EQ(cloud->getNumGlyphs(), KNOWN.size());
    for (std::size_t i = 0; i < KNOWN.size(); ++i)
    {
        const osg::Vec3 semiAxes = (*cloud->getSemiAxes())[i];
        const osg::Vec4 q = (*cloud->getOrientations())[i];
        const osg::Quat rotation(q.x(), q.y(), q.z(), q.w());
        EXPECT_NEAR(rotation.length(), 1.0, 1e-6);
        for (int k = 0; k < 3; ++k)
        {
            EXPECT_NEAR(semiAxes[k], 0.5 * std::abs(KNOWN[i].eigenvalues[k]), 1e-5)
                << "tensor " << i << " axis " << k;
            if (i == 3 && k < 2)
                continue; // a double eigenvalue: any axes in its plane
            osg::Vec3d body;
            body[k] = 1.0;
            const double alignment = (rotation * body) * (KNOWN[i].rotation * body);
            EXPECT_NEAR(std::abs(alignment), 1.0, 1e-6) << "tensor " << i << " axis " << k;
        }
    }
}

TEST(TensorGlyphs, KindlmannsSuperquadricsShowLinearPlanarAndIsotropicTensors)
{
    // Westin's metrics of the magnitudes (the sum 5): linear (3, 1, 1): c_l = 0.4, c_p = 0, a glyph
    // symmetric about the major eigenvector; planar (2, 2, 1): c_l = 0, c_p = 0.4, symmetric about
    // the minor one; isotropic: a sphere. Exponents (1 - c)^3: 0.216 along the axis of symmetry.
    const osg::Quat turn(0.7, osg::Vec3d(1.0, 0.4, 0.2));
    const std::vector<KnownTensor> tensors = {{osg::Vec3d(3.0, 1.0, 1.0), turn},
                                              {osg::Vec3d(-2.0, 2.0, 1.0), turn},
                                              {osg::Vec3d(2.0, 2.0, 2.0), turn}};
    const osg::Vec3d symmetryAxes[2] = {turn * osg::Vec3d(1.0, 0.0, 0.0), turn * osg::Vec3d(0.0, 0.0, 1.0)};
    const osg::Vec2 exponents[3] = {osg::Vec2(0.216f, 1.0f), osg::Vec2(0.216f, 1.0f), osg::Vec2(1.0f, 1.0f)};
    const osg::Vec3 semiAxes[3] = {osg::Vec3(0.5f, 0.5f, 1.5f), osg::Vec3(1.0f, 1.0f, 0.5f),
                                   osg::Vec3(1.0f, 1.0f, 1.0f)};
    GlyphMappingOptions options = tensorOptions();
    std::string error;
    ASSERT_TRUE(setGlyphMappingOption(options, "glyph", "superquadric", error)) << error;
    osg::ref_ptr<osgGlyphs::GlyphCloud> cloud = mapTensors(csvOf(tensors), options, error);
    ASSERT_TRUE(cloud.valid()) << error;
    EXPECT_EQ(cloud->getShape(), osgGlyphs::GlyphShape::Superquadric);
    ASSERT_TRUE(cloud->getExponents());
    for (std::size_t i = 0; i < tensors.size(); ++i)
    {
        const osg::Vec2 e = (*cloud->getExponents())[i];
        EXPECT_NEAR(e.x(), exponents[i].x(), 1e-5f) << i;
        EXPECT_NEAR(e.y(), exponents[i].y(), 1e-5f) << i;
        for (int k = 0; k < 3; ++k)
            EXPECT_NEAR((*cloud->getSemiAxes())[i][k], semiAxes[i][k], 1e-5f) << i << " axis " << k;
        if (i == 2)
            continue;
        const osg::Vec4 q = (*cloud->getOrientations())[i];
        const osg::Vec3d bodyZ = osg::Quat(q.x(), q.y(), q.z(), q.w()) * osg::Vec3d(0.0, 0.0, 1.0);
        EXPECT_NEAR(std::abs(bodyZ * symmetryAxes[i]), 1.0, 1e-6) << i;
    }

    // Without tensors, superquadrics have no exponents to draw.
    GlyphMappingOptions plain;
    ASSERT_TRUE(setGlyphMappingOption(plain, "glyph", "superquadric", error)) << error;
    EXPECT_FALSE(mapTensors(csvOf(tensors), plain, error));
    EXPECT_NE(error.find("glyph superquadric draws tensors"), std::string::npos) << error;
}

TEST(TensorGlyphs, NineColumnsGiveTheSymmetricPart)
{
    // xy = 2 and yx = 0 average to 1: the tensor [[1,1,0],[1,1,0],[0,0,3]] has eigenvalues 3, 2, 0.
    std::string error;
    GlyphMappingOptions options = tensorOptions("a,b,c,d,e,f,g,h,i");
    osg::ref_ptr<osgGlyphs::GlyphCloud> cloud =
        mapTensors("x,y,z,a,b,c,d,e,f,g,h,i\n0,0,0,1,2,0,0,1,0,0,0,3\n", options, error);
    ASSERT_TRUE(cloud.valid()) << error;
    const osg::Vec3 semiAxes = (*cloud->getSemiAxes())[0];
    EXPECT_NEAR(semiAxes.x(), 1.5f, 1e-6f);
    EXPECT_NEAR(semiAxes.y(), 1.0f, 1e-6f);
    EXPECT_NEAR(semiAxes.z(), 0.05f * 0.2f, 1e-7f) << "a zero eigenvalue: 1/20 of the radius, not flat";
}

TEST(TensorGlyphs, ColourByTraceAnisotropyAndSignedEigenvalues)
{
    const std::string csv = csvOf(KNOWN);
    const std::pair<const char*, std::vector<float>> cases[] = {{"trace", {4.5f, -3.0f, -8.5f, 11.0f}},
                                                                {"eigenvalue1", {3.0f, 2.0f, -0.5f, 5.0f}},
                                                                {"eigenvalue3", {0.5f, -4.0f, -6.0f, 1.0f}},
                                                                {"anisotropy", {0.0f, 0.0f, 0.0f, 0.0f}}};
    for (const auto& [quantity, expected] : cases)
    {
        std::string error;
        GlyphMappingOptions options = tensorOptions();
        ASSERT_TRUE(setGlyphMappingOption(options, "color-by", quantity, error)) << error;
        GlyphMapper mapper(options);
        osg::ref_ptr<osgGlyphs::GlyphCloud> cloud = mapTensors(csv, options, error, &mapper);
        ASSERT_TRUE(cloud.valid()) << error;
        ASSERT_NE(cloud->getScalars(), nullptr) << quantity;
        for (std::size_t i = 0; i < KNOWN.size(); ++i)
        {
            float value = expected[i];
            if (std::string(quantity) == "anisotropy")
            {
                const osg::Vec3d l = KNOWN[i].eigenvalues;
                const double mean = (l.x() + l.y() + l.z()) / 3.0;
                // Above 1 for tensors of mixed signs (not diffusion tensors): clamped.
                value = float(std::min(
                    1.0, std::sqrt(1.5 * (l - osg::Vec3d(mean, mean, mean)).length2() / l.length2())));
            }
            EXPECT_NEAR((*cloud->getScalars())[i], value, 1e-5f) << quantity << " of tensor " << i;
        }
        const ColorKey& key = mapper.getColorKey();
        EXPECT_EQ(key.title, quantity);
        if (std::string(quantity) != "anisotropy")
        {
            EXPECT_EQ(key.min, -key.max) << quantity << ": a range even about zero shows the sign";
        }
    }
}

TEST(TensorGlyphs, TheLammpsStressFieldMaps)
{
    std::string error;
    osg::ref_ptr<PointDataset> dataset = readPointFile(
        std::string(OSGGLYPHS_LAMMPS_DATA_DIR) + "/ellipsoids/dump.ellipsoids", PointReadOptions(), error);
    ASSERT_TRUE(dataset.valid()) << error;
    GlyphMappingOptions options;
    ASSERT_TRUE(setGlyphMappingOption(
        options, "tensor", "c_stress[1],c_stress[2],c_stress[3],c_stress[4],c_stress[5],c_stress[6]", error))
        << error;
    GlyphMapper mapper(options);
    ASSERT_TRUE(mapper.prepare(*dataset, 4, error)) << error;
    osg::ref_ptr<osgGlyphs::GlyphCloud> cloud = mapper.createCloud(*dataset->getFrame(4), error);
    ASSERT_TRUE(cloud.valid()) << error;
    EXPECT_EQ(cloud->getNumGlyphs(), 144u);
    EXPECT_EQ(cloud->getNumSkippedGlyphs(), 0u);
    EXPECT_NE(mapper.describe().find("tensors c_stress[1]"), std::string::npos) << mapper.describe();
}

TEST(TensorGlyphs, AZeroTensorIsASmallSphereAndBadOptionsAreOneError)
{
    std::string error;
    osg::ref_ptr<osgGlyphs::GlyphCloud> cloud =
        mapTensors("x,y,z,sxx,syy,szz,sxy,sxz,syz\n0,0,0,0,0,0,0,0,0\n", tensorOptions(), error);
    ASSERT_TRUE(cloud.valid()) << error;
    for (int k = 0; k < 3; ++k)
        EXPECT_FLOAT_EQ((*cloud->getSemiAxes())[0][k], 0.05f * 0.2f);
    EXPECT_EQ(cloud->getNumSkippedGlyphs(), 0u);

    GlyphMappingOptions options;
    EXPECT_FALSE(setGlyphMappingOption(options, "tensor", "a,b,c,d,e", error));
    EXPECT_NE(error.find("give 6 column names"), std::string::npos) << error;

    options = tensorOptions("sxx,syy,szz,sxy,sxz,nope");
    options.optionPrefix = "--";
    EXPECT_FALSE(mapTensors(csvOf(KNOWN), options, error).valid());
    EXPECT_NE(error.find("--tensor: no column 'nope'"), std::string::npos) << error;

    options = tensorOptions();
    options.optionPrefix = "--";
    ASSERT_TRUE(setGlyphMappingOption(options, "glyph", "cone", error)) << error;
    EXPECT_FALSE(mapTensors(csvOf(KNOWN), options, error).valid());
    EXPECT_NE(error.find("--tensor draws ellipsoids or superquadrics, not --glyph cone"), std::string::npos)
        << error;
}
