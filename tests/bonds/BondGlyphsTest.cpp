// Bonds drawn as half-bond cylinders (osgGlyphsData/BondGlyphs): the half-bond tails, vectors and
// colours of open, periodic and triclinic bonds against hand-computed truth, nearest images of a
// file's bond list against the bond finder's, bad bond lists, in-place updates; and renders of
// one bond (two halves) against an exact cylinder, and of a bond between its atoms against exact
// spheres and cylinders (colours, depth, the halves meeting at the midpoint).

#include "GlyphTestScenes.h"

#include <osgGlyphsData/BondGlyphs>

#include <osgGlyphs/ColorMap>
#include <osgGlyphs/GlyphCloud>

#include <cmath>
#include <iostream>

using namespace osgGlyphsTest;
using osgGlyphs::GlyphCloud;
using osgGlyphsData::Bond;
using osgGlyphsData::PeriodicBox;

namespace
{

const osg::Vec4ub RED(255, 0, 0, 255);
const osg::Vec4ub GREEN(0, 255, 0, 255);
const osg::Vec4ub BLUE(0, 0, 255, 255);

Bond bond(uint32_t first, uint32_t second, int32_t i = 0, int32_t j = 0, int32_t k = 0)
{
    return Bond{first, second, {i, j, k}};
}

void expectVecNear(const osg::Vec3f& actual, const osg::Vec3f& expected, const std::string& what)
{
    EXPECT_NEAR(actual.x(), expected.x(), 1e-5f) << what;
    EXPECT_NEAR(actual.y(), expected.y(), 1e-5f) << what;
    EXPECT_NEAR(actual.z(), expected.z(), 1e-5f) << what;
}

osg::ref_ptr<GlyphCloud> atomCloud(const std::vector<osg::Vec3f>& positions, float radius)
{
    osg::ref_ptr<GlyphCloud> cloud = new GlyphCloud;
    cloud->setPositions(new osg::Vec3Array(positions.begin(), positions.end()));
    cloud->setRadius(radius);
    return cloud;
}

}

TEST(BondGeometry, OpenBondsRunFromEachAtomToTheMidpoint)
{
    const std::vector<osg::Vec3f> atoms = {osg::Vec3f(0, 0, 0), osg::Vec3f(2, 0, 0), osg::Vec3f(1, 3, -1)};
    const std::vector<Bond> bonds = {bond(0, 1), bond(1, 2)};
    std::vector<osg::Vec3f> tails, vectors;
    std::string error;
    ASSERT_TRUE(osgGlyphsData::computeHalfBonds(atoms, bonds, nullptr, tails, vectors, error)) << error;
    ASSERT_EQ(tails.size(), 4u);
    ASSERT_EQ(vectors.size(), 4u);
    expectVecNear(tails[0], osg::Vec3f(0, 0, 0), "bond 0, first half");
    expectVecNear(vectors[0], osg::Vec3f(1, 0, 0), "bond 0, first half");
    expectVecNear(tails[1], osg::Vec3f(2, 0, 0), "bond 0, second half");
    expectVecNear(vectors[1], osg::Vec3f(-1, 0, 0), "bond 0, second half");
    // Atoms 1 (2, 0, 0) and 2 (1, 3, -1): the midpoint (1.5, 1.5, -0.5).
    expectVecNear(tails[2], osg::Vec3f(2, 0, 0), "bond 1, first half");
    expectVecNear(vectors[2], osg::Vec3f(-0.5f, 1.5f, -0.5f), "bond 1, first half");
    expectVecNear(tails[3], osg::Vec3f(1, 3, -1), "bond 1, second half");
    expectVecNear(vectors[3], osg::Vec3f(0.5f, -1.5f, 0.5f), "bond 1, second half");
    // Both halves end at the midpoint.
    expectVecNear(tails[2] + vectors[2], tails[3] + vectors[3], "the halves' meeting point");

    EXPECT_EQ(osgGlyphsData::getBondOfGlyph(0), 0u);
    EXPECT_EQ(osgGlyphsData::getBondOfGlyph(3), 1u);
    EXPECT_EQ(osgGlyphsData::getAtomOfGlyph(bonds, 2), 1u);
    EXPECT_EQ(osgGlyphsData::getAtomOfGlyph(bonds, 3), 2u);
}

