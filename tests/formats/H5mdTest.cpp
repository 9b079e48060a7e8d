/* HDF5 (osgGlyphsHdf5): h5py's H5MD of the melt against the LAMMPS dump it was written from (plain,
 * gzip-compressed, fixed species, two particle groups); a SWIFT-style snapshot against the
 * formulas it was written from; datasets named by the user; shares; and malformed files written
 * here through HDF5's C library. */

#include "BondTruth.h"
#include "FormatTestData.h"
#include "Hdf5Layout.h"

#include <osgGlyphsData/PointReader>
#include <osgGlyphsHdf5/Hdf5Formats>

#include <cmath>

using namespace formattest;
using namespace osgGlyphsData;

namespace
{

const double Box = 8.3979809569125372;

/** The formulas make_h5md.py wrote the snapshot from. */
double snapshotValue(const std::string& kind, int type, int i)
{
    if (kind == "x")
        return 10000.0 + 0.123456789 * i + type;
    if (kind == "y")
        return 12000.0 + 0.0987654321 * i;
    if (kind == "z")
        return 9000.0 + std::sqrt(i + 1.0);
    if (kind == "id")
        return type * 1000 + i + 1;
    return 0.01 * (i + 1); // mass
}

std::string h5md(const std::string& name)
{
    return dataPath("h5md/" + name);
}

osg::ref_ptr<FrameSource> melt()
{
    return openFrames(dataPath("melt.lammpstrj"));
}

struct Registration
{
    Registration() { osgGlyphsHdf5::registerFormats(); }
} registration;

/** Expects every frame's columns (names in both) to match within tolerance. */
void expectFramesMatch(const FrameSource& expected, const FrameSource& actual,
                       const std::vector<std::string>& columns, double tolerance)
{
    ASSERT_EQ(expected.getNumFrames(), actual.getNumFrames());
    for (std::size_t frame = 0; frame < expected.getNumFrames(); ++frame)
    {
        SCOPED_TRACE("frame " + std::to_string(frame));
        osg::ref_ptr<PointData> want = frameOf(expected, frame);
        osg::ref_ptr<PointData> got = frameOf(actual, frame);
        ASSERT_TRUE(want && got);
        for (const std::string& column : columns)
            expectColumnMatches(*want, *got, column, tolerance);
    }
}

std::string scratch(const std::string& name, const hdf5layout::Layout& layout)
{
    const std::string path = ::testing::TempDir() + "osgglyphs_format_" + name;
    EXPECT_TRUE(hdf5layout::writeLayout(path, layout));
    return path;
}

/** Expects the error of reading path to be one line naming the file, the dataset and, when frame
 * is given, the frame, and saying what (when what is given). */
void expectError(const std::string& path, const std::string& dataset, const std::string& what,
                 const std::string& frame = std::string())
{
    const std::string error = firstError(path, "h5md");
    SCOPED_TRACE(error);
    EXPECT_FALSE(error.empty());
    EXPECT_EQ(error.rfind(path + ": ", 0), 0u);
    EXPECT_EQ(error.find('\n'), std::string::npos);
    EXPECT_NE(error.find("dataset " + dataset + ":"), std::string::npos);
    if (!frame.empty())
    {
        EXPECT_NE(error.find("frame " + frame + ":"), std::string::npos);
    }
    EXPECT_NE(error.find(what), std::string::npos);
}

}

TEST(H5md, FramesAreTheDumpsFrames)
{
    osg::ref_ptr<FrameSource> dump = melt();
    osg::ref_ptr<FrameSource> file = openFrames(h5md("melt.h5md"));
    ASSERT_TRUE(dump && file);
    EXPECT_EQ(file->getFormat(), "h5md");
    // The dump's six significant digits, stored as float32.
    expectFramesMatch(*dump, *file, {"x", "y", "z", "vx", "vy", "vz"}, 1e-5);
    expectFramesMatch(*dump, *file, {"id", "type"}, 0.0);
    for (std::size_t frame = 0; frame < 6; ++frame)
    {
        const FrameInfo info = file->getFrameInfo(frame);
        EXPECT_EQ(info.timestep, int64_t(20 * frame));
        EXPECT_TRUE(info.hasTime);
        EXPECT_NEAR(info.time, 0.005 * 20 * double(frame), 1e-12);
        EXPECT_EQ(info.points, 500u);
    }
    osg::ref_ptr<PointData> last = frameOf(*file, 5);
    ASSERT_TRUE(last && last->hasBox());
    EXPECT_EQ(last->getTimestep(), 100);
    EXPECT_EQ(last->getFilePointCount(), 500u);
    EXPECT_DOUBLE_EQ(last->getBox().xMin(), 0.0);
    EXPECT_DOUBLE_EQ(last->getBox().xMax(), Box);
    EXPECT_DOUBLE_EQ(last->getBox().zMax(), Box);
    EXPECT_FALSE(last->isTriclinic());
    EXPECT_EQ(last->getColumnLabels("species"), (std::vector<std::string>{"1", "2"}));
    const std::vector<float>& type = *last->getColumn("type");
    const std::vector<float>& species = *last->getColumn("species");
    for (std::size_t i = 0; i < type.size(); ++i)
        ASSERT_EQ(species[i], type[i] - 1.0f) << i;
}

