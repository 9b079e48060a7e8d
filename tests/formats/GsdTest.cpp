/* GSD: gsd.hoomd's file of the melt against the LAMMPS dump it was written from, a triclinic box and
 * the per-particle quantities against the values written (gsd/write_gsd.py), the 1.0 file layer,
 * chunks taken from frame 0, shares, cut files and files that lie. */

#include "FormatTestData.h"

#include <cstring>

using namespace formattest;
using namespace osgGlyphsData;

namespace
{

const double MELT_BOX = 8.3979809569125372;

std::string gsdPath(const std::string& name)
{
    return dataPath("gsd/" + name);
}

/** An entry of a GSD file's index, where it lies, and its chunk's name. */
struct Entry
{
    std::size_t at;
    uint64_t frame, rows;
    int64_t location;
    uint32_t columns;
    uint16_t id;
    uint8_t type;
    std::string name;
};

template <typename T>
T valueAt(const std::string& bytes, std::size_t at)
{
    T value;
    std::memcpy(&value, bytes.data() + at, sizeof(T));
    return value;
}

template <typename T>
std::string withValue(std::string bytes, std::size_t at, T value)
{
    std::memcpy(&bytes[at], &value, sizeof(T));
    return bytes;
}

/** The index of a GSD 2.x file, read by the specification. */
std::vector<Entry> readIndex(const std::string& bytes)
{
    const std::size_t indexAt = valueAt<uint64_t>(bytes, 8), namesAt = valueAt<uint64_t>(bytes, 24);
    std::vector<std::string> names;
    for (std::size_t at = namesAt; bytes[at] != '\0'; at += names.back().size() + 1)
        names.push_back(std::string(bytes.c_str() + at));
    std::vector<Entry> entries;
    for (std::size_t at = indexAt; valueAt<int64_t>(bytes, at + 16) != 0; at += 32)
    {
        Entry entry{at,
                    valueAt<uint64_t>(bytes, at),
                    valueAt<uint64_t>(bytes, at + 8),
                    valueAt<int64_t>(bytes, at + 16),
                    valueAt<uint32_t>(bytes, at + 24),
                    valueAt<uint16_t>(bytes, at + 28),
                    valueAt<uint8_t>(bytes, at + 30),
                    ""};
        entry.name = names.at(entry.id);
        entries.push_back(entry);
    }
    return entries;
}

/** The frame's entry of that chunk; fails the test when there is none. */
Entry findEntry(const std::vector<Entry>& entries, uint64_t frame, const std::string& name)
{
    for (const Entry& entry : entries)
    {
        if (entry.frame == frame && entry.name == name)
            return entry;
    }
    ADD_FAILURE() << "no " << name << " in frame " << frame;
    return Entry{};
}

bool hasEntry(const std::vector<Entry>& entries, uint64_t frame, const std::string& name)
{
    for (const Entry& entry : entries)
    {
        if (entry.frame == frame && entry.name == name)
            return true;
    }
    return false;
}

/** Expects a column to hold the values of f(point). */
template <typename F>
void expectValues(const PointData& data, const std::string& name, F f, double tolerance = 1e-6)
{
    ASSERT_TRUE(data.hasColumn(name)) << name;
    const int column = data.findColumn(name);
    for (std::size_t i = 0; i < data.getNumPoints(); ++i)
        EXPECT_NEAR(data.getValue(std::size_t(column), i), f(double(i)), tolerance) << name << " of " << i;
}

std::vector<std::string> labels(std::initializer_list<const char*> names)
{
    return std::vector<std::string>(names.begin(), names.end());
}

}

