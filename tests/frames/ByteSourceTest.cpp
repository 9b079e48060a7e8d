// Random access to plain, gzip and zstd files (frames/ByteSource.h): the bytes at any offset, in any
// order, against the plain content; checkpoints saved and restored; truncated, corrupt and growing
// files; corrupt checkpoint blobs. The data: a pseudo-random LAMMPS dump of about 6 MB, compressed
// here with zlib and libzstd, as one member (frame) and as several.

#include "frames/ByteSource.h"
#include "frames/GzipSource.h"
#include "frames/ZstdSource.h"

#include <gtest/gtest.h>
#include <zlib.h>
#include <zstd.h>

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <fstream>
#include <functional>
#include <iostream>
#include <iterator>
#include <random>
#include <thread>
#include <unistd.h>

using namespace osgGlyphsData::frames;

namespace
{

const uint64_t SPAN = uint64_t(256) << 10;
const std::size_t CONTENT_SIZE = std::size_t(6) << 20;
// Where the members (frames) of "gzip members" and "zstd frames" start; the last is the content's end.
const std::vector<uint64_t> CUTS = {0, 1234567, 1234567, 3000001, 4654321, CONTENT_SIZE};

std::string makeDump(std::size_t targetSize)
{
    std::mt19937 random(20240611u);
    std::string text;
    text.reserve(targetSize + 4096);
    char line[160];
    const int atoms = 2000;
    for (int step = 0; text.size() < targetSize; step += 100)
    {
        std::snprintf(
            line, sizeof(line),
            "ITEM: TIMESTEP\n%d\nITEM: NUMBER OF ATOMS\n%d\nITEM: BOX BOUNDS pp pp pp\n0 40\n0 40\n0 40\n"
            "ITEM: ATOMS id type x y z vx vy vz\n",
            step, atoms);
        text += line;
        for (int id = 1; id <= atoms; ++id)
        {
            double values[6];
            for (int i = 0; i < 6; ++i)
                values[i] = (i < 3 ? 40.0 : 2.0) * (double(random()) / 4294967296.0) - (i < 3 ? 0.0 : 1.0);
            std::snprintf(line, sizeof(line), "%d %d %.6f %.6f %.6f %.5f %.5f %.5f\n", id, 1 + id % 3,
                          values[0], values[1], values[2], values[3], values[4], values[5]);
            text += line;
        }
    }
    return text;
}

std::string gzipMember(const std::string& content, int level)
{
    z_stream stream = {};
    EXPECT_EQ(deflateInit2(&stream, level, Z_DEFLATED, 15 + 16, 8, Z_DEFAULT_STRATEGY), Z_OK);
    std::string out(deflateBound(&stream, uLong(content.size())), '\0');
    stream.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(content.data()));
    stream.avail_in = uInt(content.size());
    stream.next_out = reinterpret_cast<Bytef*>(&out[0]);
    stream.avail_out = uInt(out.size());
    EXPECT_EQ(deflate(&stream, Z_FINISH), Z_STREAM_END);
    out.resize(stream.total_out);
    deflateEnd(&stream);
    return out;
}

std::string zstdFrame(const std::string& content, bool contentSizeKnown)
{
    std::string out(ZSTD_compressBound(content.size()), '\0');
    ZSTD_CCtx* context = ZSTD_createCCtx();
    ZSTD_CCtx_setParameter(context, ZSTD_c_checksumFlag, 1);
    ZSTD_CCtx_setParameter(context, ZSTD_c_contentSizeFlag, contentSizeKnown ? 1 : 0);
    ZSTD_inBuffer input = {content.data(), content.size(), 0};
    ZSTD_outBuffer output = {&out[0], out.size(), 0};
    EXPECT_EQ(ZSTD_compressStream2(context, &output, &input, ZSTD_e_end), 0u);
    ZSTD_freeCCtx(context);
    out.resize(output.pos);
    return out;
}

std::string skippableFrame(std::size_t size)
{
    std::string frame("\x5a\x2a\x4d\x18", 4);
    for (int i = 0; i < 4; ++i)
        frame.push_back(char((size >> (8 * i)) & 0xff));
    return frame + std::string(size, 's');
}

void writeFile(const std::string& path, const std::string& bytes, bool append = false)
{
    std::ofstream file(path, std::ios::binary | (append ? std::ios::app : std::ios::trunc));
    file.write(bytes.data(), std::streamsize(bytes.size()));
    ASSERT_TRUE(file.good()) << path;
}

/** A compressed file and where its members (frames) start in the content. */
struct Sample
{
    std::string name;
    Compression compression;
    std::string path;
    std::string bytes;
    std::vector<uint64_t> boundaries;
};

