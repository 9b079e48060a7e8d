#include "GlyphChunks.h"
#include "RadixSort.h"

#include <algorithm>
#include <cstdint>

using namespace osgGlyphs::detail;

namespace
{

const int MORTON_BITS = 10; // per axis: a 1024^3 grid over the cloud

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
    // Each glyph's box is computed twice, both times in the glyphs' own order (memory order),
    // rather than held (24 bytes a glyph): for its centre, then for its chunk's box.
    std::vector<uint32_t> ids;
    std::vector<osg::Vec3f> centres;
    osg::BoundingBox centreBox;
    for (unsigned int i = 0; i < numGlyphs; ++i)
    {
        const osg::BoundingBox box = glyphBox(i);
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
    const uint32_t NO_CHUNK = 0xffffffffu;
    std::vector<uint32_t> chunkOf(numGlyphs, NO_CHUNK);
    result.ids.resize(keys.size());
    for (uint32_t c = 0; c < result.chunks.size(); ++c)
        for (size_t k = result.chunks[c].first; k < result.chunks[c].first + result.chunks[c].count; ++k)
        {
            const uint32_t id = uint32_t(keys[k] & 0xffffffffu);
            result.ids[k] = id;
            chunkOf[id] = c;
        }
    keys = std::vector<uint64_t>();
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