TEST(BondGeometry, PeriodicBondsLeaveTheBoxOnOppositeFaces)
{
    // A 10 x 10 x 10 box from (0, 0, 0): atoms near the x faces, bonded across them.
    const PeriodicBox box(osg::BoundingBoxd(0, 0, 0, 10, 10, 10));
    std::vector<osg::Vec3f> atoms = {osg::Vec3f(0.5f, 5, 5), osg::Vec3f(9.5f, 5, 5)};
    std::vector<Bond> bonds = {bond(0, 1)};
    std::string error;
    ASSERT_TRUE(osgGlyphsData::setNearestImages(atoms, box, bonds, error)) << error;
    EXPECT_EQ(bonds[0].image[0], -1);
    EXPECT_EQ(bonds[0].image[1], 0);
    EXPECT_EQ(bonds[0].image[2], 0);
    std::vector<osg::Vec3f> tails, vectors;
    ASSERT_TRUE(osgGlyphsData::computeHalfBonds(atoms, bonds, &box, tails, vectors, error)) << error;
    // The second atom's image is at (-0.5, 5, 5): the first half runs to x = 0, the second to x = 10.
    expectVecNear(vectors[0], osg::Vec3f(-0.5f, 0, 0), "first half");
    expectVecNear(vectors[1], osg::Vec3f(0.5f, 0, 0), "second half");
    expectVecNear(tails[0] + vectors[0], osg::Vec3f(0, 5, 5), "first half's end on the x = 0 face");
    expectVecNear(tails[1] + vectors[1], osg::Vec3f(10, 5, 5), "second half's end on the x = 10 face");

    // Along an edge that is not periodic the atoms bond straight through the box.
    PeriodicBox open = box;
    open.periodic[0] = false;
    ASSERT_TRUE(osgGlyphsData::setNearestImages(atoms, open, bonds, error)) << error;
    EXPECT_EQ(bonds[0].image[0], 0);
    ASSERT_TRUE(osgGlyphsData::computeHalfBonds(atoms, bonds, &open, tails, vectors, error)) << error;
    expectVecNear(vectors[0], osg::Vec3f(4.5f, 0, 0), "open edge");
}

TEST(BondGeometry, TriclinicImagesAgreeWithTheBondFinder)
{
    // Tilt xy = 2: the b edge is (2, 10, 0). Atom 1 lies across the y faces from atom 0: its
    // image (0, -1, 0) is at (7 - 2, 9.5 - 10, 5) = (5, -0.5, 5), 1 from atom 0.
    const PeriodicBox box(osg::BoundingBoxd(0, 0, 0, 10, 10, 10), osg::Vec3d(2, 0, 0));
    const std::vector<osg::Vec3f> atoms = {osg::Vec3f(5, 0.5f, 5), osg::Vec3f(7, 9.5f, 5),
                                           osg::Vec3f(0.2f, 0.4f, 9.8f)};
    std::vector<Bond> found;
    std::string error;
    ASSERT_TRUE(osgGlyphsData::findBonds(atoms, {}, osgGlyphsData::BondCutoffs(1.5), &box, found, error))
        << error;
    ASSERT_EQ(found.size(), 1u);
    EXPECT_EQ(found[0].image[1], -1);

    std::vector<Bond> listed = {bond(0, 1, 5, 5, 5)}; // a file's list: images unknown
    ASSERT_TRUE(osgGlyphsData::setNearestImages(atoms, box, listed, error)) << error;
    for (int axis = 0; axis < 3; ++axis)
        EXPECT_EQ(listed[0].image[axis], found[0].image[axis]) << "axis " << axis;
    std::vector<osg::Vec3f> tails, vectors;
    ASSERT_TRUE(osgGlyphsData::computeHalfBonds(atoms, listed, &box, tails, vectors, error)) << error;
    expectVecNear(vectors[0], osg::Vec3f(0, -0.5f, 0), "first half");
    expectVecNear(vectors[1], osg::Vec3f(0, 0.5f, 0), "second half");
}