TEST(Gsd, MeltFramesAreTheDumpsFramesInHoomdsCentredBox)
{
    osg::ref_ptr<FrameSource> dump = openFrames(dataPath("melt.lammpstrj"));
    osg::ref_ptr<FrameSource> gsd = openFrames(gsdPath("melt.gsd"));
    ASSERT_TRUE(dump && gsd);
    EXPECT_EQ(gsd->getFormat(), "gsd");
    ASSERT_EQ(gsd->getNumFrames(), 6u);
    for (std::size_t frame = 0; frame < 6; ++frame)
    {
        SCOPED_TRACE("frame " + std::to_string(frame));
        osg::ref_ptr<PointData> want = frameOf(*dump, frame);
        osg::ref_ptr<PointData> got = frameOf(*gsd, frame);
        ASSERT_TRUE(want && got);
        ASSERT_EQ(got->getNumPoints(), 500u);
        EXPECT_EQ(got->getColumnNames(),
                  std::vector<std::string>({"x", "y", "z", "species", "vx", "vy", "vz"}));
        // The dump's six digits, moved by half the box and stored as float32.
        for (const char* axis : {"x", "y", "z"})
        {
            const int w = want->findColumn(axis), g = got->findColumn(axis);
            for (std::size_t i = 0; i < 500; ++i)
                ASSERT_NEAR(got->getValue(g, i), want->getValue(w, i) - MELT_BOX / 2, 1e-6) << axis << i;
        }
        for (const char* velocity : {"vx", "vy", "vz"})
            expectColumnMatches(*want, *got, velocity, 1e-6);
        // Types 1 and 2 of the dump are type ids 0 and 1, named A and B (frame 0's, in every frame).
        const int type = want->findColumn("type"), species = got->findColumn("species");
        for (std::size_t i = 0; i < 500; ++i)
            ASSERT_EQ(got->getValue(species, i), want->getValue(type, i) - 1) << i;
        EXPECT_EQ(got->getColumnLabels("species"), labels({"A", "B"}));
        EXPECT_EQ(got->getTimestep(), want->getTimestep());
        EXPECT_EQ(gsd->getFrameInfo(frame).timestep, want->getTimestep());
        EXPECT_EQ(gsd->getFrameInfo(frame).points, 500u);
        EXPECT_EQ(got->getFilePointCount(), 500u);
        ASSERT_TRUE(got->hasBox());
        EXPECT_FALSE(got->isTriclinic());
        EXPECT_NEAR(got->getBox().xMin(), -MELT_BOX / 2, 1e-6);
        EXPECT_NEAR(got->getBox().yMax(), MELT_BOX / 2, 1e-6);
        EXPECT_NEAR(got->getBox().zMax() - got->getBox().zMin(), MELT_BOX, 1e-6);
    }
}

TEST(Gsd, ChunksAFrameOmitsComeFromFrameZero)
{
    // The writer left them out of frames 1 to 5 (they equal frame 0's), and frame 0 has no step.
    const std::vector<Entry> index = readIndex(readBytes(gsdPath("melt.gsd")));
    EXPECT_FALSE(hasEntry(index, 0, "configuration/step"));
    for (uint64_t frame = 1; frame < 6; ++frame)
    {
        for (const char* name : {"particles/typeid", "particles/types", "particles/N", "configuration/box"})
            EXPECT_FALSE(hasEntry(index, frame, name)) << name << " in " << frame;
        EXPECT_TRUE(hasEntry(index, frame, "particles/position"));
    }
    // shapes.gsd: frame 1 has 4 particles, so frame 0's diameters and orientations (6 particles) do
    // not apply: the schema's defaults do; frame 2 has 6 again and takes frame 0's.
    osg::ref_ptr<FrameSource> shapes = openFrames(gsdPath("shapes.gsd"));
    ASSERT_TRUE(shapes);
    osg::ref_ptr<PointData> first = frameOf(*shapes, 1);
    ASSERT_TRUE(first);
    ASSERT_EQ(first->getNumPoints(), 4u);
    expectValues(*first, "diameter", [](double) { return 1.0; });
    expectValues(*first, "quatw", [](double) { return 1.0; });
    expectValues(*first, "quatk", [](double) { return 0.0; });
    expectValues(*first, "mass", [](double i) { return 1.0 + i; });
    osg::ref_ptr<PointData> second = frameOf(*shapes, 2);
    ASSERT_TRUE(second);
    ASSERT_EQ(second->getNumPoints(), 6u);
    expectValues(*second, "diameter", [](double i) { return 0.5 + 0.25 * i; });
    expectValues(*second, "quatk", [](double i) { return std::sin(0.125 * i); });
    expectValues(*second, "x", [](double i) { return i - 2.5 + 200.0; });
    EXPECT_EQ(second->getTimestep(), 200);
    EXPECT_NEAR(second->getBox().xMin(), -5.0, 0.0);
}

