#include "BinRounds.h"
#include "ChunkDrawer.h"
#include "OcclusionContext.h"
#include "ScreenCover.h"

#include <osgGlyphs/GlyphCloud>

#include <osg/ContextData>

#include <algorithm>

using namespace osgGlyphs;
using namespace osgGlyphs::detail;

namespace
{

/** A cloud of the bin that culls with chunks, and its chunks in view. */
struct PlannedCloud
{
    osgUtil::RenderLeaf* leaf;
    std::shared_ptr<const GlyphChunks> chunks;
    CloudRound* round;
};

/** One chunk in view of one of the bin's clouds. */
struct BinChunk
{
    unsigned int cloud;
    unsigned int chunk;
};

void render(osgUtil::RenderLeaf* leaf, osg::RenderInfo& renderInfo, osgUtil::RenderLeaf*& previous)
{
    leaf->render(renderInfo, previous);
    previous = leaf;
}

}

void osgGlyphs::detail::drawBinInRounds(osg::RenderInfo& renderInfo, osgUtil::RenderLeaf*& previous,
                                        const std::vector<osgUtil::RenderLeaf*>& leaves)
{
    osg::State& state = *renderInfo.getState();
    const osg::Viewport* viewport = state.getCurrentViewport();
    GLint sampleBuffers = 0;
    glGetIntegerv(GL_SAMPLE_BUFFERS, &sampleBuffers);
    std::vector<PlannedCloud> clouds;
    BinRounds rounds;
    std::vector<ChunkInView> inView; // every cloud's, with the index into `where` as its chunk
    std::vector<BinChunk> where;
    for (osgUtil::RenderLeaf* leaf : leaves)
    {
        const auto* cloud = dynamic_cast<const GlyphCloud*>(leaf->getDrawable());
        std::shared_ptr<const GlyphChunks> chunks = cloud ? cloud->getCullingChunks() : nullptr;
        if (!chunks || !viewport || sampleBuffers != 0 || rounds.count(chunks.get()))
        {
            render(leaf, renderInfo, previous); // drawn as it would be alone, before the clouds
            continue;
        }
        osg::Matrixd modelViewProjection = leaf->_modelview.valid() ? *leaf->_modelview : osg::Matrixd();
        if (leaf->_projection.valid())
            modelViewProjection.postMult(*leaf->_projection);
        CloudRound& round = rounds[chunks.get()];
        for (const ChunkInView& chunk :
             projectChunks(*chunks, modelViewProjection, viewport->width(), viewport->height(), 0.0f, 1.0f))
        {
            round.inView.push_back(chunk.chunk);
            where.push_back({static_cast<unsigned int>(clouds.size()), chunk.chunk});
            inView.push_back(chunk);
            inView.back().chunk = static_cast<unsigned int>(where.size() - 1);
        }
        clouds.push_back({leaf, chunks, &round});
    }
    if (clouds.empty())
        return;

    OcclusionContext* context = osg::get<OcclusionContext>(state.getContextID());
    context->setBinRounds(&rounds);
    const bool drawnBefore = context->recordDraw(renderInfo);
    std::stable_sort(inView.begin(), inView.end(),
                     [](const ChunkInView& a, const ChunkInView& b) { return a.nearest < b.nearest; });
    const size_t cover = putScreenCoverFirst(inView, int(viewport->width()), int(viewport->height()));
    std::vector<size_t> ends = getRoundEnds(cover, inView.size(), drawnBefore);
    bool testing = false;
    unsigned int drawnSinceRead = 0, unclaimedReads = 0;
    size_t begin = 0;
    for (unsigned int roundIndex = 0; roundIndex < ends.size(); ++roundIndex)
    {
        // Every cloud draws in the first round (its first draw in the frame), the others only
        // where they have chunks to draw.
        if (roundIndex > 0 && begin >= inView.size())
            break;
        if ((roundIndex > 0 || drawnBefore) && !(testing && drawnSinceRead == 0))
        {
            testing = context->readDepth(state, *viewport);
            ++unclaimedReads; // counted by the next cloud drawn
            drawnSinceRead = 0;
        }
        for (PlannedCloud& cloud : clouds)
        {
            cloud.round->round = roundIndex;
            cloud.round->chunks.clear();
            cloud.round->testing = testing;
        }
        const size_t end = std::min(inView.size(), std::max(begin + 1, ends[roundIndex]));
        for (size_t k = begin; k < end; ++k)
            if (!(testing && isChunkHidden(inView[k], context->getPyramid())))
            {
                const BinChunk& chunk = where[inView[k].chunk];
                clouds[chunk.cloud].round->chunks.push_back(chunk.chunk);
            }
        begin = end;
        for (PlannedCloud& cloud : clouds)
        {
            CloudRound& round = *cloud.round;
            if (roundIndex > 0 && (round.drewAll || round.chunks.empty()))
                continue;
            round.depthReadbacks = unclaimedReads;
            unclaimedReads = 0;
            render(cloud.leaf, renderInfo, previous);
            // What it drew: the round's chunks, or all in view where it could not be culled.
            for (unsigned int chunk : round.chunks)
                drawnSinceRead += cloud.chunks->chunks[chunk].count;
        }
    }
    context->setBinRounds(nullptr);
}
