/* PDB, GRO and LAMMPS data files, and topologies: the files their real writers made of the melt
 * (tests/data/formats/pdb: MDAnalysis, GROMACS, LAMMPS) against the LAMMPS dump they came from;
 * variants written here (PDB columns, GRO precisions, data file styles); shares; files that lie;
 * and a DCD given its atoms' names and elements by a PDB or LAMMPS data topology. */

#include "FormatTestData.h"

#include <osgGlyphsData/Elements>
#include <osgGlyphsData/GlyphMapping>
#include <osgGlyphsData/PointReader>

#include <osgGlyphs/GlyphCloud>

#include <sstream>

using namespace formattest;
using namespace osgGlyphsData;

namespace
{

std::string pdbData(const std::string& name)
{
    return dataPath("pdb/" + name);
}

osg::ref_ptr<FrameSource> melt()
{
    return openFrames(dataPath("melt.lammpstrj"));
}

/** The label of a point in a categorical column. */
std::string labelOf(const PointData& frame, const std::string& column, std::size_t point)
{
    const std::vector<float>* values = frame.getColumn(column);
    const std::vector<std::string>& labels = frame.getColumnLabels(column);
    if (!values || point >= values->size())
        return "<no column " + column + ">";
    const std::size_t index = static_cast<std::size_t>((*values)[point]);
    return index < labels.size() ? labels[index] : "<no label>";
}

/** Expects the atoms of frame (from its atom first on) to be named as make_pdb.py names the melt's:
 * type 1 argon, type 2 neon. */
void expectMeltAtoms(const PointData& dump, const PointData& frame, bool withResidues, std::size_t first = 0)
{
    const std::vector<float>& types = *dump.getColumn("type");
    ASSERT_TRUE(frame.hasColumn("element") && frame.hasColumn("species"));
    std::size_t wrong = 0;
    for (std::size_t i = 0; i < frame.getNumPoints(); ++i)
    {
        const bool argon = types[first + i] == 1.0f;
        const float element = (*frame.getColumn("element"))[i];
        const std::string species = labelOf(frame, "species", i);
        if ((element != (argon ? 18.0f : 10.0f) || species != (argon ? "Ar" : "Ne")) && wrong++ < 3)
            ADD_FAILURE() << "atom " << first + i << ": element " << element << ", species " << species;
        if (!withResidues)
            continue;
        if ((labelOf(frame, "name", i) != (argon ? "Ar" : "Ne") ||
             labelOf(frame, "residue", i) != (argon ? "LJ1" : "LJ2")) &&
            wrong++ < 3)
            ADD_FAILURE() << "atom " << first + i << ": name " << labelOf(frame, "name", i) << ", residue "
                          << labelOf(frame, "residue", i);
    }
    EXPECT_EQ(wrong, 0u);
}

/** Frames 0, 2, 4 of the dump: what make_pdb.sh wrote as models and GRO frames. */
const std::size_t WRITTEN_FRAMES[3] = {0, 2, 4};

/** The lines of a text. */
std::vector<std::string> linesOf(const std::string& text)
{
    std::vector<std::string> lines;
    std::istringstream stream(text);
    for (std::string line; std::getline(stream, line);)
        lines.push_back(line);
    return lines;
}

std::string joinLines(const std::vector<std::string>& lines)
{
    std::string text;
    for (const std::string& line : lines)
        text += line + "\n";
    return text;
}

/** An ATOM record in PDB's columns. */
std::string atomRecord(int serial, const std::string& name, double x, double y, double z,
                       const std::string& element = "")
{
    char line[100];
    std::snprintf(line, sizeof(line), "ATOM  %5d %-4s RES A%4d    %8.3f%8.3f%8.3f  1.00  0.00          %2s",
                  serial, name.c_str(), serial, x, y, z, element.c_str());
    return line;
}

/** The error of opening path with a topology and reading every frame; empty when all went well. */
std::string topologyError(const std::string& path, const std::string& topology)
{
    FrameSourceOptions options;
    options.topology = topology;
    options.indexLocation = FrameIndexLocation::None;
    options.warning = [](const std::string&) {};
    std::string error;
    osg::ref_ptr<FrameSource> source = FrameSource::open(path, options, error);
    if (!source)
        return error;
    source->waitForIndex();
    for (std::size_t frame = 0; frame < source->getNumFrames(); ++frame)
    {
        if (!source->readFrame(frame, error))
            return error;
    }
    return std::string();
}

struct BadFile
{
    std::string name, text, expected;
};

/** Expects each file to fail with one line naming the file and the expected words. */
void expectFailures(const std::vector<BadFile>& cases, const std::string& extension)
{
    for (const BadFile& bad : cases)
    {
        SCOPED_TRACE(bad.name);
        const std::string path = writeScratchFile("bad." + extension, bad.text);
        const std::string error = firstError(path);
        EXPECT_EQ(error.find(path), 0u) << error;
        EXPECT_NE(error.find(bad.expected), std::string::npos) << error;
        EXPECT_EQ(error.find('\n'), std::string::npos) << error;
    }
}

}