TEST(Gsd, PerParticleQuantitiesAreTheValuesWritten)
{
    for (const char* name : {"shapes.gsd", "shapes_v1.gsd"})
    {
        SCOPED_TRACE(name);
        osg::ref_ptr<FrameSource> shapes = openFrames(gsdPath(name));
        ASSERT_TRUE(shapes);
        osg::ref_ptr<PointData> frame = frameOf(*shapes, 0);
        ASSERT_TRUE(frame);
        ASSERT_EQ(frame->getNumPoints(), 6u);
        EXPECT_EQ(frame->getColumnNames(), std::vector<std::string>({"x",
                                                                     "y",
                                                                     "z",
                                                                     "species",
                                                                     "quatw",
                                                                     "quati",
                                                                     "quatj",
                                                                     "quatk",
                                                                     "angmomw",
                                                                     "angmomi",
                                                                     "angmomj",
                                                                     "angmomk",
                                                                     "ix",
                                                                     "iy",
                                                                     "iz",
                                                                     "mass",
                                                                     "charge",
                                                                     "diameter",
                                                                     "body",
                                                                     "moment_inertia_x",
                                                                     "moment_inertia_y",
                                                                     "moment_inertia_z"}));
        expectValues(*frame, "x", [](double i) { return i - 2.5; });
        expectValues(*frame, "y", [](double i) { return 0.5 * i; });
        expectValues(*frame, "z", [](double i) { return -0.25 * i; });
        expectValues(
            *frame, "species", [](double i) { return std::fmod(i, 3.0); }, 0.0);
        EXPECT_EQ(frame->getColumnLabels("species"), labels({"E1", "E2", "E3"}));
        expectValues(*frame, "quatw", [](double i) { return std::cos(0.125 * i); });
        expectValues(*frame, "quati", [](double) { return 0.0; });
        expectValues(*frame, "quatk", [](double i) { return std::sin(0.125 * i); });
        expectValues(*frame, "angmomi", [](double i) { return i; });
        expectValues(*frame, "angmomk", [](double i) { return -i; });
        expectValues(
            *frame, "ix", [](double i) { return i - 3.0; }, 0.0);
        expectValues(
            *frame, "iy", [](double i) { return -i; }, 0.0);
        expectValues(
            *frame, "iz", [](double) { return 7.0; }, 0.0);
        expectValues(*frame, "mass", [](double i) { return 1.0 + i; });
        expectValues(*frame, "charge", [](double i) { return -1.0 + 0.5 * i; });
        expectValues(*frame, "diameter", [](double i) { return 0.5 + 0.25 * i; });
        expectValues(
            *frame, "body", [](double i) { return i < 2 ? -1.0 : std::floor(i / 2); }, 0.0);
        expectValues(*frame, "moment_inertia_x", [](double i) { return i; });
        expectValues(*frame, "moment_inertia_z", [](double i) { return 3.0 * i; });
        EXPECT_EQ(frame->getTimestep(), 0);
        osg::ref_ptr<PointData> later = frameOf(*shapes, 1);
        ASSERT_TRUE(later);
        expectValues(*later, "y", [](double i) { return 0.5 * i + 100.0; });
        EXPECT_EQ(later->getTimestep(), 100);
    }
}

