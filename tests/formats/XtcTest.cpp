/* XTC and TRR: the files MDAnalysis and GROMACS's trjconv wrote (tests/data/formats/xtc,
 * make_xtc.sh) against the LAMMPS dump they came from, or the formula of the made-up points; both
 * XTC paths (9 atoms as floats, more compressed, with integers over 24 bits), single and double
 * TRR; any order, shares, cut files and files that lie. */

#include "FormatTestData.h"

#include <cstring>
#include <limits>

using namespace formattest;
using namespace osgGlyphsData;

namespace
{

/** Positions of the melt in the files: the dump's LJ lengths read as Angstrom, written in nm. */
const double NM = 0.1;
/** Half the last digit of XTC's precision (1000 per nm), and float rounding of values below 1 nm. */
const double XTC_TOLERANCE = 0.5e-3 + 1e-6;
const double BOX = 0.83979809569125372;

std::string xtcPath(const std::string& name)
{
    return dataPath("xtc/" + name);
}

osg::ref_ptr<FrameSource> melt()
{
    return openFrames(dataPath("melt.lammpstrj"));
}

uint32_t readWord(const std::string& bytes, std::size_t at)
{
    uint32_t value = 0;
    for (int i = 0; i < 4; ++i)
        value = (value << 8) | static_cast<unsigned char>(bytes[at + std::size_t(i)]);
    return value;
}

void writeWord(std::string& bytes, std::size_t at, uint32_t value)
{
    for (int i = 3; i >= 0; --i, value >>= 8)
        bytes[at + std::size_t(i)] = static_cast<char>(value & 0xff);
}

template <typename Real>
void writeReal(std::string& bytes, std::size_t at, Real value)
{
    unsigned char raw[sizeof(Real)];
    std::memcpy(raw, &value, sizeof(Real));
    for (std::size_t i = 0; i < sizeof(Real); ++i)
        bytes[at + i] = static_cast<char>(raw[sizeof(Real) - 1 - i]);
}

/** Where each frame of a compressed XTC (more than 9 atoms) starts. */
std::vector<std::size_t> xtcFrames(const std::string& bytes)
{
    std::vector<std::size_t> frames;
    for (std::size_t at = 0; at + 92 <= bytes.size(); at += 92 + (readWord(bytes, at + 88) + 3) / 4 * 4)
        frames.push_back(at);
    return frames;
}

/** Where each frame of a TRR starts, and the size of its header (76 + time and lambda). */
std::vector<std::size_t> trrFrames(const std::string& bytes, std::size_t real)
{
    std::vector<std::size_t> frames;
    for (std::size_t at = 0; at + 76 <= bytes.size();)
    {
        frames.push_back(at);
        std::size_t size = 76 + 2 * real;
        for (int block = 0; block < 10; ++block)
            size += readWord(bytes, at + 24 + 4 * std::size_t(block));
        at += size;
    }
    return frames;
}

/** Expects the first atoms of frame to be the dump frame's, the named dump columns scaled. */
void expectAtomsMatch(const PointData& dump, const PointData& frame,
                      const std::vector<std::string>& dumpColumns, const std::vector<std::string>& columns,
                      double factor, double tolerance)
{
    ASSERT_LE(frame.getNumPoints(), dump.getNumPoints());
    for (std::size_t c = 0; c < columns.size(); ++c)
    {
        const int want = dump.findColumn(dumpColumns[c]);
        const int got = frame.findColumn(columns[c]);
        ASSERT_TRUE(want >= 0 && got >= 0) << columns[c];
        std::size_t wrong = 0;
        for (std::size_t i = 0; i < frame.getNumPoints(); ++i)
        {
            const double expected = dump.getValue(std::size_t(want), i) * factor;
            const double actual = frame.getValue(std::size_t(got), i);
            if (!(std::fabs(expected - actual) <= tolerance) && wrong++ < 3)
                ADD_FAILURE() << columns[c] << " of atom " << i + 1 << ": " << actual << ", expected "
                              << expected;
        }
        EXPECT_EQ(wrong, 0u) << columns[c];
    }
}

void expectCubicBox(const PointData& frame, double edge)
{
    ASSERT_TRUE(frame.hasBox());
    EXPECT_FALSE(frame.isTriclinic());
    EXPECT_NEAR(frame.getBox().xMin(), 0.0, 1e-9);
    EXPECT_NEAR(frame.getBox().xMax() - frame.getBox().xMin(), edge, 1e-6);
    EXPECT_NEAR(frame.getBox().yMax() - frame.getBox().yMin(), edge, 1e-6);
    EXPECT_NEAR(frame.getBox().zMax() - frame.getBox().zMin(), edge, 1e-6);
}

/** Every frame of the file against the dump: the named columns, the step and the time (0.1 ps a
 * frame), the box. */
void expectMeltFrames(const std::string& path, const std::vector<std::string>& dumpColumns,
                      const std::vector<std::string>& columns, const std::vector<double>& factors,
                      double tolerance, const std::vector<int64_t>& steps, std::size_t atoms)
{
    SCOPED_TRACE(path);
    osg::ref_ptr<FrameSource> dump = melt();
    osg::ref_ptr<FrameSource> file = openFrames(path);
    ASSERT_TRUE(dump && file);
    ASSERT_EQ(file->getNumFrames(), 6u);
    for (std::size_t frame = 0; frame < 6; ++frame)
    {
        SCOPED_TRACE("frame " + std::to_string(frame));
        osg::ref_ptr<PointData> want = frameOf(*dump, frame);
        osg::ref_ptr<PointData> got = frameOf(*file, frame);
        ASSERT_TRUE(want && got);
        ASSERT_EQ(got->getNumPoints(), atoms);
        EXPECT_EQ(got->getFilePointCount(), atoms);
        for (std::size_t c = 0; c < columns.size(); ++c)
            expectAtomsMatch(*want, *got, {dumpColumns[c]}, {columns[c]}, factors[c], tolerance);
        const FrameInfo info = file->getFrameInfo(frame);
        EXPECT_EQ(info.timestep, steps[frame]);
        EXPECT_EQ(got->getTimestep(), steps[frame]);
        EXPECT_TRUE(info.hasTime);
        EXPECT_NEAR(info.time, 0.1 * double(frame), 1e-6);
        expectCubicBox(*got, BOX);
    }
}

const std::vector<int64_t> DUMP_STEPS = {0, 20, 40, 60, 80, 100};
const std::vector<int64_t> FRAME_STEPS = {0, 1, 2, 3, 4, 5};
const std::vector<std::string> POSITIONS = {"x", "y", "z"};
const std::vector<std::string> ALL = {"x", "y", "z", "vx", "vy", "vz", "fx", "fy", "fz"};
const std::vector<std::string> DUMP_ALL = {"x", "y", "z", "vx", "vy", "vz", "vx", "vy", "vz"};
/** The files' forces are minus the dump's velocities (write_xtc.py). */
const std::vector<double> TRR_FACTORS = {NM, NM, NM, NM, NM, NM, -1.0, -1.0, -1.0};

/** The made-up points of scatter.xtc (write_xtc.py), in nm. */
double scatterPosition(int64_t atom, int axis, int64_t frame)
{
    const int64_t molecule = atom / 3;
    const double h =
        double((molecule * 2654435761LL + axis * 40503LL + frame * 97LL) % 1000003LL) / 1000003.0;
    const double centre = molecule % 400 == 7 ? h * 20000.0 : h * 20.0;
    const double offsets[3][3] = {{0.0, 0.0, 0.0}, {0.0957, 0.0, 0.0}, {-0.024, 0.0927, 0.0}};
    return centre + offsets[atom % 3][axis];
}

/** The error of reading every frame of bytes written to a scratch file. */
std::string errorOf(const std::string& name, const std::string& bytes, std::string& path)
{
    path = writeScratchFile(name, bytes);
    return firstError(path);
}

struct Lie
{
    std::string name, bytes, expected;
};

void expectErrors(const std::string& extension, const std::vector<Lie>& lies)
{
    for (const Lie& lie : lies)
    {
        SCOPED_TRACE(lie.name);
        std::string path;
        const std::string error = errorOf("bad." + extension, lie.bytes, path);
        EXPECT_NE(error.find(path), std::string::npos) << error;
        EXPECT_NE(error.find(lie.expected), std::string::npos) << error;
        EXPECT_EQ(error.find('\n'), std::string::npos) << error;
    }
}

std::vector<std::string> warningsOf(const std::string& path, std::size_t& frames)
{
    FrameSourceOptions options;
    std::vector<std::string> warnings;
    options.warning = [&warnings](const std::string& warning) { warnings.push_back(warning); };
    osg::ref_ptr<FrameSource> source = openFrames(path, options);
    frames = source ? source->getNumFrames() : 0;
    return warnings;
}

std::vector<float> joinedShares(const std::string& path, std::size_t frame, const std::string& column)
{
    std::vector<float> joined;
    for (unsigned int index = 0; index < 3; ++index)
    {
        FrameSourceOptions options;
        options.share = {index, 3};
        osg::ref_ptr<FrameSource> source = openFrames(path, options);
        osg::ref_ptr<PointData> part = source ? frameOf(*source, frame) : nullptr;
        if (!part || !part->hasColumn(column))
        {
            ADD_FAILURE() << column << " of share " << index;
            return joined;
        }
        const std::vector<float>& values = *part->getColumn(column);
        joined.insert(joined.end(), values.begin(), values.end());
    }
    return joined;
}

}