TEST(BondGeometry, BadBondListsAreRefusedWithTheBondNamed)
{
    const std::vector<osg::Vec3f> atoms = {osg::Vec3f(0, 0, 0), osg::Vec3f(1, 0, 0)};
    std::vector<osg::Vec3f> tails, vectors;
    std::string error;
    EXPECT_FALSE(
        osgGlyphsData::computeHalfBonds(atoms, {bond(0, 1), bond(1, 7)}, nullptr, tails, vectors, error));
    EXPECT_EQ(error, "bond 1 (atoms 1 and 7): atom 7 is past the 2 atoms");
    EXPECT_FALSE(
        osgGlyphsData::computeHalfBonds(atoms, {bond(0, 1, 1, 0, 0)}, nullptr, tails, vectors, error));
    EXPECT_EQ(error, "bond 0 (atoms 0 and 1): a periodic image (1 0 0) without a box");
    std::vector<Bond> bonds = {bond(0, 2)};
    EXPECT_FALSE(osgGlyphsData::setNearestImages(atoms, PeriodicBox(), bonds, error));
    EXPECT_EQ(error, "bond 0 (atoms 0 and 2): atom 2 is past the 2 atoms");

    osg::ref_ptr<GlyphCloud> cloud = atomCloud(atoms, 0.5f);
    EXPECT_FALSE(osgGlyphsData::makeBondCloud(*cloud, {bond(0, 1)}, nullptr, 0.0f, error).valid());
    EXPECT_NE(error.find("bond radius"), std::string::npos) << error;
    EXPECT_FLOAT_EQ(osgGlyphsData::getDefaultBondRadius(*cloud), 0.2f);
}

TEST(BondGeometry, HalvesTakeTheirAtomsColours)
{
    const std::vector<osg::Vec3f> atoms = {osg::Vec3f(0, 0, 0), osg::Vec3f(2, 0, 0), osg::Vec3f(0, 2, 0)};
    const std::vector<Bond> bonds = {bond(0, 1), bond(0, 2)};
    std::string error;

    // RGBA colours.
    osg::ref_ptr<GlyphCloud> rgba = atomCloud(atoms, 0.5f);
    rgba->setColors(makeArray<osg::Vec4ubArray>({RED, GREEN, BLUE}).get());
    osg::ref_ptr<GlyphCloud> bondCloud = osgGlyphsData::makeBondCloud(*rgba, bonds, nullptr, 0.2f, error);
    ASSERT_TRUE(bondCloud.valid()) << error;
    EXPECT_EQ(bondCloud->getShape(), osgGlyphs::GlyphShape::Cylinder);
    EXPECT_EQ(bondCloud->getAnchor(), osgGlyphs::GlyphAnchor::Tail);
    EXPECT_EQ(bondCloud->getLengthScale(), 1.0f);
    EXPECT_EQ(bondCloud->getRadius(), 0.2f);
    EXPECT_EQ(bondCloud->getNumGlyphs(), 4u);
    ASSERT_EQ(bondCloud->getColorMode(), osgGlyphs::GlyphColorMode::RGBA);
    const std::vector<osg::Vec4ub> expected = {RED, GREEN, RED, BLUE};
    EXPECT_EQ(bondCloud->getColors()->asVector(), expected);
    std::cout << "GPU bytes per bond, RGBA colours: " << 2.0 * bondCloud->getGPUBytesPerGlyph() << std::endl;

    // Scalars: the same values per half, the same map and range.
    osg::ref_ptr<GlyphCloud> scalar = atomCloud(atoms, 0.5f);
    scalar->setColorMap(osgGlyphs::ColorMap::getBuiltin("coolwarm"));
    scalar->setScalars(makeArray<osg::FloatArray>({1.0f, 3.0f, 5.0f}).get());
    bondCloud = osgGlyphsData::makeBondCloud(*scalar, bonds, nullptr, 0.2f, error);
    ASSERT_TRUE(bondCloud.valid()) << error;
    ASSERT_EQ(bondCloud->getColorMode(), osgGlyphs::GlyphColorMode::Scalar);
    const std::vector<float> expectedScalars = {1.0f, 3.0f, 1.0f, 5.0f};
    EXPECT_EQ(bondCloud->getScalars()->asVector(), expectedScalars);
    EXPECT_EQ(bondCloud->getColorMap(), scalar->getColorMap());
    std::cout << "GPU bytes per bond, scalars: " << 2.0 * bondCloud->getGPUBytesPerGlyph() << std::endl;
    EXPECT_EQ(bondCloud->getScalarRangeMin(), 1.0f);
    EXPECT_EQ(bondCloud->getScalarRangeMax(), 5.0f);
    scalar->setScalarRange(-2.0f, 7.0f);
    ASSERT_TRUE(osgGlyphsData::updateBondCloud(*bondCloud, *scalar, {bond(0, 1)}, nullptr, error)) << error;
    EXPECT_EQ(bondCloud->getScalarRangeMin(), -2.0f);
    EXPECT_EQ(bondCloud->getScalarRangeMax(), 7.0f);
    EXPECT_EQ(bondCloud->getScalarQuantisationRange(), scalar->getScalarQuantisationRange());

    // The uniform colour.
    osg::ref_ptr<GlyphCloud> uniform = atomCloud(atoms, 0.5f);
    uniform->setColor(osg::Vec4(0.2f, 0.4f, 0.6f, 1.0f));
    bondCloud = osgGlyphsData::makeBondCloud(*uniform, bonds, nullptr, 0.2f, error);
    ASSERT_TRUE(bondCloud.valid()) << error;
    EXPECT_EQ(bondCloud->getColorMode(), osgGlyphs::GlyphColorMode::Uniform);
    EXPECT_EQ(bondCloud->getColor(), osg::Vec4(0.2f, 0.4f, 0.6f, 1.0f));
}