TEST(Pdb, MDAnalysisModelsAreTheDumpsFrames)
{
    osg::ref_ptr<FrameSource> dump = melt();
    osg::ref_ptr<FrameSource> pdb = openFrames(pdbData("melt.pdb"));
    ASSERT_TRUE(dump && pdb);
    EXPECT_EQ(pdb->getFormat(), "pdb");
    ASSERT_EQ(pdb->getNumFrames(), 3u);
    for (std::size_t model = 0; model < 3; ++model)
    {
        SCOPED_TRACE("model " + std::to_string(model));
        osg::ref_ptr<PointData> want = frameOf(*dump, WRITTEN_FRAMES[model]);
        osg::ref_ptr<PointData> got = frameOf(*pdb, model);
        ASSERT_TRUE(want && got);
        // Three decimals of Angstrom.
        for (const char* axis : {"x", "y", "z"})
            expectColumnMatches(*want, *got, axis, 1e-3);
        expectColumnMatches(*want, *got, "id", 0.0);
        expectColumnMatches(*want, *got, "id", 0.0, 1.0, "residue_id");
        expectMeltAtoms(*want, *got, true);
        EXPECT_EQ(got->getFilePointCount(), 500u);
        EXPECT_EQ(pdb->getFrameInfo(model).points, 500u);
    }
    osg::ref_ptr<PointData> first = frameOf(*pdb, 0);
    ASSERT_TRUE(first && first->hasBox());
    EXPECT_NEAR(first->getBox().xMax() - first->getBox().xMin(), 8.3979809569125372, 1e-3);
    EXPECT_NEAR(first->getBox().zMax() - first->getBox().zMin(), 8.3979809569125372, 1e-3);
    EXPECT_FALSE(first->isTriclinic());
    EXPECT_EQ(labelOf(*first, "chain", 0), "A");
    EXPECT_EQ((*first->getColumn("occupancy"))[0], 1.0f);
    EXPECT_EQ((*first->getColumn("bfactor"))[0], 1.5f);
    const std::vector<std::string> columns = first->getColumnNames();
    EXPECT_EQ(columns, (std::vector<std::string>{"id", "name", "residue", "chain", "residue_id", "x", "y",
                                                 "z", "occupancy", "bfactor", "element", "species"}));
}

TEST(Pdb, GromacsWithoutElementsGuessesThemFromTheNames)
{
    osg::ref_ptr<FrameSource> dump = melt();
    osg::ref_ptr<FrameSource> pdb = openFrames(pdbData("melt_gmx.pdb"));
    ASSERT_TRUE(dump && pdb);
    ASSERT_EQ(pdb->getNumFrames(), 1u);
    osg::ref_ptr<PointData> want = frameOf(*dump, 0);
    osg::ref_ptr<PointData> got = frameOf(*pdb, 0);
    ASSERT_TRUE(want && got);
    // From melt.gro's three decimals of nm.
    for (const char* axis : {"x", "y", "z"})
        expectColumnMatches(*want, *got, axis, 6e-3);
    expectMeltAtoms(*want, *got, true);
    EXPECT_EQ(labelOf(*got, "chain", 0), "");
    ASSERT_TRUE(got->hasBox());
    EXPECT_NEAR(got->getBox().yMax(), 8.398, 1e-3);
}

TEST(Pdb, ModelsReadInAnyOrderAreTheSame)
{
    osg::ref_ptr<FrameSource> pdb = openFrames(pdbData("melt.pdb"));
    ASSERT_TRUE(pdb);
    osg::ref_ptr<PointData> late = frameOf(*pdb, 2);
    osg::ref_ptr<PointData> early = frameOf(*pdb, 0);
    osg::ref_ptr<PointData> lateAgain = frameOf(*pdb, 2);
    ASSERT_TRUE(late && early && lateAgain);
    expectColumnMatches(*late, *lateAgain, "x", 0.0);
    EXPECT_NE(late->getValue(late->findColumn("x"), 0), early->getValue(early->findColumn("x"), 0));
}

TEST(Pdb, SharesTogetherAreTheWholeFrame)
{
    for (const std::string name : {"melt.pdb", "melt.gro"})
    {
        SCOPED_TRACE(name);
        osg::ref_ptr<PointData> whole = frameOf(*openFrames(pdbData(name)), 1);
        ASSERT_TRUE(whole);
        std::vector<float> x, ids;
        std::vector<std::string> species;
        for (unsigned int index = 0; index < 3; ++index)
        {
            FrameSourceOptions options;
            options.share = {index, 3};
            osg::ref_ptr<PointData> part = frameOf(*openFrames(pdbData(name), options), 1);
            ASSERT_TRUE(part);
            EXPECT_EQ(part->getFilePointCount(), 500u);
            x.insert(x.end(), part->getColumn("x")->begin(), part->getColumn("x")->end());
            ids.insert(ids.end(), part->getColumn("id")->begin(), part->getColumn("id")->end());
            for (std::size_t i = 0; i < part->getNumPoints(); ++i)
                species.push_back(labelOf(*part, "species", i));
        }
        EXPECT_EQ(x, *whole->getColumn("x"));
        EXPECT_EQ(ids, *whole->getColumn("id"));
        ASSERT_EQ(species.size(), whole->getNumPoints());
        for (std::size_t i = 0; i < species.size(); ++i)
            EXPECT_EQ(species[i], labelOf(*whole, "species", i)) << i;
    }
}