TEST(H5md, FramesReadInAnyOrderAreTheSame)
{
    osg::ref_ptr<FrameSource> file = openFrames(h5md("melt.h5md"));
    ASSERT_TRUE(file);
    osg::ref_ptr<PointData> late = frameOf(*file, 5);
    osg::ref_ptr<PointData> early = frameOf(*file, 1);
    osg::ref_ptr<PointData> lateAgain = frameOf(*file, 5);
    ASSERT_TRUE(late && early && lateAgain);
    expectColumnMatches(*late, *lateAgain, "x", 0.0);
    EXPECT_NE(late->getValue(0, 1), early->getValue(0, 1));
}

TEST(H5md, GzipChunkedFileReadsAsThePlainOne)
{
    osg::ref_ptr<FrameSource> plain = openFrames(h5md("melt.h5md"));
    osg::ref_ptr<FrameSource> gzip = openFrames(h5md("melt_gzip.h5md"));
    ASSERT_TRUE(plain && gzip);
    expectFramesMatch(*plain, *gzip, {"x", "y", "z", "id", "type", "species"}, 0.0);
    for (std::size_t frame = 0; frame < 6; ++frame)
    {
        EXPECT_EQ(gzip->getFrameInfo(frame).timestep, plain->getFrameInfo(frame).timestep);
        EXPECT_DOUBLE_EQ(gzip->getFrameInfo(frame).time, plain->getFrameInfo(frame).time);
    }
    // The box from time-dependent edge vectors, stepped by a fixed interval.
    osg::ref_ptr<PointData> frame = frameOf(*gzip, 4);
    ASSERT_TRUE(frame && frame->hasBox());
    EXPECT_DOUBLE_EQ(frame->getBox().yMax(), Box);
    EXPECT_FALSE(frame->isTriclinic());
}

TEST(H5md, FixedElementsAndTheLastValueBeforeAStep)
{
    osg::ref_ptr<FrameSource> dump = melt();
    osg::ref_ptr<FrameSource> file = openFrames(h5md("melt_fixed.h5md"));
    ASSERT_TRUE(dump && file);
    expectFramesMatch(*dump, *file, {"x", "y", "z"}, 1e-5);
    expectFramesMatch(*dump, *file, {"id", "type"}, 0.0);
    // Velocities at steps 0, 40, 80: frame n has those of the frame at or before it.
    for (std::size_t frame = 0; frame < 6; ++frame)
    {
        SCOPED_TRACE("frame " + std::to_string(frame));
        osg::ref_ptr<PointData> want = frameOf(*dump, frame - frame % 2);
        osg::ref_ptr<PointData> got = frameOf(*file, frame);
        ASSERT_TRUE(want && got);
        for (const char* column : {"vx", "vy", "vz"})
            expectColumnMatches(*want, *got, column, 1e-5);
        const std::vector<float>& type = *got->getColumn("type");
        const std::vector<float>& charge = *got->getColumn("charge");
        for (std::size_t i = 0; i < type.size(); ++i)
            ASSERT_EQ(charge[i], type[i] == 2.0f ? -0.5f : 0.25f) << i;
        EXPECT_EQ(*got->getColumn("mass"), std::vector<float>(500, 1.0f));
        EXPECT_EQ(got->getColumnLabels("species"), (std::vector<std::string>{"1", "2"}));
    }
}

