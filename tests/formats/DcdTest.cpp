/* DCD: MDAnalysis's DCD of the melt against the LAMMPS dump it was written from; both byte orders
 * and both record marker sizes; shares; and files that lie. */

#include "FormatTestData.h"

#include <algorithm>
#include <cstring>

using namespace formattest;
using namespace osgGlyphsData;

namespace
{

/** A DCD's Fortran records: each payload with its offset in the file. */
struct Record
{
    std::size_t offset;
    std::string payload;
};

std::vector<Record> splitRecords(const std::string& bytes)
{
    std::vector<Record> records;
    std::size_t at = 0;
    while (at + 4 <= bytes.size())
    {
        uint32_t length;
        std::memcpy(&length, bytes.data() + at, 4);
        records.push_back({at, bytes.substr(at + 4, length)});
        at += 8 + length;
    }
    return records;
}

template <typename Word>
void swapWords(std::string& payload, std::size_t from = 0)
{
    for (std::size_t i = from; i + sizeof(Word) <= payload.size(); i += sizeof(Word))
        std::reverse(payload.begin() + std::ptrdiff_t(i), payload.begin() + std::ptrdiff_t(i + sizeof(Word)));
}

template <typename Marker>
std::string joinRecords(const std::vector<Record>& records, bool bigEndian)
{
    std::string bytes;
    for (const Record& record : records)
    {
        Marker length = Marker(record.payload.size());
        std::string marker(reinterpret_cast<const char*>(&length), sizeof(length));
        if (bigEndian)
            std::reverse(marker.begin(), marker.end());
        bytes += marker + record.payload + marker;
    }
    return bytes;
}

/** The melt's DCD in the other byte order: the control words, counts and coordinates swapped, the
 * cell as doubles, the signature and title as they are. */
std::string bigEndianDcd(const std::string& little)
{
    std::vector<Record> records = splitRecords(little);
    for (std::size_t i = 0; i < records.size(); ++i)
    {
        if (i == 0)
            swapWords<uint32_t>(records[i].payload, 4);
        else if (i == 1)
            std::reverse(records[i].payload.begin(), records[i].payload.begin() + 4);
        else if (records[i].payload.size() == 48)
            swapWords<uint64_t>(records[i].payload);
        else
            swapWords<uint32_t>(records[i].payload);
    }
    return joinRecords<uint32_t>(records, true);
}

osg::ref_ptr<FrameSource> melt()
{
    return openFrames(dataPath("melt.lammpstrj"));
}

}

TEST(Dcd, MDAnalysisFramesAreTheDumpsFrames)
{
    osg::ref_ptr<FrameSource> dump = melt();
    osg::ref_ptr<FrameSource> dcd = openFrames(dataPath("melt.dcd"));
    ASSERT_TRUE(dump && dcd);
    EXPECT_EQ(dcd->getFormat(), "dcd");
    EXPECT_EQ(dcd->getNumFrames(), 6u);
    // The dump's six significant digits, stored as float32.
    expectPositionsMatch(*dump, *dcd, 1e-5);
    osg::ref_ptr<PointData> first = frameOf(*dcd, 0);
    ASSERT_TRUE(first && first->hasBox());
    EXPECT_NEAR(first->getBox().xMax() - first->getBox().xMin(), 8.3979809569125372, 1e-5);
    EXPECT_NEAR(first->getBox().zMax() - first->getBox().zMin(), 8.3979809569125372, 1e-5);
    EXPECT_FALSE(first->isTriclinic());
    EXPECT_EQ(first->getFilePointCount(), 500u);
}

TEST(Dcd, FramesReadInAnyOrderAreTheSame)
{
    osg::ref_ptr<FrameSource> dcd = openFrames(dataPath("melt.dcd"));
    ASSERT_TRUE(dcd);
    osg::ref_ptr<PointData> late = frameOf(*dcd, 5);
    osg::ref_ptr<PointData> early = frameOf(*dcd, 1);
    osg::ref_ptr<PointData> lateAgain = frameOf(*dcd, 5);
    ASSERT_TRUE(late && early && lateAgain);
    expectColumnMatches(*late, *lateAgain, "x", 0.0);
    EXPECT_NE(late->getValue(0, 0), early->getValue(0, 0));
}