TEST(Pdb, ReadsTheColumnsOfOtherWriters)
{
    // VMD's trajectories: no MODEL, each frame up to END, a CRYST1 each; hybrid-36 serials; the
    // elements of names by PDB's alignment.
    const std::string text = joinLines({
        "CRYST1   10.000   20.000   30.000  90.00  90.00  90.00 P 1           1",
        atomRecord(1, " CA", 1.0, 2.0, 3.0),
        atomRecord(2, "CA", 1.5, 2.5, 3.5),
        atomRecord(3, "1HB", 0.0, 0.0, 0.0),
        atomRecord(4, "HG11", 0.0, 0.0, 0.0),
        atomRecord(5, "FE", 0.0, 0.0, 0.0),
        atomRecord(6, " OW", 0.0, 0.0, -1.25, "  "),
        "HETATMA0000 Cl   CL  B9999      -1.000  -2.000  -3.000  0.50 12.50          Cl",
        "TER",
        "END",
        "CRYST1   11.000   21.000   31.000  90.00  90.00 120.00 P 1           1",
        atomRecord(1, " CA", 2.0, 2.0, 3.0),
        atomRecord(2, "CA", 1.5, 2.5, 3.5),
        atomRecord(3, "1HB", 0.0, 0.0, 0.0),
        atomRecord(4, "HG11", 0.0, 0.0, 0.0),
        atomRecord(5, "FE", 0.0, 0.0, 0.0),
        atomRecord(6, " OW", 0.0, 0.0, -1.25),
        "HETATMA0000 Cl   CL  B9999      -1.000  -2.000  -3.000",
        "CONECT    1    2",
        "END",
    });
    osg::ref_ptr<FrameSource> pdb = openFrames(writeScratchFile("vmd.pdb", text));
    ASSERT_TRUE(pdb);
    ASSERT_EQ(pdb->getNumFrames(), 2u);
    osg::ref_ptr<PointData> first = frameOf(*pdb, 0);
    osg::ref_ptr<PointData> second = frameOf(*pdb, 1);
    ASSERT_TRUE(first && second);
    ASSERT_EQ(first->getNumPoints(), 7u);
    EXPECT_EQ(*first->getColumn("element"), (std::vector<float>{6, 20, 1, 1, 26, 8, 17}));
    EXPECT_EQ(labelOf(*first, "species", 1), "Ca");
    EXPECT_EQ(labelOf(*first, "name", 0), "CA");
    EXPECT_EQ((*first->getColumn("id"))[6], 100000.0f);
    EXPECT_EQ((*first->getColumn("residue_id"))[6], 9999.0f);
    EXPECT_EQ(labelOf(*first, "residue", 6), "CL");
    EXPECT_EQ(labelOf(*first, "chain", 6), "B");
    EXPECT_EQ((*first->getColumn("occupancy"))[6], 0.5f);
    EXPECT_EQ((*first->getColumn("bfactor"))[6], 12.5f);
    EXPECT_EQ((*first->getColumn("z"))[5], -1.25f);
    // Blank occupancy and temperature factor: 1 and 0.
    EXPECT_EQ((*second->getColumn("occupancy"))[6], 1.0f);
    EXPECT_EQ((*second->getColumn("bfactor"))[6], 0.0f);
    EXPECT_EQ((*second->getColumn("x"))[0], 2.0f);
    ASSERT_TRUE(first->hasBox() && second->hasBox());
    EXPECT_NEAR(first->getBox().zMax(), 30.0, 1e-9);
    EXPECT_FALSE(first->isTriclinic());
    // gamma 120: b = (-10.5, 18.19, 0).
    EXPECT_NEAR(second->getTilt().x(), -10.5, 1e-9);
    EXPECT_NEAR(second->getBox().yMax(), 21.0 * std::sqrt(3.0) / 2.0, 1e-9);
}

