// FrameSource: trajectories read frame by frame through an index built on a worker thread,
// persisted, found stale or corrupt, extended for a growing file; gzip and zstd frames bit for bit
// the plain file's; malformed frames failing alone.

#include "TrajectoryTestData.h"

#include "frames/FrameIndexFile.h"

#include <osgGlyphsData/FrameSource>
#include <osgGlyphsData/PointReader>

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <random>

using namespace trajectorytest;
using osgGlyphsData::FrameSource;
using osgGlyphsData::FrameSourceOptions;

namespace
{

struct Opened
{
    osg::ref_ptr<FrameSource> source;
    std::vector<std::string> warnings;
};

/** Opens path with its warnings kept and the index in the test's folder. */
osg::ref_ptr<FrameSource> openSource(const std::string& path, std::vector<std::string>& warnings,
                                     FrameSourceOptions options = FrameSourceOptions())
{
    options.warning = [&warnings](const std::string& warning) { warnings.push_back(warning); };
    std::string error;
    osg::ref_ptr<FrameSource> source = FrameSource::open(path, options, error);
    EXPECT_TRUE(source.valid()) << error;
    return source;
}

/** Every column of two frames equal, bit for bit. */
void expectSameFrame(const osgGlyphsData::PointData& expected, const osgGlyphsData::PointData& actual,
                     const std::string& what)
{
    ASSERT_EQ(expected.getColumnNames(), actual.getColumnNames()) << what;
    ASSERT_EQ(expected.getNumPoints(), actual.getNumPoints()) << what;
    EXPECT_EQ(expected.getTimestep(), actual.getTimestep()) << what;
    for (std::size_t c = 0; c < expected.getNumColumns(); ++c)
    {
        EXPECT_EQ(*expected.getColumn(c), *actual.getColumn(c))
            << what << " column " << expected.getColumnNames()[c];
        EXPECT_EQ(expected.getColumnOrigin(c), actual.getColumnOrigin(c)) << what;
    }
}

/** The frames of the whole-file reader. */
osg::ref_ptr<osgGlyphsData::PointDataset> readWhole(const std::string& path, const std::string& format)
{
    osgGlyphsData::PointReadOptions options;
    options.format = format;
    options.warning = [](const std::string&) {};
    std::string error;
    osg::ref_ptr<osgGlyphsData::PointDataset> dataset = osgGlyphsData::readPointFile(path, options, error);
    EXPECT_TRUE(dataset.valid()) << error;
    return dataset;
}

/** Reads every frame of source in a shuffled order and compares it with the whole-file reading. */
void expectFramesMatch(FrameSource& source, const osgGlyphsData::PointDataset& whole, unsigned seed)
{
    source.waitForIndex();
    ASSERT_EQ(source.getNumFrames(), whole.getNumFrames());
    std::vector<std::size_t> order(whole.getNumFrames());
    for (std::size_t i = 0; i < order.size(); ++i)
        order[i] = i;
    std::shuffle(order.begin(), order.end(), std::mt19937(seed));
    for (std::size_t frame : order)
    {
        std::string error;
        osg::ref_ptr<osgGlyphsData::PointData> data = source.readFrame(frame, error);
        ASSERT_TRUE(data.valid()) << error;
        expectSameFrame(*whole.getFrame(frame), *data,
                        source.getSource() + " frame " + std::to_string(frame));
    }
}

bool contains(const std::vector<std::string>& lines, const std::string& part)
{
    return std::any_of(lines.begin(), lines.end(),
                       [&part](const std::string& line) { return line.find(part) != std::string::npos; });
}

}

