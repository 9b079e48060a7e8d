/* osgGlyphs - private: random access to a gzip file (one or more members), as zlib's zran example
 * describes. */

#ifndef OSGGLYPHS_FRAMES_GZIPSOURCE_H
#define OSGGLYPHS_FRAMES_GZIPSOURCE_H 1

#include "StreamSource.h"

#include <zlib.h>

#include <vector>

namespace osgGlyphsData
{
namespace frames
{

/** A restart point of a gzip file (see GzipCheckpoints). */
struct GzipPoint
{
    /** The compressed offset of the first whole byte after the point (at a member start: of the
     * member's header). */
    uint64_t in = 0;
    /** How many high bits of the byte before in come after the point (0 to 7). */
    int bits = 0;
    /** The uncompressed offset. */
    uint64_t out = 0;
    /** The uncompressed offset where the point's member starts; out at a member start. */
    uint64_t memberOut = 0;
    /** The CRC-32 of the member's bytes before out, to check its trailer. */
    uint32_t memberCrc = 0;
    /** The last min(32 KiB, out - memberOut) uncompressed bytes, in zlib's format (as compress()
     * writes it); empty at a member start. */
    std::shared_ptr<const std::string> window;

    bool isMemberStart() const { return out == memberOut; }
};

/** The restart points of a gzip file: at each member start, and at deflate block boundaries at
 * least every span uncompressed bytes (a point follows the last by span plus at most a block),
 * with the 32 KiB window before them, compressed (about 16 KiB of a LAMMPS dump's text).
 *
 * toBytes() is CheckpointTable's with the magic "GZCP" and per point, little-endian: in (8), out (8),
 * memberOut (8), memberCrc (4), bits (1), the window's compressed size (4) and the window (zlib
 * format). */
class GzipCheckpoints : public CheckpointTable<GzipPoint>
{
public:
    static constexpr uint64_t DefaultSpan = uint64_t(1) << 20;
    static constexpr std::size_t WindowSize = 32768;

    explicit GzipCheckpoints(uint64_t span = DefaultSpan);

    uint64_t getSpan() const { return _span; }

    /** Whether a reader that decompressed without a gap from runStart should add a point at out. */
    bool wantsPoint(uint64_t runStart, uint64_t out, bool memberStart) const;

    /** Adds point when it is still wanted, and covers up to its offset. */
    void addPoint(uint64_t runStart, Point point);

protected:
    void writePoint(std::string& body, const Point& point) const override;
    bool readPoint(BlobReader& reader, const Point* previous, Point& point) const override;

private:
    bool wanted(uint64_t runStart, uint64_t out, bool memberStart) const;

    const uint64_t _span;
};

/** Reads a gzip file at any offset: goes on where its inflate stream stands, else restarts at the
 * last checkpoint before the offset. Adds checkpoints as it decompresses. */
class GzipSource : public StreamSource<GzipCheckpoints>
{
public:
    /** checkpoints: nullptr for new ones. */
    GzipSource(std::unique_ptr<SourceFile> file, std::shared_ptr<GzipCheckpoints> checkpoints);
    ~GzipSource() override;

    Compression getCompression() const override { return Compression::Gzip; }

protected:
    /** Reads a member's header, or passes the zeros after a member. */
    bool startUnit() override;
    /** Inflates up to the end of a deflate block, adding a checkpoint at its end when one is due. */
    std::size_t decodeSome(unsigned char* out, std::size_t size) override;
    /** Checks the CRC and size of a member whose deflate data restarted at a point inside it. */
    void readTrailer() override;
    /** Restarts inflating at a point inside a member, from its window. */
    void enter(const Point& point) override;

private:
    void notePoint();
    std::shared_ptr<const std::string> packWindow(std::size_t length);

    z_stream _stream;
    z_stream _packer; // compresses the windows of new points
    bool _packerReady = false;
    bool _raw = true;
    uint64_t _memberOut = 0;
    uint32_t _memberCrc = 0;
    std::vector<unsigned char> _window;
};

}
}

#endif