TEST(Gsd, TriclinicBoxIsHoomdsCentredCell)
{
    osg::ref_ptr<FrameSource> gsd = openFrames(gsdPath("triclinic.gsd"));
    ASSERT_TRUE(gsd);
    osg::ref_ptr<PointData> frame = frameOf(*gsd, 0);
    ASSERT_TRUE(frame && frame->hasBox());
    // The box written: Lx 4, Ly 5, Lz 6, xy 0.5, xz -0.25, yz 0.125; tilts times Ly, Lz and Lz; the
    // corner at -(a1 + a2 + a3) / 2.
    EXPECT_TRUE(frame->isTriclinic());
    EXPECT_NEAR((frame->getTilt() - osg::Vec3d(2.5, -1.5, 0.75)).length(), 0.0, 1e-12);
    EXPECT_NEAR((frame->getBox()._min - osg::Vec3d(-2.5, -2.875, -3.0)).length(), 0.0, 1e-12);
    EXPECT_NEAR((frame->getBox()._max - osg::Vec3d(1.5, 2.125, 3.0)).length(), 0.0, 1e-12);
    // Each particle sits where the box's fractional coordinates put it (HOOMD's makeCoordinates).
    ASSERT_EQ(frame->getNumPoints(), 8u);
    for (std::size_t i = 0; i < 8; ++i)
    {
        const osg::Vec3d fraction((i & 1) * 0.5 + 0.25, ((i >> 1) & 1) * 0.5 + 0.25,
                                  ((i >> 2) & 1) * 0.5 + 0.125);
        const osg::Vec3d expected = frame->scaledToCartesian(fraction);
        const osg::Vec3d got(frame->getValue(0, i), frame->getValue(1, i), frame->getValue(2, i));
        EXPECT_NEAR((got - expected).length(), 0.0, 1e-6) << i;
        EXPECT_EQ(frame->getValue(std::size_t(frame->findColumn("species")), i), double(i % 2));
    }
    EXPECT_EQ(frame->getColumnLabels("species"), labels({"solvent", "colloid"}));
    EXPECT_EQ(frame->getTimestep(), 12345678901);
    EXPECT_FALSE(frame->hasColumn("diameter"));
}

TEST(Gsd, FramesReadInAnyOrderAreTheSame)
{
    osg::ref_ptr<FrameSource> gsd = openFrames(gsdPath("melt.gsd"));
    ASSERT_TRUE(gsd);
    osg::ref_ptr<PointData> late = frameOf(*gsd, 5);
    osg::ref_ptr<PointData> early = frameOf(*gsd, 1);
    osg::ref_ptr<PointData> lateAgain = frameOf(*gsd, 5);
    ASSERT_TRUE(late && early && lateAgain);
    for (const char* column : {"x", "vz", "species"})
        expectColumnMatches(*late, *lateAgain, column, 0.0);
    EXPECT_NE(late->getValue(0, 0), early->getValue(0, 0));
    EXPECT_EQ(late->getTimestep(), 100);
    EXPECT_EQ(early->getTimestep(), 20);
}

TEST(Gsd, SharesTogetherAreTheWholeFrame)
{
    for (const char* name : {"melt.gsd", "shapes.gsd"})
    {
        SCOPED_TRACE(name);
        osg::ref_ptr<PointData> whole = frameOf(*openFrames(gsdPath(name)), 2);
        ASSERT_TRUE(whole);
        std::vector<std::vector<float>> joined(whole->getNumColumns());
        for (unsigned int index = 0; index < 4; ++index)
        {
            FrameSourceOptions options;
            options.share = {index, 4};
            osg::ref_ptr<PointData> part = frameOf(*openFrames(gsdPath(name), options), 2);
            ASSERT_TRUE(part);
            ASSERT_EQ(part->getColumnNames(), whole->getColumnNames());
            EXPECT_EQ(part->getFilePointCount(), whole->getNumPoints());
            for (std::size_t column = 0; column < joined.size(); ++column)
            {
                const std::vector<float>& values = *part->getColumn(column);
                joined[column].insert(joined[column].end(), values.begin(), values.end());
            }
        }
        for (std::size_t column = 0; column < joined.size(); ++column)
            EXPECT_EQ(joined[column], *whole->getColumn(column)) << whole->getColumnNames()[column];
    }
}