/** The directory of the samples, shared by the test processes (ctest runs each test in a process of
 * its own): they are made once, and written under a temporary name then renamed, so that processes
 * running at once find them whole or not at all. Bump the version when makeDump() or a sample
 * changes. */
std::string cacheDirectory()
{
#ifdef OSGGLYPHS_BYTESOURCE_TEST_DIR
    std::string directory = OSGGLYPHS_BYTESOURCE_TEST_DIR "/";
#else
    std::string directory = ::testing::TempDir();
#endif
    directory += "osgglyphs_bytesource_v1/";
    EXPECT_EQ(system(("mkdir -p " + directory).c_str()), 0);
    return directory;
}

/** The file at path, made by make when it is not there yet. */
std::string cached(const std::string& path, const std::function<std::string()>& make)
{
    std::ifstream file(path, std::ios::binary);
    if (file)
        return std::string(std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>());
    const std::string bytes = make();
    const std::string temporary = path + "." + std::to_string(getpid());
    writeFile(temporary, bytes);
    EXPECT_EQ(std::rename(temporary.c_str(), path.c_str()), 0) << path;
    return bytes;
}

/** The plain content and the samples, made when a test first asks for them. directory: this
 * process' own files (cut, corrupt, growing). */
struct Data
{
    std::string cache;
    std::string directory;
    std::string content;
    std::string plainPath;
    std::vector<std::unique_ptr<Sample>> samples;

    Data() : cache(cacheDirectory())
    {
        directory = ::testing::TempDir() + "osgglyphs_bytesource_" + std::to_string(getpid()) + "/";
        EXPECT_EQ(system(("mkdir -p " + directory).c_str()), 0);
        plainPath = cache + "dump.lammpstrj";
        content = cached(plainPath, [] { return makeDump(CONTENT_SIZE); });
    }
};

std::unique_ptr<Data> theData;

Data& data()
{
    if (!theData)
        theData.reset(new Data);
    return *theData;
}

/** gzip, zstd (one member, one frame of unknown content size), gzip members, zstd frames (with
 * an empty one, and skippable frames). */
std::string makeSample(const std::string& name)
{
    const std::string& content = data().content;
    if (name == "gzip")
        return gzipMember(content, 4);
    if (name == "zstd")
        return zstdFrame(content, false);
    const bool gzip = name == "gzip members";
    std::string bytes = gzip ? "" : skippableFrame(100);
    for (std::size_t i = 0; i + 1 < CUTS.size(); ++i)
    {
        const uint64_t end = i + 2 < CUTS.size() ? CUTS[i + 1] : content.size();
        const std::string part = content.substr(CUTS[i], end - CUTS[i]);
        bytes += gzip ? gzipMember(part, 1) : zstdFrame(part, i % 2 == 0);
        if (!gzip && i == 2)
            bytes += skippableFrame(70000);
    }
    return bytes;
}

const Sample& sample(const std::string& name)
{
    for (const std::unique_ptr<Sample>& s : data().samples)
        if (s->name == name)
            return *s;
    const bool gzip = name.compare(0, 4, "gzip") == 0, single = name == "gzip" || name == "zstd";
    std::string path = data().cache + (single ? "dump" : gzip ? "members" : "frames");
    path += gzip ? ".gz" : ".zst";
    std::unique_ptr<Sample> made(
        new Sample{name, gzip ? Compression::Gzip : Compression::Zstd, path,
                   cached(path, [&name] { return makeSample(name); }),
                   std::vector<uint64_t>(CUTS.begin(), CUTS.end() - (single ? 5 : 1))});
    data().samples.push_back(std::move(made));
    return *data().samples.back();
}

/** Removes the samples' directory at the end. */
class SampleCleanup : public ::testing::Environment
{
public:
    void TearDown() override
    {
        if (theData)
        {
            EXPECT_EQ(system(("rm -rf " + theData->directory).c_str()), 0);
        }
        theData.reset();
    }
};

::testing::Environment* const cleanup = ::testing::AddGlobalTestEnvironment(new SampleCleanup);

std::unique_ptr<ByteSource> open(const std::string& path, Compression compression,
                                 std::shared_ptr<Checkpoints> checkpoints = nullptr)
{
    std::string error;
    std::unique_ptr<ByteSource> source = openByteSource(path, compression, checkpoints, error);
    EXPECT_TRUE(source) << error;
    return source;
}

/** Reads at offset and compares with the content; false (with a failure) on a difference. */
bool readsContent(ByteSource& source, uint64_t offset, std::size_t size)
{
    std::string got(size, '\0');
    const std::size_t count = source.read(offset, &got[0], size);
    const std::size_t expected =
        offset >= data().content.size()
            ? 0
            : std::min<std::size_t>(size, data().content.size() - std::size_t(offset));
    EXPECT_EQ(count, expected) << "at " << offset;
    if (count != expected)
        return false;
    const bool same = data().content.compare(std::size_t(std::min<uint64_t>(offset, data().content.size())),
                                             count, got, 0, count) == 0;
    EXPECT_TRUE(same) << source.getName() << ": different bytes at " << offset << " (" << size << ")";
    return same;
}

