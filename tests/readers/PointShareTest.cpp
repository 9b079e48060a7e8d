/* Reading and generating one share of a dataset (osgGlyphsData::PointShare): the shares of every
 * format together are the whole dataset, once, in order; bad shares are refused. No MPI here. */

#include "ReaderTestUtil.h"

#include <osgGlyphsData/PointShare>
#include <osgGlyphsData/RandomCloud>

#include <algorithm>
#include <cmath>

using namespace osgGlyphsData;
using namespace readertest;

namespace
{

/** The dataset's share of text in a format; fails the test on an error. */
osg::ref_ptr<PointDataset> readShare(const std::string& text, const std::string& format, PointShare share)
{
    PointReadOptions options;
    options.share = share;
    std::vector<std::string> warnings;
    std::string error;
    osg::ref_ptr<PointDataset> dataset = readWithOptions(text, format, options, warnings, error);
    EXPECT_TRUE(dataset.valid()) << error;
    return dataset;
}

/** Column name of every frame, share after share, for count shares: equal to the whole reading.
 * With pointRanges, each share holds its getShareRange() of each frame's points; else (shares of
 * a frame's bytes) any number of them. */
void expectSharesMakeWhole(const std::string& text, const std::string& format, const std::string& name,
                           unsigned int count, bool pointRanges = true)
{
    std::string error;
    osg::ref_ptr<PointDataset> whole = readString(text, format, error);
    ASSERT_TRUE(whole.valid()) << error;
    std::vector<std::vector<float>> joined(whole->getNumFrames());
    for (unsigned int index = 0; index < count; ++index)
    {
        osg::ref_ptr<PointDataset> share = readShare(text, format, PointShare{index, count});
        ASSERT_TRUE(share.valid());
        ASSERT_EQ(share->getNumFrames(), whole->getNumFrames())
            << format << " share " << index << " of " << count;
        for (std::size_t frame = 0; frame < joined.size(); ++frame)
        {
            const std::vector<float> part = column(*share->getFrame(frame), name);
            const PointRange range =
                getShareRange(PointShare{index, count}, whole->getFrame(frame)->getNumPoints());
            if (pointRanges)
            {
                EXPECT_EQ(part.size(), range.end - range.begin)
                    << format << " share " << index << " of " << count;
            }
            joined[frame].insert(joined[frame].end(), part.begin(), part.end());
        }
    }
    for (std::size_t frame = 0; frame < joined.size(); ++frame)
        EXPECT_EQ(joined[frame], column(*whole->getFrame(frame), name))
            << format << " in " << count << " shares";
}

const std::string DUMP =
    "ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n7\nITEM: BOX BOUNDS pp pp pp\n0 10\n0 10\n0 10\n"
    "ITEM: ATOMS id type x y z\n"
    "1 1 0.5 1 1\n2 1 1.5 1 1\n3 2 2.5 1 1\n4 2 3.5 1 1\n5 1 4.5 1 1\n6 1 5.5 1 1\n7 2 6.5 1 1\n"
    "ITEM: TIMESTEP\n10\nITEM: NUMBER OF ATOMS\n2\nITEM: BOX BOUNDS pp pp pp\n0 10\n0 10\n0 10\n"
    "ITEM: ATOMS id type x y z\n1 1 7.5 2 2\n2 2 8.5 2 2\n";

}

TEST(PointShare, RangesCoverEveryPointOnceInOrder)
{
    for (unsigned int count = 1; count <= 7; ++count)
    {
        for (uint64_t total : {uint64_t(0), uint64_t(1), uint64_t(5), uint64_t(13), uint64_t(1) << 62})
        {
            uint64_t next = 0;
            for (unsigned int index = 0; index < count; ++index)
            {
                const PointRange range = getShareRange(PointShare{index, count}, total);
                EXPECT_EQ(range.begin, next);
                EXPECT_LE(range.begin, range.end);
                EXPECT_LE(range.end - range.begin, total / count + 1);
                next = range.end;
            }
            EXPECT_EQ(next, total) << total << " points in " << count << " shares";
        }
    }
}