TEST(BondGeometry, UpdatesFollowTheAtomsInPlace)
{
    osg::ref_ptr<GlyphCloud> atoms =
        atomCloud({osg::Vec3f(0, 0, 0), osg::Vec3f(2, 0, 0), osg::Vec3f(0, 2, 0)}, 0.5f);
    atoms->setColors(makeArray<osg::Vec4ubArray>({RED, GREEN, BLUE}).get());
    std::string error;
    osg::ref_ptr<GlyphCloud> bonds = osgGlyphsData::makeBondCloud(*atoms, {bond(0, 1)}, nullptr, 0.2f, error);
    ASSERT_TRUE(bonds.valid()) << error;
    const osg::Vec3Array* positions = bonds->getPositions();
    const osg::Vec3Array* vectors = bonds->getVectors();
    const osg::Vec4ubArray* colors = bonds->getColors();

    (*atoms->getPositions())[1] = osg::Vec3f(4, 0, 0);
    atoms->dirtyGlyphs();
    ASSERT_TRUE(osgGlyphsData::updateBondCloud(*bonds, *atoms, {bond(0, 1), bond(1, 2)}, nullptr, error))
        << error;
    EXPECT_EQ(bonds->getPositions(), positions);
    EXPECT_EQ(bonds->getVectors(), vectors);
    EXPECT_EQ(bonds->getColors(), colors);
    EXPECT_EQ(bonds->getNumGlyphs(), 4u);
    expectVecNear((*vectors)[0], osg::Vec3f(2, 0, 0), "moved atom");
    expectVecNear((*vectors)[2], osg::Vec3f(-2, 1, 0), "new bond");
    EXPECT_EQ((*colors)[3], BLUE);

    // A bad list leaves the cloud as it was.
    EXPECT_FALSE(osgGlyphsData::updateBondCloud(*bonds, *atoms, {bond(0, 3)}, nullptr, error));
    EXPECT_EQ(bonds->getNumGlyphs(), 4u);
}