/** What a read of everything throws; an empty message when nothing is thrown. */
SourceError readAllError(ByteSource& source)
{
    std::vector<char> buffer(1 << 20);
    uint64_t offset = 0;
    try
    {
        while (std::size_t got = source.read(offset, buffer.data(), buffer.size()))
            offset += got;
    }
    catch (const SourceError& error)
    {
        return error;
    }
    return SourceError();
}

uint64_t restarts(ByteSource& source)
{
    if (auto* gzip = dynamic_cast<GzipSource*>(&source))
        return gzip->getRestarts();
    return dynamic_cast<ZstdSource&>(source).getRestarts();
}

uint64_t decoded(ByteSource& source)
{
    if (auto* gzip = dynamic_cast<GzipSource*>(&source))
        return gzip->getDecodedBytes();
    return dynamic_cast<ZstdSource&>(source).getDecodedBytes();
}

std::shared_ptr<Checkpoints> newCheckpoints(Compression compression)
{
    if (compression == Compression::Gzip)
        return std::make_shared<GzipCheckpoints>(SPAN);
    return std::make_shared<ZstdCheckpoints>();
}

std::string reseal(const char* magic, const std::string& body)
{
    std::string bytes(magic, 4);
    bytes += std::string("\x01\0\0\0", 4);
    const uint32_t crc = uint32_t(crc32(0, reinterpret_cast<const Bytef*>(body.data()), uInt(body.size())));
    for (int i = 0; i < 4; ++i)
        bytes.push_back(char((crc >> (8 * i)) & 0xff));
    return bytes + body;
}

void putNumber(std::string& bytes, std::size_t at, uint64_t value)
{
    for (int i = 0; i < 8; ++i)
        bytes[at + i] = char((value >> (8 * i)) & 0xff);
}

class ByteSourceTest : public ::testing::Test
{
};

class ByteSourceSamples : public ByteSourceTest, public ::testing::WithParamInterface<std::string>
{
};

TEST_F(ByteSourceTest, CompressionFromNameAndMagic)
{
    std::string stripped;
    EXPECT_EQ(compressionFromName("run/dump.lammpstrj.gz", stripped), Compression::Gzip);
    EXPECT_EQ(stripped, "run/dump.lammpstrj");
    EXPECT_EQ(compressionFromName("dump.xyz.zst", stripped), Compression::Zstd);
    EXPECT_EQ(stripped, "dump.xyz");
    EXPECT_EQ(compressionFromName("dump.gzip.xyz", stripped), Compression::None);
    EXPECT_EQ(stripped, "dump.gzip.xyz");
    EXPECT_EQ(compressionFromName(".gz", stripped), Compression::None);

    const unsigned char gzip[] = {0x1f, 0x8b, 8}, zstd[] = {0x28, 0xb5, 0x2f, 0xfd},
                        text[] = {'I', 'T', 'E', 'M'};
    EXPECT_EQ(compressionFromMagic(gzip, 3), Compression::Gzip);
    EXPECT_EQ(compressionFromMagic(gzip, 1), Compression::None);
    EXPECT_EQ(compressionFromMagic(zstd, 4), Compression::Zstd);
    EXPECT_EQ(compressionFromMagic(zstd, 3), Compression::None);
    EXPECT_EQ(compressionFromMagic(text, 4), Compression::None);
}

TEST_F(ByteSourceTest, OpenFailuresNameTheFile)
{
    std::string error;
    EXPECT_FALSE(openByteSource(data().directory + "missing.gz", Compression::Gzip, nullptr, error));
    EXPECT_EQ(error.rfind(data().directory + "missing.gz: ", 0), 0u) << error;
    EXPECT_FALSE(
        openByteSource(sample("gzip").path, Compression::Gzip, std::make_shared<ZstdCheckpoints>(), error));
    EXPECT_EQ(error.rfind(sample("gzip").path + ": ", 0), 0u) << error;
}

TEST_F(ByteSourceTest, PlainFileReadsAtOffsets)
{
    std::unique_ptr<ByteSource> source = open(data().plainPath, Compression::None);
    ASSERT_TRUE(source);
    EXPECT_EQ(source->getFileSize(), data().content.size());
    EXPECT_FALSE(source->getCheckpoints());
    std::mt19937 random(7);
    for (int i = 0; i < 50; ++i)
        readsContent(*source, random() % (data().content.size() + 100), 1 + random() % 100000);
    readsContent(*source, data().content.size() - 5, 100);
}