TEST(H5md, ParticleGroupsAreReadTogether)
{
    osg::ref_ptr<FrameSource> dump = melt();
    std::vector<std::string> warnings;
    FrameSourceOptions options;
    options.warning = [&warnings](const std::string& warning) { warnings.push_back(warning); };
    osg::ref_ptr<FrameSource> file = openFrames(h5md("melt_groups.h5md"), options);
    ASSERT_TRUE(dump && file);
    expectFramesMatch(*dump, *file, {"x", "y", "z"}, 1e-5);
    expectFramesMatch(*dump, *file, {"id"}, 0.0);
    osg::ref_ptr<PointData> frame = frameOf(*file, 3);
    ASSERT_TRUE(frame);
    EXPECT_EQ(frame->getColumnLabels("group"), (std::vector<std::string>{"left", "right"}));
    const std::vector<float>& group = *frame->getColumn("group");
    EXPECT_EQ(group[199], 0.0f);
    EXPECT_EQ(group[200], 1.0f);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("2 particle groups"), std::string::npos);
}

TEST(H5md, SharesTogetherAreTheWholeFrame)
{
    for (const std::string& path :
         {h5md("melt.h5md"), h5md("melt_gzip.h5md"), h5md("melt_groups.h5md"), h5md("snapshot.hdf5")})
    {
        SCOPED_TRACE(path);
        osg::ref_ptr<PointData> whole = frameOf(*openFrames(path), 0);
        ASSERT_TRUE(whole);
        std::vector<double> x, id;
        for (unsigned int index = 0; index < 3; ++index)
        {
            FrameSourceOptions options;
            options.share = {index, 3};
            osg::ref_ptr<PointData> part = frameOf(*openFrames(path, options), 0);
            ASSERT_TRUE(part);
            EXPECT_EQ(part->getFilePointCount(), whole->getNumPoints());
            for (std::size_t i = 0; i < part->getNumPoints(); ++i)
            {
                x.push_back(part->getValue(std::size_t(part->findColumn("x")), i));
                id.push_back(part->getValue(std::size_t(part->findColumn("id")), i));
            }
        }
        ASSERT_EQ(x.size(), whole->getNumPoints());
        for (std::size_t i = 0; i < x.size(); ++i)
        {
            ASSERT_EQ(x[i], whole->getValue(std::size_t(whole->findColumn("x")), i)) << i;
            ASSERT_EQ(id[i], whole->getValue(std::size_t(whole->findColumn("id")), i)) << i;
        }
    }
}

TEST(Hdf5, SnapshotKeepsDoublePrecisionCoordinates)
{
    std::vector<std::string> warnings;
    FrameSourceOptions options;
    options.warning = [&warnings](const std::string& warning) { warnings.push_back(warning); };
    osg::ref_ptr<FrameSource> file = openFrames(h5md("snapshot.hdf5"), options);
    ASSERT_TRUE(file);
    EXPECT_EQ(file->getFormat(), "hdf5");
    EXPECT_EQ(file->getNumFrames(), 1u);
    EXPECT_TRUE(file->getFrameInfo(0).hasTime);
    EXPECT_DOUBLE_EQ(file->getFrameInfo(0).time, 0.5);
    osg::ref_ptr<PointData> frame = frameOf(*file, 0);
    ASSERT_TRUE(frame);
    ASSERT_EQ(frame->getNumPoints(), 100u);
    EXPECT_EQ(frame->getColumnLabels("particle_type"), (std::vector<std::string>{"PartType0", "PartType1"}));
    for (int point = 0; point < 100; ++point)
    {
        const int type = point < 40 ? 0 : 1;
        const int i = point - 40 * type;
        SCOPED_TRACE("point " + std::to_string(point));
        for (const char* axis : {"x", "y", "z"})
        {
            const double want = snapshotValue(axis, type, i);
            const double got = frame->getValue(std::size_t(frame->findColumn(axis)), std::size_t(point));
            // Far tighter than a float near 1e4 (about 5e-4): the column's double origin.
            ASSERT_NEAR(got, want, 1e-5) << axis;
            ASSERT_LE(std::fabs(got - want), 1e-6 * std::fabs(want)) << axis;
        }
        ASSERT_EQ(frame->getValue(std::size_t(frame->findColumn("id")), std::size_t(point)),
                  snapshotValue("id", type, i));
        ASSERT_EQ((*frame->getColumn("particle_type"))[std::size_t(point)], float(type));
        ASSERT_EQ((*frame->getColumn("vy"))[std::size_t(point)], -float(i));
        // PartType1 has no Masses: the header's MassTable gives them.
        ASSERT_NEAR(frame->getValue(std::size_t(frame->findColumn("mass")), std::size_t(point)),
                    type == 0 ? snapshotValue("mass", 0, i) : 0.25, 1e-7);
        ASSERT_EQ((*frame->getColumn("Densities"))[std::size_t(point)], type == 0 ? float(i + 1) : 0.0f);
    }
    EXPECT_NE(frame->getColumnOrigin("x"), 0.0);
    ASSERT_TRUE(frame->hasBox());
    EXPECT_DOUBLE_EQ(frame->getBox().xMax(), 20000.0);
    // PartType1's missing Masses (from the header) and Densities (0).
    ASSERT_EQ(warnings.size(), 2u);
    const std::string both = warnings[0] + "\n" + warnings[1];
    EXPECT_NE(both.find(": PartType1 has no mass; its particles get 0.25 (from the header)"),
              std::string::npos);
    EXPECT_NE(both.find(": PartType1 has no Densities; its particles get 0"), std::string::npos);
}