TEST(Pdb, MalformedLinesFailNamingTheFileLineAndWhat)
{
    const std::string good = atomRecord(1, "Ar", 1.0, 2.0, 3.0, "AR");
    std::string badX = good;
    badX.replace(30, 8, "   1.x00");
    std::string badSerial = good;
    badSerial.replace(6, 5, "  ?12");
    const std::vector<BadFile> cases = {
        {"empty lines", "\n\n", "no ATOM or HETATM records"},
        {"short atom", joinLines({"MODEL 1", good, good.substr(0, 50), "ENDMDL"}),
         ":3: frame 0: an atom record of 50 characters: x y z need columns 31-54"},
        {"bad x", joinLines({good, badX}), ":2: frame 0: columns 31-38 (x): '1.x00' is not a number"},
        {"nan z", joinLines({good, good.substr(0, 46) + "     nan"}),
         ":2: frame 0: columns 47-54 (z): 'nan' is not a finite number"},
        {"huge y", joinLines({good.substr(0, 38) + " 1.0e+39" + good.substr(46)}),
         ":1: frame 0: columns 39-46 (y): '1.0e+39' is out of the range of a float"},
        {"bad serial", joinLines({badSerial}), ":1: frame 0: columns 7-11 (serial): '?12' is not an integer"},
        {"model without endmdl", joinLines({"MODEL 1", good, "MODEL 2", good, "ENDMDL"}),
         ":3: MODEL inside the model that MODEL at line 1 opened: ENDMDL is missing"},
        {"only model unended", joinLines({"REMARK", "MODEL 1", good}),
         ":2: the model that MODEL at line 2 opened has no ENDMDL: the file ends at line 3"},
        {"endmdl alone", joinLines({good, "ENDMDL"}), ":2: ENDMDL without MODEL"},
        {"atom outside models", joinLines({"MODEL 1", good, "ENDMDL", good}),
         ":4: an atom record outside MODEL ... ENDMDL"},
        {"model after atoms", joinLines({good, "MODEL 1", good, "ENDMDL"}),
         ":2: MODEL after atom records outside a model (from line 1)"},
        {"bad cell", joinLines({"CRYST1   10.000   nan     30.000  90.00  90.00  90.00", good}),
         ":1: columns 16-24 (b): 'nan' is not a finite number"},
        {"binary", std::string("\x01\x02\x03\x00\x05", 5) + std::string(3u << 20, 'x'), "not a text file"},
    };
    expectFailures(cases, "pdb");
}

TEST(Pdb, ALastModelCutShortIsLeftOutWithAWarning)
{
    std::vector<std::string> lines = linesOf(readBytes(pdbData("melt.pdb")));
    lines.resize(1200); // inside model 3
    FrameSourceOptions options;
    std::vector<std::string> warnings;
    options.warning = [&warnings](const std::string& warning) { warnings.push_back(warning); };
    osg::ref_ptr<FrameSource> pdb = openFrames(writeScratchFile("cut.pdb", joinLines(lines)), options);
    ASSERT_TRUE(pdb);
    EXPECT_EQ(pdb->getNumFrames(), 2u);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find(":1007: frame 2: the model that MODEL at line 1007 opened has no ENDMDL"),
              std::string::npos)
        << warnings[0];
}

TEST(Gro, MDAnalysisFramesAreTheDumpsFrames)
{
    osg::ref_ptr<FrameSource> dump = melt();
    osg::ref_ptr<FrameSource> gro = openFrames(pdbData("melt.gro"));
    ASSERT_TRUE(dump && gro);
    EXPECT_EQ(gro->getFormat(), "gro");
    ASSERT_EQ(gro->getNumFrames(), 3u);
    for (std::size_t frame = 0; frame < 3; ++frame)
    {
        SCOPED_TRACE("frame " + std::to_string(frame));
        osg::ref_ptr<PointData> want = frameOf(*dump, WRITTEN_FRAMES[frame]);
        osg::ref_ptr<PointData> got = frameOf(*gro, frame);
        ASSERT_TRUE(want && got);
        // nm with three decimals, nm/ps with four (MDAnalysis takes the dump's units as Angstrom
        // and Angstrom/ps).
        for (const char* axis : {"x", "y", "z"})
            expectColumnMatches(*want, *got, axis, 1e-3, 0.1);
        for (const char* axis : {"vx", "vy", "vz"})
            expectColumnMatches(*want, *got, axis, 1e-4, 0.1);
        expectColumnMatches(*want, *got, "id", 0.0);
        expectColumnMatches(*want, *got, "id", 0.0, 1.0, "residue_id");
        expectMeltAtoms(*want, *got, true);
        ASSERT_TRUE(got->hasBox());
        EXPECT_NEAR(got->getBox().xMax(), 0.83979809569125372, 1e-5);
        EXPECT_EQ(got->getFilePointCount(), 500u);
    }
    osg::ref_ptr<PointData> late = frameOf(*gro, 2);
    osg::ref_ptr<PointData> early = frameOf(*gro, 0);
    osg::ref_ptr<PointData> lateAgain = frameOf(*gro, 2);
    ASSERT_TRUE(late && early && lateAgain);
    expectColumnMatches(*late, *lateAgain, "vx", 0.0);
    EXPECT_EQ(late->getColumnNames(),
              (std::vector<std::string>{"id", "name", "residue", "residue_id", "x", "y", "z", "vx", "vy",
                                        "vz", "element", "species"}));
}