TEST_F(ByteSourceTest, NotCompressedDataIsAnError)
{
    for (Compression compression : {Compression::Gzip, Compression::Zstd})
    {
        std::unique_ptr<ByteSource> source = open(data().plainPath, compression);
        char byte = 0;
        try
        {
            source->read(0, &byte, 1);
            ADD_FAILURE() << "no error";
        }
        catch (const SourceError& error)
        {
            EXPECT_EQ(error.message,
                      data().plainPath + ": byte 0: not " +
                          (compression == Compression::Gzip ? "gzip data (no gzip magic number)"
                                                            : "zstd data (no zstd magic number)"));
            EXPECT_FALSE(error.endOfInput);
        }
    }
}

TEST_P(ByteSourceSamples, RandomReadsInRandomOrder)
{
    const Sample& s = sample(GetParam());
    std::unique_ptr<ByteSource> source = open(s.path, s.compression, newCheckpoints(s.compression));
    ASSERT_TRUE(source);
    EXPECT_EQ(source->getFileSize(), s.bytes.size());
    EXPECT_EQ(source->getCompression(), s.compression);
    std::mt19937 random(11);
    const std::size_t size = data().content.size();
    for (int i = 0; i < 60 && !HasFailure(); ++i)
        readsContent(*source, random() % size, 1 + random() % (i % 3 ? 5000 : 300000));
    readsContent(*source, size - 10, 100);
    readsContent(*source, size, 100);
    readsContent(*source, size + 12345, 100);
    readsContent(*source, 0, 10);
}

TEST_P(ByteSourceSamples, SequentialReadsNeverRestart)
{
    const Sample& s = sample(GetParam());
    std::unique_ptr<ByteSource> source = open(s.path, s.compression, newCheckpoints(s.compression));
    ASSERT_TRUE(source);
    uint64_t offset = 0;
    for (std::size_t size = 1; offset < data().content.size() && readsContent(*source, offset, size);
         size = size * 7 % 300007 + 1)
        offset += size;
    EXPECT_EQ(restarts(*source), 0u);
    EXPECT_EQ(decoded(*source), data().content.size());
    std::shared_ptr<Checkpoints> checkpoints = source->getCheckpoints();
    EXPECT_EQ(checkpoints->getCoveredEnd(), data().content.size());
    if (s.compression == Compression::Gzip)
        EXPECT_GE(checkpoints->size(), data().content.size() / (2 * SPAN));
    else
        EXPECT_EQ(checkpoints->size(), s.boundaries.size() - (s.name == "zstd frames" ? 1 : 0)); // one empty
}

TEST_P(ByteSourceSamples, ReadsAcrossMemberBoundaries)
{
    const Sample& s = sample(GetParam());
    std::unique_ptr<ByteSource> source = open(s.path, s.compression);
    ASSERT_TRUE(source);
    for (uint64_t boundary : s.boundaries)
    {
        readsContent(*source, boundary > 70 ? boundary - 70 : 0, 100);
        readsContent(*source, boundary, 10);
        readsContent(*source, 0, 1);
    }
}

TEST_P(ByteSourceSamples, CheckpointsRestoredJumpWithoutDecodingFromTheStart)
{
    const Sample& s = sample(GetParam());
    std::unique_ptr<ByteSource> scan = open(s.path, s.compression, newCheckpoints(s.compression));
    ASSERT_TRUE(scan);
    readsContent(*scan, 0, data().content.size());
    const std::string saved = scan->getCheckpoints()->toBytes();

    std::shared_ptr<Checkpoints> restored = newCheckpoints(s.compression);
    ASSERT_TRUE(restored->fromBytes(saved));
    EXPECT_EQ(restored->size(), scan->getCheckpoints()->size());
    EXPECT_EQ(restored->getCoveredEnd(), data().content.size());
    EXPECT_EQ(restored->toBytes(), saved);
    if (s.compression == Compression::Gzip)
        std::cout << "[          ] " << s.name << ": " << restored->size() << " checkpoints, " << saved.size()
                  << " bytes, " << saved.size() / restored->size() << " bytes a point\n";

    std::unique_ptr<ByteSource> jump = open(s.path, s.compression, restored);
    const uint64_t offset = data().content.size() - 3000;
    readsContent(*jump, offset, 3000);
    const uint64_t jumps = s.name == "zstd" ? 0 : 1; // a fresh source stands at the only frame's start
    EXPECT_EQ(restarts(*jump), jumps);
    // From the last checkpoint: within a span and a deflate block (gzip), or the last frame (zstd).
    const uint64_t limit =
        s.compression == Compression::Gzip ? 2 * SPAN : offset - s.boundaries.back() + 3000;
    EXPECT_LE(decoded(*jump), limit);
    readsContent(*jump, 1000000, 2000000);
    EXPECT_EQ(restarts(*jump), jumps + 1);
}

