/* osgGlyphs - private: the rounds of occlusion culling, for one cloud or a bin of clouds. Not installed. */

#ifndef OSGGLYPHS_CULLINGROUNDS_H
#define OSGGLYPHS_CULLINGROUNDS_H 1

#include "ScreenCover.h"

#include <osg/RenderInfo>
#include <osg/Viewport>

#include <vector>

namespace osgGlyphs
{
namespace detail
{

class OcclusionContext;

/** The one round loop of occlusion culling. A cloud drawn alone (drawChunks) and a
 * FRONT_TO_BACK_BIN's clouds drawn together (drawBinInRounds) run it over their chunks in view,
 * nearest first; they differ in what a round's draw is. The first round lays down the front over
 * the view (putScreenCoverFirst); before each round after it, or before the first too when
 * another cloud drew into the camera this frame, the depth is read back into the context's
 * pyramid and the round's chunks behind it are left out. */
class CullingRounds
{
public:
    virtual ~CullingRounds() = default;

    /** Runs the rounds over inView (sorted nearest first; reordered). */
    void run(osg::RenderInfo& renderInfo, const osg::Viewport& viewport, OcclusionContext& context,
             std::vector<ChunkInView>& inView);

protected:
    /** The depth was read back before a round: testing is whether the pyramid holds it. */
    virtual void depthRead(bool testing) = 0;
    /** One of the round's chunks in view, and whether it lies behind the pyramid. */
    virtual void choose(unsigned int round, const ChunkInView& chunk, bool hidden) = 0;
    /** Draws the round's chunks that were not hidden; returns the glyphs drawn. */
    virtual unsigned int draw(unsigned int round, bool testing) = 0;
};

}
}

#endif