TEST(Xtc, MDAnalysisAndGromacsFramesAreTheDumpsFrames)
{
    // MDAnalysis writes the frame's index as its step; trjconv keeps the TRR's steps.
    expectMeltFrames(xtcPath("melt.xtc"), POSITIONS, POSITIONS, {NM, NM, NM}, XTC_TOLERANCE, FRAME_STEPS,
                     500);
    expectMeltFrames(xtcPath("melt_gmx.xtc"), POSITIONS, POSITIONS, {NM, NM, NM}, XTC_TOLERANCE, DUMP_STEPS,
                     500);
    osg::ref_ptr<FrameSource> xtc = openFrames(xtcPath("melt.xtc"));
    ASSERT_TRUE(xtc);
    EXPECT_EQ(xtc->getFormat(), "xtc");
}

TEST(Xtc, NineAtomsAreStoredAsFloats)
{
    // Up to 9 atoms, XTC stores the floats themselves: float precision, not 1/1000.
    expectMeltFrames(xtcPath("melt9.xtc"), POSITIONS, POSITIONS, {NM, NM, NM}, 1e-6, FRAME_STEPS, 9);
}

TEST(Xtc, LargeIntegersAndMoleculesAreTheFormulasPoints)
{
    const std::string bytes = readBytes(xtcPath("scatter.xtc"));
    ASSERT_GE(bytes.size(), 92u);
    // The points span more than 2^24 integers on an axis: each integer is sent on its own.
    EXPECT_GT(int64_t(int32_t(readWord(bytes, 72))) - int32_t(readWord(bytes, 60)), 0xffffff);
    osg::ref_ptr<FrameSource> xtc = openFrames(xtcPath("scatter.xtc"));
    ASSERT_TRUE(xtc);
    ASSERT_EQ(xtc->getNumFrames(), 2u);
    for (std::size_t frame = 0; frame < 2; ++frame)
    {
        SCOPED_TRACE("frame " + std::to_string(frame));
        osg::ref_ptr<PointData> data = frameOf(*xtc, frame);
        ASSERT_TRUE(data);
        ASSERT_EQ(data->getNumPoints(), 3000u);
        EXPECT_NEAR(xtc->getFrameInfo(frame).time, 2.5 * double(frame), 1e-6);
        expectCubicBox(*data, 20.0);
        std::size_t wrong = 0;
        for (std::size_t atom = 0; atom < 3000; ++atom)
        {
            for (int axis = 0; axis < 3; ++axis)
            {
                const double want = scatterPosition(int64_t(atom), axis, int64_t(frame));
                // Float rounding of the writer's input, of position * precision, of the output.
                const double tolerance =
                    0.5e-3 + 4.0 * std::fabs(want) * std::numeric_limits<float>::epsilon();
                const double got = data->getValue(std::size_t(axis), atom);
                if (!(std::fabs(got - want) <= tolerance) && wrong++ < 3)
                    ADD_FAILURE() << "axis " << axis << " of atom " << atom + 1 << ": " << got
                                  << ", expected " << want;
            }
        }
        EXPECT_EQ(wrong, 0u);
    }
}