TEST_F(ByteSourceTest, GzipMembersEndingWithAFlush)
{
    // gzflush(Z_SYNC_FLUSH) before gzclose(): a block boundary at the end of each member's content,
    // where a point of the member (at every boundary, span 1) stands at the next member's start.
    std::string bytes;
    for (std::size_t at = 0; at < 300000; at += 100000)
    {
        z_stream stream = {};
        ASSERT_EQ(deflateInit2(&stream, 6, Z_DEFLATED, 15 + 16, 8, Z_DEFAULT_STRATEGY), Z_OK);
        std::string out(200000, '\0');
        stream.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(data().content.data() + at));
        stream.avail_in = 100000;
        stream.next_out = reinterpret_cast<Bytef*>(&out[0]);
        stream.avail_out = uInt(out.size());
        ASSERT_EQ(deflate(&stream, Z_SYNC_FLUSH), Z_OK);
        ASSERT_EQ(deflate(&stream, Z_FINISH), Z_STREAM_END);
        bytes += out.substr(0, stream.total_out);
        deflateEnd(&stream);
    }
    const std::string path = data().directory + "flushed.gz";
    writeFile(path, bytes);
    auto checkpoints = std::make_shared<GzipCheckpoints>(1);
    std::unique_ptr<ByteSource> scan = open(path, Compression::Gzip, checkpoints);
    ASSERT_TRUE(scan);
    std::string got(400000, '\0');
    ASSERT_EQ(scan->read(0, &got[0], got.size()), 300000u);
    EXPECT_EQ(got.compare(0, 300000, data().content, 0, 300000), 0);
    auto restored = std::make_shared<GzipCheckpoints>(1);
    ASSERT_TRUE(restored->fromBytes(checkpoints->toBytes()));
    std::unique_ptr<ByteSource> jump = open(path, Compression::Gzip, restored);
    for (uint64_t offset : {250000u, 100000u, 99999u, 200000u, 150000u})
    {
        ASSERT_EQ(jump->read(offset, &got[0], 100), 100u);
        EXPECT_EQ(got.compare(0, 100, data().content, offset, 100), 0) << offset;
    }
}

TEST_F(ByteSourceTest, GzipPointsAreAtMostASpanAndABlockApart)
{
    const Sample& s = sample("gzip");
    auto checkpoints = std::make_shared<GzipCheckpoints>(SPAN);
    std::unique_ptr<ByteSource> source = open(s.path, s.compression, checkpoints);
    ASSERT_TRUE(source);
    readsContent(*source, 0, data().content.size());
    GzipCheckpoints::Point point;
    for (uint64_t offset = 0; offset < data().content.size(); offset += 10007)
    {
        ASSERT_TRUE(checkpoints->findPoint(offset, point));
        EXPECT_LE(point.out, offset);
        EXPECT_LT(offset - point.out, SPAN + (uint64_t(128) << 10)) << offset;
    }
}

TEST_F(ByteSourceTest, ReplacedCheckpointsAreNotExtendedAcrossAGap)
{
    for (const char* name : {"gzip", "gzip members", "zstd frames"})
    {
        const Sample& s = sample(name);
        std::unique_ptr<ByteSource> all = open(s.path, s.compression, newCheckpoints(s.compression));
        std::unique_ptr<ByteSource> some = open(s.path, s.compression, newCheckpoints(s.compression));
        ASSERT_TRUE(all && some);
        readsContent(*all, 0, data().content.size());
        readsContent(*some, 0, 1000000);
        const std::string full = all->getCheckpoints()->toBytes(), start = some->getCheckpoints()->toBytes();

        std::shared_ptr<Checkpoints> checkpoints = newCheckpoints(s.compression);
        ASSERT_TRUE(checkpoints->fromBytes(full));
        std::unique_ptr<ByteSource> source = open(s.path, s.compression, checkpoints);
        readsContent(*source, 3500000, 1000);
        // Replaced by points up to 1 MB: the source, from a point after 3 MB, must not add to them.
        ASSERT_TRUE(checkpoints->fromBytes(start));
        readsContent(*source, 3501000, 4000000);
        EXPECT_EQ(checkpoints->toBytes(), start) << name;
        // From the start again, it does.
        readsContent(*source, 0, data().content.size());
        EXPECT_EQ(checkpoints->getCoveredEnd(), data().content.size()) << name;
        EXPECT_EQ(checkpoints->size(), all->getCheckpoints()->size()) << name;
    }
}

