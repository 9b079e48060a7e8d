/* osgGlyphs - private: the passes of a DepthPeeling node in one graphics context. Not installed. */

#ifndef OSGGLYPHS_PEELINGPASSES_H
#define OSGGLYPHS_PEELINGPASSES_H 1

#include <osg/FrameBufferObject>
#include <osg/Geometry>
#include <osg/StateSet>
#include <osg/Texture2D>
#include <osgUtil/RenderBin>

namespace osgGlyphs
{
namespace detail
{

/** Draws a render bin in layers by depth peeling, and blends the layers over the target that was
 * bound (see DepthPeeling). The cull traversal places the peeled drawables under
 * getPassStateSet(), which puts them in the bin, and sets this as the bin's draw callback. */
class PeelingPasses : public osgUtil::RenderBin::DrawCallback
{
public:
    PeelingPasses();

    /** Above the peeled drawables: the render bin, the peel define and the previous layer. */
    osg::StateSet* getPassStateSet() { return _passStateSet.get(); }

    void setNumLayers(unsigned int layers) { _numLayers = layers; }

    void drawImplementation(osgUtil::RenderBin* bin, osg::RenderInfo& renderInfo,
                            osgUtil::RenderLeaf*& previous) override;

    /** Releases the GL objects of a context (all without one); the targets are made anew. */
    void releaseGLObjects(osg::State* state);

protected:
    /** The textures and framebuffers of a target of this size. */
    struct Targets
    {
        int width = 0;
        int height = 0;
        osg::ref_ptr<osg::Texture2D> opaqueDepth, layerDepth, previousDepth, nearestDepth, layerColor,
            accumulatedColor;
        osg::ref_ptr<osg::FrameBufferObject> opaque, layer, previous, nearest, accumulated;

        void releaseGLObjects(osg::State* state) const;
    };

    /** Makes the targets of this size, after releasing the old ones in the context. */
    void resizeTargets(osg::State& state, int width, int height);

    /** Draws the quad that covers the viewport under one of the composition StateSets. */
    void compose(osg::RenderInfo& renderInfo, osg::StateSet* stateSet);

    unsigned int _numLayers = 1;
    Targets _targets;
    osg::ref_ptr<osg::StateSet> _passStateSet;
    osg::ref_ptr<osg::StateSet> _underStateSet; // a layer under the accumulated layers
    osg::ref_ptr<osg::StateSet> _overStateSet;  // the accumulated layers over the target
    osg::ref_ptr<osg::StateSet> _depthStateSet; // the nearest layer's depth into the target
    osg::ref_ptr<osg::Geometry> _quad;
};

}
}

#endif