TEST(Xtc, FramesReadInAnyOrderAreTheSame)
{
    for (const char* name : {"melt.xtc", "scatter.xtc", "melt9.xtc"})
    {
        SCOPED_TRACE(name);
        osg::ref_ptr<FrameSource> xtc = openFrames(xtcPath(name));
        ASSERT_TRUE(xtc);
        std::vector<osg::ref_ptr<PointData>> inOrder;
        for (std::size_t frame = 0; frame < xtc->getNumFrames(); ++frame)
            inOrder.push_back(frameOf(*xtc, frame));
        const std::size_t last = xtc->getNumFrames() - 1;
        for (std::size_t frame : {last, std::size_t(1), last, std::size_t(0)})
        {
            osg::ref_ptr<PointData> again = frameOf(*openFrames(xtcPath(name)), frame);
            ASSERT_TRUE(again && inOrder[frame]);
            for (const std::string& axis : POSITIONS)
                expectColumnMatches(*inOrder[frame], *again, axis, 0.0);
        }
        EXPECT_NE(inOrder[last]->getValue(0, 0), inOrder[0]->getValue(0, 0));
    }
}

TEST(Xtc, SharesTogetherAreTheWholeFrame)
{
    for (const char* name : {"melt.xtc", "melt9.xtc"})
    {
        SCOPED_TRACE(name);
        osg::ref_ptr<PointData> whole = frameOf(*openFrames(xtcPath(name)), 2);
        ASSERT_TRUE(whole);
        for (const std::string& axis : POSITIONS)
            EXPECT_EQ(joinedShares(xtcPath(name), 2, axis), *whole->getColumn(axis)) << axis;
    }
}