// Element radii are in Angstrom: GROMACS' nanometres take a tenth of them, PDB's Angstrom all.
TEST(Gro, ElementRadiiAreInNanometres)
{
    for (const char* name : {"melt.gro", "melt.pdb"})
    {
        SCOPED_TRACE(name);
        osg::ref_ptr<PointData> frame = frameOf(*openFrames(pdbData(name)), 0);
        ASSERT_TRUE(frame && frame->hasColumn("element"));
        osg::ref_ptr<PointDataset> dataset = new PointDataset;
        dataset->addFrame(frame.get());
        GlyphMapper mapper{GlyphMappingOptions()};
        std::string error;
        ASSERT_TRUE(mapper.prepare(*dataset, 0, error)) << error;
        osg::ref_ptr<osgGlyphs::GlyphCloud> cloud = mapper.createCloud(*frame, error);
        ASSERT_TRUE(cloud && cloud->getRadii()) << error;
        const float argon = getElement(18).covalentRadius;
        const double unit = std::string(name) == "melt.gro" ? 10.0 : 1.0;
        EXPECT_EQ(frame->getAngstromsPerUnit(), unit);
        EXPECT_NEAR((*cloud->getRadii())[0], argon / unit, 1e-6);
    }
}

TEST(Gro, ReadsOtherPrecisionsTriclinicBoxesAndGromacsTitles)
{
    // GROMACS' layout at 5 decimals (fields of 10), no velocities, a triclinic box; then a frame
    // of the usual layout with velocities.
    const std::string text = "Generated by trjconv : melt t=  12.50000 step= 6250\n"
                             "    2\n"
                             "    1SOL     OW    1   1.23456  -2.00001   0.00000\n"
                             "    1SOL    HW1    2   1.10000   2.00000  10.00000\n"
                             "   3.00000   4.00000   5.00000   0.00000   0.00000   1.00000   0.00000   "
                             "0.50000   0.25000\n"
                             "second frame\n"
                             "2\n"
                             "    2NA      NA99999   0.100   0.200   0.300  1.0000 -2.0000  3.5000\n"
                             "    3CL      CL    0   0.400   0.500   0.600  0.1000  0.2000  0.3000\n"
                             "   1.00000   2.00000   3.00000\n";
    osg::ref_ptr<FrameSource> gro = openFrames(writeScratchFile("variants.gro", text));
    ASSERT_TRUE(gro);
    ASSERT_EQ(gro->getNumFrames(), 2u);
    const FrameInfo info = gro->getFrameInfo(0);
    EXPECT_EQ(info.timestep, 6250);
    EXPECT_TRUE(info.hasTime);
    EXPECT_DOUBLE_EQ(info.time, 12.5);
    EXPECT_EQ(gro->getFrameInfo(1).timestep, 1);
    osg::ref_ptr<PointData> first = frameOf(*gro, 0);
    osg::ref_ptr<PointData> second = frameOf(*gro, 1);
    ASSERT_TRUE(first && second);
    EXPECT_EQ(*first->getColumn("x"), (std::vector<float>{1.23456f, 1.1f}));
    EXPECT_EQ(*first->getColumn("y"), (std::vector<float>{-2.00001f, 2.0f}));
    EXPECT_FALSE(first->hasColumn("vx"));
    EXPECT_EQ(*first->getColumn("element"), (std::vector<float>{8, 1}));
    EXPECT_EQ(labelOf(*first, "name", 1), "HW1");
    EXPECT_EQ(labelOf(*first, "residue", 0), "SOL");
    ASSERT_TRUE(first->hasBox());
    EXPECT_EQ(first->getBox().xMax(), 3.0);
    EXPECT_EQ(first->getBox().zMax(), 5.0);
    EXPECT_EQ(first->getTilt(), osg::Vec3d(1.0, 0.5, 0.25));
    EXPECT_EQ(*second->getColumn("vy"), (std::vector<float>{-2.0f, 0.2f}));
    EXPECT_EQ(*second->getColumn("id"), (std::vector<float>{99999, 0}));
    EXPECT_EQ(*second->getColumn("element"), (std::vector<float>{11, 17}));
    EXPECT_EQ(second->getBox().yMax(), 2.0);
}

