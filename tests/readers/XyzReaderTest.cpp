// XYZ and extended XYZ: frames, properties, species, lattice, and malformed frames.

#include "ReaderTestUtil.h"

#include <osgGlyphsData/Elements>

using namespace osgGlyphsData;
using namespace readertest;

namespace
{

osg::ref_ptr<PointDataset> readXyz(const std::string& text)
{
    std::string error;
    osg::ref_ptr<PointDataset> dataset = readString(text, "xyz", error, "in.xyz");
    EXPECT_TRUE(dataset.valid()) << error;
    return dataset.valid() ? dataset : osg::ref_ptr<PointDataset>(new PointDataset);
}

} // namespace

TEST(XyzReader, ReadsPlainXyzWithElements)
{
    osg::ref_ptr<PointDataset> dataset =
        readXyz("3\nwater\nO 0.0 0.0 0.1173\nH 0.0 0.7572 -0.4692\nh 0 -0.7572 -0.4692\n");
    ASSERT_EQ(dataset->getNumFrames(), 1u);
    const PointData& frame = *dataset->getFrame(0);
    ASSERT_EQ(frame.getColumnNames(), (std::vector<std::string>{"element", "species", "x", "y", "z"}));
    EXPECT_EQ(column(frame, "element"), (std::vector<float>{8.0f, 1.0f, 1.0f}));
    EXPECT_EQ(column(frame, "species"), (std::vector<float>{0.0f, 1.0f, 2.0f}));
    EXPECT_EQ(frame.getColumnLabels("species"), (std::vector<std::string>{"O", "H", "h"}));
    EXPECT_EQ(column(frame, "y"), (std::vector<float>{0.0f, 0.7572f, -0.7572f}));
    EXPECT_EQ(column(frame, "z"), (std::vector<float>{0.1173f, -0.4692f, -0.4692f}));
    EXPECT_FALSE(frame.hasBox());
}

TEST(XyzReader, NamesExtraPlainColumnsAndKeepsUnknownSpecies)
{
    osg::ref_ptr<PointDataset> dataset = readXyz("2\n\nXx 1 2 3 4 5\n6 1 2 3 4 5\n");
    const PointData& frame = *dataset->getFrame(0);
    ASSERT_EQ(frame.getColumnNames(),
              (std::vector<std::string>{"element", "species", "x", "y", "z", "column_5", "column_6"}));
    EXPECT_EQ(column(frame, "element"), (std::vector<float>{0.0f, 6.0f}));
    EXPECT_EQ(frame.getColumnLabels("species"), (std::vector<std::string>{"Xx", "6"}));
    EXPECT_EQ(column(frame, "column_6"), (std::vector<float>{5.0f, 5.0f}));
}

TEST(XyzReader, ReadsExtendedXyzProperties)
{
    osg::ref_ptr<PointDataset> dataset = readXyz(
        "2\nLattice=\"10 0 0 1 12 0 2 3 14\" Properties=species:S:1:pos:R:3:velo:R:3:Z:I:1:fixed:L:1:tag:S:1 "
        "step=42 pbc=\"T T T\"\n"
        "Cu 1 2 3 0.1 0.2 0.3 29 T alpha\n"
        "Fe 4 5 6 -0.1 -0.2 -0.3 26 F beta\n");
    const PointData& frame = *dataset->getFrame(0);
    ASSERT_EQ(frame.getColumnNames(), (std::vector<std::string>{"element", "species", "x", "y", "z", "velo_x",
                                                                "velo_y", "velo_z", "Z", "fixed", "tag"}));
    EXPECT_EQ(column(frame, "element"), (std::vector<float>{29.0f, 26.0f}));
    EXPECT_EQ(column(frame, "x"), (std::vector<float>{1.0f, 4.0f}));
    EXPECT_EQ(column(frame, "velo_z"), (std::vector<float>{0.3f, -0.3f}));
    EXPECT_EQ(column(frame, "Z"), (std::vector<float>{29.0f, 26.0f}));
    EXPECT_EQ(column(frame, "fixed"), (std::vector<float>{1.0f, 0.0f}));
    EXPECT_EQ(column(frame, "tag"), (std::vector<float>{0.0f, 1.0f}));
    EXPECT_EQ(frame.getColumnLabels("tag"), (std::vector<std::string>{"alpha", "beta"}));
    EXPECT_EQ(frame.getTimestep(), 42);
    ASSERT_TRUE(frame.hasBox());
    EXPECT_EQ(frame.getBox()._max, osg::Vec3d(10, 12, 14));
    EXPECT_EQ(frame.getTilt(), osg::Vec3d(1, 2, 3));
}

