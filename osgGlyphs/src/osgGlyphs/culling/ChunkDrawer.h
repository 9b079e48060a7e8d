/* osgGlyphs - private: draws a cloud's chunks, culled. Not installed. */

#ifndef OSGGLYPHS_CHUNKDRAWER_H
#define OSGGLYPHS_CHUNKDRAWER_H 1

#include "DepthPyramid.h"
#include "GlyphChunks.h"
#include "ScreenCover.h"

#include <osgGlyphs/GlyphCulling>

#include <osg/RenderInfo>

namespace osgGlyphs
{
namespace detail
{

/** Draws the chunks of a cloud whose vertex arrays (in the chunks' order, see DrawnArrays) are set
 * up and whose program is applied, and sets statistics to what it did. It skips the chunks
 * outside the view; for GlyphCulling::Occlusion, where the depth can be tested, it draws the rest
 * in rounds: first the chunks that lay down the cloud's front over the view
 * (putScreenCoverFirst), then the others nearest first. Before each round after the first it
 * reads the depth back into a pyramid, skips the round's chunks that lie behind it and has the
 * glyph programs skip the glyphs that do. Where outcomes is given, it gets each chunk's
 * GlyphCullingOutcome. In a FRONT_TO_BACK_BIN the bin chooses the rounds for all its clouds
 * together (drawBinInRounds), which draws each cloud once a round: this draws the round's chunks
 * and adds to statistics. Returns whether this is the cloud's first draw in the frame. */
bool drawChunks(osg::RenderInfo& renderInfo, const GlyphChunks& chunks, GlyphCulling culling,
                GlyphCullingStatistics& statistics, std::vector<unsigned char>* outcomes = nullptr);

/** A cloud's chunks in view with this model-view-projection and window, nearest first. */
std::vector<ChunkInView> projectChunks(const GlyphChunks& chunks, const osg::Matrixd& modelViewProjection,
                                       double width, double height, float depthNear, float depthFar);

/** Where the rounds end in a list of `size` chunks in view, nearest first, of which the first
 * `cover` lay down the front: after those, then at fractions of the rest, or at its end only for
 * a list that is tested from its first round on. */
std::vector<size_t> getRoundEnds(size_t cover, size_t size, bool testedFromStart);

/** Whether the chunk lies wholly behind the pyramid. */
bool isChunkHidden(const ChunkInView& chunk, const DepthPyramid& pyramid);

}
}

#endif