TEST(Gsd, AFileCutShortLosesItsLastFramesWithAWarning)
{
    const std::string bytes = readBytes(gsdPath("melt.gsd"));
    const std::vector<Entry> index = readIndex(bytes);
    const Entry velocity4 = findEntry(index, 4, "particles/velocity");
    const Entry velocity5 = findEntry(index, 5, "particles/velocity");
    const struct
    {
        std::size_t size, frames;
        std::string place, lost;
    } cuts[] = {
        {bytes.size() - 100, 5, "frame 5: byte " + std::to_string(velocity5.at) + ": 'particles/velocity'",
         "frame 5 is left out"},
        {std::size_t(velocity4.location) + 10, 4,
         "frame 4: byte " + std::to_string(velocity4.at) + ": 'particles/velocity'",
         "frames 4 to 5 are left out"},
    };
    for (const auto& cut : cuts)
    {
        SCOPED_TRACE(cut.size);
        const std::string path = writeScratchFile("cut.gsd", bytes.substr(0, cut.size));
        FrameSourceOptions options;
        std::vector<std::string> warnings;
        options.warning = [&warnings](const std::string& warning) { warnings.push_back(warning); };
        osg::ref_ptr<FrameSource> gsd = openFrames(path, options);
        ASSERT_TRUE(gsd);
        EXPECT_EQ(gsd->getNumFrames(), cut.frames);
        ASSERT_EQ(warnings.size(), 1u);
        EXPECT_NE(warnings.front().find(path), std::string::npos) << warnings.front();
        EXPECT_NE(warnings.front().find("cut short"), std::string::npos) << warnings.front();
        EXPECT_NE(warnings.front().find(cut.place), std::string::npos) << warnings.front();
        EXPECT_NE(warnings.front().find(cut.lost), std::string::npos) << warnings.front();
        EXPECT_TRUE(frameOf(*gsd, cut.frames - 1).valid());
    }
}

namespace
{

/** A file's bytes, and what its error must say. */
struct BadFile
{
    std::string name, bytes, expected;
};

/** Expects each file, written to the scratch file of that name (one per test: tests run side by
 * side), to fail with one line naming its path and saying what is expected. */
void expectOneLineErrors(const std::vector<BadFile>& cases, const std::string& scratchName)
{
    for (const BadFile& bad : cases)
    {
        SCOPED_TRACE(bad.name);
        const std::string path = writeScratchFile(scratchName, bad.bytes);
        const std::string error = firstError(path);
        EXPECT_NE(error.find(path), std::string::npos) << error;
        EXPECT_NE(error.find(bad.expected), std::string::npos) << error;
        EXPECT_EQ(error.find('\n'), std::string::npos) << error;
    }
}

}