TEST(PointShare, RefusesSharesThatAreNone)
{
    std::string error;
    EXPECT_TRUE(checkPointShare(PointShare{2, 3}, error));
    EXPECT_FALSE(checkPointShare(PointShare{0, 0}, error));
    EXPECT_EQ(error, "share 0 of 0: a dataset splits into at least 1 share");
    EXPECT_FALSE(checkPointShare(PointShare{3, 3}, error));
    EXPECT_EQ(error, "share 3 of 3: shares are counted from 0 to 2");

    PointReadOptions options;
    options.share = PointShare{5, 2};
    std::vector<std::string> warnings;
    EXPECT_FALSE(readWithOptions(DUMP, "lammps", options, warnings, error, "dump.test").valid());
    EXPECT_EQ(error, "dump.test: share 5 of 2: shares are counted from 0 to 1");

    RandomCloudOptions random;
    random.share = PointShare{1, 0};
    EXPECT_FALSE(createRandomCloud(random, error).valid());
    EXPECT_EQ(error, "random cloud: share 1 of 0: a dataset splits into at least 1 share");
}

TEST(PointShare, LammpsSharesAreTheRowsThatStartInTheirPartOfEachFrameAndKeepEveryFrame)
{
    for (unsigned int count = 1; count <= 5; ++count)
        expectSharesMakeWhole(DUMP, "lammps", "x", count, false);
    // The first frame's 84 bytes of rows split at 28 and 56: share 2 of 3 holds the rows starting
    // at 60 and 72. The second frame's 24 split at 8 and 16: share 2 holds none. The frame stays,
    // with its timestep and box.
    osg::ref_ptr<PointDataset> share = readShare(DUMP, "lammps", PointShare{2, 3});
    ASSERT_EQ(share->getNumFrames(), 2u);
    EXPECT_EQ(column(*share->getFrame(0), "x"), (std::vector<float>{5.5f, 6.5f}));
    EXPECT_EQ(share->getFrame(0)->getFilePointCount(), 7u);
    EXPECT_EQ(share->getFrame(1)->getNumPoints(), 0u);
    EXPECT_EQ(share->getFrame(1)->getTimestep(), 10);
    EXPECT_TRUE(share->getFrame(1)->hasBox());
}

TEST(PointShare, AMalformedRowFailsTheShareThatHoldsIt)
{
    std::string dump = DUMP;
    dump.replace(dump.find("6 1 5.5 1 1"), 11, "6 1 oops 1 1"); // line 15, the 6th atom: share 1 of 2
    PointReadOptions options;
    std::vector<std::string> warnings;
    std::string error;
    options.share = PointShare{0, 2};
    EXPECT_TRUE(readWithOptions(dump, "lammps", options, warnings, error, "dump.bad").valid()) << error;
    options.share = PointShare{1, 2};
    EXPECT_FALSE(readWithOptions(dump, "lammps", options, warnings, error, "dump.bad").valid());
    EXPECT_TRUE(hasError(error, "dump.bad:15:", "oops")) << error;
}

TEST(PointShare, XyzSharesAreTheRowsThatStartInTheirPartOfEachFrameAndVtkSharesRangesOfThePoints)
{
    const std::string xyz = "5\nframe\nH 0 0 0\nO 1 0 0\nH 2 0 0\nC 3 0 0\nN 4 0 0\n\n"
                            "3\nframe\nH 5 0 0\nO 6 0 0\nH 7 0 0\n";
    const std::string vtk =
        "# vtk DataFile Version 3.0\nshare\nASCII\nDATASET POLYDATA\nPOINTS 5 float\n"
        "0 0 0 1 0 0 2 0 0 3 0 0 4 0 0\nPOINT_DATA 5\nSCALARS t float 1\nLOOKUP_TABLE default\n"
        "10 11 12 13 14\n";
    for (unsigned int count = 1; count <= 4; ++count)
    {
        expectSharesMakeWhole(xyz, "xyz", "x", count, false);
        expectSharesMakeWhole(xyz, "xyz", "element", count, false);
        expectSharesMakeWhole(vtk, "vtk", "x", count);
        expectSharesMakeWhole(vtk, "vtk", "t", count);
    }
}

TEST(PointShare, PlySharesAreRangesOfTheVertexElement)
{
    const std::string header = "element vertex 5\nproperty float x\nproperty uchar red\nelement face 1\n"
                               "property list uchar int vertex_indices\nend_header\n";
    std::string ascii = "ply\nformat ascii 1.0\n" + header + "0 10\n1 11\n2 12\n3 13\n4 14\n3 0 1 2\n";
    Bytes binary(false);
    binary.text("ply\nformat binary_little_endian 1.0\n" + header);
    for (int i = 0; i < 5; ++i)
        binary.put(float(i)).put(uint8_t(10 + i));
    binary.put(uint8_t(3)).put(int32_t(0)).put(int32_t(1)).put(int32_t(2));
    for (unsigned int count = 1; count <= 4; ++count)
    {
        expectSharesMakeWhole(ascii, "ply", "x", count);
        expectSharesMakeWhole(ascii, "ply", "red", count);
        expectSharesMakeWhole(binary.str(), "ply", "x", count);
        expectSharesMakeWhole(binary.str(), "ply", "red", count);
    }
}

