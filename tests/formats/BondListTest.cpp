/* The bonds files list (PointData::getBonds()): a LAMMPS data file's Bonds, the CONECT records of
 * the PDB that MDAnalysis wrote of it (tests/data/bonds, make_pdb.py) and the bonds/group of the GSD
 * the gsd package wrote of it (make_gsd.py), against the data file's own Bonds lines read here; a LAMMPS dump
 * given them by the data file as its topology, every bond the length LAMMPS's harmonic bonds keep in every
 * frame; shares; and files that lie. */

#include "BondTruth.h"
#include "FormatTestData.h"

#include <osgGlyphsData/BondGlyphs>
#include <osgGlyphsData/PointReader>
#include <osgGlyphsData/PointShare>

#include <set>
#include <sstream>

using namespace formattest;
using namespace osgGlyphsData;

namespace
{

struct BadFile
{
    std::string name, text, expected;
};

}

TEST(BondList, ALammpsDataFileListsItsBonds)
{
    osg::ref_ptr<PointData> frame = frameOf(*openFrames(bondData("polymer.data")), 0);
    ASSERT_TRUE(frame);
    ASSERT_TRUE(frame->getBonds());
    EXPECT_EQ(frame->getBonds()->size(), 180u);
    expectWellFormed(*frame);
    const IdPairs truth = bondsOfDataFile(bondData("polymer.data"));
    ASSERT_EQ(truth.size(), 180u);
    EXPECT_EQ(bondsById(*frame), truth);
    expectBondedLengths(*frame); // across the periodic faces too: the file wraps the atoms

    // A data file without Bonds lists none.
    EXPECT_FALSE(frameOf(*openFrames(dataPath("pdb/melt.data")), 0)->getBonds());
}

TEST(BondList, PdbConectListsTheSameBondsOnce)
{
    osg::ref_ptr<PointData> frame = frameOf(*openFrames(bondData("polymer.pdb")), 0);
    ASSERT_TRUE(frame);
    expectWellFormed(*frame);
    EXPECT_EQ(bondsById(*frame), bondsOfDataFile(bondData("polymer.data")));
    expectBondedLengths(*frame);

    // A PDB without CONECT lists none.
    EXPECT_FALSE(frameOf(*openFrames(dataPath("pdb/melt.pdb")), 0)->getBonds());
}

TEST(BondList, ATopologyGivesEveryFrameOfADumpItsBonds)
{
    FrameSourceOptions options;
    options.topology = bondData("polymer.data");
    osg::ref_ptr<FrameSource> dump = openFrames(bondData("polymer.lammpstrj"), options);
    ASSERT_TRUE(dump);
    ASSERT_EQ(dump->getNumFrames(), 5u);
    EXPECT_FALSE(frameOf(*openFrames(bondData("polymer.lammpstrj")), 0)->getBonds());
    const IdPairs truth = bondsOfDataFile(bondData("polymer.data"));
    osg::ref_ptr<PointData> first = frameOf(*dump, 0);
    for (std::size_t index : {4u, 0u, 2u})
    {
        SCOPED_TRACE("frame " + std::to_string(index));
        osg::ref_ptr<PointData> frame = frameOf(*dump, index);
        ASSERT_TRUE(frame && frame->getBonds());
        EXPECT_EQ(bondsById(*frame), truth);
        expectBondedLengths(*frame);
        // One list for every frame: its memory does not grow with the frames.
        EXPECT_EQ(frame->getBonds().get(), first->getBonds().get());
    }
}

// Frames 1 to 4 of the GSD hold no bonds chunks: they take frame 0's, as GSD's readers do.
TEST(BondList, AGsdFileListsItsBondsInEveryFrame)
{
    osg::ref_ptr<FrameSource> gsd = openFrames(bondData("polymer.gsd"));
    ASSERT_TRUE(gsd);
    ASSERT_EQ(gsd->getNumFrames(), 5u);
    const IdPairs truth = bondsOfDataFile(bondData("polymer.data"));
    osg::ref_ptr<PointData> first = frameOf(*gsd, 0);
    ASSERT_TRUE(first && first->getBonds());
    for (std::size_t index : {0u, 4u, 2u})
    {
        SCOPED_TRACE("frame " + std::to_string(index));
        osg::ref_ptr<PointData> frame = frameOf(*gsd, index);
        ASSERT_TRUE(frame && frame->getBonds());
        expectWellFormed(*frame);
        EXPECT_EQ(bondsByIndex(*frame), truth);
        expectBondedLengths(*frame);
        EXPECT_EQ(frame->getBonds().get(), first->getBonds().get());
    }
    // A share holds the bonds between its own particles, by its own indices.
    FrameSourceOptions options;
    options.share = {2, 5};
    osg::ref_ptr<PointData> part = frameOf(*openFrames(bondData("polymer.gsd"), options), 3);
    ASSERT_TRUE(part);
    expectShareHoldsItsOwnBonds(*part, options.share, 192, truth);
    // A GSD without bonds lists none.
    EXPECT_FALSE(frameOf(*openFrames(dataPath("gsd/melt.gsd")), 0)->getBonds());
}

