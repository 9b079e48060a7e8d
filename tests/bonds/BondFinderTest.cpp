// osgGlyphsData::findBonds against an O(n^2) search over the nearest images, hand-made bonds across
// every periodic face, and each bad input with its message.

#include <osgGlyphsData/BondFinder>
#include <osgGlyphsData/PointData>

#include "../hostile/AllocationMeter.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <tuple>
#include <vector>

using namespace osgGlyphsData;

namespace
{

typedef std::tuple<uint32_t, uint32_t, int32_t, int32_t, int32_t> BondKey;

BondKey keyOf(const Bond& b)
{
    return BondKey(b.first, b.second, b.image[0], b.image[1], b.image[2]);
}

std::vector<BondKey> keysOf(const std::vector<Bond>& bonds)
{
    std::vector<BondKey> keys;
    for (const Bond& b : bonds)
        keys.push_back(keyOf(b));
    return keys;
}

/** Every pair i < j whose nearest image is within the cutoff of their types (inclusive): the
 * images searched are all those within one of the rounded fractional displacement, so that the
 * nearest is found in any cell. */
std::vector<BondKey> bruteForce(const std::vector<osg::Vec3f>& positions, const std::vector<int>& types,
                                const BondCutoffs& cutoffs, const PeriodicBox* box)
{
    std::vector<BondKey> keys;
    for (std::size_t i = 0; i < positions.size(); ++i)
        for (std::size_t j = i + 1; j < positions.size(); ++j)
        {
            const osg::Vec3f& a = positions[i];
            const osg::Vec3f& b = positions[j];
            const osg::Vec3d d0(double(b.x()) - a.x(), double(b.y()) - a.y(), double(b.z()) - a.z());
            const double cutoff =
                types.empty() ? cutoffs.getCutoff(0, 0) : cutoffs.getCutoff(types[i], types[j]);
            if (cutoff == 0.0)
                continue;
            int32_t centre[3] = {0, 0, 0};
            int range[3] = {0, 0, 0};
            if (box)
            {
                // Fractional displacement through the cell's edges.
                const double sz = d0.z() / box->lengths.z();
                const double sy = (d0.y() - box->tilt.z() * sz) / box->lengths.y();
                const double sx = (d0.x() - box->tilt.x() * sy - box->tilt.y() * sz) / box->lengths.x();
                const double s[3] = {sx, sy, sz};
                for (int axis = 0; axis < 3; ++axis)
                {
                    if (box->periodic[axis])
                    {
                        centre[axis] = static_cast<int32_t>(-std::round(s[axis]));
                        range[axis] = 1;
                    }
                }
            }
            double best = std::numeric_limits<double>::infinity();
            int32_t bestImage[3] = {0, 0, 0};
            for (int di = -range[0]; di <= range[0]; ++di)
                for (int dj = -range[1]; dj <= range[1]; ++dj)
                    for (int dk = -range[2]; dk <= range[2]; ++dk)
                    {
                        const int32_t image[3] = {centre[0] + di, centre[1] + dj, centre[2] + dk};
                        const osg::Vec3d d = box ? d0 + box->getImageOffset(image) : d0;
                        if (d.length2() < best)
                        {
                            best = d.length2();
                            std::copy(image, image + 3, bestImage);
                        }
                    }
            if (best <= cutoff * cutoff)
                keys.emplace_back(uint32_t(i), uint32_t(j), bestImage[0], bestImage[1], bestImage[2]);
        }
    return keys;
}

std::vector<osg::Vec3f> randomCloud(std::size_t count, const osg::Vec3d& low, const osg::Vec3d& high,
                                    unsigned seed)
{
    std::mt19937 random(seed);
    std::vector<osg::Vec3f> positions(count);
    for (osg::Vec3f& p : positions)
        for (int axis = 0; axis < 3; ++axis)
            p[axis] =
                static_cast<float>(std::uniform_real_distribution<double>(low[axis], high[axis])(random));
    return positions;
}

std::vector<int> randomTypes(std::size_t count, int numTypes, unsigned seed)
{
    std::mt19937 random(seed);
    std::vector<int> types(count);
    for (int& t : types)
        t = std::uniform_int_distribution<int>(1, numTypes)(random);
    return types;
}

/** findBonds succeeds, its bonds are sorted with first < second, and equal the brute force's. */
void expectBruteForce(const std::vector<osg::Vec3f>& positions, const std::vector<int>& types,
                      const BondCutoffs& cutoffs, const PeriodicBox* box, std::size_t minBonds = 1)
{
    std::vector<Bond> bonds;
    std::string error;
    ASSERT_TRUE(findBonds(positions, types, cutoffs, box, bonds, error)) << error;
    EXPECT_TRUE(error.empty());
    for (std::size_t b = 0; b < bonds.size(); ++b)
    {
        ASSERT_LT(bonds[b].first, bonds[b].second);
        if (b > 0)
        {
            ASSERT_LT(std::make_pair(bonds[b - 1].first, bonds[b - 1].second),
                      std::make_pair(bonds[b].first, bonds[b].second));
        }
    }
    const std::vector<BondKey> expected = bruteForce(positions, types, cutoffs, box);
    EXPECT_GE(expected.size(), minBonds);
    EXPECT_EQ(keysOf(bonds), expected);
}

/** Three types: 1-1 and 2-3 of their own cutoffs, 3-3 never bonded, the rest the default. */
BondCutoffs threeTypeCutoffs(double scale)
{
    BondCutoffs cutoffs(1.0 * scale);
    cutoffs.setPairCutoff(1, 1, 1.3 * scale);
    cutoffs.setPairCutoff(3, 2, 0.7 * scale);
    cutoffs.setPairCutoff(3, 3, 0.0);
    return cutoffs;
}

std::string findError(const std::vector<osg::Vec3f>& positions, const std::vector<int>& types,
                      const BondCutoffs& cutoffs, const PeriodicBox* box)
{
    std::vector<Bond> bonds(3);
    std::string error;
    EXPECT_FALSE(findBonds(positions, types, cutoffs, box, bonds, error));
    EXPECT_TRUE(bonds.empty());
    EXPECT_FALSE(error.empty());
    return error;
}

}