TEST(Xtc, TheWideByteCountOfGromacs2023ReadsTheSame)
{
    // Magic 2023: the byte count takes 8 bytes; the frames are otherwise the same.
    const std::string bytes = readBytes(xtcPath("melt.xtc"));
    std::string wide;
    const std::vector<std::size_t> frames = xtcFrames(bytes);
    ASSERT_EQ(frames.size(), 6u);
    for (std::size_t i = 0; i < frames.size(); ++i)
    {
        const std::size_t end = i + 1 < frames.size() ? frames[i + 1] : bytes.size();
        std::string frame = bytes.substr(frames[i], end - frames[i]);
        writeWord(frame, 0, 2023);
        frame.insert(88, std::string(4, '\0'));
        wide += frame;
    }
    osg::ref_ptr<FrameSource> reference = openFrames(xtcPath("melt.xtc"));
    osg::ref_ptr<FrameSource> other = openFrames(writeScratchFile("wide.xtc", wide));
    ASSERT_TRUE(reference && other);
    expectPositionsMatch(*reference, *other, 0.0);
}

TEST(Xtc, ALastFrameCutShortIsLeftOutWithAWarning)
{
    const std::string bytes = readBytes(xtcPath("melt.xtc"));
    const std::size_t last = xtcFrames(bytes).back();
    for (std::size_t keep : {bytes.size() - 100, last + 20, last + 90})
    {
        SCOPED_TRACE(keep);
        std::size_t frames = 0;
        const std::vector<std::string> warnings =
            warningsOf(writeScratchFile("cut.xtc", bytes.substr(0, keep)), frames);
        EXPECT_EQ(frames, 5u);
        ASSERT_EQ(warnings.size(), 1u);
        EXPECT_NE(warnings.front().find("frame 5: byte " + std::to_string(last)), std::string::npos)
            << warnings.front();
        EXPECT_NE(warnings.front().find("cut short"), std::string::npos) << warnings.front();
    }
}

