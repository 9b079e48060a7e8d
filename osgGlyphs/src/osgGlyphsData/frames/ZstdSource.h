/* osgGlyphs - private: random access to a zstd file (one or more frames). */

#ifndef OSGGLYPHS_FRAMES_ZSTDSOURCE_H
#define OSGGLYPHS_FRAMES_ZSTDSOURCE_H 1

#include "StreamSource.h"

struct ZSTD_DCtx_s;

namespace osgGlyphsData
{
namespace frames
{

/** A restart point of a zstd file (see ZstdCheckpoints). */
struct ZstdPoint
{
    /** The compressed offset of the frame's magic number. */
    uint64_t in = 0;
    /** The uncompressed offset of the frame's first byte. */
    uint64_t out = 0;
};

/** The restart points of a zstd file: the starts of its frames (a zstd frame cannot be entered
 * elsewhere). Skippable frames are points too, where they start a new uncompressed offset.
 *
 * toBytes() is CheckpointTable's with the magic "ZSCP" and per point, little-endian: in (8) and
 * out (8). */
class ZstdCheckpoints : public CheckpointTable<ZstdPoint>
{
public:
    ZstdCheckpoints();

    /** Adds point when a reader that decompressed without a gap from runStart passes it first,
     * and covers up to it. */
    void addPoint(uint64_t runStart, const Point& point);

protected:
    void writePoint(std::string& body, const Point& point) const override;
    bool readPoint(BlobReader& reader, const Point* previous, Point& point) const override;
};

/** Reads a zstd file at any offset: goes on where its stream stands, else restarts at the start of
 * the frame that holds the offset (from the first frame, in a file of one frame). */
class ZstdSource : public StreamSource<ZstdCheckpoints>
{
public:
    /** checkpoints: nullptr for new ones. */
    ZstdSource(std::unique_ptr<SourceFile> file, std::shared_ptr<ZstdCheckpoints> checkpoints);
    ~ZstdSource() override;

    Compression getCompression() const override { return Compression::Zstd; }

protected:
    /** Reads a frame's magic number: starts a frame, or passes a skippable one. */
    bool startUnit() override;
    /** Decodes on, feeding the decoder no more than it asks for. */
    std::size_t decodeSome(unsigned char* out, std::size_t size) override;

private:
    void skipFrame();

    ZSTD_DCtx_s* _context;
    std::size_t _wanted = 1;
};

}
}

#endif
