// LAMMPS text dumps: frames, boxes, scaled and triclinic coordinates, and malformed dumps.

#include "ReaderTestUtil.h"

using namespace osgGlyphsData;
using namespace readertest;

namespace
{

const char* const twoFrames = "ITEM: TIMESTEP\n"
                              "100\n"
                              "ITEM: NUMBER OF ATOMS\n"
                              "3\n"
                              "ITEM: BOX BOUNDS pp pp pp\n"
                              "0.0 10.0\n"
                              "-5.0 5.0\n"
                              "0.0 2.5e1\n"
                              "ITEM: ATOMS id type x y z vx vy vz c_pe\n"
                              "1 1 0.5 -1.25 3 0.1 0.2 0.3 -6.5\n"
                              "2 2 1.5 2.75 4e-1 -0.1 -0.2 -0.3 -7.25\n"
                              "3 1 9.5 4.5 24 0 0 0 -1e-3\n"
                              "ITEM: TIMESTEP\n"
                              "200\n"
                              "ITEM: NUMBER OF ATOMS\n"
                              "2\n"
                              "ITEM: BOX BOUNDS ff pp ss\n"
                              "1 11\n"
                              "-6 6\n"
                              "0 30\n"
                              "ITEM: ATOMS id type xu yu zu\n"
                              "2 2 12 0 1\n"
                              "1 1 -3 1 2\n";

osg::ref_ptr<PointDataset> readDump(const std::string& text)
{
    std::string error;
    osg::ref_ptr<PointDataset> dataset = readString(text, "lammps", error, "in.lammpstrj");
    EXPECT_TRUE(dataset.valid()) << error;
    return dataset.valid() ? dataset : osg::ref_ptr<PointDataset>(new PointDataset);
}

// A one-frame dump with the given box item and lines, and columns of atoms.
std::string dump(const std::string& boxItem, const std::string& boxLines, const std::string& columns,
                 const std::string& atoms, const std::string& count = "1")
{
    return "ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n" + count + "\nITEM: BOX BOUNDS " + boxItem + "\n" +
           boxLines + "ITEM: ATOMS " + columns + "\n" + atoms;
}

const std::string cube = "0 1\n0 1\n0 1\n";

} // namespace

TEST(LammpsReader, ReadsFramesWithTimestepsBoxesAndColumns)
{
    osg::ref_ptr<PointDataset> dataset = readDump(twoFrames);
    ASSERT_EQ(dataset->getNumFrames(), 2u);
    EXPECT_EQ(dataset->getFormat(), "lammps");
    const PointData& first = *dataset->getFrame(0);
    EXPECT_EQ(first.getTimestep(), 100);
    ASSERT_EQ(first.getColumnNames(),
              (std::vector<std::string>{"id", "type", "x", "y", "z", "vx", "vy", "vz", "c_pe"}));
    EXPECT_EQ(column(first, "id"), (std::vector<float>{1, 2, 3}));
    EXPECT_EQ(column(first, "type"), (std::vector<float>{1, 2, 1}));
    EXPECT_EQ(column(first, "y"), (std::vector<float>{-1.25f, 2.75f, 4.5f}));
    EXPECT_EQ(column(first, "z"), (std::vector<float>{3.0f, 0.4f, 24.0f}));
    EXPECT_EQ(column(first, "c_pe"), (std::vector<float>{-6.5f, -7.25f, -0.001f}));
    ASSERT_TRUE(first.hasBox());
    EXPECT_EQ(first.getBox()._min, osg::Vec3d(0, -5, 0));
    EXPECT_EQ(first.getBox()._max, osg::Vec3d(10, 5, 25));
    EXPECT_FALSE(first.isTriclinic());

    const PointData& second = *dataset->getFrame(1);
    EXPECT_EQ(second.getTimestep(), 200);
    EXPECT_EQ(second.getNumPoints(), 2u);
    EXPECT_EQ(second.getBox()._min, osg::Vec3d(1, -6, 0));
    std::vector<osg::Vec3f> positions;
    std::string error;
    ASSERT_TRUE(getPositions(second, {}, positions, error)) << error;
    EXPECT_EQ(positions[1], osg::Vec3f(-3, 1, 2));
}

