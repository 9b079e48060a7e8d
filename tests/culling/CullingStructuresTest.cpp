// The structures of culling against brute force: the depth pyramid bounds every rectangle's
// farthest depth from above, tightly at level 0; the spatial order is a permutation of the drawn
// glyphs, and each chunk's box holds its glyphs.

#include "culling/DepthPyramid.h"
#include "culling/GlyphChunks.h"
#include "culling/ScreenCover.h"
#include <osgGlyphsInternal/RadixSort.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <random>
#include <set>

using namespace osgGlyphs::detail;

namespace
{

std::vector<unsigned int> orderOf(const GlyphChunks& chunks)
{
    return chunks.ids;
}

}

TEST(DepthPyramid, BoundsEveryRectangleFromAbove)
{
    std::mt19937 random(3);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    // One pyramid, built again over images of other sizes: it keeps its levels' storage.
    DepthPyramid pyramid;
    for (const auto& size :
         {std::pair<int, int>(64, 64), std::pair<int, int>(37, 23), std::pair<int, int>(1, 9),
          std::pair<int, int>(9, 1), std::pair<int, int>(65, 34)})
    {
        const int width = size.first, height = size.second;
        std::vector<float> depth(size_t(width) * height);
        for (float& d : depth)
            d = unit(random);
        pyramid.build(depth, width, height);
        ASSERT_TRUE(pyramid.valid());
        EXPECT_EQ(pyramid.getWidth(pyramid.getNumLevels() - 1), 1);
        EXPECT_EQ(pyramid.getHeight(pyramid.getNumLevels() - 1), 1);
        // Each texel is the farthest of exactly the pixels its class comment gives it.
        for (int level = 1; level < pyramid.getNumLevels(); ++level)
        {
            const int w = pyramid.getWidth(level), h = pyramid.getHeight(level);
            ASSERT_EQ(pyramid.getLevel(level).size(), size_t(w) * h);
            std::vector<float> truth(size_t(w) * h, 0.0f);
            for (int y = 0; y < height; ++y)
                for (int x = 0; x < width; ++x)
                {
                    float& texel =
                        truth[size_t(std::min(y >> level, h - 1)) * w + std::min(x >> level, w - 1)];
                    texel = std::max(texel, depth[size_t(y) * width + x]);
                }
            ASSERT_EQ(pyramid.getLevel(level), truth) << width << "x" << height << ", level " << level;
        }
        for (int trial = 0; trial < 2000; ++trial)
        {
            int x0 = int(unit(random) * width), x1 = int(unit(random) * width);
            int y0 = int(unit(random) * height), y1 = int(unit(random) * height);
            if (x0 > x1)
                std::swap(x0, x1);
            if (y0 > y1)
                std::swap(y0, y1);
            float truth = 0.0f;
            for (int y = y0; y <= y1; ++y)
                for (int x = x0; x <= x1; ++x)
                    truth = std::max(truth, depth[size_t(y) * width + x]);
            for (int texels : {2, 4, 16})
                ASSERT_GE(pyramid.farthest(x0, y0, x1, y1, texels), truth)
                    << width << "x" << height << " [" << x0 << "," << x1 << "]x[" << y0 << "," << y1 << "]";
            if (x1 - x0 < 2 && y1 - y0 < 2)
            {
                EXPECT_EQ(pyramid.farthest(x0, y0, x1, y1), truth) << "level 0 is exact";
            }
        }
    }
}

TEST(GlyphChunks, OrderIsAPermutationOfTheDrawnGlyphsAndBoxesHoldThem)
{
    std::mt19937 random(5);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    std::vector<osg::BoundingBox> boxes(5000);
    for (size_t i = 0; i < boxes.size(); ++i)
    {
        if (i % 97 == 0)
            continue; // not drawn
        // A cluster of coincident glyphs as well: more than a chunk in one cell.
        const osg::Vec3 centre =
            i < 1500 ? osg::Vec3(0.5f, 0.5f, 0.5f) : osg::Vec3(unit(random), unit(random), unit(random));
        boxes[i].expandBy(centre - osg::Vec3(0.01f, 0.01f, 0.01f));
        boxes[i].expandBy(centre + osg::Vec3(0.01f, 0.01f, 0.01f));
    }
    const GlyphChunks chunks = buildGlyphChunks(
        unsigned(boxes.size()), [&](unsigned int i) { return boxes[i]; }, 64);
    const std::vector<unsigned int> order = orderOf(chunks);
    std::multiset<unsigned int> ids(order.begin(), order.end());
    unsigned int drawn = 0;
    for (unsigned int i = 0; i < boxes.size(); ++i)
    {
        drawn += boxes[i].valid();
        EXPECT_EQ(ids.count(i), boxes[i].valid() ? 1u : 0u) << i;
    }
    EXPECT_EQ(order.size(), drawn);
    unsigned int covered = 0;
    for (const GlyphChunk& chunk : chunks.chunks)
    {
        EXPECT_EQ(chunk.first, covered);
        covered += chunk.count;
        for (unsigned int k = chunk.first; k < chunk.first + chunk.count; ++k)
        {
            const osg::BoundingBox& box = boxes[order[k]];
            EXPECT_TRUE(chunk.box.contains(box._min) && chunk.box.contains(box._max));
        }
    }
    EXPECT_EQ(covered, drawn);
    EXPECT_GT(chunks.chunks.size(), drawn / 64);
}