TEST(XyzReader, ReadsSeveralFrames)
{
    osg::ref_ptr<PointDataset> dataset = readXyz("1\nframe 1\nC 0 0 0\n2\nframe 2\nC 1 1 1\nN 2 2 2\n\n");
    ASSERT_EQ(dataset->getNumFrames(), 2u);
    EXPECT_EQ(dataset->getFrame(0)->getNumPoints(), 1u);
    EXPECT_EQ(dataset->getFrame(1)->getNumPoints(), 2u);
    EXPECT_EQ(dataset->getFrame(1)->getTimestep(), 1);
    EXPECT_EQ(column(*dataset->getFrame(1), "element"), (std::vector<float>{6.0f, 7.0f}));
    EXPECT_EQ(column(*dataset->getFrame(1), "x"), (std::vector<float>{1.0f, 2.0f}));
}

TEST(XyzReader, RejectsMalformedCountsAndTruncatedFrames)
{
    EXPECT_EQ(readError("three\nc\nH 0 0 0\n", "xyz", "bad.xyz"),
              "bad.xyz:1: not an XYZ file: expected the number of atoms of frame 1, found 'three'");
    EXPECT_EQ(readError("1\nc\nH 0 0 0\nx\n", "xyz", "bad.xyz"),
              "bad.xyz:4: expected the number of atoms of frame 2, found 'x'");
    EXPECT_EQ(readError("3\nc\nH 0.00 0.00 0.00\nH 1.00 1.00 1.00\n", "xyz", "bad.xyz"),
              "bad.xyz:4: unexpected end of file: frame 1 has 2 of 3 rows");
    EXPECT_EQ(readError("2\n", "xyz", "bad.xyz"),
              "bad.xyz:1: unexpected end of file, expected the comment line after the atom count");
    EXPECT_EQ(readError("999999999999\nc\nH 0 0 0\n", "xyz", "bad.xyz"),
              "bad.xyz:3: unexpected end of file: frame 1 has 1 of 999999999999 rows");
    EXPECT_EQ(readError("\n\n", "xyz", "bad.xyz"), "bad.xyz:2: no atoms: the file has only blank lines");
}

TEST(XyzReader, RejectsBadAtomLines)
{
    EXPECT_EQ(readError("2\nc\nH 0 0 0\nH 0.0 0.0\n", "xyz", "bad.xyz"),
              "bad.xyz:4: wrong number of columns: 3 fields, expected 4 (species x y z)");
    EXPECT_EQ(readError("1\nc\nH 0 0\n", "xyz", "bad.xyz"),
              "bad.xyz:3: an atom line needs at least 4 fields (species x y z), this one has 3");
    EXPECT_EQ(readError("1\nc\nH 0 nan 0\n", "xyz", "bad.xyz"),
              "bad.xyz:3: column 'y': 'nan' is not a finite number");
    EXPECT_EQ(readError("1\nProperties=species:S:1:pos:R:3:q:R:1\nH 0 0 0 charge\n", "xyz", "bad.xyz"),
              "bad.xyz:3: column 'q': 'charge' is not a number");
    EXPECT_EQ(readError("1\nProperties=species:S:1:pos:R:3:f:L:1\nH 0 0 0 maybe\n", "xyz", "bad.xyz"),
              "bad.xyz:3: column 'f': 'maybe' is not a logical value (T or F)");
}