TEST_P(ByteSourceSamples, TwoSourcesOnTwoThreadsShareCheckpoints)
{
    const Sample& s = sample(GetParam());
    std::shared_ptr<Checkpoints> checkpoints = newCheckpoints(s.compression);
    std::unique_ptr<ByteSource> scanner = open(s.path, s.compression, checkpoints);
    std::unique_ptr<ByteSource> reader = open(s.path, s.compression, checkpoints);
    ASSERT_TRUE(scanner && reader);
    std::atomic<bool> scanned(false);
    std::thread scanning(
        [&]
        {
            readsContent(*scanner, 0, data().content.size());
            scanned = true;
        });
    std::mt19937 random(5);
    for (int reads = 0; !HasFailure() && (!scanned || reads < 20); ++reads)
    {
        const uint64_t covered = checkpoints->getCoveredEnd();
        readsContent(*reader, covered ? random() % covered : 0, 1 + random() % 20000);
    }
    scanning.join();
    EXPECT_EQ(checkpoints->getCoveredEnd(), data().content.size());
}

TEST_P(ByteSourceSamples, TruncatedFileEndsInsideTheStream)
{
    const Sample& s = sample(GetParam());
    const std::string path = data().directory + "truncated";
    const std::size_t size = s.bytes.size() * 6 / 10;
    writeFile(path, s.bytes.substr(0, size));
    std::unique_ptr<ByteSource> source = open(path, s.compression);
    ASSERT_TRUE(source);
    const SourceError error = readAllError(*source);
    EXPECT_TRUE(error.endOfInput);
    const std::string what = s.compression == Compression::Gzip ? "the gzip stream ends inside a member"
                                                                : "the zstd stream ends inside a frame";
    EXPECT_EQ(error.message, path + ": byte " + std::to_string(size) + ": " + what);
    readsContent(*source, 1000, 100000);
}

TEST_P(ByteSourceSamples, CorruptBytesHalfWay)
{
    const Sample& s = sample(GetParam());
    const std::string path = data().directory + "corrupt";
    std::string bytes = s.bytes;
    const std::size_t at = bytes.size() / 2;
    std::mt19937 random(3);
    for (std::size_t i = at; i < at + 300; ++i)
        bytes[i] = char(random());
    writeFile(path, bytes);
    std::unique_ptr<ByteSource> source = open(path, s.compression);
    ASSERT_TRUE(source);
    const SourceError error = readAllError(*source);
    EXPECT_FALSE(error.endOfInput);
    const std::string prefix = path + ": byte ";
    ASSERT_EQ(error.message.rfind(prefix, 0), 0u) << error.message;
    // The byte where inflate stopped (gzip), the start of the block at fault (zstd: at most 128 KiB).
    const uint64_t byte = std::stoull(error.message.substr(prefix.size()));
    EXPECT_GE(byte, s.compression == Compression::Gzip ? at : at - (128 << 10) - 3);
    EXPECT_LE(byte, bytes.size());
    const std::string what =
        s.compression == Compression::Gzip ? ": corrupt gzip data (" : ": corrupt zstd data (";
    EXPECT_NE(error.message.find(what), std::string::npos) << error.message;
    EXPECT_EQ(error.message.find('\n'), std::string::npos);
    char end[200];
    EXPECT_THROW(source->read(data().content.size() - 100, end, 200), SourceError); // right after the error
    readsContent(*source, 0, data().content.size() / 4);
    readsContent(*source, data().content.size() / 8, 1000);
    // Reads to the end fail again (deflate may decode corrupt data without an error up to the
    // member's CRC-32, so only reads through the trailer must fail).
    EXPECT_THROW(source->read(data().content.size() - 100, end, 200), SourceError);
    EXPECT_THROW(source->read(data().content.size() - 100, end, 200), SourceError);
}

TEST_F(ByteSourceTest, GzipTrailerIsCheckedFromACheckpointToo)
{
    const Sample& s = sample("gzip");
    for (std::size_t field : {std::size_t(8), std::size_t(3)})
    {
        const std::string path = data().directory + "trailer.gz";
        std::string bytes = s.bytes;
        bytes[bytes.size() - field] ^= 1;
        writeFile(path, bytes);
        const std::string what = field == 8 ? "4: corrupt gzip data (incorrect data check)"
                                            : "8: corrupt gzip data (incorrect length check)";
        std::unique_ptr<ByteSource> scan = open(path, s.compression, newCheckpoints(s.compression));
        ASSERT_TRUE(scan);
        const SourceError fromStart = readAllError(*scan);
        std::shared_ptr<Checkpoints> checkpoints = newCheckpoints(s.compression);
        ASSERT_TRUE(checkpoints->fromBytes(scan->getCheckpoints()->toBytes()));
        std::unique_ptr<ByteSource> jump = open(path, s.compression, checkpoints);
        readsContent(*jump, data().content.size() - 1000, 1000);
        char byte;
        try
        {
            jump->read(data().content.size(), &byte, 1);
            ADD_FAILURE() << "no error";
        }
        catch (const SourceError& error)
        {
            EXPECT_EQ(error.message, fromStart.message);
        }
        const std::size_t number = std::stoull(fromStart.message.substr(path.size() + 7));
        EXPECT_EQ(number, bytes.size() - 8 + (field == 8 ? 4 : 8)) << fromStart.message;
        EXPECT_NE(fromStart.message.find(what.substr(3)), std::string::npos) << fromStart.message;
        EXPECT_EQ(restarts(*jump), 1u);
    }
}