TEST(FrameSource, FirstFrameThenAnIndexOfEveryFrame)
{
    const std::string folder = scratchFolder("index");
    const std::string path = folder + "/melt.lammpstrj";
    writeFile(path, lammpsDump(12, 50));
    std::vector<std::string> warnings;
    osg::ref_ptr<FrameSource> source = openSource(path, warnings);
    ASSERT_TRUE(source.valid());
    ASSERT_NE(source->getFirstFrame(), nullptr);
    EXPECT_EQ(source->getFirstFrame()->getNumPoints(), 50u);
    EXPECT_EQ(source->getFormat(), "lammps");
    expectFramesMatch(*source, *readWhole(path, "lammps"), 1);
    for (std::size_t f = 0; f < 12; ++f)
    {
        const osgGlyphsData::FrameInfo info = source->getFrameInfo(f);
        EXPECT_EQ(info.timestep, int64_t(100 * f));
        EXPECT_EQ(info.points, 50u);
        EXPECT_EQ(info.fileFrame, f);
    }
    EXPECT_TRUE(warnings.empty()) << warnings.front();
    std::string error;
    EXPECT_FALSE(source->readFrame(12, error).valid());
    EXPECT_NE(error.find("no frame 12"), std::string::npos) << error;
}

TEST(FrameSource, XyzTrajectories)
{
    const std::string folder = scratchFolder("xyz");
    const std::string path = folder + "/motion.xyz";
    std::string text;
    for (int f = 0; f < 9; ++f)
        text += xyzFrame(f, 30) + (f % 3 == 0 ? "\n" : ""); // blank lines between some frames
    writeFile(path, text);
    std::vector<std::string> warnings;
    osg::ref_ptr<FrameSource> source = openSource(path, warnings);
    ASSERT_TRUE(source.valid());
    expectFramesMatch(*source, *readWhole(path, "xyz"), 2);
    std::string error;
    EXPECT_EQ(source->readFrame(4, error)->getTimestep(), 400);
    EXPECT_TRUE(warnings.empty());
}

TEST(FrameSource, TheIndexIsKeptFoundStaleAndFoundCorrupt)
{
    const std::string folder = scratchFolder("persist");
    const std::string path = folder + "/run.lammpstrj";
    writeFile(path, lammpsDump(6, 20));
    std::vector<std::string> warnings;
    std::string indexPath;
    {
        osg::ref_ptr<FrameSource> source = openSource(path, warnings);
        source->waitForIndex();
        EXPECT_FALSE(source->isIndexReused());
        source = nullptr; // the index is written before the thread ends
    }
    indexPath = path + ".glyphindex";
    ASSERT_TRUE(std::filesystem::exists(indexPath));
    {
        osg::ref_ptr<FrameSource> source = openSource(path, warnings);
        EXPECT_TRUE(source->isIndexReused());
        EXPECT_TRUE(source->isIndexComplete()); // at once: no scan
        expectFramesMatch(*source, *readWhole(path, "lammps"), 3);
    }
    EXPECT_TRUE(warnings.empty());

    // The same size, other contents: the stamp (time, last bytes) tells it.
    std::string text = lammpsDump(6, 20);
    text[text.size() - 3] = text[text.size() - 3] == '1' ? '2' : '1';
    writeFile(path, text);
    {
        osg::ref_ptr<FrameSource> source = openSource(path, warnings);
        EXPECT_FALSE(source->isIndexReused());
        EXPECT_TRUE(contains(warnings, "earlier version of the file"))
            << (warnings.empty() ? "" : warnings[0]);
        source->waitForIndex();
    }

    // A corrupt index: one byte flipped in the middle.
    for (const std::size_t at : {std::size_t(9), std::size_t(100), std::size_t(0)})
    {
        std::string index = readFile(indexPath);
        ASSERT_GT(index.size(), at);
        index[at] ^= 0x5a;
        writeFile(indexPath, index);
        warnings.clear();
        osg::ref_ptr<FrameSource> source = openSource(path, warnings);
        EXPECT_FALSE(source->isIndexReused());
        ASSERT_EQ(warnings.size(), 1u);
        EXPECT_NE(warnings[0].find(indexPath), std::string::npos) << warnings[0];
        EXPECT_NE(warnings[0].find("built again"), std::string::npos) << warnings[0];
        expectFramesMatch(*source, *readWhole(path, "lammps"), 4);
    }
    // Cut short.
    std::string index = readFile(indexPath);
    writeFile(indexPath, index.substr(0, index.size() / 2));
    warnings.clear();
    osg::ref_ptr<FrameSource> source = openSource(path, warnings);
    EXPECT_FALSE(source->isIndexReused());
    EXPECT_TRUE(contains(warnings, "corrupt"));
}

