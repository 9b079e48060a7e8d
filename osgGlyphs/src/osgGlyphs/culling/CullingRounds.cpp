#include "CullingRounds.h"
#include "ChunkDrawer.h"
#include "OcclusionContext.h"

#include <algorithm>

using namespace osgGlyphs::detail;

void CullingRounds::run(osg::RenderInfo& renderInfo, const osg::Viewport& viewport, OcclusionContext& context,
                        std::vector<ChunkInView>& inView)
{
    osg::State& state = *renderInfo.getState();
    // After another cloud in the same camera and frame even the first round is tested: the depth
    // buffer already holds that cloud's glyphs. The rest is then one round, since read-backs of
    // the cloud's own few layers cost more than they cull.
    const bool drawnBefore = context.recordDraw(renderInfo);
    const size_t cover = putScreenCoverFirst(inView, int(viewport.width()), int(viewport.height()));
    const std::vector<size_t> ends = getRoundEnds(cover, inView.size(), drawnBefore);
    bool testing = false;
    unsigned int drawnSinceRead = 0;
    size_t begin = 0;
    for (unsigned int round = 0; round < ends.size(); ++round)
    {
        if (round > 0 && begin >= inView.size())
            break;
        // What the rounds so far drew is what this one is tested against; after a round that drew
        // nothing the pyramid read before it still holds.
        if ((round > 0 || drawnBefore) && !(testing && drawnSinceRead == 0))
        {
            testing = context.readDepth(state, viewport);
            depthRead(testing);
            drawnSinceRead = 0;
        }
        const size_t end = std::min(inView.size(), std::max(begin + 1, ends[round]));
        for (size_t k = begin; k < end; ++k)
            choose(round, inView[k], testing && isChunkHidden(inView[k], context.getPyramid()));
        begin = end;
        drawnSinceRead += draw(round, testing);
    }
}