TEST(Gro, MalformedLinesFailNamingTheFileLineAndWhat)
{
    const std::string atom = "    1LJ1     Ar    1   0.000   0.000   0.000\n";
    const std::vector<BadFile> cases = {
        {"count past the end", "melt\n   10\n" + atom + atom + "   1.0 1.0 1.0\n",
         ":2: frame 0: the atom count 10 runs past the end of the file, which holds 3 atom line(s) after it"},
        {"no box", "melt\n2\n" + atom + atom, ":2: frame 0: the atom count 2 runs past the end"},
        {"bad count", "melt\n 1O\n" + atom + "1 1 1\n", ":2: frame 0: the atom count: '1O' is not a count"},
        {"title only", "melt\n", ":1: frame 0: the file ends after the title line"},
        {"bad x", "melt\n1\n    1LJ1     Ar    1   0.0x0   0.000   0.000\n1 1 1\n",
         ":3: frame 0: columns 21-28 (x): '0.0x0' is not a number"},
        {"short atom", "melt\n2\n" + atom + "    1LJ1     Ar    1   0.000   0.000\n1 1 1\n",
         ":4: frame 0: an atom line of 36 characters: x y z need columns 21-44"},
        {"velocities missing",
         "melt\n2\n    1LJ1     Ar    1   0.000   0.000   0.000  0.1000  0.2000  0.3000\n" + atom + "1 1 1\n",
         ":4: frame 0: an atom line of 44 characters: x y z vx vy vz need columns 21-68"},
        {"no decimal points", "melt\n1\n    1LJ1     Ar    1       0       0       0\n1 1 1\n",
         ":3: frame 0: the first atom line has no two numbers with decimal points"},
        {"bad atom number", "melt\n1\n    1LJ1     Ar  1x1   0.000   0.000   0.000\n1 1 1\n",
         ":3: frame 0: columns 16-20 (atom number): '1x1' is not an integer"},
        {"bad box", "melt\n1\n" + atom + "1 1\n",
         ":4: frame 0: the box line holds 2 fields, expected 3 or 9"},
        {"box not a number", "melt\n1\n" + atom + "1 inf 1\n", ":4: frame 0: the box line's field 2: 'inf'"},
    };
    expectFailures(cases, "gro");
}

TEST(Gro, ALastFrameCutShortIsLeftOutWithAWarning)
{
    std::vector<std::string> lines = linesOf(readBytes(pdbData("melt.gro")));
    lines.resize(503 + 300);
    FrameSourceOptions options;
    std::vector<std::string> warnings;
    options.warning = [&warnings](const std::string& warning) { warnings.push_back(warning); };
    osg::ref_ptr<FrameSource> gro = openFrames(writeScratchFile("cut.gro", joinLines(lines)), options);
    ASSERT_TRUE(gro);
    EXPECT_EQ(gro->getNumFrames(), 1u);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find(":505: frame 1: the atom count 500 runs past the end of the file, which holds "
                               "298 atom line(s) after it; the frame is cut short and left out"),
              std::string::npos)
        << warnings[0];
}

TEST(LammpsData, WriteDataIsTheDumpsFirstFrameSortedById)
{
    osg::ref_ptr<FrameSource> dump = melt();
    osg::ref_ptr<FrameSource> data = openFrames(pdbData("melt.data"));
    ASSERT_TRUE(dump && data);
    EXPECT_EQ(data->getFormat(), "lammpsdata");
    EXPECT_EQ(formatFromExtension("data.melt"), "lammpsdata");
    ASSERT_EQ(data->getNumFrames(), 1u);
    osg::ref_ptr<PointData> want = frameOf(*dump, 0);
    osg::ref_ptr<PointData> got = frameOf(*data, 0);
    ASSERT_TRUE(want && got);
    EXPECT_EQ(got->getColumnNames(), (std::vector<std::string>{"id", "type", "x", "y", "z", "ix", "iy", "iz",
                                                               "vx", "vy", "vz", "mass"}));
    expectColumnMatches(*want, *got, "id", 0.0);
    expectColumnMatches(*want, *got, "type", 0.0);
    // The dump's six significant digits; the data file's seventeen.
    for (const char* axis : {"x", "y", "z"})
        expectColumnMatches(*want, *got, axis, 1e-5);
    for (const char* axis : {"vx", "vy", "vz"})
        expectColumnMatches(*want, *got, axis, 1e-5);
    for (std::size_t i = 0; i < got->getNumPoints(); ++i)
        ASSERT_EQ((*got->getColumn("mass"))[i], (*got->getColumn("type"))[i] == 1.0f ? 1.0f : 0.5f) << i;
    ASSERT_TRUE(got->hasBox());
    EXPECT_EQ(got->getBox().xMax(), 8.397980956912537);
    EXPECT_EQ(got->getFilePointCount(), 500u);

    // Shares of the atoms in id order.
    std::vector<float> ids;
    for (unsigned int index = 0; index < 3; ++index)
    {
        FrameSourceOptions options;
        options.share = {index, 3};
        osg::ref_ptr<PointData> part = frameOf(*openFrames(pdbData("melt.data"), options), 0);
        ASSERT_TRUE(part);
        ids.insert(ids.end(), part->getColumn("id")->begin(), part->getColumn("id")->end());
    }
    EXPECT_EQ(ids, *got->getColumn("id"));
}