TEST_P(ByteSourceSamples, GrowingFileIsReadOnceItGrew)
{
    const Sample& s = sample(GetParam());
    const std::string path = data().directory + "growing";
    const std::size_t part = s.bytes.size() * 4 / 10;
    writeFile(path, s.bytes.substr(0, part));
    std::unique_ptr<ByteSource> source = open(path, s.compression);
    ASSERT_TRUE(source);
    EXPECT_TRUE(readAllError(*source).endOfInput);
    readsContent(*source, 10, 1000);
    writeFile(path, s.bytes.substr(part, s.bytes.size() / 10), true);
    EXPECT_TRUE(readAllError(*source).endOfInput);
    writeFile(path, s.bytes.substr(part + s.bytes.size() / 10), true);
    readsContent(*source, 0, data().content.size());
}

TEST_F(ByteSourceTest, GrowingByWholeMembers)
{
    for (const char* name : {"gzip members", "zstd frames"})
    {
        const Sample& s = sample(name);
        const std::string path = data().directory + "members";
        // The end of the third member (frame) in the compressed bytes: compress it again.
        const std::string first =
            s.compression == Compression::Gzip
                ? gzipMember(data().content.substr(0, 1234567), 1)
                : skippableFrame(100) + zstdFrame(data().content.substr(0, 1234567), true);
        ASSERT_EQ(s.bytes.compare(0, first.size(), first), 0);
        writeFile(path, first);
        std::unique_ptr<ByteSource> source = open(path, s.compression);
        ASSERT_TRUE(source);
        std::string got(2000000, '\0');
        EXPECT_EQ(source->read(1000000, &got[0], got.size()), 234567u);
        EXPECT_EQ(source->read(1234567, &got[0], got.size()), 0u);
        writeFile(path, s.bytes.substr(first.size()), true);
        readsContent(*source, 1234567, 1000);
        readsContent(*source, 1000000, data().content.size());
    }
}

TEST_F(ByteSourceTest, GzipGarbageAfterAMemberIsNamedButTrailingZerosAreNot)
{
    const Sample& s = sample("gzip");
    const std::string path = data().directory + "trailing.gz";
    writeFile(path, s.bytes + std::string(1000, '\0'));
    std::unique_ptr<ByteSource> zeros = open(path, s.compression);
    ASSERT_TRUE(zeros);
    readsContent(*zeros, 0, data().content.size() + 10);

    writeFile(path, s.bytes + std::string(10, '\0') + "garbage");
    std::unique_ptr<ByteSource> garbage = open(path, s.compression);
    ASSERT_TRUE(garbage);
    const SourceError error = readAllError(*garbage);
    EXPECT_EQ(error.message, path + ": byte " + std::to_string(s.bytes.size() + 10) +
                                 ": garbage after the end of a gzip member (not a new member)");
    EXPECT_FALSE(error.endOfInput);
    readsContent(*garbage, 5000000, 1000);
}

TEST_F(ByteSourceTest, ZstdGarbageAfterAFrameIsNamed)
{
    const Sample& s = sample("zstd");
    const std::string path = data().directory + "trailing.zst";
    writeFile(path, s.bytes + "garbage");
    std::unique_ptr<ByteSource> source = open(path, s.compression);
    ASSERT_TRUE(source);
    const SourceError error = readAllError(*source);
    EXPECT_EQ(error.message, path + ": byte " + std::to_string(s.bytes.size()) +
                                 ": garbage after the end of a zstd frame (not a new frame)");
}