TEST(LammpsReader, ConvertsScaledCoordinates)
{
    osg::ref_ptr<PointDataset> dataset =
        readDump(dump("pp pp pp", "-2 2\n0 10\n5 6\n", "id type xs ys zs", "1 1 0.25 0.5 1\n"));
    std::vector<osg::Vec3f> positions;
    std::string error;
    ASSERT_TRUE(getPositions(*dataset->getFrame(0), {}, positions, error)) << error;
    EXPECT_EQ(positions[0], osg::Vec3f(-1, 5, 6));
}

TEST(LammpsReader, ConvertsTriclinicBoundsAndScaledCoordinates)
{
    // LAMMPS writes the bounding box of the tilted cell: xlo_bound = xlo + min(0, xy, xz, xy + xz), ...
    // The cell here: xlo 0, xhi 10, ylo 0, yhi 8, zlo 0, zhi 6; xy 2, xz -1, yz 0.5.
    osg::ref_ptr<PointDataset> dataset = readDump(dump("xy xz yz pp pp pp", "-1 12 2\n0 8.5 -1\n0 6 0.5\n",
                                                       "id xs ys zs", "1 0.5 0.5 0.5\n2 1 1 1\n", "2"));
    const PointData& frame = *dataset->getFrame(0);
    ASSERT_TRUE(frame.hasBox());
    EXPECT_EQ(frame.getBox()._min, osg::Vec3d(0, 0, 0));
    EXPECT_EQ(frame.getBox()._max, osg::Vec3d(10, 8, 6));
    EXPECT_EQ(frame.getTilt(), osg::Vec3d(2, -1, 0.5));
    std::vector<osg::Vec3f> positions;
    std::string error;
    ASSERT_TRUE(getPositions(frame, {}, positions, error)) << error;
    EXPECT_EQ(positions[0], osg::Vec3f(5 + 1 - 0.5f, 4 + 0.25f, 3));
    EXPECT_EQ(positions[1], osg::Vec3f(10 + 2 - 1, 8 + 0.5f, 6));
}

TEST(LammpsReader, ReadsElementColumnsOldDumpsAndExtraItems)
{
    osg::ref_ptr<PointDataset> dataset = readDump("ITEM: UNITS\nmetal\nITEM: TIME\n0.5\n" +
                                                  dump("pp pp pp", cube, "id element x y z", "1 Cu 0 0 0\n"));
    const PointData& frame = *dataset->getFrame(0);
    ASSERT_EQ(frame.getColumnNames(), (std::vector<std::string>{"id", "element", "species", "x", "y", "z"}));
    EXPECT_EQ(column(frame, "element"), (std::vector<float>{29.0f}));
    EXPECT_EQ(frame.getColumnLabels("species"), (std::vector<std::string>{"Cu"}));

    osg::ref_ptr<PointDataset> old = readDump(dump("", cube, "", "1 1 0.1 0.2 0.3\n2 1 0.4 0.5 0.6\n", "2"));
    ASSERT_EQ(old->getFrame(0)->getColumnNames(), (std::vector<std::string>{"id", "type", "xs", "ys", "zs"}));
    EXPECT_EQ(column(*old->getFrame(0), "zs"), (std::vector<float>{0.3f, 0.6f}));
}

TEST(LammpsReader, ToleratesWindowsLineEndsAndBlankLines)
{
    std::string text = twoFrames;
    std::string crlf;
    for (char c : text)
        crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
    osg::ref_ptr<PointDataset> dataset = readDump(crlf + "\r\n\r\n");
    ASSERT_EQ(dataset->getNumFrames(), 2u);
    EXPECT_EQ(column(*dataset->getFrame(0), "c_pe"), (std::vector<float>{-6.5f, -7.25f, -0.001f}));
}

