#include "GlyphChunks.h"

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

/** Sorts (code << 32 | id) by the code, least significant digit first, 11 bits at a time. */
void radixSort(std::vector<uint64_t>& keys)
{
    std::vector<uint64_t> scratch(keys.size());
    for (int shift = 32; shift < 32 + 3 * MORTON_BITS; shift += 11)
    {
        size_t offsets[2049] = {};
        for (uint64_t key : keys)
            ++offsets[((key >> shift) & 0x7ff) + 1];
        for (size_t digit = 1; digit < 2049; ++digit)
            offsets[digit] += offsets[digit - 1];
        for (uint64_t key : keys)
            scratch[offsets[(key >> shift) & 0x7ff]++] = key;
        keys.swap(scratch);
    }
}

struct Splitter
{
    const std::vector<uint64_t>& keys;
    const osg::DrawElementsUInt& order;
    const std::function<osg::BoundingBox(unsigned int)>& glyphBox;
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
            for (size_t k = begin; k < end; ++k)
                chunk.box.expandBy(glyphBox(order[k]));
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
    // The glyph boxes are computed again where needed rather than held: 24 bytes a glyph.
    std::vector<uint32_t> ids;
    osg::BoundingBox centres;
    for (unsigned int i = 0; i < numGlyphs; ++i)
    {
        const osg::BoundingBox box = glyphBox(i);
        if (!box.valid())
            continue;
        ids.push_back(i);
        centres.expandBy(box.center());
    }

    std::vector<uint64_t> keys(ids.size());
    const osg::Vec3d extent = centres.valid() ? osg::Vec3d(centres._max - centres._min) : osg::Vec3d();
    const double cells = double(1 << MORTON_BITS);
    // Centres and extents overflow a float for boxes near its limit: a cell of NaN is cell 0.
    auto cell = [&](double value, double lo, double size)
    {
        const double at = (value - lo) / size * cells;
        return uint32_t(size > 0.0 && at > 0.0 ? std::min(at, cells - 1.0) : 0.0);
    };
    for (size_t k = 0; k < ids.size(); ++k)
    {
        const osg::Vec3 c = glyphBox(ids[k]).center();
        const uint32_t code = spreadBits(cell(c.x(), centres.xMin(), extent.x())) |
                              spreadBits(cell(c.y(), centres.yMin(), extent.y())) << 1 |
                              spreadBits(cell(c.z(), centres.zMin(), extent.z())) << 2;
        keys[k] = uint64_t(code) << 32 | ids[k];
    }
    ids = std::vector<uint32_t>();
    radixSort(keys);

    GlyphChunks result;
    result.order = new osg::DrawElementsUInt(GL_POINTS, keys.size());
    for (size_t k = 0; k < keys.size(); ++k)
        (*result.order)[k] = uint32_t(keys[k] & 0xffffffffu);
    Splitter{keys, *result.order, glyphBox, std::max(1u, maxChunkSize), result.chunks}.split(0, keys.size(),
                                                                                             0);
    return result;
}