TEST(BondFinder, OpenCloudOneTypeMatchesBruteForce)
{
    // 1500 atoms in 12^3: about 3.6 neighbours within 1.1.
    const std::vector<osg::Vec3f> positions =
        randomCloud(1500, osg::Vec3d(-6, -6, -6), osg::Vec3d(6, 6, 6), 1);
    expectBruteForce(positions, {}, BondCutoffs(1.1), nullptr, 1000);
}

TEST(BondFinder, OpenCloudTypePairsMatchBruteForce)
{
    const std::vector<osg::Vec3f> positions =
        randomCloud(1500, osg::Vec3d(0, 0, 0), osg::Vec3d(12, 12, 12), 2);
    const std::vector<int> types = randomTypes(positions.size(), 3, 3);
    expectBruteForce(positions, types, threeTypeCutoffs(1.0), nullptr, 500);
    // Types that the cutoffs do not name take the default; type 0 of an empty list too.
    BondCutoffs named(0.9);
    named.setPairCutoff(7, 9, 1.4);
    named.setPairCutoff(0, 0, 1.2);
    expectBruteForce(positions, types, named, nullptr, 500);
    expectBruteForce(positions, {}, named, nullptr, 500);
}

TEST(BondFinder, PeriodicOrthogonalMatchesBruteForce)
{
    const PeriodicBox box(osg::BoundingBoxd(-1, 2, 3, 11, 12, 15));
    // Atoms inside the box and up to two boxes outside (unwrapped coordinates).
    std::vector<osg::Vec3f> positions = randomCloud(1200, osg::Vec3d(-1, 2, 3), osg::Vec3d(11, 12, 15), 4);
    const std::vector<osg::Vec3f> outside =
        randomCloud(300, osg::Vec3d(-25, -18, -21), osg::Vec3d(35, 32, 39), 5);
    positions.insert(positions.end(), outside.begin(), outside.end());
    const std::vector<int> types = randomTypes(positions.size(), 3, 6);
    expectBruteForce(positions, types, threeTypeCutoffs(1.0), &box, 500);
}