TEST(LammpsReader, RejectsTruncatedDumps)
{
    const std::string text = twoFrames;
    EXPECT_EQ(readError(text.substr(0, text.find("3 1 9.5")), "lammps", "cut.lammpstrj"),
              "cut.lammpstrj:11: unexpected end of file: ITEM: ATOMS has 2 of 3 rows");
    EXPECT_EQ(readError(text.substr(0, text.find("-5.0 5.0")), "lammps", "cut.lammpstrj"),
              "cut.lammpstrj:6: unexpected end of file, expected the y bounds of ITEM: BOX BOUNDS");
    EXPECT_EQ(readError(text.substr(0, text.find("2 2 1.5")), "lammps", "cut.lammpstrj"),
              "cut.lammpstrj:10: unexpected end of file: ITEM: ATOMS has 1 of 3 rows");
    EXPECT_EQ(
        readError(text.substr(0, text.find("1 1 0.5") + 10), "lammps", "cut.lammpstrj"),
        "cut.lammpstrj:10: wrong number of columns: 4 fields, expected 9 (id type x y z vx vy vz c_pe)");
    std::string shortLine = text;
    shortLine.replace(shortLine.find("2 2 1.5 2.75 4e-1"), 17, "2 2 1.5 2.75");
    EXPECT_EQ(
        readError(shortLine, "lammps", "short.lammpstrj"),
        "short.lammpstrj:11: wrong number of columns: 8 fields, expected 9 (id type x y z vx vy vz c_pe)");
}

// A dump that a simulation is still writing: the complete frames load; the frame being written is
// left out with one warning naming the file, the line and the frame.
TEST(LammpsReader, LeavesOutATruncatedLastFrame)
{
    const std::string text = twoFrames;
    const std::string suffix = "; frame 2 is incomplete and left out";
    const std::vector<std::pair<std::size_t, std::string>> cuts = {
        {text.find("ITEM: NUMBER OF ATOMS\n2"),
         "cut.lammpstrj:14: unexpected end of file: the last timestep has no ITEM: ATOMS section"},
        {text.find("-6 6"),
         "cut.lammpstrj:18: unexpected end of file, expected the y bounds of ITEM: BOX BOUNDS"},
        {text.find("1 1 -3"), "cut.lammpstrj:22: unexpected end of file: ITEM: ATOMS has 1 of 2 rows"},
        {text.find("1 1 -3") + 4,
         "cut.lammpstrj:23: wrong number of columns: 2 fields, expected 5 (id type xu yu zu)"},
        {text.find("2 2 12") + 3,
         "cut.lammpstrj:22: wrong number of columns: 2 fields, expected 5 (id type xu yu zu)"},
    };
    for (const auto& cut : cuts)
    {
        std::vector<std::string> warnings;
        std::string error;
        osg::ref_ptr<PointDataset> dataset = readWithOptions(
            text.substr(0, cut.first), "lammps", PointReadOptions(), warnings, error, "cut.lammpstrj");
        ASSERT_TRUE(dataset.valid()) << error;
        ASSERT_EQ(dataset->getNumFrames(), 1u);
        EXPECT_EQ(dataset->getFrame(0)->getTimestep(), 100);
        EXPECT_EQ(warnings, std::vector<std::string>{cut.second + suffix});
        EXPECT_EQ(dataset->getWarnings(), warnings);
        const PointStreamPosition end = dataset->getEndOfCompleteFrames();
        EXPECT_EQ(end.offset, text.find("ITEM: TIMESTEP\n200"));
        EXPECT_EQ(end.line, 12u);
        EXPECT_EQ(end.frame, 1u);
    }
}

// A frame cut short with more frames after it is a malformed file, not one still being written.
TEST(LammpsReader, RejectsATruncatedFrameBeforeOthers)
{
    std::string text = twoFrames;
    text.erase(text.find("1 1 -3"));
    text += "ITEM: TIMESTEP\n300\nITEM: NUMBER OF ATOMS\n1\nITEM: ATOMS id x y z\n1 0 0 0\n";
    EXPECT_EQ(readError(text, "lammps", "cut.lammpstrj"),
              "cut.lammpstrj:23: 'ITEM: TIMESTEP' after 1 of 2 rows of ITEM: ATOMS");
}