TEST(PointShare, CsvSharesAreTheLinesThatStartInTheirPartOfTheBytes)
{
    // The 30 body bytes split at 15: share 1 of 2 holds the lines starting at body bytes 18 and 24.
    const std::string csv = "x,y,z\n0,0,0\n1,0,0\n2,0,0\n3,0,0\n4,0,0\n";
    EXPECT_EQ(column(*readShare(csv, "csv", PointShare{0, 2})->getFrame(0), "x"),
              (std::vector<float>{0.0f, 1.0f, 2.0f}));
    EXPECT_EQ(column(*readShare(csv, "csv", PointShare{1, 2})->getFrame(0), "x"),
              (std::vector<float>{3.0f, 4.0f}));

    // Lines of unequal lengths among comments, blank lines and CRLF ends: every row once, in order.
    std::string uneven = "# made by a test\nx;y;z\r\n";
    for (int i = 0; i < 60; ++i)
    {
        uneven += std::to_string(i) + "." + std::string(1 + i * 7 % 13, '5') + ";" + std::to_string(i % 4) +
                  ";0\r\n";
        if (i % 9 == 4)
            uneven += "# note\n\n";
    }
    std::string error;
    osg::ref_ptr<PointDataset> whole = readString(uneven, "csv", error);
    ASSERT_TRUE(whole.valid()) << error;
    for (unsigned int count = 1; count <= 7; ++count)
    {
        std::vector<float> joined;
        for (unsigned int index = 0; index < count; ++index)
        {
            const std::vector<float> part =
                column(*readShare(uneven, "csv", PointShare{index, count})->getFrame(0), "x");
            joined.insert(joined.end(), part.begin(), part.end());
        }
        EXPECT_EQ(joined, column(*whole->getFrame(0), "x")) << count << " shares";
    }
}

TEST(PointShare, CsvSharesOfAPipeTakeEveryCountthRow)
{
    // A stream of unknown size cannot be split by its bytes.
    const std::string csv = "x,y,z\n0,0,0\n1,0,0\n2,0,0\n3,0,0\n4,0,0\n";
    PipeBuffer pipe(csv);
    std::istream stream(&pipe);
    PointReadOptions options;
    options.share = PointShare{1, 2};
    std::string error;
    osg::ref_ptr<PointDataset> share = readPointStream(stream, "csv", "pipe", options, error);
    ASSERT_TRUE(share.valid()) << error;
    EXPECT_EQ(column(*share->getFrame(0), "x"), (std::vector<float>{1.0f, 3.0f}));
}

TEST(PointShare, ACsvShareNamesTheFilesLineNumbers)
{
    // 3.5 MB: share 2 of 3 seeks past the first two thirds (beyond the first block it read), without
    // counting their lines; its error still names the file's line 390004.
    std::string csv = "# comment\nx,y,z\n";
    for (int i = 0; i < 400000; ++i)
        csv += (i == 390000 ? std::string("oops") : std::to_string(i)) + ",0,0\n" + (i == 40 ? "\n" : "");
    std::vector<std::string> warnings;
    std::string error;
    PointReadOptions options;
    options.share = PointShare{2, 3};
    EXPECT_FALSE(readWithOptions(csv, "csv", options, warnings, error, "rows.csv").valid());
    EXPECT_TRUE(hasError(error, "rows.csv:390004:", "oops")) << error;
    options.share = PointShare{1, 3};
    EXPECT_TRUE(readWithOptions(csv, "csv", options, warnings, error, "rows.csv").valid()) << error;
}

namespace
{

/** Bytes share index of count read of text (through the progress callback). */
uint64_t bytesReadByShare(const std::string& text, const std::string& format, PointShare share)
{
    PointReadOptions options;
    options.share = share;
    uint64_t bytes = 0;
    options.progress = [&bytes](uint64_t read, uint64_t) { bytes = read; };
    std::vector<std::string> warnings;
    std::string error;
    EXPECT_TRUE(readWithOptions(text, format, options, warnings, error).valid()) << error;
    return bytes;
}

}