// Boxes near the limit of a float have centres and extents that overflow it: the order still holds
// each drawn glyph once, and casts no NaN to a cell number (UBSan).
TEST(GlyphChunks, BoxesBeyondTheRangeOfAFloatAreOrderedToo)
{
    const float huge = 3e38f;
    std::vector<osg::BoundingBox> boxes(4);
    boxes[0].set(-huge, -huge, -huge, -huge * 0.5f, -huge * 0.5f, -huge * 0.5f);
    boxes[1].set(huge * 0.5f, huge * 0.5f, huge * 0.5f, huge, huge, huge);
    boxes[2].set(-1.0f, -1.0f, -1.0f, 1.0f, 1.0f, 1.0f);
    boxes[3].set(huge, huge, huge, std::numeric_limits<float>::infinity(), huge, huge);
    const GlyphChunks chunks = buildGlyphChunks(
        unsigned(boxes.size()), [&](unsigned int i) { return boxes[i]; }, 1);
    const std::vector<unsigned int> order = orderOf(chunks);
    const std::multiset<unsigned int> ids(order.begin(), order.end());
    EXPECT_EQ(ids, (std::multiset<unsigned int>{0, 1, 2, 3}));
}

// Glyphs already in spatial order are drawn from the caller's arrays (no copy), with glyphs not
// drawn after them; any other order, or a glyph left out before others, is not the identity.
TEST(GlyphChunks, GlyphsInSpatialOrderAreTheIdentity)
{
    // A 16^3 lattice listed in Morton order, then the same listed row by row.
    auto mortonCell = [](unsigned int i)
    {
        unsigned int x = 0, y = 0, z = 0;
        for (unsigned int bit = 0; bit < 4; ++bit)
        {
            x |= ((i >> (3 * bit)) & 1u) << bit;
            y |= ((i >> (3 * bit + 1)) & 1u) << bit;
            z |= ((i >> (3 * bit + 2)) & 1u) << bit;
        }
        return osg::Vec3(float(x), float(y), float(z));
    };
    auto rowCell = [](unsigned int i)
    { return osg::Vec3(float(i % 16), float(i / 16 % 16), float(i / 256)); };
    auto boxes = [](auto cell)
    {
        return [cell](unsigned int i) {
            return osg::BoundingBox(cell(i) - osg::Vec3(0.4f, 0.4f, 0.4f),
                                    cell(i) + osg::Vec3(0.4f, 0.4f, 0.4f));
        };
    };
    const GlyphChunks inOrder = buildGlyphChunks(4096, boxes(mortonCell), 64);
    EXPECT_TRUE(inOrder.isIdentity(4096));
    EXPECT_TRUE(inOrder.isIdentity(4097)) << "a last glyph not drawn";
    EXPECT_FALSE(inOrder.isIdentity(4095));
    const GlyphChunks byRows = buildGlyphChunks(4096, boxes(rowCell), 64);
    EXPECT_FALSE(byRows.isIdentity(4096));
    const GlyphChunks firstLeftOut = buildGlyphChunks(
        4096, [&](unsigned int i) { return i == 0 ? osg::BoundingBox() : boxes(mortonCell)(i); }, 64);
    EXPECT_FALSE(firstLeftOut.isIdentity(4096));
}

namespace
{

ChunkInView chunkInView(unsigned int chunk, float nearest, int x0, int y0, int x1, int y1)
{
    return ChunkInView{chunk, nearest, x0, y0, x1, y1};
}

std::vector<unsigned int> chunkIds(const std::vector<ChunkInView>& chunks)
{
    std::vector<unsigned int> ids;
    for (const ChunkInView& chunk : chunks)
        ids.push_back(chunk.chunk);
    return ids;
}

}