// Reading a growing dump again from where its complete frames ended gets the frames it gained.
TEST(LammpsReader, ResumesAGrowingDumpAfterItsCompleteFrames)
{
    const std::string text = twoFrames;
    PointReadOptions options;
    options.growing = true;
    std::vector<std::string> warnings;
    std::string error;
    osg::ref_ptr<PointDataset> first = readWithOptions(text.substr(0, text.find("1 1 -3")), "lammps", options,
                                                       warnings, error, "run.lammpstrj");
    ASSERT_TRUE(first.valid()) << error;
    ASSERT_EQ(first->getNumFrames(), 1u);

    options.start = first->getEndOfCompleteFrames();
    osg::ref_ptr<PointDataset> second = readWithOptions(text.substr(options.start.offset), "lammps", options,
                                                        warnings, error, "run.lammpstrj");
    ASSERT_TRUE(second.valid()) << error;
    ASSERT_EQ(second->getNumFrames(), 1u);
    EXPECT_EQ(second->getFrame(0)->getTimestep(), 200);
    EXPECT_EQ(column(*second->getFrame(0), "xu"), (std::vector<float>{12.0f, -3.0f}));
    EXPECT_EQ(second->getEndOfCompleteFrames().offset, text.size());
    EXPECT_EQ(second->getEndOfCompleteFrames().line, 23u);
    EXPECT_EQ(second->getEndOfCompleteFrames().frame, 2u);

    // Nothing new yet: no frame, and no error.
    options.start = second->getEndOfCompleteFrames();
    osg::ref_ptr<PointDataset> none =
        readWithOptions("", "lammps", options, warnings, error, "run.lammpstrj");
    ASSERT_TRUE(none.valid()) << error;
    EXPECT_EQ(none->getNumFrames(), 0u);
    EXPECT_EQ(none->getEndOfCompleteFrames(), options.start);

    // Messages count the lines on from the start.
    EXPECT_EQ(readWithOptions("ITEM: TIMESTEP\nabc\n", "lammps", options, warnings, error, "run.lammpstrj"),
              nullptr);
    EXPECT_EQ(error, "run.lammpstrj:25: ITEM: TIMESTEP: 'abc' is not an integer timestep");
}

// Of a dump still being written, a last line without its end may be half a line: "1 1 -3 1 2" of
// "1 1 -3 1 25". A file read as it is keeps such a line; one read as growing leaves its frame out.
TEST(LammpsReader, LeavesOutAFrameWhoseLastLineHasNoEndOfAGrowingDump)
{
    const std::string text = std::string(twoFrames).substr(0, std::string(twoFrames).size() - 1);
    std::vector<std::string> warnings;
    std::string error;
    osg::ref_ptr<PointDataset> dataset =
        readWithOptions(text, "lammps", PointReadOptions(), warnings, error, "run.lammpstrj");
    ASSERT_TRUE(dataset.valid()) << error;
    EXPECT_EQ(dataset->getNumFrames(), 2u);
    EXPECT_TRUE(warnings.empty());

    PointReadOptions growing;
    growing.growing = true;
    dataset = readWithOptions(text, "lammps", growing, warnings, error, "run.lammpstrj");
    ASSERT_TRUE(dataset.valid()) << error;
    EXPECT_EQ(dataset->getNumFrames(), 1u);
    // Expected of a growing file: described, not warned about.
    EXPECT_TRUE(warnings.empty());
    EXPECT_EQ(dataset->getIncompleteFrame(),
              "run.lammpstrj:23: the last line has no end yet: frame 2 is incomplete and left out");
    EXPECT_EQ(dataset->getEndOfCompleteFrames().line, 12u);
}

// Frames without atoms cost memory and show nothing: they are left out, with one warning.
TEST(LammpsReader, LeavesOutFramesWithoutAtoms)
{
    const std::string empty = "ITEM: TIMESTEP\n150\nITEM: NUMBER OF ATOMS\n0\nITEM: ATOMS id x y z\n";
    std::string text = twoFrames;
    text.insert(text.find("ITEM: TIMESTEP\n200"), empty + empty);
    std::vector<std::string> warnings;
    std::string error;
    osg::ref_ptr<PointDataset> dataset =
        readWithOptions(text, "lammps", PointReadOptions(), warnings, error, "gaps.lammpstrj");
    ASSERT_TRUE(dataset.valid()) << error;
    ASSERT_EQ(dataset->getNumFrames(), 2u);
    EXPECT_EQ(dataset->getFrame(1)->getTimestep(), 200);
    EXPECT_EQ(warnings, std::vector<std::string>{
                            "gaps.lammpstrj:13: 2 frames without atoms left out, the first frame 2"});
    EXPECT_EQ(dataset->getEndOfCompleteFrames().frame, 4u);

    EXPECT_EQ(readError(empty + empty, "lammps", "empty.lammpstrj"),
              "empty.lammpstrj:1: no atoms: all 2 frames are empty");
}

