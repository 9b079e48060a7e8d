/* osgGlyphs - private: random access to a gzip file (one or more members), as zlib's zran example
 * describes. */

#ifndef OSGGLYPHS_FRAMES_GZIPSOURCE_H
#define OSGGLYPHS_FRAMES_GZIPSOURCE_H 1

#include "ByteSource.h"

#include <zlib.h>

#include <mutex>
#include <vector>

namespace osgGlyphsData
{
namespace frames
{

/** The restart points of a gzip file: at each member start, and at deflate block boundaries at
 * least every span uncompressed bytes (a point follows the last by span plus at most a block),
 * with the 32 KiB window before them, compressed (about 16 KiB of a LAMMPS dump's text).
 *
 * toBytes(), all little-endian: "GZCP", version 1 (4 bytes), the CRC-32 of what follows (4), the
 * covered end (8), the number of points (8), then per point: in (8), out (8), memberOut (8),
 * memberCrc (4), bits (1), the window's compressed size (4) and the window (zlib format). */
class GzipCheckpoints : public Checkpoints
{
public:
    static constexpr uint64_t DefaultSpan = uint64_t(1) << 20;
    static constexpr std::size_t WindowSize = 32768;

    struct Point
    {
        /** The compressed offset of the first whole byte after the point (at a member start: of
         * the member's header). */
        uint64_t in = 0;
        /** How many high bits of the byte before in come after the point (0 to 7). */
        int bits = 0;
        /** The uncompressed offset. */
        uint64_t out = 0;
        /** The uncompressed offset where the point's member starts; out at a member start. */
        uint64_t memberOut = 0;
        /** The CRC-32 of the member's bytes before out, to check its trailer. */
        uint32_t memberCrc = 0;
        /** The last min(32 KiB, out - memberOut) uncompressed bytes, in zlib's format (as
         * compress() writes it); empty at a member start. */
        std::shared_ptr<const std::string> window;

        bool isMemberStart() const { return out == memberOut; }
    };

    explicit GzipCheckpoints(uint64_t span = DefaultSpan);

    std::size_t size() const override;
    uint64_t getCoveredEnd() const override;
    std::string toBytes() const override;
    bool fromBytes(const std::string& bytes) override;

    uint64_t getSpan() const { return _span; }

    /** The last point at or before offset; false when there is none. */
    bool findPoint(uint64_t offset, Point& point) const;

    /** Whether a reader that decompressed without a gap from runStart should add a point at out. */
    bool wantsPoint(uint64_t runStart, uint64_t out, bool memberStart) const;

    /** Adds point when it is still wanted, and covers up to its offset. */
    void addPoint(uint64_t runStart, Point point);

    /** Records that a reader decompressed without a gap from runStart to end. */
    void cover(uint64_t runStart, uint64_t end);

private:
    bool wanted(uint64_t runStart, uint64_t out, bool memberStart) const;

    mutable std::mutex _mutex;
    const uint64_t _span;
    std::vector<Point> _points;
    uint64_t _coveredEnd = 0;
};

/** Reads a gzip file at any offset: goes on where its inflate stream stands, else restarts at the
 * last checkpoint before the offset. Adds checkpoints as it decompresses. */
class GzipSource : public ByteSource
{
public:
    /** checkpoints: nullptr for new ones. */
    GzipSource(std::unique_ptr<SourceFile> file, std::shared_ptr<GzipCheckpoints> checkpoints);
    ~GzipSource() override;

    const std::string& getName() const override { return _file->getName(); }
    Compression getCompression() const override { return Compression::Gzip; }
    std::size_t read(uint64_t offset, char* out, std::size_t size) override;
    uint64_t getFileSize() const override { return _file->getSize(); }
    std::shared_ptr<Checkpoints> getCheckpoints() const override { return _checkpoints; }

    /** For tests and measurements: how often decompression restarted, and the bytes it produced. */
    uint64_t getRestarts() const { return _restarts; }
    uint64_t getDecodedBytes() const { return _decoded; }

private:
    enum class Mode
    {
        MemberStart, // before a member's header, or the end
        Inflating,
        Trailer, // after a member's deflate data restarted mid-member: its CRC and size
        Failed   // corrupt data: the next read restarts
    };

    void moveTo(uint64_t offset);
    void restart(const GzipCheckpoints::Point* point);
    void restartInside(const GzipCheckpoints::Point& point);
    std::size_t produce(unsigned char* out, std::size_t size);
    bool startMember();
    std::size_t inflateSome(unsigned char* out, std::size_t size);
    void notePoint();
    std::shared_ptr<const std::string> packWindow(std::size_t length);
    void readTrailer();
    [[noreturn]] void failCorrupt(uint64_t byte, const std::string& what);

    std::unique_ptr<SourceFile> _file;
    std::shared_ptr<GzipCheckpoints> _checkpoints;
    SourceInput _input;
    z_stream _stream;
    z_stream _packer; // compresses the windows of new points
    bool _packerReady = false;
    bool _raw = true;
    Mode _mode = Mode::MemberStart;
    uint64_t _out = 0;
    uint64_t _runStart = 0;
    uint64_t _memberOut = 0;
    uint32_t _memberCrc = 0;
    std::vector<unsigned char> _window;
    std::vector<unsigned char> _discard;
    uint64_t _restarts = 0;
    uint64_t _decoded = 0;
};

}
}

#endif