TEST(Hdf5, DatasetsNamedByTheUser)
{
    FrameSourceOptions options;
    options.datasets = {"/data/points", "/data/temperature", "/data/spin"};
    osg::ref_ptr<FrameSource> file = openFrames(h5md("custom.h5"), options);
    ASSERT_TRUE(file);
    osg::ref_ptr<PointData> frame = frameOf(*file, 0);
    ASSERT_TRUE(frame);
    EXPECT_EQ(frame->getColumnNames(),
              (std::vector<std::string>{"x", "y", "z", "temperature", "spin_x", "spin_y", "spin_z"}));
    for (std::size_t i = 0; i < 30; ++i)
    {
        ASSERT_EQ(frame->getValue(1, i), 2.0 * double(i));
        ASSERT_EQ(frame->getValue(3, i), 300.0 + double(i));
        ASSERT_EQ(frame->getValue(6, i), 0.5 * double(i));
    }
    // Without them the file is neither H5MD nor a snapshot.
    const std::string error = firstError(h5md("custom.h5"));
    EXPECT_EQ(error.rfind(h5md("custom.h5") + ": neither H5MD", 0), 0u) << error;
    // A dataset of another length than the positions.
    options.datasets = {"/data/points", "/meta/history"};
    std::string failure;
    options.indexLocation = FrameIndexLocation::None;
    EXPECT_FALSE(FrameSource::open(h5md("custom.h5"), options, failure));
    EXPECT_NE(failure.find("frame 0: dataset /meta/history: holds 5 values for the 30 particles"),
              std::string::npos)
        << failure;
}

TEST(H5md, ElementsNamedByTheUser)
{
    FrameSourceOptions options;
    options.datasets = {"/particles/all/position", "/particles/all/id"};
    osg::ref_ptr<FrameSource> file = openFrames(h5md("melt.h5md"), options);
    ASSERT_TRUE(file);
    osg::ref_ptr<PointData> frame = frameOf(*file, 2);
    ASSERT_TRUE(frame);
    EXPECT_EQ(frame->getColumnNames(), (std::vector<std::string>{"x", "y", "z", "id"}));
    expectColumnMatches(*frameOf(*melt(), 2), *frame, "id", 0.0);
    // readPointFile reads them too.
    PointReadOptions read;
    read.datasets = {"/particles/all/position", "/particles/all/velocity"};
    std::string error;
    osg::ref_ptr<PointDataset> dataset = readPointFile(h5md("melt.h5md"), read, error);
    ASSERT_TRUE(dataset) << error;
    ASSERT_EQ(dataset->getNumFrames(), 6u);
    EXPECT_EQ(dataset->getFrame(0)->getColumnNames(),
              (std::vector<std::string>{"x", "y", "z", "vx", "vy", "vz"}));
}