TEST(BondFinder, PeriodicAlongSomeEdgesMatchesBruteForce)
{
    const PeriodicBox box(osg::BoundingBoxd(0, 0, 0, 10, 10, 10), osg::Vec3d(0, 0, 0), true, false, true);
    // Along y the atoms go past the box, which does not limit them there.
    const std::vector<osg::Vec3f> positions =
        randomCloud(1500, osg::Vec3d(0, -3, 0), osg::Vec3d(10, 13, 10), 7);
    expectBruteForce(positions, randomTypes(positions.size(), 3, 8), threeTypeCutoffs(1.0), &box, 500);
}

TEST(BondFinder, TriclinicMatchesBruteForce)
{
    const PeriodicBox box(osg::BoundingBoxd(1, 1, 1, 11, 13, 12), osg::Vec3d(4.0, -3.0, 5.5));
    // Fractional coordinates in [-0.5, 1.5): atoms inside the cell and around it.
    std::mt19937 random(9);
    std::vector<osg::Vec3f> positions(1500);
    for (osg::Vec3f& p : positions)
    {
        std::uniform_real_distribution<double> s(-0.5, 1.5);
        const double a = s(random), b = s(random), c = s(random);
        const osg::Vec3d r = box.corner + osg::Vec3d(10 * a + 4.0 * b - 3.0 * c, 12 * b + 5.5 * c, 11 * c);
        p.set(float(r.x()), float(r.y()), float(r.z()));
    }
    expectBruteForce(positions, randomTypes(positions.size(), 3, 10), threeTypeCutoffs(1.4), &box, 500);
}

TEST(BondFinder, SmallBoxesOfOneOrTwoCellsMatchBruteForce)
{
    // Cutoffs just under half the box: two cells along each edge, neighbours wrap onto one cell.
    const PeriodicBox box(osg::BoundingBoxd(0, 0, 0, 4, 4, 4));
    const std::vector<osg::Vec3f> positions = randomCloud(300, osg::Vec3d(0, 0, 0), osg::Vec3d(4, 4, 4), 11);
    expectBruteForce(positions, {}, BondCutoffs(1.99), &box, 100);
    // One cell along x (cutoff over a third of the width), several along the others.
    const PeriodicBox flat(osg::BoundingBoxd(0, 0, 0, 2.5, 12, 12));
    const std::vector<osg::Vec3f> slab = randomCloud(600, osg::Vec3d(0, 0, 0), osg::Vec3d(2.5, 12, 12), 12);
    expectBruteForce(slab, {}, BondCutoffs(1.2), &flat, 100);
}

TEST(BondFinder, TinyCutoffOverHugeExtentCapsTheGrid)
{
    // 10^21 cells of the cutoff's size would span the atoms: the grid has about one per atom.
    std::vector<osg::Vec3f> positions = randomCloud(1000, osg::Vec3d(0, 0, 0), osg::Vec3d(1e6, 1e6, 1e6), 13);
    positions.push_back(positions[10] + osg::Vec3f(0.0f, 0.0625f, 0.0f));
    positions.push_back(positions[20] + osg::Vec3f(0.125f, 0.0f, 0.0f));
    expectBruteForce(positions, {}, BondCutoffs(0.1), nullptr, 1);
    const PeriodicBox box(osg::BoundingBoxd(0, 0, 0, 1e6, 1e6, 1e6));
    expectBruteForce(positions, {}, BondCutoffs(0.1), &box, 1);
    // What the search holds: a few arrays of the atoms and cells, well under a megabyte.
    for (const PeriodicBox* b : {static_cast<const PeriodicBox*>(nullptr), &box})
    {
        std::vector<Bond> bonds;
        bonds.reserve(16);
        std::string error;
        hostiletest::AllocationMeter meter(256 * hostiletest::MiB);
        EXPECT_TRUE(findBonds(positions, {}, BondCutoffs(0.1), b, bonds, error)) << error;
        EXPECT_FALSE(meter.wasCapReached());
        EXPECT_LT(meter.getPeakBytes(), std::ptrdiff_t(hostiletest::MiB));
    }
}