namespace
{

/** One bond of two halves, red and green, against the exact cylinder of the whole bond. */
class BondRender : public ::testing::Test
{
protected:
    Renderer renderer{200, 150};
};

}

TEST_F(BondRender, HalvesMatchAnExactCylinderAndMeetAtTheMidpoint)
{
    renderer.setLookAt(osg::Vec3d(1.0, -9.0, 3.0), osg::Vec3d(), osg::Vec3d(0.0, 0.0, 1.0));
    const osg::Vec3f a(-2.2f, 0.3f, -0.6f), b(2.0f, -0.5f, 0.9f);
    const float radius = 0.35f;
    osg::ref_ptr<GlyphCloud> atoms = atomCloud({a, b}, 0.6f);
    atoms->setColors(makeArray<osg::Vec4ubArray>({RED, GREEN}).get());
    atoms->setLit(false);
    std::string error;
    osg::ref_ptr<GlyphCloud> bonds =
        osgGlyphsData::makeBondCloud(*atoms, {bond(0, 1)}, nullptr, radius, error);
    ASSERT_TRUE(bonds.valid()) << error;
    EXPECT_FALSE(bonds->getLit());
    const Frame frame = renderer.render(group({bonds.get()}).get());
    saveFrame(frame, "bond_halves");

    // The truth: the whole bond as one exact cylinder, and as its two halves (labels 0 red, 1 green).
    osg::Vec3d axis = osg::Vec3d(b) - osg::Vec3d(a);
    const double length = axis.normalize();
    AnalyticScene whole;
    whole.addCylinder(a, axis, length, radius);
    AnalyticScene halves;
    halves.addCylinder(a, axis, 0.5 * length, radius);
    halves.addCylinder(b, -axis, 0.5 * length, radius);

    // Silhouette: the intersection over union of the covered pixels with the exact cylinder's,
    // over the pixels whose label is certain in both (silhouettes and the seam are left out).
    int both = 0, either = 0, compared = 0;
    for (int y = 0; y < frame.height(); ++y)
        for (int x = 0; x < frame.width(); ++x)
        {
            const int label = whole.certainLabel(frame, x, y);
            if (label == AnalyticScene::AMBIGUOUS ||
                halves.certainLabel(frame, x, y) == AnalyticScene::AMBIGUOUS)
                continue;
            ++compared;
            const bool truth = label >= 0, shown = frame.isCovered(x, y);
            both += truth && shown ? 1 : 0;
            either += truth || shown ? 1 : 0;
        }
    ASSERT_GT(both, 1000) << "the bond should cover a good part of the view";
    const double iou = double(both) / double(either);
    EXPECT_GE(iou, 0.998) << both << " of " << either << " pixels";
    std::cout << "IoU with the exact cylinder " << iou << " over " << compared << " pixels" << std::endl;

    // Colours and depth: each certain pixel shows its half's colour at the exact depth.
    const Agreement agreement = compareWithTruth(frame, halves, {RED, GREEN}, 5e-7, 0.15);
    EXPECT_GT(agreement.covered, 1000);
    EXPECT_EQ(agreement.wrongLabel, 0);
    EXPECT_LE(agreement.wrongDepth, agreement.covered / 200)
        << "worst depth error " << agreement.worstDepthError;

    // The colours change at the midplane: along the projected axis, each pixel shows red where
    // the surface it shows (the exact cylinder's, ray-cast) lies on the first atom's side of the
    // plane through the midpoint across the axis, green on the other, but for pixels within a
    // hundredth of the bond's length of that plane.
    const osg::Vec3d middle = (osg::Vec3d(a) + osg::Vec3d(b)) * 0.5;
    const osg::Vec3d pa = frame.project(a), pb = frame.project(b);
    int red = 0, green = 0, misplaced = 0, nearSeam = 0;
    for (int step = 20; step <= 380; ++step) // the ends left out: the projected end centres lie on the rim
    {
        const double t = step / 400.0;
        const int x = int(pa.x() * (1.0 - t) + pb.x() * t), y = int(pa.y() * (1.0 - t) + pb.y() * t);
        osg::Vec3d origin, direction;
        frame.pixelRay(x + 0.5, y + 0.5, origin, direction);
        const RayHit hit = whole.cast(origin, direction);
        ASSERT_TRUE(hit.hit()) << x << " " << y;
        const double side = (hit.point - middle) * axis;
        if (std::abs(side) < 0.01 * length)
        {
            ++nearSeam;
            continue;
        }
        const int shown = labelOfColor(frame.colorAt(x, y), {RED, GREEN});
        red += shown == 0 ? 1 : 0;
        green += shown == 1 ? 1 : 0;
        misplaced += shown != (side < 0.0 ? 0 : 1) ? 1 : 0;
    }
    EXPECT_GT(red, 100);
    EXPECT_GT(green, 100);
    EXPECT_EQ(misplaced, 0) << nearSeam << " pixels near the seam left out";
}