TEST(H5md, MalformedFilesFailWithOneLineNamingTheDataset)
{
    using namespace hdf5layout;
    const std::string position = "/particles/all/position";
    {
        Layout layout = smallH5md();
        layout.erase(position + "/value");
        layout.erase(position + "/step");
        layout.erase(position + "/time");
        expectError(scratch("missing.h5md", layout), position, "missing");
    }
    {
        Layout layout = smallH5md();
        layout[position + "/value"].dims = {3, 4, 4};
        expectError(scratch("wide.h5md", layout), position + "/value", "4 values a particle");
    }
    {
        Layout layout = smallH5md();
        layout[position + "/value"].kind = Kind::String;
        expectError(scratch("strings.h5md", layout), position + "/value", "holds string values, not numbers");
    }
    {
        Layout layout = smallH5md();
        layout[position + "/step"].dims = {2};
        expectError(scratch("steps.h5md", layout), position + "/step", "holds 2 values for the 3 of");
    }
    {
        Layout layout = smallH5md();
        layout[position + "/value"] = {{3, hsize_t(1) << 40, 3}, Kind::Unwritten};
        expectError(scratch("absurd.h5md", layout), position + "/value", "dims that its data cannot fill");
    }
    {
        Layout layout = smallH5md();
        layout["/particles/all/id/value"].dims = {3, 3};
        expectError(scratch("ids.h5md", layout), "/particles/all/id/value",
                    "holds 3 values for the 4 particles of " + position + "/value", "0");
    }
    {
        Layout layout = smallH5md();
        layout["/particles/all/id/step"].dims = {4};
        expectError(scratch("idsteps.h5md", layout), "/particles/all/id/step", "holds 4 values for the 3",
                    "0");
    }
    {
        Layout layout = smallH5md();
        layout["/particles/all/species"] = {{4}, Kind::String};
        expectError(scratch("species.h5md", layout), "/particles/all/species", "not numbers", "0");
    }
    {
        Layout layout = smallH5md();
        layout["/particles/all/velocity/value"] = {{3, 4, 3}, Kind::Float};
        layout["/particles/all/velocity/step"] = {{3}, Kind::Int, 5.0, 10.0};
        expectError(scratch("late.h5md", layout), "/particles/all/velocity/value",
                    "has no value at step 0 or before it", "0");
    }
    {
        Layout layout = smallH5md();
        layout[position + "/value"].kind = Kind::NotANumber;
        expectError(scratch("nan.h5md", layout), position + "/value",
                    "the position of particle 0 is not a finite number", "0");
    }
    {
        Layout layout = smallH5md();
        layout["/particles/all/box/edges"].dims = {2};
        expectError(scratch("box.h5md", layout), "/particles/all/box/edges", "for a box of dimension 3", "0");
    }
}

TEST(H5md, AValidSmallFileReads)
{
    // The layout the malformed files start from reads: their failures are the changes'.
    const std::string path = scratch("small.h5md", hdf5layout::smallH5md());
    EXPECT_EQ(firstError(path, "h5md"), "");
    osg::ref_ptr<FrameSource> file = openFrames(path);
    ASSERT_TRUE(file);
    EXPECT_EQ(file->getNumFrames(), 3u);
    EXPECT_EQ(file->getFrameInfo(2).timestep, 20);
    osg::ref_ptr<PointData> frame = frameOf(*file, 1);
    ASSERT_TRUE(frame);
    EXPECT_EQ((*frame->getColumn("x"))[0], 6.0f); // frame 1 starts at 4 particles x 3 values
    EXPECT_EQ((*frame->getColumn("id"))[0], 5.0f);
}

TEST(Hdf5, NotHdf5)
{
    const std::string path = writeScratchFile("text.h5", "not an HDF5 file\n");
    const std::string error = firstError(path);
    EXPECT_EQ(error.rfind(path + ": not an HDF5 file", 0), 0u) << error;
    EXPECT_TRUE(isFrameFileFormat("h5md"));
    EXPECT_TRUE(isFrameFileFormat("hdf5"));
    EXPECT_EQ(formatFromExtension("run.h5md"), "h5md");
    EXPECT_EQ(formatFromExtension("snap_012.hdf5"), "hdf5");
}