TEST(FrameSource, AnIndexCutShortByClosingIsScannedOn)
{
    const std::string folder = scratchFolder("partial");
    const std::string path = folder + "/run.lammpstrj";
    writeFile(path, lammpsDump(9, 20));
    std::vector<std::string> warnings;
    openSource(path, warnings)->waitForIndex();
    // As a source closed while scanning leaves it: the first three frames, not complete.
    osgGlyphsData::frames::StoredFrameIndex index;
    std::string error;
    ASSERT_TRUE(osgGlyphsData::frames::readFrameIndex(path + ".glyphindex", index, error)) << error;
    ASSERT_TRUE(index.complete);
    index.end = {index.frames[3].offset, index.frames[3].line, 3};
    index.frames.resize(3);
    index.complete = false;
    ASSERT_TRUE(osgGlyphsData::frames::writeFrameIndex(path + ".glyphindex", index, error)) << error;

    osg::ref_ptr<FrameSource> source = openSource(path, warnings);
    EXPECT_TRUE(source->isIndexReused());
    expectFramesMatch(*source, *readWhole(path, "lammps"), 7);
    EXPECT_TRUE(warnings.empty());
}

TEST(FrameSource, TheIndexGoesToTheCacheFolderWhenAsked)
{
    const std::string folder = scratchFolder("cache");
    const std::string path = folder + "/run.lammpstrj";
    writeFile(path, lammpsDump(3, 10));
    FrameSourceOptions options;
    options.indexLocation = osgGlyphsData::FrameIndexLocation::Cache;
    options.cacheFolder = folder + "/cache";
    std::vector<std::string> warnings;
    {
        osg::ref_ptr<FrameSource> source = openSource(path, warnings, options);
        source->waitForIndex();
        EXPECT_EQ(source->getIndexPath().rfind(options.cacheFolder, 0), 0u) << source->getIndexPath();
    }
    EXPECT_FALSE(std::filesystem::exists(path + ".glyphindex"));
    osg::ref_ptr<FrameSource> source = openSource(path, warnings, options);
    EXPECT_TRUE(source->isIndexReused());
}

TEST(FrameSource, AGrowingFileIsIndexedOnAndAShrinkingOneIsAnError)
{
    const std::string folder = scratchFolder("growing");
    const std::string path = folder + "/live.lammpstrj";
    const std::string frame3 = lammpsFrame(3, 15);
    writeFile(path, lammpsDump(3, 15) + frame3.substr(0, frame3.size() / 2));
    FrameSourceOptions options;
    options.growing = true;
    std::vector<std::string> warnings;
    osg::ref_ptr<FrameSource> source = openSource(path, warnings, options);
    source->waitForIndex();
    EXPECT_EQ(source->getNumFrames(), 3u);
    EXPECT_TRUE(warnings.empty()) << warnings.front(); // a half-written frame is no warning

    std::size_t added = 0;
    std::string error;
    ASSERT_TRUE(source->poll(added, error)) << error;
    EXPECT_EQ(added, 0u);
    appendFile(path, frame3.substr(frame3.size() / 2) + lammpsFrame(4, 15));
    ASSERT_TRUE(source->poll(added, error)) << error;
    EXPECT_EQ(added, 2u);
    osg::ref_ptr<osgGlyphsData::PointData> data = source->readFrame(4, error);
    ASSERT_TRUE(data.valid()) << error;
    EXPECT_EQ(data->getTimestep(), 400);

    // Reopened: the index of the first three frames is extended, not rebuilt.
    {
        appendFile(path, lammpsFrame(5, 15));
        std::vector<std::string> reopenWarnings;
        osg::ref_ptr<FrameSource> reopened = openSource(path, reopenWarnings, options);
        EXPECT_TRUE(reopened->isIndexReused());
        reopened->waitForIndex();
        EXPECT_EQ(reopened->getNumFrames(), 6u);
        EXPECT_TRUE(reopenWarnings.empty());
    }

    writeFile(path, lammpsDump(2, 15));
    EXPECT_FALSE(source->poll(added, error));
    EXPECT_NE(error.find(path + ": the file shrank or was rewritten"), std::string::npos) << error;
}