TEST(Dcd, BigEndianAnd64BitMarkersReadTheSame)
{
    const std::string little = readBytes(dataPath("melt.dcd"));
    const std::string big = writeScratchFile("big.dcd", bigEndianDcd(little));
    const std::string wide = writeScratchFile("wide.dcd", joinRecords<uint64_t>(splitRecords(little), false));
    osg::ref_ptr<FrameSource> reference = openFrames(dataPath("melt.dcd"));
    for (const std::string& path : {big, wide})
    {
        SCOPED_TRACE(path);
        osg::ref_ptr<FrameSource> other = openFrames(path);
        ASSERT_TRUE(reference && other);
        expectPositionsMatch(*reference, *other, 0.0);
        osg::ref_ptr<PointData> frame = frameOf(*other, 3);
        ASSERT_TRUE(frame && frame->hasBox());
        EXPECT_NEAR(frame->getBox().yMax(), 8.3979809569125372, 1e-5);
    }
}

TEST(Dcd, SharesTogetherAreTheWholeFrame)
{
    osg::ref_ptr<PointData> whole = frameOf(*openFrames(dataPath("melt.dcd")), 2);
    ASSERT_TRUE(whole);
    std::vector<float> joined;
    for (unsigned int index = 0; index < 3; ++index)
    {
        FrameSourceOptions options;
        options.share = {index, 3};
        osg::ref_ptr<PointData> part = frameOf(*openFrames(dataPath("melt.dcd"), options), 2);
        ASSERT_TRUE(part);
        const std::vector<float>& x = *part->getColumn("x");
        joined.insert(joined.end(), x.begin(), x.end());
    }
    EXPECT_EQ(joined, *whole->getColumn("x"));
}

TEST(Dcd, ALastFrameCutShortIsLeftOutWithAWarning)
{
    const std::string bytes = readBytes(dataPath("melt.dcd"));
    const std::string path = writeScratchFile("cut.dcd", bytes.substr(0, bytes.size() - 100));
    FrameSourceOptions options;
    std::vector<std::string> warnings;
    options.warning = [&warnings](const std::string& warning) { warnings.push_back(warning); };
    osg::ref_ptr<FrameSource> dcd = openFrames(path, options);
    ASSERT_TRUE(dcd);
    EXPECT_EQ(dcd->getNumFrames(), 5u);
    ASSERT_FALSE(warnings.empty());
    EXPECT_NE(warnings.front().find("frame 5"), std::string::npos) << warnings.front();
    EXPECT_NE(warnings.front().find("cut short"), std::string::npos) << warnings.front();
}

TEST(Dcd, FilesThatLieFailNamingTheFileFrameAndByte)
{
    const std::string good = readBytes(dataPath("melt.dcd"));
    const std::vector<Record> records = splitRecords(good);
    ASSERT_GE(records.size(), 7u);
    auto withWord = [&good](std::size_t offset, int32_t value)
    {
        std::string bytes = good;
        std::memcpy(&bytes[offset], &value, 4);
        return bytes;
    };
    const std::size_t atoms = records[2].offset + 4;
    // Frame 1's x record: the frame's cell record, then x.
    const std::size_t frameBytes = (good.size() - records[3].offset) / 6;
    const std::size_t xRecord = records[3].offset + frameBytes + 56;
    float nan = std::nanf("");
    std::string withNan = good;
    std::memcpy(&withNan[xRecord + 4 + 4 * 7], &nan, 4);

    const struct
    {
        std::string name, bytes, expected;
    } cases[] = {
        {"empty", "", "the file is empty"},
        {"header only", good.substr(0, 60), "byte"},
        {"not dcd", std::string(200, 'x'), "not a DCD file"},
        {"negative atoms", withWord(atoms, -5), "the atom count is -5"},
        {"absurd atoms", withWord(atoms, 2000000000), "no frame"},
        {"title lies", withWord(records[1].offset, 1 << 30), "past the end of the file"},
        {"x marker lies", withWord(xRecord, 1996),
         "frame 1: byte " + std::to_string(xRecord) + ": x record announces 1996"},
        {"nan", withNan,
         "frame 1: byte " + std::to_string(xRecord + 4 + 28) + ": x of atom 8 is not a finite number"},
    };
    for (const auto& bad : cases)
    {
        SCOPED_TRACE(bad.name);
        const std::string path = writeScratchFile("bad.dcd", bad.bytes);
        const std::string error = firstError(path);
        EXPECT_NE(error.find(path), std::string::npos) << error;
        EXPECT_NE(error.find(bad.expected), std::string::npos) << error;
    }
}
