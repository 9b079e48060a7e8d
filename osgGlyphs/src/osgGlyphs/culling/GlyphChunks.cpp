#include "GlyphChunks.h"
#include <osgGlyphsInternal/RadixSort.h>

#include <algorithm>
#include <cstdint>

using namespace osgGlyphs::detail;

namespace
{

const int MORTON_BITS = 10; // per axis: a 1024^3 grid over the cloud

/** The most glyphs whose boxes are held while their chunks are made (24 MiB). */
const unsigned int MAX_HELD_BOXES = 1u << 20;

/** Spreads the low 10 bits of v to every third bit. */
uint32_t spreadBits(uint32_t v)
{
    v &= 0x3ff;
    v = (v | (v << 16)) & 0x030000ff;
    v = (v | (v << 8)) & 0x0300f00f;
    v = (v | (v << 4)) & 0x030c30c3;
    v = (v | (v << 2)) & 0x09249249;
    return v;
}

/** Cuts the sorted keys into chunks along the octree; the chunks' boxes are left empty. */
struct Splitter
{
    const std::vector<uint64_t>& keys;
    unsigned int maxChunkSize;
    std::vector<GlyphChunk>& chunks;

    /** Cuts keys[begin, end), one octree cell at this level, into chunks. */
    void split(size_t begin, size_t end, int level)
    {
        if (end - begin <= maxChunkSize || level == MORTON_BITS)
        {
            GlyphChunk chunk;
            chunk.first = static_cast<unsigned int>(begin);
            chunk.count = static_cast<unsigned int>(end - begin);
            chunks.push_back(chunk);
            return;
        }
        const int shift = 32 + 3 * (MORTON_BITS - 1 - level);
        size_t childBegin = begin;
        while (childBegin < end)
        {
            const uint64_t cell = keys[childBegin] >> shift;
            size_t childEnd = childBegin + 1;
            while (childEnd < end && (keys[childEnd] >> shift) == cell)
                ++childEnd;
            split(childBegin, childEnd, level + 1);
            childBegin = childEnd;
        }
    }
};

}

GlyphChunks osgGlyphs::detail::buildGlyphChunks(unsigned int numGlyphs,
                                                const std::function<osg::BoundingBox(unsigned int)>& glyphBox,
                                                unsigned int maxChunkSize)
{
    // The boxes of a small cloud (a tile) are held; those of a large one are computed twice, both
    // times in the glyphs' own order (memory order), rather than held (24 bytes a glyph): for
    // their centres, then for their chunks' boxes.
    const bool holdBoxes = numGlyphs <= MAX_HELD_BOXES;
    std::vector<osg::BoundingBox> boxes(holdBoxes ? numGlyphs : 0);
    std::vector<uint32_t> ids;
    std::vector<osg::Vec3f> centres;
    ids.reserve(numGlyphs);
    centres.reserve(numGlyphs);
    osg::BoundingBox centreBox;
    for (unsigned int i = 0; i < numGlyphs; ++i)
    {
        const osg::BoundingBox box = glyphBox(i);
        if (holdBoxes)
            boxes[i] = box;
        if (!box.valid())
            continue;
        ids.push_back(i);
        centres.push_back(box.center());
        centreBox.expandBy(centres.back());
    }

    std::vector<uint64_t> keys(ids.size());
    const osg::Vec3d extent = centreBox.valid() ? osg::Vec3d(centreBox._max - centreBox._min) : osg::Vec3d();
    const double cells = double(1 << MORTON_BITS);
    // Centres and extents overflow a float for boxes near its limit: a cell of NaN is cell 0.
    auto cell = [&](double value, double lo, double size)
    {
        const double at = (value - lo) / size * cells;
        return uint32_t(size > 0.0 && at > 0.0 ? std::min(at, cells - 1.0) : 0.0);
    };
    for (size_t k = 0; k < ids.size(); ++k)
    {
        const osg::Vec3f& c = centres[k];
        const uint32_t code = spreadBits(cell(c.x(), centreBox.xMin(), extent.x())) |
                              spreadBits(cell(c.y(), centreBox.yMin(), extent.y())) << 1 |
                              spreadBits(cell(c.z(), centreBox.zMin(), extent.z())) << 2;
        keys[k] = uint64_t(code) << 32 | ids[k];
    }
    ids = std::vector<uint32_t>();
    centres = std::vector<osg::Vec3f>();
    // By the code; stable, so glyphs of one code stay in the order of their ids.
    radixSort(keys, 3 * MORTON_BITS, [](uint64_t key) { return key >> 32; });

    GlyphChunks result;
    Splitter{keys, std::max(1u, maxChunkSize), result.chunks}.split(0, keys.size(), 0);
    result.ids.resize(keys.size());
    for (size_t k = 0; k < keys.size(); ++k)
        result.ids[k] = uint32_t(keys[k] & 0xffffffffu);
    keys = std::vector<uint64_t>();
    if (holdBoxes)
    {
        for (GlyphChunk& chunk : result.chunks)
            for (unsigned int k = chunk.first; k < chunk.first + chunk.count; ++k)
                chunk.box.expandBy(boxes[result.ids[k]]);
        return result;
    }
    const uint32_t NO_CHUNK = 0xffffffffu;
    std::vector<uint32_t> chunkOf(numGlyphs, NO_CHUNK);
    for (uint32_t c = 0; c < result.chunks.size(); ++c)
        for (unsigned int k = result.chunks[c].first; k < result.chunks[c].first + result.chunks[c].count;
             ++k)
            chunkOf[result.ids[k]] = c;
    for (unsigned int i = 0; i < numGlyphs; ++i)
        if (chunkOf[i] != NO_CHUNK)
            result.chunks[chunkOf[i]].box.expandBy(glyphBox(i));
    return result;
}

bool GlyphChunks::isIdentity(unsigned int numGlyphs) const
{
    if (ids.size() > numGlyphs)
        return false;
    for (unsigned int k = 0; k < ids.size(); ++k)
        if (ids[k] != k)
            return false;
    return true;
}