TEST(FrameSource, MalformedFramesFailAloneNamingTheLine)
{
    const std::string folder = scratchFolder("malformed");
    const std::string path = folder + "/broken.lammpstrj";
    // Frame 2 (of 0..5) cut short by frame 3; garbage after frame 4; frame 5 holds more rows
    // than it announces.
    std::string frame2 = lammpsFrame(2, 10);
    frame2 = frame2.substr(0, frame2.find("\n", frame2.find("ITEM: ATOMS")) + 1);
    frame2 += "1 1 1.0 2.0 3.0 0.5\n2 1 1.0 2.0 3.0 0.5\n";
    std::string frame5 = lammpsFrame(5, 10) + "11 1 1.0 2.0 3.0 0.5\n";
    const std::string text = lammpsFrame(0, 10) + lammpsFrame(1, 10) + frame2 + lammpsFrame(3, 10) +
                             lammpsFrame(4, 10) + "this is not a dump\nnor this\n" + frame5 +
                             lammpsFrame(6, 10);
    writeFile(path, text);
    std::vector<std::string> warnings;
    osg::ref_ptr<FrameSource> source = openSource(path, warnings);
    source->waitForIndex();
    ASSERT_EQ(source->getNumFrames(), 7u);
    ASSERT_TRUE(contains(warnings, "frame 3 has 2 of its 10 rows")) << (warnings.empty() ? "" : warnings[0]);
    EXPECT_TRUE(contains(warnings, "2 lines that belong to no frame, after frame 5 ('this is not a dump')"));
    EXPECT_TRUE(contains(warnings, "1 line that belongs to no frame")) << "frame 6's row beyond its count";
    for (const std::string& warning : warnings)
        EXPECT_EQ(warning.rfind(path + ":", 0), 0u) << warning;

    std::string error;
    EXPECT_FALSE(source->readFrame(2, error).valid());
    // The reader's own message: the file, the line where the rows end early.
    EXPECT_EQ(error.rfind(path + ":", 0), 0u) << error;
    EXPECT_NE(error.find("rows"), std::string::npos) << error;
    for (std::size_t f : {0u, 1u, 3u, 4u, 5u, 6u})
    {
        osg::ref_ptr<osgGlyphsData::PointData> data = source->readFrame(f, error);
        ASSERT_TRUE(data.valid()) << "frame " << f << ": " << error;
        EXPECT_EQ(data->getNumPoints(), 10u);
        EXPECT_EQ(data->getTimestep(), int64_t(100 * f));
    }
}

TEST(FrameSource, CompressedFramesAreThePlainFilesBitForBit)
{
    const std::string folder = scratchFolder("compressed");
    const std::string plain = folder + "/melt.lammpstrj";
    const std::string text = lammpsDump(40, 400); // about 1 MB: several gzip restart points
    writeFile(plain, text);
    writeFile(plain + ".gz", gzipBytes(text));
    writeFile(plain + ".zst", zstdBytes(text));
    osg::ref_ptr<osgGlyphsData::PointDataset> whole = readWhole(plain, "lammps");
    for (const std::string suffix : {".gz", ".zst"})
    {
        std::vector<std::string> warnings;
        osg::ref_ptr<FrameSource> source = openSource(plain + suffix, warnings);
        ASSERT_TRUE(source.valid());
        EXPECT_EQ(source->getFormat(), "lammps");
        EXPECT_EQ(source->getCompressionName(), suffix == ".gz" ? "gzip" : "zstd");
        expectFramesMatch(*source, *whole, 5);
        EXPECT_TRUE(warnings.empty());
        source = nullptr;
        // Reopened through its index and restart points.
        source = openSource(plain + suffix, warnings);
        EXPECT_TRUE(source->isIndexReused());
        expectFramesMatch(*source, *whole, 6);
    }
    // A compressed file without the suffix is recognised by its first bytes.
    writeFile(folder + "/named.lammpstrj", gzipBytes(text));
    std::vector<std::string> warnings;
    osg::ref_ptr<FrameSource> source = openSource(folder + "/named.lammpstrj", warnings);
    ASSERT_TRUE(source.valid());
    EXPECT_EQ(source->getCompressionName(), "gzip");
}

