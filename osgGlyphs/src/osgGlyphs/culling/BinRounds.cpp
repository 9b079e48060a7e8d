#include "BinRounds.h"
#include "ChunkDrawer.h"
#include "CullingRounds.h"
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

/** The bin's rounds: each sets what every cloud is to draw in it (CloudRound) and renders the
 * clouds' leaves, whose draws find it through the context (OcclusionContext::findBinRound). */
class BinCloudRounds : public CullingRounds
{
public:
    BinCloudRounds(osg::RenderInfo& renderInfo, osgUtil::RenderLeaf*& previous,
                   std::vector<PlannedCloud>& clouds, const std::vector<BinChunk>& where)
        : _renderInfo(renderInfo), _previous(previous), _clouds(clouds), _where(where)
    {
    }

protected:
    void depthRead(bool) override { ++_unclaimedReads; }

    void choose(unsigned int, const ChunkInView& chunk, bool hidden) override
    {
        if (!hidden)
            _clouds[_where[chunk.chunk].cloud].round->chunks.push_back(_where[chunk.chunk].chunk);
    }

    unsigned int draw(unsigned int round, bool testing) override
    {
        unsigned int drawn = 0;
        for (PlannedCloud& cloud : _clouds)
        {
            CloudRound& planned = *cloud.round;
            planned.round = round;
            planned.testing = testing;
            // Every cloud draws in the first round (its first draw in the frame), the others only
            // where it has chunks to draw.
            if (round == 0 || (!planned.drewAll && !planned.chunks.empty()))
            {
                planned.depthReadbacks = _unclaimedReads; // counted by the next cloud drawn
                _unclaimedReads = 0;
                render(cloud.leaf, _renderInfo, _previous);
                // What it drew: the round's chunks, or all in view where it could not be culled.
                for (unsigned int chunk : planned.chunks)
                    drawn += cloud.chunks->chunks[chunk].count;
            }
            planned.chunks.clear();
        }
        return drawn;
    }

private:
    osg::RenderInfo& _renderInfo;
    osgUtil::RenderLeaf*& _previous;
    std::vector<PlannedCloud>& _clouds;
    const std::vector<BinChunk>& _where;
    unsigned int _unclaimedReads = 0;
};

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
    std::stable_sort(inView.begin(), inView.end(),
                     [](const ChunkInView& a, const ChunkInView& b) { return a.nearest < b.nearest; });
    BinCloudRounds(renderInfo, previous, clouds, where).run(renderInfo, *viewport, *context, inView);
    context->setBinRounds(nullptr);
}