TEST(PointShare, CsvAndBinaryPlySharesSeekToTheirPart)
{
    // 8 MB: a share reads its quarter and at most a block (1 MiB) either side of it.
    std::string csv = "x,y,z\n";
    Bytes ply(false);
    const int rows = 400000;
    ply.text("ply\nformat binary_little_endian 1.0\nelement vertex " + std::to_string(rows / 2) +
             "\nproperty double x\nproperty double y\nproperty double z\nend_header\n");
    for (int i = 0; i < rows; ++i)
    {
        csv += std::to_string(1000000 + i) + ",0.25,0.125\n";
        if (i < rows / 2)
            ply.put(double(i)).put(0.25).put(0.125);
    }
    for (const auto& [text, format] : {std::make_pair(csv, "csv"), std::make_pair(ply.str(), "ply")})
    {
        const uint64_t share = bytesReadByShare(text, format, PointShare{3, 4});
        EXPECT_LT(share, text.size() / 4 + 2 * (uint64_t(1) << 20))
            << format << " of " << text.size() << " bytes";
    }
}

TEST(PointShare, RandomSharesAreTheGlyphsOfTheWholeCloud)
{
    RandomCloudOptions options;
    options.count = 1001;
    options.shape = osgGlyphs::GlyphShape::Cone;
    osg::ref_ptr<osgGlyphs::GlyphCloud> whole = createRandomCloud(options);
    for (unsigned int count = 1; count <= 4; ++count)
    {
        std::vector<osg::Vec3f> positions, vectors;
        std::vector<float> scalars;
        for (unsigned int index = 0; index < count; ++index)
        {
            options.share = PointShare{index, count};
            std::string error;
            osg::ref_ptr<osgGlyphs::GlyphCloud> share = createRandomCloud(options, error);
            ASSERT_TRUE(share.valid()) << error;
            EXPECT_EQ(share->getRadius(), whole->getRadius());
            EXPECT_EQ(share->getLengthScale(), whole->getLengthScale());
            positions.insert(positions.end(), share->getPositions()->begin(), share->getPositions()->end());
            vectors.insert(vectors.end(), share->getVectors()->begin(), share->getVectors()->end());
            scalars.insert(scalars.end(), share->getScalars()->begin(), share->getScalars()->end());
        }
        EXPECT_TRUE(positions == whole->getPositions()->asVector()) << count << " shares";
        EXPECT_TRUE(vectors == whole->getVectors()->asVector()) << count << " shares";
        EXPECT_TRUE(scalars == whole->getScalars()->asVector()) << count << " shares";
    }
}

TEST(PointShare, RandomEllipsoidsSpanTheirSmallestAxisShare)
{
    RandomCloudOptions options;
    options.count = 2000;
    options.radius = 0.02f;
    options.shape = osgGlyphs::GlyphShape::Ellipsoid;
    for (float smallest : {0.25f, 0.6f, 1.0f})
    {
        options.smallestAxis = smallest;
        std::string error;
        osg::ref_ptr<osgGlyphs::GlyphCloud> cloud = createRandomCloud(options, error);
        ASSERT_TRUE(cloud.valid()) << error;
        float least = 1.0f, most = 0.0f;
        for (const osg::Vec3& axes : *cloud->getSemiAxes())
        {
            EXPECT_EQ(axes.x(), options.radius);
            for (float other : {axes.y(), axes.z()})
            {
                least = std::min(least, other / options.radius);
                most = std::max(most, other / options.radius);
            }
        }
        EXPECT_GE(least, smallest * (1.0f - 1e-6f));
        EXPECT_LT(least, smallest + 0.01f) << "4000 draws reach the share";
        EXPECT_LE(most, 1.0f + 1e-6f);
        EXPECT_GT(most, 0.99f);
    }
    for (float wrong : {0.0f, -0.5f, 1.5f, std::nanf("")})
    {
        options.smallestAxis = wrong;
        std::string error;
        EXPECT_FALSE(createRandomCloud(options, error).valid()) << wrong;
        EXPECT_NE(error.find("smallest semi-axis share"), std::string::npos) << error;
    }
}