TEST(BondFinder, CutoffIsInclusive)
{
    // A simple cubic lattice of spacing 1.5 (exact in float and double), 4 x 4 x 4 in a periodic box
    // of 6: at a cutoff of exactly 1.5, six bonds per atom, three of them its own.
    std::vector<osg::Vec3f> positions;
    for (int k = 0; k < 4; ++k)
        for (int j = 0; j < 4; ++j)
            for (int i = 0; i < 4; ++i)
                positions.emplace_back(0.75f + 1.5f * i, 0.75f + 1.5f * j, 0.75f + 1.5f * k);
    const PeriodicBox box(osg::BoundingBoxd(0, 0, 0, 6, 6, 6));
    std::vector<Bond> bonds;
    std::string error;
    ASSERT_TRUE(findBonds(positions, {}, BondCutoffs(1.5), &box, bonds, error)) << error;
    EXPECT_EQ(bonds.size(), 64u * 3u);
    expectBruteForce(positions, {}, BondCutoffs(1.5), &box, 192);
    // Just under the spacing: none.
    ASSERT_TRUE(findBonds(positions, {}, BondCutoffs(std::nextafter(1.5, 0.0)), &box, bonds, error)) << error;
    EXPECT_TRUE(bonds.empty());
    // Open: the bonds across the faces go, 3 * 4 * 4 * 3 remain.
    ASSERT_TRUE(findBonds(positions, {}, BondCutoffs(1.5), nullptr, bonds, error)) << error;
    EXPECT_EQ(bonds.size(), 144u);
}

TEST(BondFinder, CutoffJustUnderHalfTheBoxBondsOnce)
{
    // One cell across each edge; the two images of the partner are 2 - 2.4e-7 and 2 + 2.4e-7 away
    // across x, with a cutoff of 2 - 1e-7 between them: one bond, to the nearer.
    const PeriodicBox box(osg::BoundingBoxd(0, 0, 0, 4, 4, 4));
    const std::vector<osg::Vec3f> positions = {{1, 1, 1}, {std::nextafter(3.0f, 0.0f), 1, 1}};
    std::vector<Bond> bonds;
    std::string error;
    ASSERT_TRUE(findBonds(positions, {}, BondCutoffs(2.0 - 1e-7), &box, bonds, error)) << error;
    ASSERT_EQ(bonds.size(), 1u);
    EXPECT_EQ(keyOf(bonds[0]), BondKey(0, 1, 0, 0, 0));
}

TEST(BondFinder, WrappingIntoTheBoxLosesNoBondAtTheCutoff)
{
    // Pairs exactly 0.5 apart (x and x + 0.5 in [1024, 1500), exact in float), several boxes away
    // from a box whose corner and length are no round numbers: their wrapped positions are
    // rounded, their distance through the positions given is exactly the cutoff.
    const PeriodicBox box(osg::BoundingBoxd(0.7, 0.3, 0.1, 101.03, 100.9, 99.7));
    std::mt19937 random(14);
    std::uniform_real_distribution<float> x(1024.0f, 1500.0f), yz(0.0f, 99.0f);
    std::vector<osg::Vec3f> positions;
    for (int pair = 0; pair < 200; ++pair)
    {
        const osg::Vec3f a(x(random), yz(random), yz(random));
        positions.push_back(a);
        positions.push_back(a + osg::Vec3f(0.5f, 0.0f, 0.0f));
    }
    std::vector<Bond> bonds;
    std::string error;
    ASSERT_TRUE(findBonds(positions, {}, BondCutoffs(0.5), &box, bonds, error)) << error;
    EXPECT_GE(bonds.size(), 200u);
    expectBruteForce(positions, {}, BondCutoffs(0.5), &box, 200);
}