TEST(LammpsData, ReadsTheAtomStyles)
{
    const std::string text = "molecule of three\n\n"
                             "   3  atoms   # a comment\n   2 atom types\n 1 bonds\n 1 bond types\n"
                             "-1 1 xlo xhi\n-2 2 ylo yhi\n-3 3 zlo zhi\n0.5 0 0 xy xz yz\n\n"
                             "Masses\n\n1 15.999 # O\n2 1.008\n\n"
                             "Bond Coeffs # harmonic\n\n1 450 0.9572\n\n"
                             "Atoms # full\n\n"
                             "3 7 2 0.4238 0.1 0.2 0.3 0 0 1\n"
                             "1 7 1 -0.8476 0.0 0.0 0.0 0 0 0\n"
                             "2 7 2 0.4238 -0.1 0.2 0.3 -1 0 0\n\n"
                             "Bonds\n\n1 1 1 2\n";
    std::string error;
    PointReadOptions options;
    options.format = "lammpsdata";
    osg::ref_ptr<PointDataset> dataset = readPointFile(writeScratchFile("full.data", text), options, error);
    ASSERT_TRUE(dataset) << error;
    const PointData& frame = *dataset->getFrame(0);
    EXPECT_EQ(frame.getColumnNames(),
              (std::vector<std::string>{"id", "mol", "type", "q", "x", "y", "z", "ix", "iy", "iz", "mass"}));
    EXPECT_EQ(*frame.getColumn("id"), (std::vector<float>{1, 2, 3}));
    EXPECT_EQ(*frame.getColumn("q"), (std::vector<float>{-0.8476f, 0.4238f, 0.4238f}));
    EXPECT_EQ(*frame.getColumn("ix"), (std::vector<float>{0, -1, 0}));
    EXPECT_EQ(*frame.getColumn("mass"), (std::vector<float>{15.999f, 1.008f, 1.008f}));
    EXPECT_EQ(frame.getTilt(), osg::Vec3d(0.5, 0.0, 0.0));
    EXPECT_EQ(frame.getBox().zMin(), -3.0);

    // Without the style's name: atomic, the only style of 5 fields.
    dataset = readPointFile(
        writeScratchFile("atomic.data", "t\n2 atoms\n1 atom types\n\nAtoms\n\n2 1 0 0 1\n1 1 0 0 2\n"),
        options, error);
    ASSERT_TRUE(dataset) << error;
    EXPECT_EQ(*dataset->getFrame(0)->getColumn("z"), (std::vector<float>{2, 1}));
    EXPECT_FALSE(dataset->getFrame(0)->hasBox());
}

TEST(LammpsData, MalformedFilesFailNamingTheFileLineAndWhat)
{
    const std::string header = "title\n2 atoms\n2 atom types\n0 1 xlo xhi\n0 1 ylo yhi\n0 1 zlo zhi\n\n";
    const std::vector<BadFile> cases = {
        {"no atoms", "title\n2 atoms\n", "no Atoms section"},
        {"ambiguous", header + "Atoms\n\n1 1 0 0 0 0\n2 1 0 0 0 0\n",
         ":10: Atoms: 6 fields are of the styles charge and molecular: name the style"},
        {"unknown style", header + "Atoms # ellipsoid\n\n1 1 1 1 0 0 0\n",
         ":8: Atoms # ellipsoid: the atom style 'ellipsoid' is not read"},
        {"wrong fields", header + "Atoms # atomic\n\n1 1 0 0 0\n2 1 0 0\n",
         ":11: Atoms: 4 fields, expected 5 as in the first atom line"},
        {"duplicate id", header + "Atoms # atomic\n\n1 1 0 0 0\n1 2 0 0 0\n",
         ":11: Atoms: atom id 1 again (line 10"},
        {"type out of range", header + "Atoms # atomic\n\n1 1 0 0 0\n2 3 0 0 0\n",
         ":11: Atoms: the type '3' is not one of the 2 atom types"},
        {"too few atoms", header + "Atoms # atomic\n\n1 1 0 0 0\n",
         "unexpected end of file, expected line 2 of the 2 of Atoms"},
        {"bad number", header + "Atoms # atomic\n\n1 1 0 0 0\n2 1 0 zero 0\n",
         ":11: Atoms: y: 'zero' is not"},
        {"missing mass", header + "Masses\n\n1 1.0\n1 2.0\n\nAtoms # atomic\n\n1 1 0 0 0\n2 2 0 0 0\n",
         ":11: Masses: no mass for type 2 (of the atom at line 16)"},
        {"bad bounds", "title\n2 atoms\n1 atom types\n1 0 xlo xhi\n",
         ":4: xlo xhi: the lower bound is above"},
        {"extra line", header + "Atoms # atomic\n\n1 1 0 0 0\n2 1 0 0 0\n3 1 0 0 0\n",
         ":12: after the Atoms lines that the header counts, '3 1 0 0 0': expected a section keyword"},
    };
    for (const BadFile& bad : cases)
    {
        SCOPED_TRACE(bad.name);
        const std::string path = writeScratchFile("bad.data", bad.text);
        const std::string error = firstError(path);
        EXPECT_EQ(error.find(path), 0u) << error;
        EXPECT_NE(error.find(bad.expected), std::string::npos) << error;
    }
}

