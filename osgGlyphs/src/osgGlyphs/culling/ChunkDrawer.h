/* osgGlyphs - private: draws a cloud's chunks, culled. Not installed. */

#ifndef OSGGLYPHS_CHUNKDRAWER_H
#define OSGGLYPHS_CHUNKDRAWER_H 1

#include "GlyphChunks.h"

#include <osgGlyphs/GlyphCulling>

#include <osg/RenderInfo>

namespace osgGlyphs
{
namespace detail
{

/** Draws the chunks of a cloud whose vertex arrays (in the chunks' order, see DrawnArrays) are set
 * up and whose program is applied. It skips the chunks outside the view; for
 * GlyphCulling::Occlusion, where the depth can be tested,
 * it draws the rest in rounds: first the chunks that lay down the cloud's front over the view
 * (putScreenCoverFirst), then the others nearest first. Before each round after the first it
 * reads the depth back into a pyramid, skips the round's chunks that lie behind it and has the
 * glyph programs skip the glyphs that do. Where outcomes is given, it gets each chunk's
 * GlyphCullingOutcome. */
GlyphCullingStatistics drawChunks(osg::RenderInfo& renderInfo, const GlyphChunks& chunks,
                                  GlyphCulling culling, std::vector<unsigned char>* outcomes = nullptr);

}
}

#endif