TEST(BondFinder, BondAcrossEachFaceJoinsTheNearestImage)
{
    const PeriodicBox box(osg::BoundingBoxd(0, 0, 0, 10, 10, 10));
    // One pair across each face, 1 apart through it (9 apart inside the box).
    const std::vector<osg::Vec3f> positions = {{0.5f, 5, 5}, {9.5f, 5, 5}, {5, 9.5f, 2},
                                               {5, 0.5f, 2}, {2, 2, 0.5f}, {2, 2, 9.5f}};
    std::vector<Bond> bonds;
    std::string error;
    ASSERT_TRUE(findBonds(positions, {}, BondCutoffs(1.5), &box, bonds, error)) << error;
    ASSERT_EQ(bonds.size(), 3u);
    // second + image = the image nearest to first.
    EXPECT_EQ(keyOf(bonds[0]), BondKey(0, 1, -1, 0, 0));
    EXPECT_EQ(keyOf(bonds[1]), BondKey(2, 3, 0, 1, 0));
    EXPECT_EQ(keyOf(bonds[2]), BondKey(4, 5, 0, 0, -1));
    for (const Bond& b : bonds)
    {
        const osg::Vec3d image = osg::Vec3d(positions[b.second]) + box.getImageOffset(b.image);
        EXPECT_NEAR((image - osg::Vec3d(positions[b.first])).length(), 1.0, 1e-6);
    }
    // Not periodic along x: the first pair is 9 apart.
    const PeriodicBox openX(osg::BoundingBoxd(0, 0, 0, 10, 10, 10), osg::Vec3d(0, 0, 0), false, true, true);
    ASSERT_TRUE(findBonds(positions, {}, BondCutoffs(1.5), &openX, bonds, error)) << error;
    ASSERT_EQ(bonds.size(), 2u);
    EXPECT_EQ(keyOf(bonds[0]), BondKey(2, 3, 0, 1, 0));
    // Open: none.
    ASSERT_TRUE(findBonds(positions, {}, BondCutoffs(1.5), nullptr, bonds, error)) << error;
    EXPECT_TRUE(bonds.empty());
}

TEST(BondFinder, BondAcrossTiltedFaceJoinsTheNearestImage)
{
    // b = (2, 10, 0): the atom at (2.5, 9.5) is, through the face across b, at (0.5, -0.5).
    const PeriodicBox box(osg::BoundingBoxd(0, 0, 0, 10, 10, 10), osg::Vec3d(2, 0, 0));
    const std::vector<osg::Vec3f> positions = {{0.5f, 0.5f, 5}, {2.5f, 9.5f, 5}};
    std::vector<Bond> bonds;
    std::string error;
    ASSERT_TRUE(findBonds(positions, {}, BondCutoffs(1.5), &box, bonds, error)) << error;
    ASSERT_EQ(bonds.size(), 1u);
    EXPECT_EQ(keyOf(bonds[0]), BondKey(0, 1, 0, -1, 0));
    EXPECT_EQ(box.getImageOffset(bonds[0].image), osg::Vec3d(-2, -10, 0));
}

