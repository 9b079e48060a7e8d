/* The bonds of the polymer test data (tests/data/bonds): its data file's Bonds read line by line,
 * as the truth that every reader's bond list is compared with, and checks of a frame's bonds. */

#ifndef OSGGLYPHS_TESTS_BONDTRUTH_H
#define OSGGLYPHS_TESTS_BONDTRUTH_H 1

#include "FormatTestData.h"

#include <osgGlyphsData/BondGlyphs>
#include <osgGlyphsData/PointShare>

#include <set>
#include <sstream>

namespace formattest
{

using osgGlyphsData::Bond;
using osgGlyphsData::PeriodicBox;
using osgGlyphsData::PointData;

/** A file of tests/data/bonds. */
inline std::string bondData(const std::string& name)
{
    return dataPath("../bonds/" + name);
}

typedef std::set<std::pair<int64_t, int64_t>> IdPairs;

/** The Bonds section of a LAMMPS data file, read line by line here: each bond's atom ids, smaller
 * first. */
inline IdPairs bondsOfDataFile(const std::string& path)
{
    std::istringstream text(readBytes(path));
    std::string line;
    while (std::getline(text, line) && line.rfind("Bonds", 0) != 0)
    {
    }
    IdPairs pairs;
    while (std::getline(text, line))
    {
        std::istringstream fields(line);
        int64_t id = 0, type = 0, a = 0, b = 0;
        if (line.empty() && pairs.empty())
            continue;
        if (!(fields >> id >> type >> a >> b))
            break;
        pairs.emplace(std::min(a, b), std::max(a, b));
    }
    return pairs;
}

/** A frame's bonds by the ids of their atoms. */
inline IdPairs bondsById(const PointData& frame)
{
    IdPairs pairs;
    const std::vector<float>* ids = frame.getColumn("id");
    if (!frame.getBonds() || !ids)
        return pairs;
    for (const Bond& bond : *frame.getBonds())
    {
        const auto a = static_cast<int64_t>((*ids)[bond.first]),
                   b = static_cast<int64_t>((*ids)[bond.second]);
        pairs.emplace(std::min(a, b), std::max(a, b));
    }
    return pairs;
}

/** A frame's bonds by the ids of their atoms, where atom id i + 1 is the frame's point i (a GSD
 * written from a dump sorted by id). */
inline IdPairs bondsByIndex(const PointData& frame)
{
    IdPairs pairs;
    for (const Bond& bond : *frame.getBonds())
        pairs.emplace(int64_t(bond.first) + 1, int64_t(bond.second) + 1);
    return pairs;
}

/** Expects a frame's bonds to be each pair once, sorted, with zero images. */
inline void expectWellFormed(const PointData& frame)
{
    ASSERT_TRUE(frame.getBonds());
    const PointData::BondList& bonds = *frame.getBonds();
    for (std::size_t k = 0; k < bonds.size(); ++k)
    {
        const Bond& bond = bonds[k];
        ASSERT_LT(bond.first, bond.second) << k;
        ASSERT_LT(bond.second, frame.getNumPoints()) << k;
        EXPECT_EQ(bond.image[0] | bond.image[1] | bond.image[2], 0) << k;
        if (k > 0)
        {
            ASSERT_TRUE(std::make_pair(bonds[k - 1].first, bonds[k - 1].second) <
                        std::make_pair(bond.first, bond.second))
                << k;
        }
    }
}

/** The lengths of a frame's bonds to the nearest images in its periodic box. */
inline std::vector<double> bondLengths(const PointData& frame)
{
    std::vector<osg::Vec3f> positions(frame.getNumPoints());
    for (std::size_t i = 0; i < positions.size(); ++i)
        positions[i].set((*frame.getColumn("x"))[i], (*frame.getColumn("y"))[i], (*frame.getColumn("z"))[i]);
    const PeriodicBox box(frame.getBox(), frame.getTilt());
    std::vector<Bond> bonds = *frame.getBonds();
    std::string error;
    EXPECT_TRUE(osgGlyphsData::setNearestImages(positions, box, bonds, error)) << error;
    std::vector<double> lengths;
    for (const Bond& bond : bonds)
        lengths.push_back((osg::Vec3d(positions[bond.second]) + box.getImageOffset(bond.image) -
                           osg::Vec3d(positions[bond.first]))
                              .length());
    return lengths;
}

/** Every bond of the chains is near the harmonic bonds' rest length, 0.97 (LAMMPS's Langevin
 * dynamics at T = 1 stretch them between 0.73 and 1.22): atoms that are not bonded are far apart. */
inline void expectBondedLengths(const PointData& frame)
{
    const std::vector<double> lengths = bondLengths(frame);
    ASSERT_FALSE(lengths.empty());
    for (std::size_t k = 0; k < lengths.size(); ++k)
        ASSERT_TRUE(lengths[k] > 0.6 && lengths[k] < 1.4) << "bond " << k << ": " << lengths[k];
}

/** Expects a share of a file sorted by id (particle i is atom id i + 1, of total) to hold the bonds
 * of truth between its own particles, by its own indices, and some to be held. */
inline void expectShareHoldsItsOwnBonds(const PointData& part, const osgGlyphsData::PointShare& share,
                                        uint64_t total, const IdPairs& truth)
{
    ASSERT_TRUE(part.getBonds());
    const osgGlyphsData::PointRange range = osgGlyphsData::getShareRange(share, total);
    IdPairs own, inShare;
    for (const auto& [a, b] : truth)
        if (uint64_t(a - 1) >= range.begin && uint64_t(b - 1) < range.end)
            own.emplace(a, b);
    for (const Bond& bond : *part.getBonds())
        inShare.emplace(int64_t(range.begin + bond.first) + 1, int64_t(range.begin + bond.second) + 1);
    EXPECT_GT(own.size(), 0u);
    EXPECT_EQ(inShare, own);
}

}

#endif