TEST(Xtc, FilesThatLieFailNamingTheFileFrameAndByte)
{
    const std::string good = readBytes(xtcPath("melt.xtc"));
    const std::vector<std::size_t> frames = xtcFrames(good);
    ASSERT_EQ(frames.size(), 6u);
    const std::size_t one = frames[1], two = frames[2];
    auto with = [&good](std::size_t at, uint32_t value)
    {
        std::string bytes = good;
        writeWord(bytes, at, value);
        return bytes;
    };
    auto withBoth = [&with](std::size_t frame, uint32_t atoms)
    {
        std::string bytes = with(frame + 4, atoms);
        writeWord(bytes, frame + 52, atoms);
        return bytes;
    };
    const uint32_t count = readWord(good, one + 88);
    std::string noise = good;
    std::fill(noise.begin() + std::ptrdiff_t(one + 92), noise.begin() + std::ptrdiff_t(one + 100), '\xff');
    const std::string b = ": byte ";
    const std::string at1 = "frame 1" + b, at2 = "frame 2" + b;
    const std::vector<Lie> lies = {
        {"empty", "", "empty"},
        {"not xtc", std::string(200, 'x'), "not an XTC file"},
        {"magic", with(two, 1996), at2 + std::to_string(two) + ": the magic number is 1996"},
        {"atoms", with(one + 4, 499), at1 + std::to_string(one + 52) + ": the atom count before"},
        // The run of small differences that would pass atom 499 starts at byte 3897.
        {"both atom counts fewer", withBoth(one, 499),
         at1 + "3897: atom 494: a run of 6 atoms goes past the frame's 499"},
        {"both atom counts more", withBoth(one, 501),
         at1 + std::to_string(one + 92 + count) + ": the compressed coordinates end before atom 501"},
        {"negative atoms", with(one + 4, uint32_t(-3)),
         at1 + std::to_string(one + 4) + ": the atom count is -3"},
        {"byte count longer", with(one + 88, count + 8),
         at2 + std::to_string(two + 8) + ": the magic number"},
        {"byte count absurd", with(one + 88, 1u << 30), at1 + std::to_string(one + 88) + ": the compressed"},
        {"precision", with(one + 56, 0), at1 + std::to_string(one + 56) + ": the precision is 0"},
        {"range", with(one + 72, uint32_t(-5)), at1 + std::to_string(one + 56) + ": the range of axis 0"},
        {"small index", with(one + 84, 8), at1 + std::to_string(one + 56) + ": the size index"},
        {"noise", noise, at1 + std::to_string(one + 92) + ": atom 1 lies beyond the frame's range"},
    };
    expectErrors("xtc", lies);

    std::string nine = readBytes(xtcPath("melt9.xtc"));
    const std::size_t frame9 = 56 + 12 * 9;
    writeReal(nine, frame9 + 56 + 4 * 7, std::numeric_limits<float>::quiet_NaN());
    expectErrors("xtc", {{"nan", nine,
                          at1 + std::to_string(frame9 + 56 + 28) + ": y of atom 3 is not a finite number"}});
}

TEST(Trr, MDAnalysisAndGromacsFramesAreTheDumpsFrames)
{
    // Single precision from MDAnalysis; double from gmx_d trjconv (its first 100 atoms).
    expectMeltFrames(xtcPath("melt.trr"), DUMP_ALL, ALL, TRR_FACTORS, 1e-6 * 5, DUMP_STEPS, 500);
    expectMeltFrames(xtcPath("melt9.trr"), DUMP_ALL, ALL, TRR_FACTORS, 1e-6 * 5, DUMP_STEPS, 9);
    const std::string gmx = readBytes(xtcPath("melt_gmx_d.trr"));
    ASSERT_GE(gmx.size(), 76u);
    EXPECT_EQ(readWord(gmx, 32), 72u) << "a box of 9 doubles";
    expectMeltFrames(xtcPath("melt_gmx_d.trr"), DUMP_ALL, ALL, TRR_FACTORS, 1e-6 * 5, DUMP_STEPS, 100);
    osg::ref_ptr<FrameSource> trr = openFrames(xtcPath("melt.trr"));
    ASSERT_TRUE(trr);
    EXPECT_EQ(trr->getFormat(), "trr");
}

TEST(Trr, FramesReadInAnyOrderAreTheSameAndSharesJoin)
{
    for (const char* name : {"melt.trr", "melt_gmx_d.trr"})
    {
        SCOPED_TRACE(name);
        osg::ref_ptr<FrameSource> trr = openFrames(xtcPath(name));
        ASSERT_TRUE(trr);
        std::vector<osg::ref_ptr<PointData>> inOrder;
        for (std::size_t frame = 0; frame < trr->getNumFrames(); ++frame)
            inOrder.push_back(frameOf(*trr, frame));
        for (std::size_t frame : {5, 1, 5, 0})
        {
            osg::ref_ptr<PointData> again = frameOf(*openFrames(xtcPath(name)), frame);
            ASSERT_TRUE(again && inOrder[frame]);
            for (const std::string& column : ALL)
                expectColumnMatches(*inOrder[frame], *again, column, 0.0);
        }
        for (const std::string& column : ALL)
            EXPECT_EQ(joinedShares(xtcPath(name), 3, column), *inOrder[3]->getColumn(column)) << column;
    }
}

