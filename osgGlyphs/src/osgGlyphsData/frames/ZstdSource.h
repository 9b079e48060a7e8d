/* osgGlyphs - private: random access to a zstd file (one or more frames). */

#ifndef OSGGLYPHS_FRAMES_ZSTDSOURCE_H
#define OSGGLYPHS_FRAMES_ZSTDSOURCE_H 1

#include "ByteSource.h"

#include <mutex>
#include <vector>

struct ZSTD_DCtx_s;

namespace osgGlyphsData
{
namespace frames
{

/** The restart points of a zstd file: the starts of its frames (a zstd frame cannot be entered
 * elsewhere). Skippable frames are points too, where they start a new uncompressed offset.
 *
 * toBytes(), all little-endian: "ZSCP", version 1 (4 bytes), the CRC-32 of what follows (4), the
 * covered end (8), the number of points (8), then per point: in (8) and out (8). */
class ZstdCheckpoints : public Checkpoints
{
public:
    struct Point
    {
        /** The compressed offset of the frame's magic number. */
        uint64_t in = 0;
        /** The uncompressed offset of the frame's first byte. */
        uint64_t out = 0;
    };

    std::size_t size() const override;
    uint64_t getCoveredEnd() const override;
    std::string toBytes() const override;
    bool fromBytes(const std::string& bytes) override;

    /** The last point at or before offset; false when there is none. */
    bool findPoint(uint64_t offset, Point& point) const;

    /** Adds point when a reader that decompressed without a gap from runStart passes it first,
     * and covers up to it. */
    void addPoint(uint64_t runStart, const Point& point);

    /** Records that a reader decompressed without a gap from runStart to end. */
    void cover(uint64_t runStart, uint64_t end);

private:
    mutable std::mutex _mutex;
    std::vector<Point> _points;
    uint64_t _coveredEnd = 0;
};

/** Reads a zstd file at any offset: goes on where its stream stands, else restarts at the start of
 * the frame that holds the offset (from the first frame, in a file of one frame). */
class ZstdSource : public ByteSource
{
public:
    /** checkpoints: nullptr for new ones. */
    ZstdSource(std::unique_ptr<SourceFile> file, std::shared_ptr<ZstdCheckpoints> checkpoints);
    ~ZstdSource() override;

    const std::string& getName() const override { return _file->getName(); }
    Compression getCompression() const override { return Compression::Zstd; }
    std::size_t read(uint64_t offset, char* out, std::size_t size) override;
    uint64_t getFileSize() const override { return _file->getSize(); }
    std::shared_ptr<Checkpoints> getCheckpoints() const override { return _checkpoints; }

    /** For tests and measurements: how often decompression restarted, and the bytes it produced. */
    uint64_t getRestarts() const { return _restarts; }
    uint64_t getDecodedBytes() const { return _decoded; }

private:
    enum class Mode
    {
        FrameStart, // before a frame's magic number, or the end
        Decoding,
        Failed // corrupt data: the next read restarts
    };

    void moveTo(uint64_t offset);
    std::size_t produce(unsigned char* out, std::size_t size);
    bool startFrame();
    void skipFrame();
    std::size_t decodeSome(unsigned char* out, std::size_t size);
    [[noreturn]] void failCorrupt(uint64_t byte, const std::string& what);

    std::unique_ptr<SourceFile> _file;
    std::shared_ptr<ZstdCheckpoints> _checkpoints;
    SourceInput _input;
    ZSTD_DCtx_s* _context;
    Mode _mode = Mode::FrameStart;
    uint64_t _out = 0;
    uint64_t _runStart = 0;
    std::size_t _wanted = 1;
    std::vector<unsigned char> _discard;
    uint64_t _restarts = 0;
    uint64_t _decoded = 0;
};

}
}

#endif