TEST(FrameSource, ACompressedStreamCorruptHalfWayKeepsTheFramesBeforeIt)
{
    const std::string folder = scratchFolder("corrupt");
    // Large enough that the middle lies several zstd blocks (128 KiB each) from the start.
    const std::string text = lammpsDump(30, 1500);
    for (const std::string suffix : {".gz", ".zst"})
    {
        const std::string path = folder + "/melt.lammpstrj" + suffix;
        std::string bytes = suffix == ".gz" ? gzipBytes(text) : zstdBytes(text);
        for (std::size_t i = bytes.size() / 2; i < bytes.size() / 2 + 64; ++i)
            bytes[i] = static_cast<char>(bytes[i] ^ 0xa5);
        writeFile(path, bytes);
        std::vector<std::string> warnings;
        osg::ref_ptr<FrameSource> source = openSource(path, warnings);
        ASSERT_TRUE(source.valid());
        source->waitForIndex();
        EXPECT_GT(source->getNumFrames(), 5u) << suffix;
        EXPECT_LT(source->getNumFrames(), 30u) << suffix;
        ASSERT_TRUE(contains(warnings, "cannot be indexed")) << suffix;
        EXPECT_TRUE(contains(warnings, path + ": byte ")) << warnings.front();
        // The frames well before the damage read as they are; after it, gzip decodes damaged bytes
        // until its checksum (at the member's end) tells: those frames fail alone, naming their line.
        for (std::size_t f = 0; f < source->getNumFrames(); ++f)
        {
            std::string error;
            if (!source->readFrame(f, error).valid())
            {
                EXPECT_GE(f, 5u) << error;
                EXPECT_EQ(error.rfind(path + ":", 0), 0u) << error;
                EXPECT_EQ(error.find('\n'), std::string::npos) << error;
            }
        }
    }
    // Cut short: the frames before the cut.
    const std::string path = folder + "/cut.lammpstrj.gz";
    const std::string bytes = gzipBytes(text);
    writeFile(path, bytes.substr(0, bytes.size() * 2 / 3));
    std::vector<std::string> warnings;
    osg::ref_ptr<FrameSource> source = openSource(path, warnings);
    source->waitForIndex();
    EXPECT_GT(source->getNumFrames(), 10u);
    EXPECT_LT(source->getNumFrames(), 30u);
}

TEST(FrameSource, SingleFrameFormatsAreOneFrame)
{
    const std::string folder = scratchFolder("single");
    const std::string path = folder + "/points.csv";
    writeFile(path, "x,y,z,c\n1,2,3,4\n5,6,7,8\n");
    std::vector<std::string> warnings;
    osg::ref_ptr<FrameSource> source = openSource(path, warnings);
    ASSERT_TRUE(source.valid());
    EXPECT_TRUE(source->isIndexComplete());
    EXPECT_EQ(source->getNumFrames(), 1u);
    std::string error;
    EXPECT_EQ(source->readFrame(0, error)->getNumPoints(), 2u);
    EXPECT_FALSE(source->readFrame(1, error).valid());
    EXPECT_FALSE(std::filesystem::exists(path + ".glyphindex"));
}

TEST(FrameSource, OpeningFailsInOneLine)
{
    const std::string folder = scratchFolder("open");
    std::string error;
    FrameSourceOptions options;
    EXPECT_FALSE(FrameSource::open(folder + "/missing.lammpstrj", options, error).valid());
    EXPECT_EQ(error.rfind(folder + "/missing.lammpstrj: cannot open", 0), 0u) << error;
    writeFile(folder + "/bad.lammpstrj", "not a dump\n");
    EXPECT_FALSE(FrameSource::open(folder + "/bad.lammpstrj", options, error).valid());
    EXPECT_EQ(error,
              folder + "/bad.lammpstrj:1: not a LAMMPS dump: expected 'ITEM: TIMESTEP', found 'not a dump'");
    writeFile(folder + "/what.unknown", "1 2 3\n");
    EXPECT_FALSE(FrameSource::open(folder + "/what.unknown", options, error).valid());
    EXPECT_NE(error.find("cannot tell the point format"), std::string::npos);
}