TEST(Trr, ALastFrameCutShortIsLeftOutWithAWarning)
{
    const std::string bytes = readBytes(xtcPath("melt.trr"));
    const std::size_t last = trrFrames(bytes, 4).back();
    for (std::size_t keep : {bytes.size() - 100, last + 20, last + 80})
    {
        SCOPED_TRACE(keep);
        std::size_t frames = 0;
        const std::vector<std::string> warnings =
            warningsOf(writeScratchFile("cut.trr", bytes.substr(0, keep)), frames);
        EXPECT_EQ(frames, 5u);
        ASSERT_EQ(warnings.size(), 1u);
        EXPECT_NE(warnings.front().find("frame 5: byte " + std::to_string(last)), std::string::npos)
            << warnings.front();
        EXPECT_NE(warnings.front().find("cut short"), std::string::npos) << warnings.front();
    }
}

TEST(Trr, FramesWithoutPositionsAreLeftOutWithAWarning)
{
    // Frame 0 as if written with velocities and forces only: its x block taken out.
    const std::string good = readBytes(xtcPath("melt.trr"));
    const std::size_t x = 84 + 36;
    std::string bytes = good.substr(0, x) + good.substr(x + 6000);
    writeWord(bytes, 52, 0);
    std::size_t count = 0;
    const std::string path = writeScratchFile("nox.trr", bytes);
    const std::vector<std::string> warnings = warningsOf(path, count);
    EXPECT_EQ(count, 5u);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings.front().find("frame 0: byte 0: 1 frames without positions"), std::string::npos)
        << warnings.front();
    osg::ref_ptr<FrameSource> trr = openFrames(path);
    ASSERT_TRUE(trr);
    EXPECT_EQ(trr->getFrameInfo(0).fileFrame, 1u);
    EXPECT_EQ(trr->getFrameInfo(0).timestep, 20);
    osg::ref_ptr<PointData> first = frameOf(*trr, 0);
    osg::ref_ptr<PointData> dump = frameOf(*melt(), 1);
    ASSERT_TRUE(first && dump);
    expectAtomsMatch(*dump, *first, {"x"}, {"x"}, NM, 1e-6);
}

TEST(Trr, FilesThatLieFailNamingTheFileFrameAndByte)
{
    const std::string good = readBytes(xtcPath("melt.trr"));
    const std::vector<std::size_t> frames = trrFrames(good, 4);
    ASSERT_EQ(frames.size(), 6u);
    const std::size_t one = frames[1], two = frames[2];
    auto with = [&good](std::size_t at, uint32_t value)
    {
        std::string bytes = good;
        writeWord(bytes, at, value);
        return bytes;
    };
    // Frame 1: header 84 bytes, box 36, then x, v, f of 6000 bytes each.
    const std::size_t x = one + 84 + 36, v = x + 6000;
    std::string nanX = good, nanV = good;
    writeReal(nanX, x + 4 * (3 * 7), std::numeric_limits<float>::quiet_NaN());
    writeReal(nanV, v + 4 * (3 * 2 + 1), std::numeric_limits<float>::infinity());
    std::string version = good;
    version[one + 14] = 'Y';
    const std::string b = ": byte ";
    const std::string at1 = "frame 1" + b;
    const std::vector<Lie> lies = {
        {"empty", "", "empty"},
        {"not trr", std::string(200, 'x'), "not a TRR file"},
        {"xtc", readBytes(xtcPath("melt.xtc")), "not a TRR file: it starts with 1995"},
        {"magic", with(two, 1995), "frame 2" + b + std::to_string(two) + ": the magic number is 1995"},
        {"version", version, at1 + std::to_string(one + 4) + ": the version"},
        {"atoms", with(one + 64, 499),
         at1 + std::to_string(one + 52) + ": the block 'x' announces 6000 bytes"},
        {"x size", with(one + 52, 6004), at1 + std::to_string(one + 52) + ": the block 'x' announces 6004"},
        {"no precision", with(one + 32, 40),
         at1 + std::to_string(one + 24) + ": the block sizes give no precision"},
        {"energies", with(one + 28, 16), at1 + std::to_string(one + 28) + ": the frame holds a block 'e'"},
        {"negative atoms", with(one + 64, uint32_t(-1)),
         at1 + std::to_string(one + 64) + ": the atom count is -1"},
        {"nan x", nanX, at1 + std::to_string(x + 84) + ": x of atom 8 is not a finite number"},
        {"infinite vy", nanV, at1 + std::to_string(v + 28) + ": vy of atom 3 is not a finite number"},
    };
    expectErrors("trr", lies);
}
