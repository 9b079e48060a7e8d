/* osgGlyphs - private: the rounds in which FRONT_TO_BACK_BIN culls all its clouds together. Not installed. */

#ifndef OSGGLYPHS_BINROUNDS_H
#define OSGGLYPHS_BINROUNDS_H 1

#include "GlyphChunks.h"

#include <osgUtil/RenderLeaf>

#include <map>
#include <vector>

namespace osgGlyphs
{
namespace detail
{

/** What the bin's draw decided for one of its clouds, for the draw of the current round. */
struct CloudRound
{
    /** The cloud's chunks in view, and how many of them it drew in the rounds so far. */
    std::vector<unsigned int> inView;
    unsigned int chunksDrawn = 0;
    /** The round and the chunks to draw in it; whether they were tested against the pyramid
     * (then the glyph programs test each glyph too). */
    unsigned int round = 0;
    std::vector<unsigned int> chunks;
    bool testing = false;
    /** The bin's read-backs since the cloud last drew: they count in its statistics. */
    unsigned int depthReadbacks = 0;
    /** Whether the cloud drew every chunk in view in the first round: it could not be tested
     * (its state tests depth otherwise than occlusion culling needs). */
    bool drewAll = false;
};

/** The clouds of one draw of the bin, by their chunks, while the bin draws them. */
using BinRounds = std::map<const GlyphChunks*, CloudRound>;

/** Draws the bin's leaves: first those that are not clouds culling with chunks, then the clouds'
 * chunks in rounds over all of them together, nearest first, as one cloud culls its own
 * (drawChunks): one read-back a round for the whole bin, not one for each cloud. */
void drawBinInRounds(osg::RenderInfo& renderInfo, osgUtil::RenderLeaf*& previous,
                     const std::vector<osgUtil::RenderLeaf*>& leaves);

}
}

#endif