TEST(BondList, SharesHoldTheBondsBetweenTheirOwnAtoms)
{
    const IdPairs truth = bondsOfDataFile(bondData("polymer.data"));
    for (const std::string& file : {std::string("polymer.data"), std::string("polymer.pdb")})
    {
        SCOPED_TRACE(file);
        IdPairs inShares;
        std::size_t crossing = 0;
        for (unsigned int index = 0; index < 5; ++index)
        {
            FrameSourceOptions options;
            options.share = {index, 5};
            osg::ref_ptr<PointData> part = frameOf(*openFrames(bondData(file), options), 0);
            ASSERT_TRUE(part);
            expectWellFormed(*part);
            const IdPairs own = bondsById(*part);
            inShares.insert(own.begin(), own.end());
            // The bonds from this share's atoms to the next share's (ids 1... in file order).
            const PointRange range = getShareRange(options.share, 192);
            for (const auto& [a, b] : truth)
                crossing += uint64_t(a - 1) >= range.begin && uint64_t(a - 1) < range.end &&
                                    uint64_t(b - 1) >= range.end
                                ? 1
                                : 0;
        }
        EXPECT_GT(crossing, 0u);
        EXPECT_EQ(inShares.size(), truth.size() - crossing);
        for (const auto& pair : inShares)
            EXPECT_EQ(truth.count(pair), 1u) << pair.first << "-" << pair.second;
    }
}

TEST(BondList, MalformedBondsFailNamingTheFileLineAndWhat)
{
    const std::string header = "title\n2 atoms\n1 atom types\n1 bonds\n1 bond types\n\n";
    const std::string atoms = "Atoms # atomic\n\n1 1 0 0 0\n2 1 0 0 1\n\n";
    const std::vector<BadFile> cases = {
        {"missing atom", header + atoms + "Bonds\n\n1 1 1 3\n", ":14: Bonds: atom id 3 is not in Atoms"},
        {"self", header + atoms + "Bonds\n\n1 1 2 2\n", ":14: Bonds: atom id '2' bonded to itself"},
        {"before atoms", header + "Bonds\n\n1 1 1 2\n\n" + atoms, ":7: Bonds before Atoms"},
        {"fields", header + atoms + "Bonds\n\n1 1 1\n", ":14: Bonds: 3 fields, expected 4"},
        {"type", header + atoms + "Bonds\n\n1 2 1 2\n", ":14: Bonds: the bond type '2' is not one of the 1"},
        {"too few", "title\n2 atoms\n1 atom types\n2 bonds\n\n" + atoms + "Bonds\n\n1 1 1 2\n",
         "expected line 2 of the 2 of Bonds"},
        {"no count", "title\n2 atoms\n1 atom types\n\n" + atoms + "Bonds\n\n1 1 1 2\n",
         "Bonds without a count of bonds in the header"},
    };
    for (const BadFile& bad : cases)
    {
        SCOPED_TRACE(bad.name);
        const std::string path = writeScratchFile("bad.data", bad.text);
        const std::string error = firstError(path, "lammpsdata");
        EXPECT_EQ(error.find(path), 0u) << error;
        EXPECT_NE(error.find(bad.expected), std::string::npos) << error;
    }

    const std::string pdbAtoms =
        "ATOM      1  C   UNK X   1       0.000   0.000   0.000  1.00  0.00           C\n"
        "ATOM      2  C   UNK X   1       1.000   0.000   0.000  1.00  0.00           C\n";
    const std::vector<BadFile> pdbCases = {
        {"unknown serial", pdbAtoms + "CONECT    1    3\nEND\n",
         ":3: frame 0: CONECT names atom serial 3, which no atom of the frame has"},
        {"repeated serial",
         pdbAtoms + "ATOM      2  C   UNK X   1       2.000   0.000   0.000  1.00  0.00           C\n" +
             "CONECT    1    2\nEND\n",
         ":4: frame 0: CONECT names atom serial 2, which more than one atom has (line 3 repeats it)"},
        {"self", pdbAtoms + "CONECT    1    1\nEND\n", ":3: CONECT: atom 1 bonded to itself"},
        {"not a serial", pdbAtoms + "CONECT    1  two\nEND\n", ":3:"},
    };
    for (const BadFile& bad : pdbCases)
    {
        SCOPED_TRACE(bad.name);
        const std::string path = writeScratchFile("bad.pdb", bad.text);
        const std::string error = firstError(path, "pdb");
        EXPECT_EQ(error.find(path), 0u) << error;
        EXPECT_NE(error.find(bad.expected), std::string::npos) << error;
    }
}