// Against std::stable_sort: 63-bit keys with many equal ones, keys whose high digits all items
// share (skipped passes), an odd number of moving passes, and a sub-range of a larger array.
TEST(RadixSort, SortsAsStableSortDoes)
{
    using Keyed = std::pair<uint64_t, unsigned int>;
    std::mt19937_64 random(7);
    for (const uint64_t keyMask : {uint64_t(0x7fffffffffffffff), uint64_t(0x3f), uint64_t(0x1fffff)})
        for (const uint64_t sharedHigh : {uint64_t(0), uint64_t(0x5a5) << 52})
        {
            std::vector<Keyed> items(20011);
            for (unsigned int i = 0; i < items.size(); ++i)
                items[i] = {sharedHigh | (random() & keyMask & (i % 3 ? ~uint64_t(0) : uint64_t(0xff))), i};
            std::vector<Keyed> expected(items.begin() + 5, items.end() - 6);
            std::stable_sort(expected.begin(), expected.end(),
                             [](const Keyed& a, const Keyed& b) { return a.first < b.first; });
            osgGlyphs::detail::radixSort(items.data() + 5, items.data() + items.size() - 6, 63,
                                         [](const Keyed& k) { return k.first; });
            EXPECT_TRUE(std::equal(expected.begin(), expected.end(), items.begin() + 5))
                << "mask " << keyMask << ", shared " << sharedHigh;
            EXPECT_EQ(items.front().second, 0u);
            EXPECT_EQ(items.back().second, items.size() - 1);
        }
}

TEST(ScreenCover, TheChunksThatFirstCoverEachCellComeFirstInTheirOrder)
{
    // A 64x32 view: a wall of 16x16 chunks with a hole at (16..31, 16..31), then a chunk over
    // the whole view, which fills the hole, then one in the hole, behind both.
    std::vector<ChunkInView> chunks;
    unsigned int id = 0;
    for (int y = 0; y < 32; y += 16)
        for (int x = 0; x < 64; x += 16)
            if (x != 16 || y != 16)
            {
                chunks.push_back(chunkInView(id, 0.1f + 0.01f * float(id), x, y, x + 15, y + 15));
                ++id;
            }
    chunks.insert(chunks.begin() + 3, chunkInView(100, 0.12f, 0, 0, 63, 31)); // nearer than some wall chunks
    chunks.push_back(chunkInView(101, 0.6f, 16, 16, 31, 31));
    const size_t cover = putScreenCoverFirst(chunks, 64, 32);
    // The whole-view chunk covers the cells the first three wall chunks leave; those after it
    // cover nothing new, nor does the one behind the hole.
    EXPECT_EQ(cover, 4u);
    EXPECT_EQ(chunkIds(chunks), (std::vector<unsigned int>{0, 1, 2, 100, 3, 4, 5, 6, 101}));
}

TEST(ScreenCover, ChunksCoverTheCellsWhollyInsideTheirRectangle)
{
    // 8-pixel cells: a rectangle from pixel 4 to 27 holds cells 1 and 2 only.
    std::vector<ChunkInView> chunks = {chunkInView(0, 0.1f, 4, 0, 27, 7), chunkInView(1, 0.2f, 8, 0, 23, 7),
                                       chunkInView(2, 0.3f, 0, 0, 7, 7)};
    EXPECT_EQ(putScreenCoverFirst(chunks, 32, 8), 2u);
    EXPECT_EQ(chunkIds(chunks), (std::vector<unsigned int>{0, 2, 1}));
}

TEST(ScreenCover, SmallChunksCoverTheirCentresCellAndTheViewsEdgeEndsACell)
{
    // A 20-pixel-wide view: its last cell (16..19) is cut short and counts as whole.
    std::vector<ChunkInView> chunks = {chunkInView(0, 0.1f, 16, 0, 19, 7), chunkInView(1, 0.2f, 17, 2, 18, 4),
                                       chunkInView(2, 0.3f, 9, 1, 12, 3), chunkInView(3, 0.4f, 10, 0, 11, 7)};
    EXPECT_EQ(putScreenCoverFirst(chunks, 20, 8), 2u);
    EXPECT_EQ(chunkIds(chunks), (std::vector<unsigned int>{0, 2, 1, 3}));
    std::vector<ChunkInView> none;
    EXPECT_EQ(putScreenCoverFirst(none, 20, 8), 0u);
}