namespace
{

/** Two atoms and their bond, its halves starting where ends says, rendered together. */
class BondJoins : public ::testing::TestWithParam<osgGlyphsData::BondEnds>
{
protected:
    Renderer renderer{200, 150};
};

}

TEST_P(BondJoins, JoinTheAtomsSpheresSeamlessly)
{
    // Two atoms of radius 0.5 and the bond of radius 0.3 between them, across a periodic face:
    // the picture is the spheres and the two whole halves, each leaving its sphere toward the face,
    // whether the halves start at the atoms' centres or at their spheres.
    renderer.setLookAt(osg::Vec3d(0.5, -7.0, 2.0), osg::Vec3d(), osg::Vec3d(0.0, 0.0, 1.0));
    const PeriodicBox box(osg::BoundingBoxd(-3, -3, -3, 3, 3, 3));
    const osg::Vec3f a(-2.0f, 0.2f, 0.1f), b(2.1f, -0.1f, -0.2f); // 1.95 apart through the x faces
    osg::ref_ptr<GlyphCloud> atoms = atomCloud({a, b}, 0.5f);
    atoms->setColors(makeArray<osg::Vec4ubArray>({RED, GREEN}).get());
    atoms->setLit(false);
    std::vector<Bond> bonds = {bond(0, 1)};
    std::string error;
    ASSERT_TRUE(osgGlyphsData::setNearestImages(atoms->getPositions()->asVector(), box, bonds, error))
        << error;
    ASSERT_EQ(bonds[0].image[0], -1);
    osg::ref_ptr<GlyphCloud> bondCloud =
        osgGlyphsData::makeBondCloud(*atoms, bonds, &box, 0.3f, error, GetParam());
    ASSERT_TRUE(bondCloud.valid()) << error;
    const Frame frame = renderer.render(group({atoms.get(), bondCloud.get()}).get());
    saveFrame(frame, GetParam() == osgGlyphsData::BondEnds::AtAtomSurfaces ? "bond_periodic_joins_surfaces"
                                                                           : "bond_periodic_joins");

    // Truth: labels 0 and 1 the spheres, 2 and 3 the halves (red, green, red, green).
    const osg::Vec3d image = osg::Vec3d(b) + box.getImageOffset(bonds[0].image);
    osg::Vec3d axis = image - osg::Vec3d(a);
    const double half = 0.5 * axis.normalize();
    AnalyticScene truth;
    truth.addSphere(a, 0.5);
    truth.addSphere(b, 0.5);
    truth.addCylinder(a, axis, half, 0.3);
    truth.addCylinder(b, -axis, half, 0.3);
    const std::vector<osg::Vec4ub> colours = {RED, GREEN, RED, GREEN};
    int checked = 0, wrongColour = 0, wrongDepth = 0, cylinders = 0;
    for (int y = 0; y < frame.height(); ++y)
        for (int x = 0; x < frame.width(); ++x)
        {
            const int label = truth.certainLabel(frame, x, y);
            if (label == AnalyticScene::AMBIGUOUS)
                continue;
            if (label < 0)
            {
                wrongColour += frame.isCovered(x, y) ? 1 : 0;
                continue;
            }
            ++checked;
            cylinders += label >= 2 ? 1 : 0;
            wrongColour += colorNear(frame, x, y, colours[label], 2) ? 0 : 1;
            osg::Vec3d origin, direction;
            frame.pixelRay(x + 0.5, y + 0.5, origin, direction);
            const RayHit hit = truth.cast(origin, direction);
            wrongDepth += std::abs(frame.depthAt(x, y) - frame.windowDepth(hit.point)) > 5e-7 ? 1 : 0;
        }
    EXPECT_GT(checked, 1200);
    EXPECT_GT(cylinders, 200) << "the halves should show between the spheres";
    EXPECT_EQ(wrongColour, 0) << "of " << checked;
    EXPECT_LE(wrongDepth, checked / 200) << "of " << checked;
}