namespace
{

/** A LAMMPS dump of two frames of rows atoms whose rows grow longer as the ids gain digits. */
std::string twoFrameDump(int rows)
{
    std::string dump;
    for (int frame = 0; frame < 2; ++frame)
    {
        dump += "ITEM: TIMESTEP\n" + std::to_string(frame * 100) + "\nITEM: NUMBER OF ATOMS\n" +
                std::to_string(rows) +
                "\nITEM: BOX BOUNDS pp pp pp\n0 1\n0 1\n0 1\nITEM: ATOMS id type x y z\n";
        for (int i = 1; i <= rows; ++i)
            dump += std::to_string(i) + " " + std::to_string(1 + i % 3) + " 0." + std::to_string(i % 997) +
                    " 0.25 -0.125\n";
    }
    return dump;
}

/** Extended XYZ of two frames of rows atoms, a blank line after each. */
std::string twoFrameXyz(int rows)
{
    std::string xyz;
    for (int frame = 0; frame < 2; ++frame)
    {
        xyz += std::to_string(rows) +
               "\nProperties=species:S:1:pos:R:3:id:I:1 step=" + std::to_string(frame) + "\n";
        for (int i = 1; i <= rows; ++i)
            xyz += std::string(i % 5 == 0 ? "Na" : "O") + " 0." + std::to_string(i % 997) + " 1.5 -2 " +
                   std::to_string(i) + "\n";
        xyz += "\n";
    }
    return xyz;
}

/** A middle share of 4 reads its quarter of each frame, about a twentieth more to find the
 * frame's end, and up to a block (1 MiB) past each of its 3 seeks. */
void expectShareSeeks(const std::string& text, const std::string& format)
{
    const uint64_t bytes = bytesReadByShare(text, format, PointShare{1, 4});
    EXPECT_LT(bytes, text.size() * 30 / 100 + 6 * (uint64_t(1) << 20))
        << format << ": of " << text.size() << " bytes";
}

}

TEST(PointShare, LammpsAndXyzSharesOfLargeFramesAreTheWholeFrames)
{
    // 300,000 rows a frame: past the first 64 KiB, each share estimates where the frame ends.
    const std::string dump = twoFrameDump(300000), xyz = twoFrameXyz(300000);
    for (unsigned int count = 2; count <= 4; ++count)
    {
        expectSharesMakeWhole(dump, "lammps", "id", count, false);
        expectSharesMakeWhole(xyz, "xyz", "id", count, false);
        expectSharesMakeWhole(xyz, "xyz", "element", count, false);
    }
}

TEST(PointShare, LammpsAndXyzSharesSeekToTheirPartOfEachFrame)
{
    std::string dump = twoFrameDump(1000000);
    expectShareSeeks(dump, "lammps");
    expectShareSeeks(twoFrameXyz(1000000), "xyz");

    // An error after three seeks still names the file's line: row 990,000 of the second frame.
    dump.replace(dump.rfind("\n990000 ") + 1, 6, "oops00");
    PointReadOptions options;
    options.share = PointShare{3, 4};
    std::vector<std::string> warnings;
    std::string error;
    EXPECT_FALSE(readWithOptions(dump, "lammps", options, warnings, error, "big.dump").valid());
    EXPECT_TRUE(hasError(error, "big.dump:1990018:", "oops00")) << error;
}

TEST(PointShare, ALammpsFrameShorterThanItsCountEndsTheSharesAtItsNextItem)
{
    // The first frame says 9 atoms and has 7 rows: the shares end it at ITEM: TIMESTEP and read
    // its 7 rows (unifyShares then tells the count is wrong); none reads the next frame's rows.
    std::string dump = DUMP;
    dump.replace(dump.find("ATOMS\n7\n"), 8, "ATOMS\n9\n");
    for (unsigned int count = 1; count <= 3; ++count)
    {
        std::vector<float> joined;
        for (unsigned int index = 0; index < count; ++index)
        {
            PointReadOptions options;
            options.share = PointShare{index, count};
            std::vector<std::string> warnings;
            std::string error;
            osg::ref_ptr<PointDataset> share = readWithOptions(dump, "lammps", options, warnings, error);
            if (count == 1)
            {
                EXPECT_FALSE(share.valid());
                EXPECT_TRUE(hasError(error, "", "'ITEM: TIMESTEP' after 7 of 9 rows")) << error;
                continue;
            }
            ASSERT_TRUE(share.valid()) << error;
            ASSERT_EQ(share->getNumFrames(), 2u);
            EXPECT_EQ(share->getFrame(0)->getFilePointCount(), 9u);
            const std::vector<float> part = column(*share->getFrame(0), "x");
            joined.insert(joined.end(), part.begin(), part.end());
        }
        if (count > 1)
        {
            EXPECT_EQ(joined, (std::vector<float>{0.5f, 1.5f, 2.5f, 3.5f, 4.5f, 5.5f, 6.5f})) << count;
        }
    }
}