TEST(Gsd, FilesThatLieFailNamingTheFileFrameAndByte)
{
    const std::string good = readBytes(gsdPath("melt.gsd"));
    const std::vector<Entry> index = readIndex(good);
    const Entry position0 = findEntry(index, 0, "particles/position");
    const Entry position2 = findEntry(index, 2, "particles/position");
    const Entry position3 = findEntry(index, 3, "particles/position");
    const Entry position4 = findEntry(index, 4, "particles/position");
    const Entry velocity1 = findEntry(index, 1, "particles/velocity");
    const Entry count0 = findEntry(index, 0, "particles/N");
    const Entry typeid0 = findEntry(index, 0, "particles/typeid");
    const Entry box0 = findEntry(index, 0, "configuration/box");
    const Entry last = index.back();
    const std::size_t nanAt = std::size_t(position2.location) + (7 * 3 + 1) * 4;
    const auto at = [](const Entry& entry) { return "byte " + std::to_string(entry.at) + ": "; };

    const std::vector<BadFile> cases = {
        {"empty", "", "the file is empty"},
        {"short", good.substr(0, 100), "shorter than the 256-byte header"},
        {"not gsd", std::string(300, 'x'), "not a GSD file"},
        {"version 3", withValue<uint32_t>(good, 44, 3u << 16), "byte 44: GSD file layer version 3.0"},
        {"other schema", withValue<char>(good, 112, 'H'), "byte 112: the schema is 'Hoomd', not hoomd"},
        {"index cut", good.substr(0, 2000), "byte 8: the index of 128 x 32 bytes at byte 256"},
        {"index past the end", withValue<uint64_t>(good, 8, good.size() - 64), "does not lie between"},
        {"chunk past the end", withValue<int64_t>(good, position2.at + 16, int64_t(1) << 40),
         "frame 2: " + at(position2) +
             "'particles/position' (6000 bytes at byte 1099511627776) runs past the end"},
        {"rows lie", withValue<uint64_t>(good, position3.at + 8, 499),
         "frame 3: " + at(position3) + "'particles/position' holds 499 x 3 values, not 500 x 3"},
        {"N lies", withValue<uint32_t>(good, std::size_t(count0.location), 501),
         "frame 0: " + at(position0) + "'particles/position' holds 500 x 3 values, not 501 x 3"},
        {"unknown type", withValue<uint8_t>(good, velocity1.at + 30, 12),
         "frame 1: " + at(velocity1) + "'particles/velocity' has type 12, not a GSD type"},
        {"characters", withValue<uint8_t>(good, position4.at + 30, 11),
         "frame 4: " + at(position4) + "'particles/position' holds char values, not numbers"},
        {"bad name id", withValue<uint16_t>(good, last.at + 28, 200),
         "frame 5: " + at(last) + "index entry names name 200, the name list holds 7"},
        {"frames out of order", withValue<uint64_t>(good, last.at, 0), "frame 0: " + at(last)},
        {"absurd frame", withValue<uint64_t>(good, last.at, uint64_t(1) << 40), "past the 128 entries"},
        {"twice in a frame", withValue<uint64_t>(good, position3.at, 2),
         "frame 2: " + at(position3) + "'particles/position' appears twice"},
        {"nan", withValue<float>(good, nanAt, std::nanf("")),
         "frame 2: byte " + std::to_string(nanAt) + ": y of particle 7 is not a finite number"},
        {"type id past the types", withValue<uint32_t>(good, std::size_t(typeid0.location) + 4 * 10, 5),
         "byte " + std::to_string(typeid0.location + 40) +
             ": particle 10 has type id 5, particles/types names 2"},
        {"negative box", withValue<float>(good, std::size_t(box0.location) + 4, -1.0f),
         "frame 0: byte " + std::to_string(box0.location) + ": configuration/box is not a box"},
    };
    expectOneLineErrors(cases, "bad.gsd");
}

// The bonds of the GSD the gsd package wrote of the polymer (tests/data/bonds/make_gsd.py), lying.
TEST(Gsd, BondsThatLieFailNamingTheFileFrameAndByte)
{
    const std::string good = readBytes(dataPath("../bonds/polymer.gsd"));
    const std::vector<Entry> index = readIndex(good);
    const Entry group = findEntry(index, 0, "bonds/group");
    const Entry count = findEntry(index, 0, "bonds/N");
    ASSERT_EQ(group.rows, 180u);
    const std::size_t bond5 = std::size_t(group.location) + 2 * 5 * 4;
    const std::vector<BadFile> cases = {
        {"past the particles", withValue<int32_t>(good, bond5 + 4, 192),
         "frame 0: byte " + std::to_string(bond5) +
             ": bonds/group: bond 5 joins particle 192, not one of the frame's 192 (particles/N)"},
        {"negative", withValue<int32_t>(good, bond5, -3), "bond 5 joins particle -3"},
        {"to itself", withValue<int32_t>(good, bond5 + 4, valueAt<int32_t>(good, bond5)),
         "byte " + std::to_string(bond5) + ": bonds/group: bond 5 joins particle " +
             std::to_string(valueAt<int32_t>(good, bond5)) + " to itself"},
        {"N lies", withValue<uint32_t>(good, std::size_t(count.location), 181),
         "frame 0: byte " + std::to_string(group.at) +
             ": bonds/group holds 180 x 2 int32 values, not 181 x 2 particle indices"},
    };
    expectOneLineErrors(cases, "bad_bonds.gsd");
}