INSTANTIATE_TEST_SUITE_P(, BondJoins,
                         ::testing::Values(osgGlyphsData::BondEnds::AtAtomCentres,
                                           osgGlyphsData::BondEnds::AtAtomSurfaces),
                         [](const ::testing::TestParamInfo<osgGlyphsData::BondEnds>& ends) {
                             return ends.param == osgGlyphsData::BondEnds::AtAtomSurfaces ? "AtAtomSurfaces"
                                                                                          : "AtAtomCentres";
                         });

TEST(BondGeometry, HalvesStartInsideTheirAtomsSpheresWhereTheyLeaveThem)
{
    // Atoms of radii 0.5 and 0.3 at 2 apart, and a pair 0.4 apart whose halves lie inside them.
    osg::ref_ptr<GlyphCloud> atoms = atomCloud(
        {osg::Vec3f(0, 0, 0), osg::Vec3f(2, 0, 0), osg::Vec3f(0, 3, 0), osg::Vec3f(0, 3.4f, 0)}, 0.5f);
    atoms->setRadii(makeArray<osg::FloatArray>({0.5f, 0.3f, 0.5f, 0.5f}).get());
    const float bondRadius = 0.2f;
    std::string error;
    osg::ref_ptr<GlyphCloud> bonds =
        osgGlyphsData::makeBondCloud(*atoms, {bond(0, 1), bond(2, 3)}, nullptr, bondRadius, error,
                                     osgGlyphsData::BondEnds::AtAtomSurfaces);
    ASSERT_TRUE(bonds.valid()) << error;
    const osg::Vec3Array& tails = *bonds->getPositions();
    const osg::Vec3Array& vectors = *bonds->getVectors();
    const float radii[4] = {0.5f, 0.3f, 0.5f, 0.5f};
    const int atomOf[4] = {0, 1, 2, 3};
    for (int half = 0; half < 4; ++half)
    {
        const osg::Vec3f centre = (*atoms->getPositions())[atomOf[half]];
        const osg::Vec3f other = (*atoms->getPositions())[atomOf[half ^ 1]];
        const osg::Vec3f midpoint = (centre + other) * 0.5f;
        // Every half still ends at the bond's midpoint, along the bond.
        expectVecNear(tails[half] + vectors[half], midpoint, "half " + std::to_string(half));
        // Its start is 98% of the way to where the cylinder meets the sphere, capped at the
        // midpoint; the rim of its flat end is inside the sphere.
        const float radius = radii[atomOf[half]];
        const float expected = 0.98f * std::min(std::sqrt(radius * radius - bondRadius * bondRadius),
                                                (midpoint - centre).length());
        EXPECT_NEAR((tails[half] - centre).length(), expected, 1e-5f) << "half " << half;
        EXPECT_LT((tails[half] - centre).length2() + bondRadius * bondRadius, radius * radius)
            << "half " << half;
    }
    // The default keeps the halves at the centres.
    bonds = osgGlyphsData::makeBondCloud(*atoms, {bond(0, 1)}, nullptr, bondRadius, error);
    ASSERT_TRUE(bonds.valid()) << error;
    expectVecNear((*bonds->getPositions())[1], osg::Vec3f(2, 0, 0), "centre");
}