TEST(BondFinder, EmptyAndOneAtom)
{
    std::vector<Bond> bonds(2);
    std::string error = "stale";
    EXPECT_TRUE(findBonds({}, {}, BondCutoffs(1.0), nullptr, bonds, error));
    EXPECT_TRUE(bonds.empty());
    EXPECT_TRUE(error.empty());
    const PeriodicBox box;
    EXPECT_TRUE(findBonds({osg::Vec3f(0.2f, 0.3f, 0.4f)}, {5}, BondCutoffs(0.4), &box, bonds, error))
        << error;
    EXPECT_TRUE(bonds.empty());
    // A cutoff of 0: no bond, even for atoms at one place.
    BondCutoffs noCarbon(1.0);
    noCarbon.setPairCutoff(6, 6, 0.0);
    EXPECT_TRUE(findBonds({osg::Vec3f(1, 1, 1), osg::Vec3f(1, 1, 1), osg::Vec3f(1, 1, 1)}, {6, 6, 1},
                          noCarbon, nullptr, bonds, error));
    ASSERT_EQ(bonds.size(), 2u);
    EXPECT_EQ(keyOf(bonds[0]), BondKey(0, 2, 0, 0, 0));
    EXPECT_EQ(keyOf(bonds[1]), BondKey(1, 2, 0, 0, 0));
    // No cutoff at all: no bond, even for atoms at one place.
    EXPECT_TRUE(
        findBonds({osg::Vec3f(1, 1, 1), osg::Vec3f(1, 1, 1)}, {}, BondCutoffs(), nullptr, bonds, error));
    EXPECT_TRUE(bonds.empty());
}

TEST(BondFinder, BadInputsAreNamed)
{
    const std::vector<osg::Vec3f> positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    const BondCutoffs cutoffs(1.2);

    std::vector<osg::Vec3f> nan = positions;
    nan[2].y() = std::numeric_limits<float>::quiet_NaN();
    EXPECT_NE(findError(nan, {}, cutoffs, nullptr).find("atom 2 has a non-finite position"),
              std::string::npos);
    std::vector<osg::Vec3f> inf = positions;
    inf[3].z() = -std::numeric_limits<float>::infinity();
    EXPECT_NE(findError(inf, {}, cutoffs, nullptr).find("atom 3 has a non-finite position"),
              std::string::npos);

    EXPECT_NE(findError(positions, {1, 2, 3}, cutoffs, nullptr).find("3 atom types for 4 atoms"),
              std::string::npos);

    EXPECT_NE(findError(positions, {}, BondCutoffs(-1.0), nullptr).find("the default cutoff is -1"),
              std::string::npos);
    BondCutoffs nanPair(1.0);
    nanPair.setPairCutoff(2, 1, std::numeric_limits<double>::quiet_NaN());
    EXPECT_NE(findError(positions, {}, nanPair, nullptr).find("the cutoff of types 1 and 2 is nan"),
              std::string::npos);
    BondCutoffs infinite(std::numeric_limits<double>::infinity());
    EXPECT_NE(findError(positions, {}, infinite, nullptr).find("must be finite"), std::string::npos);

    // Half the box, or more, across a periodic edge: the nearest image is ambiguous.
    const PeriodicBox box(osg::BoundingBoxd(0, 0, 0, 10, 3, 10));
    BondCutoffs half(1.0);
    half.setPairCutoff(1, 4, 1.5);
    const std::string ambiguous = findError(positions, {}, half, &box);
    EXPECT_NE(ambiguous.find("the cutoff of types 1 and 4, 1.5, is not less than half the box's width 3"),
              std::string::npos)
        << ambiguous;
    EXPECT_NE(ambiguous.find("edge b"), std::string::npos) << ambiguous;
    // Not periodic along b: allowed.
    const PeriodicBox openB(osg::BoundingBoxd(0, 0, 0, 10, 3, 10), osg::Vec3d(0, 0, 0), true, false, true);
    std::vector<Bond> bonds;
    std::string error;
    EXPECT_TRUE(findBonds(positions, {}, half, &openB, bonds, error)) << error;
    // A tilt narrows the box: width across a is 10 * 3 / |b x c| < 10.
    const PeriodicBox tilted(osg::BoundingBoxd(0, 0, 0, 4, 4, 4), osg::Vec3d(3.5, 0, 0));
    EXPECT_NE(findError(positions, {}, BondCutoffs(1.9), &tilted).find("edge a"), std::string::npos);

    const PeriodicBox flat(osg::BoundingBoxd(0, 0, 0, 10, 0, 10));
    EXPECT_NE(findError(positions, {}, cutoffs, &flat).find("the box's length along y is 0"),
              std::string::npos);
    const PeriodicBox inverted(osg::BoundingBoxd(0, 0, 5, 10, 10, 2));
    EXPECT_NE(findError(positions, {}, cutoffs, &inverted).find("the box's length along z is -3"),
              std::string::npos);
    PeriodicBox nanCorner(osg::BoundingBoxd(0, 0, 0, 10, 10, 10));
    nanCorner.corner.x() = std::numeric_limits<double>::quiet_NaN();
    EXPECT_NE(findError(positions, {}, cutoffs, &nanCorner).find("is not finite"), std::string::npos);

    // An atom absurdly far from a periodic box.
    std::vector<osg::Vec3f> far = positions;
    far[1].x() = 1e20f;
    const PeriodicBox unit(osg::BoundingBoxd(0, 0, 0, 10, 10, 10));
    EXPECT_NE(findError(far, {}, cutoffs, &unit).find("atom 1 at"), std::string::npos);

    // More named types than a table holds.
    BondCutoffs many(1.0);
    for (int t = 0; t < 3000; ++t)
        many.setPairCutoff(2 * t, 2 * t + 1, 1.0);
    EXPECT_NE(findError(positions, {}, many, nullptr).find("name 6000 types"), std::string::npos);

    // 2000 atoms at one place: 2 million bonds, cutoffs far too long for the spacing.
    const std::vector<osg::Vec3f> heap(2000, osg::Vec3f(1, 2, 3));
    EXPECT_NE(findError(heap, {}, cutoffs, nullptr).find("far too long"), std::string::npos);
}

