// libFuzzer target of frames/ByteSource: random access to gzip and zstd files.
// The input is read as a gzip file and as a zstd file, as it is; then compressed here (two gzip
// members, their deflate blocks ended at drawn places so that checkpoints, every SPAN bytes, fall
// inside them; two zstd frames around a skippable one), where every byte read must be the
// input's. Each file is read sequentially and at offsets drawn from the input, then again from its
// checkpoints saved and restored (toBytes, fromBytes), which must give the same bytes; then from
// checkpoint blobs with bytes changed (as they are, and sealed again so that their checksum
// holds), which must be rejected or read without a crash. Every failure must be a SourceError of
// one line naming the file. Reads stay below READ_LIMIT uncompressed bytes, so that a small input
// that inflates to gigabytes stays quick.

#include "frames/ByteSource.h"
#include "frames/GzipSource.h"
#include "frames/ZstdSource.h"

#include <zlib.h>
#include <zstd.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

using namespace osgGlyphsData::frames;

namespace
{

const uint64_t READ_LIMIT = uint64_t(1) << 20;
const uint64_t SPAN = 512;

/** Numbers drawn from the input (xorshift, seeded with its hash). */
class Draw
{
public:
    Draw(const uint8_t* bytes, std::size_t size) : _state(1469598103934665603ull)
    {
        for (std::size_t i = 0; i < size; ++i)
            _state = (_state ^ bytes[i]) * 1099511628211ull;
        _state |= 1;
    }