TEST(XyzReader, RejectsBadProperties)
{
    EXPECT_EQ(readError("1\nProperties=species:S:1:pos:R\nH 0 0 0\n", "xyz", "bad.xyz"),
              "bad.xyz:2: Properties='species:S:1:pos:R' is not a list of name:type:count triples");
    EXPECT_EQ(readError("1\nProperties=species:S:1:pos:Q:3\nH 0 0 0\n", "xyz", "bad.xyz"),
              "bad.xyz:2: Properties: 'pos' has the type 'Q', expected S, R, I or L");
    EXPECT_EQ(readError("1\nProperties=pos:R:0\nH 0 0 0\n", "xyz", "bad.xyz"),
              "bad.xyz:2: Properties: 'pos' has the component count '0'");
    EXPECT_EQ(readError("1\nProperties=pos:R:3:x:R:1\n0 0 0 0\n", "xyz", "bad.xyz"),
              "bad.xyz:2: duplicate column 'x'");
    EXPECT_EQ(readError("1\nLattice=\"1 0 0 0 1\" Properties=pos:R:3\n0 0 0\n", "xyz", "bad.xyz"),
              "bad.xyz:2: Lattice='1 0 0 0 1' does not have 9 numbers");
}

// A file still being written: the complete frames load; the last, cut short, is left out with one
// warning naming the file, the line and the frame. A frame cut short before others is an error.
TEST(XyzReader, LeavesOutATruncatedLastFrame)
{
    const std::string complete = "2\nstep=10\nC 0 0 0\nO 1 1 1\n2\nstep=20\nC 0 0 1\nO 1 1 2\n";
    const std::string suffix = "; frame 3 is incomplete and left out";
    const std::vector<std::pair<std::string, std::string>> cuts = {
        {"2\n", "run.xyz:9: unexpected end of file, expected the comment line after the atom count"},
        {"2\nstep=30\nC 0 0 2\n", "run.xyz:11: unexpected end of file: frame 3 has 1 of 2 rows"},
        {"2\nstep=30\nC 0",
         "run.xyz:11: an atom line needs at least 4 fields (species x y z), this one has 2"},
    };
    for (const auto& cut : cuts)
    {
        std::vector<std::string> warnings;
        std::string error;
        osg::ref_ptr<PointDataset> dataset =
            readWithOptions(complete + cut.first, "xyz", PointReadOptions(), warnings, error, "run.xyz");
        ASSERT_TRUE(dataset.valid()) << error;
        ASSERT_EQ(dataset->getNumFrames(), 2u);
        EXPECT_EQ(dataset->getFrame(1)->getTimestep(), 20);
        EXPECT_EQ(warnings, std::vector<std::string>{cut.second + suffix});
        EXPECT_EQ(dataset->getEndOfCompleteFrames().offset, complete.size());
        EXPECT_EQ(dataset->getEndOfCompleteFrames().line, 8u);
    }
    EXPECT_EQ(readError(complete + "2\nstep=30\nC 0 0 2\n1\nc\nH 0 0 0\n", "xyz", "run.xyz"),
              "run.xyz:12: wrong number of columns: 1 fields, expected 4 (species x y z)");
}

// Empty frames are left out with one warning; a file of only empty frames has no atoms.
TEST(XyzReader, LeavesOutFramesWithoutAtoms)
{
    std::vector<std::string> warnings;
    std::string error;
    osg::ref_ptr<PointDataset> dataset = readWithOptions("0\n\n1\nstep=5\nC 0 0 0\n0\n\n0\nstep=7\n", "xyz",
                                                         PointReadOptions(), warnings, error, "gaps.xyz");
    ASSERT_TRUE(dataset.valid()) << error;
    ASSERT_EQ(dataset->getNumFrames(), 1u);
    EXPECT_EQ(dataset->getFrame(0)->getTimestep(), 5);
    EXPECT_EQ(warnings,
              std::vector<std::string>{"gaps.xyz:1: 3 frames without atoms left out, the first frame 1"});

    EXPECT_EQ(readError("0\n\n", "xyz", "none.xyz"), "none.xyz:1: no atoms: frame 1 is empty");
    EXPECT_EQ(readError("0\nProperties=species:S:1:pos:R:3\n0\n\n", "xyz", "none.xyz"),
              "none.xyz:1: no atoms: all 2 frames are empty");
}

// Properties that list more columns than the rows have: the rows are blamed, not the atom count.
TEST(XyzReader, BlamesRowsThatDoNotFitTheProperties)
{
    EXPECT_EQ(readError("3\nProperties=species:S:1:pos:R:3:charge:R:1:spin:R:1\nH 0 0 0\nH 1 1 1\n", "xyz",
                        "props.xyz"),
              "props.xyz:3: wrong number of columns: 4 fields, expected 6 (species x y z charge spin)");
}