// ellipsoids.gsd (write_ellipsoids.py): the Gay-Berne liquid LAMMPS wrote, its type's shape an
// Ellipsoid in particles/type_shapes. The reader gives LAMMPS's columns: the diameters along the body
// axes, and the turns, particle by particle as the dump has them (by id).
TEST(Gsd, EllipsoidTypeShapesAreTheDumpsEllipsoids)
{
    osg::ref_ptr<FrameSource> dump = openFrames(dataPath("../lammps/ellipsoids/dump.ellipsoids"));
    osg::ref_ptr<FrameSource> gsd = openFrames(gsdPath("ellipsoids.gsd"));
    ASSERT_TRUE(dump && gsd);
    ASSERT_EQ(gsd->getNumFrames(), dump->getNumFrames());
    for (std::size_t frame : {0u, 3u})
    {
        SCOPED_TRACE("frame " + std::to_string(frame));
        osg::ref_ptr<PointData> want = frameOf(*dump, frame);
        osg::ref_ptr<PointData> got = frameOf(*gsd, frame);
        ASSERT_TRUE(want && got);
        ASSERT_EQ(got->getNumPoints(), 144u);
        const std::vector<float>& ids = *want->getColumn("id");
        for (std::size_t row = 0; row < ids.size(); ++row)
        {
            const std::size_t particle = static_cast<std::size_t>(ids[row]) - 1;
            for (const char* column : {"shapex", "shapey", "shapez", "quatw", "quati", "quatj", "quatk"})
            {
                ASSERT_TRUE(got->getColumn(column)) << column;
                ASSERT_NEAR((*got->getColumn(column))[particle], (*want->getColumn(column))[row], 1e-6)
                    << column << " of atom id " << ids[row];
            }
        }
    }
    // A file without Ellipsoids in its type_shapes has no shape columns.
    EXPECT_FALSE(frameOf(*openFrames(gsdPath("shapes.gsd")), 0)->getColumn("shapex"));
}

TEST(Gsd, TypeShapesThatLieFailNamingTheFileFrameAndByte)
{
    const std::string good = readBytes(gsdPath("ellipsoids.gsd"));
    const Entry shapes = findEntry(readIndex(good), 0, "particles/type_shapes");
    const std::size_t at = std::size_t(shapes.location);
    const std::string text = good.substr(at, std::size_t(shapes.columns));
    const std::size_t a = at + text.find("1.5");
    const std::string where =
        "frame 0: byte " + std::to_string(at) + ": particles/type_shapes of type 'GB': ";
    const std::vector<BadFile> cases = {
        {"negative", withValue<char>(withValue<char>(good, a, '-'), a + 1, '1'),
         where + "an Ellipsoid's \"a\" is '-15', not a finite number > 0"},
        {"not a number", withValue<char>(good, a, 'x'), where + "an Ellipsoid's \"a\" is 'x.5'"},
        {"not an object", withValue<char>(good, at, '['), where + "not a JSON object at character 0"},
        {"cut", withValue<char>(good, at + text.find('}'), ' '), where + "no ',' or '}' after the value"},
    };
    expectOneLineErrors(cases, "bad_shapes.gsd");
}