TEST(BondFinder, TypesFromAFrameColumn)
{
    osg::ref_ptr<PointData> frame = new PointData(3);
    ASSERT_TRUE(frame->addColumn("type", std::vector<float>{1, 2, 3}));
    ASSERT_TRUE(frame->addColumn("charge", std::vector<float>{0.5f, 1, 1}));
    std::vector<int> types;
    std::string error;
    ASSERT_TRUE(getBondTypes(*frame, "type", types, error)) << error;
    EXPECT_EQ(types, (std::vector<int>{1, 2, 3}));
    EXPECT_FALSE(getBondTypes(*frame, "charge", types, error));
    EXPECT_NE(error.find("atom 0 has the type 0.5"), std::string::npos) << error;
    EXPECT_FALSE(getBondTypes(*frame, "species", types, error));
    EXPECT_NE(error.find("no column \"species\""), std::string::npos) << error;
    EXPECT_NE(error.find("type charge"), std::string::npos) << error;
}

TEST(BondFinder, BondsFollowMovingAtoms)
{
    // Found again for each frame: atoms that move apart lose their bond, those that come close gain one.
    std::vector<osg::Vec3f> positions = {{0, 0, 0}, {1, 0, 0}, {5, 0, 0}};
    const PeriodicBox box(osg::BoundingBoxd(-4, -4, -4, 8, 8, 8));
    std::vector<Bond> bonds;
    std::string error;
    ASSERT_TRUE(findBonds(positions, {}, BondCutoffs(1.2), &box, bonds, error)) << error;
    ASSERT_EQ(bonds.size(), 1u);
    EXPECT_EQ(keyOf(bonds[0]), BondKey(0, 1, 0, 0, 0));
    // Atom 1 goes 3.4 from atom 2; atom 0 comes 0.6 from atom 2 through the face at x = -4.
    positions[0].x() = -3.5f;
    positions[1].x() = 4.5f;
    positions[2].x() = 7.9f;
    ASSERT_TRUE(findBonds(positions, {}, BondCutoffs(1.2), &box, bonds, error)) << error;
    ASSERT_EQ(bonds.size(), 1u);
    EXPECT_EQ(keyOf(bonds[0]), BondKey(0, 2, -1, 0, 0));
}