// H5MD connectivity written by h5py (tests/data/bonds/make_h5md.py) from the polymer's data file:
// bonds by the particles' ids in a shuffled file, and by their indices, time-dependent with pairs
// holding the fill value; both are the data file's Bonds in every frame, each to its nearest image
// a harmonic bond's length. Triples (angles) are not bonds: left out with a warning.
TEST(H5md, ConnectivityIsTheFramesBonds)
{
    const IdPairs truth = bondsOfDataFile(bondData("polymer.data"));
    ASSERT_EQ(truth.size(), 180u);
    std::vector<std::string> warnings;
    FrameSourceOptions options;
    options.warning = [&warnings](const std::string& warning) { warnings.push_back(warning); };
    osg::ref_ptr<FrameSource> byId = openFrames(bondData("polymer.h5md"), options);
    osg::ref_ptr<FrameSource> byIndex = openFrames(bondData("polymer_indices.h5md"));
    ASSERT_TRUE(byId && byIndex);
    for (std::size_t index : {0u, 4u})
    {
        SCOPED_TRACE("frame " + std::to_string(index));
        osg::ref_ptr<PointData> shuffled = frameOf(*byId, index);
        ASSERT_TRUE(shuffled && shuffled->getBonds());
        expectWellFormed(*shuffled);
        EXPECT_EQ(bondsById(*shuffled), truth);
        expectBondedLengths(*shuffled);
        osg::ref_ptr<PointData> ordered = frameOf(*byIndex, index);
        ASSERT_TRUE(ordered && ordered->getBonds());
        expectWellFormed(*ordered);
        EXPECT_EQ(bondsByIndex(*ordered), truth);
    }
    // Bonds that no step changes (pairs and ids fixed) are one list for every frame; pairs that
    // depend on time are read for each frame.
    EXPECT_EQ(frameOf(*byId, 1)->getBonds(), frameOf(*byId, 3)->getBonds());
    EXPECT_NE(frameOf(*byIndex, 1)->getBonds(), frameOf(*byIndex, 3)->getBonds());
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("/connectivity/angles: tuples of 3 particles, not bonds: left out"),
              std::string::npos)
        << warnings[0];
    // A share holds the bonds between its own particles.
    options.share = {1, 3};
    osg::ref_ptr<PointData> part = frameOf(*openFrames(bondData("polymer_indices.h5md"), options), 2);
    ASSERT_TRUE(part);
    expectShareHoldsItsOwnBonds(*part, options.share, 192, truth);
    // A file without connectivity lists no bonds.
    EXPECT_FALSE(frameOf(*openFrames(h5md("melt.h5md")), 0)->getBonds());
}

// Pairs that lie fail the frame with one line naming the file, the frame, the dataset and the pair.
TEST(H5md, ConnectivityThatLiesFailsNamingThePair)
{
    using namespace hdf5layout;
    const std::string bonds = "/connectivity/bonds";
    {
        // Ids 1 and 2, 3 and 4: the ids of frame 0; frame 1's particles have ids 5 to 8.
        Layout layout = smallH5md();
        layout[bonds] = {{2, 2}, Kind::Int, 1.0, 1.0};
        const std::string path = scratch("bonds_ids.h5md", layout);
        osg::ref_ptr<FrameSource> file = openFrames(path);
        ASSERT_TRUE(file);
        osg::ref_ptr<PointData> first = frameOf(*file, 0);
        ASSERT_TRUE(first && first->getBonds());
        EXPECT_EQ(first->getBonds()->size(), 2u);
        std::string error;
        EXPECT_FALSE(file->readFrame(1, error));
        EXPECT_EQ(error.rfind(path + ": ", 0), 0u) << error;
        EXPECT_NE(error.find("frame 1: dataset " + bonds +
                             ": pair 0 names id 1, which no particle of "
                             "/particles/all has"),
                  std::string::npos)
            << error;
        EXPECT_EQ(error.find('\n'), std::string::npos) << error;
    }
    Layout indices = smallH5md();
    for (const char* element : {"value", "step", "time"})
        indices.erase(std::string("/particles/all/id/") + element);
    {
        Layout layout = indices;
        layout[bonds] = {{2, 2}, Kind::Int, 1.0, 1.0}; // particles 1-2 and 3-4 of 0 to 3
        expectError(scratch("bonds_past.h5md", layout), bonds,
                    "pair 1 names particle 4, past the 4 particles", "0");
    }
    {
        Layout layout = indices;
        layout[bonds] = {{1, 2}, Kind::Int, 2.0, 0.0};
        expectError(scratch("bonds_self.h5md", layout), bonds, "pair 0 bonds particle 2 to itself", "0");
    }
    {
        Layout layout = indices;
        layout[bonds] = {{2, 2}, Kind::Int, -1.0, 1.0};
        expectError(scratch("bonds_negative.h5md", layout), bonds, "pair 0 names particle -1", "0");
    }
    {
        Layout layout = smallH5md();
        layout["/particles/all/id/value"] = {{3, 4}, Kind::Int, 1.0, 0.0}; // every particle id 1
        layout[bonds] = {{1, 2}, Kind::Int, 1.0, 0.0};
        expectError(scratch("bonds_twins.h5md", layout), "/particles/all/id/value",
                    "id 1 is held by rows 0 and 1", "0");
    }
}