TEST(Topology, GivesADcdThePdbsNamesAndElements)
{
    osg::ref_ptr<FrameSource> dump = melt();
    osg::ref_ptr<FrameSource> plain = openFrames(dataPath("melt.dcd"));
    FrameSourceOptions options;
    options.topology = pdbData("melt.pdb");
    osg::ref_ptr<FrameSource> dcd = openFrames(dataPath("melt.dcd"), options);
    ASSERT_TRUE(dump && plain && dcd);
    ASSERT_EQ(dcd->getNumFrames(), 6u);
    ASSERT_TRUE(dcd->getFirstFrame()->hasColumn("species"));
    expectPositionsMatch(*plain, *dcd, 0.0);
    for (std::size_t frame : {5u, 0u, 3u, 1u, 2u, 4u})
    {
        SCOPED_TRACE("frame " + std::to_string(frame));
        osg::ref_ptr<PointData> want = frameOf(*dump, frame);
        osg::ref_ptr<PointData> got = frameOf(*dcd, frame);
        ASSERT_TRUE(want && got);
        expectMeltAtoms(*want, *got, true);
        expectColumnMatches(*want, *got, "id", 0.0);
        EXPECT_EQ(labelOf(*got, "chain", 499), "A");
        // Positions and the cell stay the trajectory's.
        EXPECT_NEAR(got->getBox().xMax(), 8.3979809569125372, 1e-5);
        EXPECT_EQ(got->getColumnNames().front(), "x");
    }
}

TEST(Topology, GivesADcdTheTypesAndMassesOfALammpsDataFile)
{
    osg::ref_ptr<FrameSource> dump = melt();
    FrameSourceOptions options;
    options.topology = pdbData("melt.data");
    osg::ref_ptr<FrameSource> dcd = openFrames(dataPath("melt.dcd"), options);
    ASSERT_TRUE(dump && dcd);
    osg::ref_ptr<PointData> want = frameOf(*dump, 4);
    osg::ref_ptr<PointData> got = frameOf(*dcd, 4);
    ASSERT_TRUE(want && got);
    expectColumnMatches(*want, *got, "type", 0.0);
    expectColumnMatches(*want, *got, "id", 0.0);
    ASSERT_TRUE(got->hasColumn("mass"));
    // Not the data file's positions, velocities or image flags.
    for (const char* perFrame : {"vx", "ix"})
        EXPECT_FALSE(got->hasColumn(perFrame)) << perFrame;
    expectColumnMatches(*frameOf(*openFrames(dataPath("melt.dcd")), 4), *got, "x", 0.0);
}

TEST(Topology, ASharesAtomsGetTheTopologysSameRows)
{
    FrameSourceOptions whole;
    whole.topology = pdbData("melt.gro");
    osg::ref_ptr<PointData> all = frameOf(*openFrames(dataPath("melt.dcd"), whole), 3);
    ASSERT_TRUE(all);
    std::vector<float> elements, x;
    for (unsigned int index = 0; index < 4; ++index)
    {
        FrameSourceOptions options = whole;
        options.share = {index, 4};
        osg::ref_ptr<PointData> part = frameOf(*openFrames(dataPath("melt.dcd"), options), 3);
        ASSERT_TRUE(part);
        elements.insert(elements.end(), part->getColumn("element")->begin(),
                        part->getColumn("element")->end());
        x.insert(x.end(), part->getColumn("x")->begin(), part->getColumn("x")->end());
        EXPECT_EQ(labelOf(*part, "species", 0), labelOf(*all, "species", 125 * index));
    }
    EXPECT_EQ(elements, *all->getColumn("element"));
    EXPECT_EQ(x, *all->getColumn("x"));
}

TEST(Topology, AnAtomCountThatDiffersFailsNamingBothFiles)
{
    // 400 atoms.
    std::vector<std::string> lines = linesOf(readBytes(pdbData("melt_gmx.pdb")));
    lines.erase(lines.begin() + 4 + 400, lines.end());
    lines.push_back("ENDMDL");
    const std::string small = writeScratchFile("small.pdb", joinLines(lines));
    const std::string dcd = dataPath("melt.dcd");
    EXPECT_EQ(topologyError(dcd, small), dcd + ": frame 0 has 500 atoms, its topology " + small + " 400");

    // A dump whose third frame has an atom less, given the dump's atoms: that frame alone fails.
    lines = linesOf(readBytes(dataPath("melt.lammpstrj")));
    ASSERT_EQ(lines[1021], "500");
    lines[1021] = "499";
    lines.erase(lines.begin() + 1027 + 499);
    const std::string dump = writeScratchFile("shrinking.lammpstrj", joinLines(lines));
    FrameSourceOptions options;
    options.topology = pdbData("melt.pdb");
    osg::ref_ptr<FrameSource> source = openFrames(dump, options);
    ASSERT_TRUE(source);
    std::string error;
    EXPECT_TRUE(source->readFrame(1, error)) << error;
    EXPECT_FALSE(source->readFrame(2, error));
    EXPECT_EQ(error, dump + ": frame 2 has 499 atoms, its topology " + pdbData("melt.pdb") + " 500");
    ASSERT_TRUE(source->getFirstFrame()->hasColumn("element"));
    EXPECT_TRUE(source->getFirstFrame()->hasColumn("type")); // the dump's own

    EXPECT_NE(topologyError(dcd, pdbData("missing.pdb")).find(pdbData("missing.pdb") + ": cannot open"),
              std::string::npos);
}