TEST_P(ByteSourceSamples, CorruptCheckpointBlobsAreRejected)
{
    const Sample& s = sample(GetParam());
    std::unique_ptr<ByteSource> scan = open(s.path, s.compression, newCheckpoints(s.compression));
    ASSERT_TRUE(scan);
    readsContent(*scan, 0, data().content.size());
    const std::string blob = scan->getCheckpoints()->toBytes();
    const bool gzip = s.compression == Compression::Gzip;
    const char* magic = gzip ? "GZCP" : "ZSCP";
    const std::string body = blob.substr(12);

    std::shared_ptr<Checkpoints> checkpoints = newCheckpoints(s.compression);
    ASSERT_TRUE(checkpoints->fromBytes(blob));
    auto rejects = [&](const std::string& bytes, const std::string& what)
    {
        EXPECT_FALSE(checkpoints->fromBytes(bytes)) << what;
        EXPECT_EQ(checkpoints->toBytes(), blob) << what;
    };
    for (std::size_t size : {std::size_t(0), std::size_t(3), std::size_t(12), std::size_t(27),
                             std::size_t(28), blob.size() / 2, blob.size() - 1})
        rejects(blob.substr(0, size), "cut at " + std::to_string(size));
    for (std::size_t at = 0; at < blob.size(); at += 1 + blob.size() / 97)
    {
        std::string flipped = blob;
        flipped[at] = char(flipped[at] ^ 0x10);
        rejects(flipped, "a bit flipped at " + std::to_string(at));
    }
    rejects(blob + "x", "a byte more");
    rejects(reseal(magic, body + "x"), "a byte more, sealed");
    rejects(reseal(magic, body.substr(0, body.size() - 1)), "a byte less, sealed");
    rejects(newCheckpoints(gzip ? Compression::Zstd : Compression::Gzip)->toBytes(), "another compression's");

    std::string bad = body;
    putNumber(bad, 8, uint64_t(1) << 62);
    rejects(reseal(magic, bad), "a huge count");
    bad = body;
    putNumber(bad, 8, 0);
    rejects(reseal(magic, bad), "a count of 0 with points following");
    bad = body;
    putNumber(bad, 16, 99);
    rejects(reseal(magic, bad), "the first point not at the start");
    if (checkpoints->size() < 2)
        return;
    bad = body;
    putNumber(bad, 0, 5);
    rejects(reseal(magic, bad), "a covered end before the last point");
    const std::size_t second = 16 + (gzip ? 33 : 16); // the second point
    bad = body;
    putNumber(bad, second + 8, 0);
    rejects(reseal(magic, bad), "the second point at uncompressed offset 0");
    bad = body;
    putNumber(bad, second, 0);
    rejects(reseal(magic, bad), "the second point at compressed offset 0");
    if (gzip)
    {
        // The second and third points (mid-member, windows of 32 KiB) swapped.
        const std::size_t third = second + 33 + std::size_t(static_cast<unsigned char>(body[second + 29])) +
                                  (std::size_t(static_cast<unsigned char>(body[second + 30])) << 8);
        const std::size_t fourth = third + 33 + std::size_t(static_cast<unsigned char>(body[third + 29])) +
                                   (std::size_t(static_cast<unsigned char>(body[third + 30])) << 8);
        bad = body.substr(0, second) + body.substr(third, fourth - third) +
              body.substr(second, third - second) + body.substr(fourth);
        ASSERT_EQ(bad.size(), body.size());
        rejects(reseal(magic, bad), "two points swapped");
        bad = body;
        bad[second + 28] = 9;
        rejects(reseal(magic, bad), "bits > 7");
        bad = body;
        bad[second + 33 + 5] ^= 0x40;
        rejects(reseal(magic, bad), "a window that does not uncompress");
        bad = body;
        putNumber(bad, second + 16, 1);
        rejects(reseal(magic, bad), "a window for another member start");
    }
}

TEST_P(ByteSourceSamples, ResealedAndEmptyBlobsAreAccepted)
{
    const Sample& s = sample(GetParam());
    std::unique_ptr<ByteSource> scan = open(s.path, s.compression, newCheckpoints(s.compression));
    ASSERT_TRUE(scan);
    readsContent(*scan, 0, 3000000);
    const std::string blob = scan->getCheckpoints()->toBytes();
    std::shared_ptr<Checkpoints> checkpoints = newCheckpoints(s.compression);
    EXPECT_TRUE(checkpoints->fromBytes(
        reseal(s.compression == Compression::Gzip ? "GZCP" : "ZSCP", blob.substr(12))));
    EXPECT_EQ(checkpoints->toBytes(), blob);
    EXPECT_EQ(checkpoints->getCoveredEnd(), 3000000u);
    EXPECT_TRUE(checkpoints->fromBytes(newCheckpoints(s.compression)->toBytes()));
    EXPECT_EQ(checkpoints->size(), 0u);
}

INSTANTIATE_TEST_SUITE_P(Compressed, ByteSourceSamples,
                         ::testing::Values("gzip", "gzip members", "zstd", "zstd frames"),
                         [](const ::testing::TestParamInfo<std::string>& param)
                         {
                             std::string name = param.param;
                             std::replace(name.begin(), name.end(), ' ', '_');
                             return name;
                         });

}