    uint64_t next(uint64_t bound)
    {
        _state ^= _state << 13;
        _state ^= _state >> 7;
        _state ^= _state << 17;
        return bound ? _state % bound : 0;
    }

private:
    uint64_t _state;
};

/** A read to make: sequential ones stop at the first that fails or ends the content. */
struct Read
{
    uint64_t offset;
    std::size_t size;
    bool sequential;
};

/** What one read gave: its bytes, or that it failed (or was not made). */
struct Result
{
    bool failed = true;
    std::string bytes;
};

const char* const FILE_NAMES[] = {"input", "input.gz", "input.zst"};

/** This process' directory for the files read, removed at exit. */
std::string directory()
{
    static const std::string path = []
    {
        const char* tmp = std::getenv("TMPDIR");
        std::string dir =
            std::string(tmp && *tmp ? tmp : "/tmp") + "/fuzz_byte_source_" + std::to_string(getpid()) + "/";
        mkdir(dir.c_str(), 0700);
        return dir;
    }();
    static const bool removedAtExit = std::atexit(
                                          []
                                          {
                                              for (const char* name : FILE_NAMES)
                                                  std::remove((path + name).c_str());
                                              rmdir(path.c_str());
                                          }) == 0;
    (void)removedAtExit;
    return path;
}

void writeFile(const std::string& path, const std::string& bytes)
{
    FILE* file = std::fopen(path.c_str(), "wb");
    if (!file || std::fwrite(bytes.data(), 1, bytes.size(), file) != bytes.size() || std::fclose(file) != 0)
        std::abort();
}

void checkMessage(const SourceError& error, const std::string& path)
{
    const std::string prefix = path + ": byte ";
    if (error.message.compare(0, prefix.size(), prefix) != 0 || error.message.find('\n') != std::string::npos)
        std::abort();
}

Result readAt(ByteSource& source, uint64_t offset, std::size_t size)
{
    Result result;
    result.bytes.resize(size);
    try
    {
        result.bytes.resize(source.read(offset, &result.bytes[0], size));
        result.failed = false;
    }
    catch (const SourceError& error)
    {
        checkMessage(error, source.getName());
        result.bytes.clear();
    }
    return result;
}

/** Sequential reads from 0 in pieces, then reads at drawn offsets. */
std::vector<Read> planReads(Draw& draw)
{
    std::vector<Read> reads;
    for (uint64_t offset = 0; offset < READ_LIMIT; offset += 65536)
        reads.push_back({offset, 65536, true});
    for (int i = 0; i < 12; ++i)
        reads.push_back(
            {draw.next(READ_LIMIT / 2 + 1) >> draw.next(18), std::size_t(1 + draw.next(20000)), false});
    return reads;
}

/** Makes the reads; with expected (the plain content), checks their bytes. */
std::vector<Result> runReads(ByteSource& source, const std::vector<Read>& reads, const std::string* expected)
{
    std::vector<Result> results;
    bool sequentialEnded = false;
    for (const Read& read : reads)
    {
        results.emplace_back();
        if (read.sequential && sequentialEnded)
            continue;
        Result& result = results.back();
        result = readAt(source, read.offset, read.size);
        sequentialEnded = sequentialEnded || result.failed || result.bytes.size() < read.size;
        if (!expected)
            continue;
        const std::size_t from = std::size_t(std::min<uint64_t>(read.offset, expected->size()));
        if (result.failed || expected->compare(from, read.size, result.bytes) != 0)
            std::abort();
    }
    return results;
}

std::shared_ptr<Checkpoints> newCheckpoints(Compression compression)
{
    if (compression == Compression::Gzip)
        return std::make_shared<GzipCheckpoints>(SPAN);
    return std::make_shared<ZstdCheckpoints>();
}

std::unique_ptr<ByteSource> open(const std::string& path, Compression compression,
                                 std::shared_ptr<Checkpoints> checkpoints)
{
    std::string error;
    std::unique_ptr<ByteSource> source = openByteSource(path, compression, checkpoints, error);
    if (!source)
        std::abort();
    return source;
}

std::string reseal(const std::string& blob)
{
    std::string sealed = blob;
    const uint32_t crc =
        uint32_t(crc32(0, reinterpret_cast<const Bytef*>(blob.data()) + 12, uInt(blob.size() - 12)));
    for (int i = 0; i < 4; ++i)
        sealed[8 + i] = char((crc >> (8 * i)) & 0xff);
    return sealed;
}

/** Reads with checkpoints restored from blob changed at drawn bytes; must not crash. */
void readWithCorruptBlob(const std::string& path, Compression compression, const std::string& blob,
                         Draw& draw, const std::vector<Read>& reads)
{
    if (blob.size() <= 12)
        return;
    std::string changed = blob;
    const int changes = 1 + int(draw.next(4));
    for (int i = 0; i < changes; ++i)
    {
        const std::size_t at = std::size_t(draw.next(changed.size()));
        changed[at] = char(changed[at] ^ (1 + draw.next(255)));
    }
    if (draw.next(4) == 0)
        changed.resize(std::size_t(draw.next(changed.size())));
    std::shared_ptr<Checkpoints> checkpoints = newCheckpoints(compression);
    checkpoints->fromBytes(changed);
    if (changed.size() <= 12 || !checkpoints->fromBytes(reseal(changed)))
        return;
    std::unique_ptr<ByteSource> source = open(path, compression, checkpoints);
    runReads(*source, reads, nullptr);
}

/** The whole exercise on one file. expected: the content, when known. */
void exercise(const std::string& path, Compression compression, const std::string* expected, Draw& draw)
{
    const std::vector<Read> reads = planReads(draw);
    std::unique_ptr<ByteSource> first = open(path, compression, newCheckpoints(compression));
    const std::vector<Result> results = runReads(*first, reads, expected);
    const std::string blob = first->getCheckpoints()->toBytes();

    std::shared_ptr<Checkpoints> restored = newCheckpoints(compression);
    if (!restored->fromBytes(blob) || restored->toBytes() != blob)
        std::abort();
    std::unique_ptr<ByteSource> second = open(path, compression, restored);
    const std::vector<Result> again = runReads(*second, reads, expected);
    for (std::size_t i = 0; i < results.size(); ++i)
        if (!results[i].failed && (again[i].failed || again[i].bytes != results[i].bytes))
            std::abort();

    readWithCorruptBlob(path, compression, blob, draw, reads);
}

/** One gzip member of bytes, its deflate blocks ended at drawn places (with Z_BLOCK, not on a byte
 * boundary, or with a flush), so that small inputs have checkpoints inside a member. */
std::string gzipMember(const uint8_t* bytes, std::size_t size, int level, Draw& draw)
{
    const int flushes[] = {Z_NO_FLUSH, Z_BLOCK, Z_PARTIAL_FLUSH, Z_SYNC_FLUSH, Z_FULL_FLUSH};
    z_stream stream = {};
    if (deflateInit2(&stream, level, Z_DEFLATED, 15 + 16, 8, Z_DEFAULT_STRATEGY) != Z_OK)
        std::abort();
    std::string out(deflateBound(&stream, uLong(size)) + 64 * (size / 64 + 2), '\0');
    stream.next_out = reinterpret_cast<Bytef*>(&out[0]);
    stream.avail_out = uInt(out.size());
    for (std::size_t at = 0; at < size;)
    {
        const std::size_t piece = std::min<std::size_t>(size - at, 64 + std::size_t(draw.next(2000)));
        stream.next_in = const_cast<Bytef*>(bytes + at);
        stream.avail_in = uInt(piece);
        if (deflate(&stream, flushes[draw.next(5)]) != Z_OK || stream.avail_in != 0)
            std::abort();
        at += piece;
    }
    if (deflate(&stream, Z_FINISH) != Z_STREAM_END)
        std::abort();
    out.resize(stream.total_out);
    deflateEnd(&stream);
    return out;
}

std::string zstdFrame(const uint8_t* bytes, std::size_t size, int level)
{
    std::string out(ZSTD_compressBound(size), '\0');
    const std::size_t got = ZSTD_compress(&out[0], out.size(), bytes, size, level);
    if (ZSTD_isError(got))
        std::abort();
    out.resize(got);
    return out;
}

}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* bytes, std::size_t size)
{
    Draw draw(bytes, size);
    const std::string input(reinterpret_cast<const char*>(bytes), size);
    const std::string raw = directory() + FILE_NAMES[0];
    writeFile(raw, input);
    exercise(raw, Compression::Gzip, nullptr, draw);
    exercise(raw, Compression::Zstd, nullptr, draw);

    const std::size_t half = std::size_t(draw.next(size + 1));
    const std::string gzip = directory() + FILE_NAMES[1];
    writeFile(gzip, gzipMember(bytes, half, 1 + int(draw.next(9)), draw) +
                        gzipMember(bytes + half, size - half, 6, draw));
    exercise(gzip, Compression::Gzip, &input, draw);

    const std::string skippable("\x50\x2a\x4d\x18\x03\0\0\0abc", 11);
    const std::string zstd = directory() + FILE_NAMES[2];
    writeFile(zstd, zstdFrame(bytes, half, 1 + int(draw.next(5))) + skippable +
                        zstdFrame(bytes + half, size - half, 3));
    exercise(zstd, Compression::Zstd, &input, draw);
    return 0;
}