TEST(LammpsReader, RejectsCountsLargerThanTheData)
{
    EXPECT_EQ(readError(dump("pp pp pp", cube, "id x y z", "1 0 0 0\nITEM: TIMESTEP\n1\n", "3"), "lammps",
                        "a.dump"),
              "a.dump:11: 'ITEM: TIMESTEP' after 1 of 3 rows of ITEM: ATOMS");
    EXPECT_EQ(readError(dump("pp pp pp", cube, "id x y z", "1 0 0 0\n", "999999999999"), "lammps", "a.dump"),
              "a.dump:10: unexpected end of file: ITEM: ATOMS has 1 of 999999999999 rows");
    EXPECT_EQ(readError(dump("pp pp pp", cube, "id", "1\n", "-4"), "lammps", "a.dump"),
              "a.dump:4: ITEM: NUMBER OF ATOMS: '-4' is not a count");
}

TEST(LammpsReader, RejectsBadFieldsNamingTheColumn)
{
    EXPECT_EQ(readError(dump("pp pp pp", cube, "id type x y z", "1 1 0 nan 0\n"), "lammps", "a.dump"),
              "a.dump:10: column 'y': 'nan' is not a finite number");
    EXPECT_EQ(readError(dump("pp pp pp", cube, "id type x y z", "1 1 0 0 INF\n"), "lammps", "a.dump"),
              "a.dump:10: column 'z': 'INF' is not a finite number");
    EXPECT_EQ(readError(dump("pp pp pp", cube, "id type x y z", "1 C 0 0 0\n"), "lammps", "a.dump"),
              "a.dump:10: column 'type': 'C' is not a number");
    EXPECT_EQ(readError(dump("pp pp pp", cube, "id type x y z", "1 1 0 0 0 7\n"), "lammps", "a.dump"),
              "a.dump:10: wrong number of columns: 6 fields, expected 5 (id type x y z)");
    EXPECT_EQ(readError(dump("pp pp pp", cube, "id x x", "1 0 0\n"), "lammps", "a.dump"),
              "a.dump:9: duplicate column 'x'");
}

TEST(LammpsReader, RejectsBadItems)
{
    EXPECT_EQ(readError("hello\n", "lammps", "a.dump"),
              "a.dump:1: not a LAMMPS dump: expected 'ITEM: TIMESTEP', found 'hello'");
    EXPECT_EQ(readError("ITEM: TIMESTEP\nten\n", "lammps", "a.dump"),
              "a.dump:2: ITEM: TIMESTEP: 'ten' is not an integer timestep");
    EXPECT_EQ(readError("ITEM: TIMESTEP\n1\nITEM: ATOMS id\n1\n", "lammps", "a.dump"),
              "a.dump:3: ITEM: ATOMS before ITEM: NUMBER OF ATOMS");
    EXPECT_EQ(readError("ITEM: TIMESTEP\n1\nITEM: BONDS\n", "lammps", "a.dump"),
              "a.dump:3: unknown item 'ITEM: BONDS'");
    EXPECT_EQ(readError(dump("pp pp pp", "0 1\n0 x\n0 1\n", "id", "1\n"), "lammps", "a.dump"),
              "a.dump:7: y bounds of ITEM: BOX BOUNDS: 'x' is not a finite number");
    EXPECT_EQ(readError(dump("pp pp pp", "0 1\n0 1 2\n0 1\n", "id", "1\n"), "lammps", "a.dump"),
              "a.dump:7: y bounds of ITEM: BOX BOUNDS: 3 numbers, expected 2 (lo hi)");
    EXPECT_EQ(readError(dump("abc origin pp pp pp", cube, "id", "1\n"), "lammps", "a.dump"),
              "a.dump:5: ITEM: BOX BOUNDS abc origin (general triclinic boxes) is not supported");
    EXPECT_EQ(readError(dump("pp pp pp", cube, "id", "1\n") + "garbage\n", "lammps", "a.dump"),
              "a.dump:11: expected an 'ITEM:' line, found 'garbage'");
}
