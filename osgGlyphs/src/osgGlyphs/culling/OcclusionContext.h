/* osgGlyphs - private: a graphics context's depth read-back and depth pyramid texture. Not installed. */

#ifndef OSGGLYPHS_OCCLUSIONCONTEXT_H
#define OSGGLYPHS_OCCLUSIONCONTEXT_H 1

#include "../state/ContextRelease.h"
#include "BinRounds.h"
#include "DepthPyramid.h"

#include <osgGlyphs/TextureUnits>

#include <osg/GLObjects>
#include <osg/Image>
#include <osg/RenderInfo>
#include <osg/State>
#include <osg/Texture2D>
#include <osg/Viewport>

namespace osgGlyphs
{
namespace detail
{

/** The most levels of the depth pyramid the glyph programs read: 2^16 pixels a side. */
const int MAX_PYRAMID_TEXTURE_LEVELS = 16;

/** What occlusion culling needs in one graphics context: the depth it reads back, the pyramid
 * built over it, and that pyramid as a texture for the glyph programs: one level, an atlas of
 * the pyramid's levels from level 1 up (llvmpipe fetches wrong texels when the lanes of one
 * texelFetch ask for different mipmap levels). Lives in the context's osg::ContextData (osg::get<>), so only
 * the context's draw thread uses it, and releases its texture when OSG deletes the context's objects. */
class OcclusionContext : public ContextRelease
{
public:
    explicit OcclusionContext(unsigned int contextID);

    /** Reads back the depth under the viewport and builds the pyramid over it; false (and no
     * pyramid) where the read failed. */
    bool readDepth(osg::State& state, const osg::Viewport& viewport);

    const DepthPyramid& getPyramid() const { return _pyramid; }

    /** Records that a cloud draws into the current camera in this frame; true when another one
     * already did, so that the depth buffer holds its glyphs (clouds side by side). */
    bool recordDraw(osg::RenderInfo& renderInfo);

    /** The rounds a FRONT_TO_BACK_BIN chose for its clouds while it draws them, or null. */
    void setBinRounds(BinRounds* rounds) { _binRounds = rounds; }
    /** What the bin being drawn chose for the cloud of these chunks this round; null outside a
     * bin's draw, or for a cloud it does not cull. */
    CloudRound* findBinRound(const GlyphChunks* chunks) const
    {
        if (!_binRounds)
            return nullptr;
        const auto found = _binRounds->find(chunks);
        return found == _binRounds->end() ? nullptr : &found->second;
    }

    /** Uploads the pyramid and binds it on DEPTH_PYRAMID_TEXTURE_UNIT; returns the levels in the
     * atlas (0: nothing to test against), whose rectangles (x, y, width, height) getAtlasLevels()
     * lists: entry j holds the pyramid's level j + 1. */
    int applyPyramidTexture(osg::State& state);
    const std::vector<GLint>& getAtlasLevels() const { return _atlasLevels; }

protected:
    void releaseContext() override;

    DepthPyramid _pyramid;
    BinRounds* _binRounds = nullptr;
    bool _atlasCurrent = false;               // the texture holds the pyramid
    const osg::Camera* _lastCamera = nullptr; // compared, never followed
    unsigned int _lastFrame = 0;
    std::vector<GLint> _atlasLevels;
    osg::ref_ptr<osg::Image> _image;
    osg::ref_ptr<osg::Texture2D> _texture;
};

}
}

#endif
