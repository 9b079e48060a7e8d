/* osgGlyphs - private: the passes of a DepthPeeling node in one graphics context. Not installed. */

#ifndef OSGGLYPHS_PEELINGPASSES_H
#define OSGGLYPHS_PEELINGPASSES_H 1

#include <osgGlyphs/DepthPeeling>

#include <osg/BufferIndexBinding>
#include <osg/BufferObject>
#include <osg/FrameBufferObject>
#include <osg/Geometry>
#include <osg/StateSet>
#include <osg/Texture2D>
#include <osgUtil/RenderBin>

#include <atomic>

namespace osgGlyphs
{
namespace detail
{

/** Draws a render bin in layers, by depth peeling or through a k-buffer, and blends the layers
 * over the target that was bound (see DepthPeeling). The cull traversal places the drawables under
 * getPassStateSet(), which puts them in the bin, and sets getDrawCallback() as the bin's draw
 * callback: both follow the method that was set last. */
class PeelingPasses : public osg::Referenced
{
public:
    PeelingPasses();

    void setNumLayers(unsigned int layers) { _numLayers = layers; }

    /** The method of the next cull; K_BUFFER falls back to PEEL_PASSES where a draw found that
     * the context lacks OpenGL 4.3, or where the k-buffer of the viewport would exceed the context's largest
     * shader storage block. */
    void setMethod(DepthPeeling::Method method, const osg::Viewport* viewport);

    /** Above the drawables: the render bin, the method's define and its textures and buffer. */
    osg::StateSet* getPassStateSet();

    /** The bin's draw callback, for the method of getPassStateSet(). */
    osg::ref_ptr<osgUtil::RenderBin::DrawCallback> getDrawCallback();

    /** Draws the bin as numLayers peeled passes. */
    void drawPeelPasses(osgUtil::RenderBin* bin, osg::RenderInfo& renderInfo, osgUtil::RenderLeaf*& previous,
                        unsigned int numLayers);

    /** Draws the bin once into a k-buffer of numLayers, then resolves it. */
    void drawKBuffer(osgUtil::RenderBin* bin, osg::RenderInfo& renderInfo, osgUtil::RenderLeaf*& previous,
                     unsigned int numLayers);

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

    /** The k-buffer's storage for this many pixels and layers, emptied. */
    void resizeKBuffer(osg::State& state, unsigned int pixels, unsigned int layers);

    /** Sizes the targets to the viewport (the window's origin to its far corner) and copies the
     * depth the stage drew into the opaque depth texture; false where it cannot (a multisampled
     * target), and then the bin is to be drawn unsorted. */
    bool copyOpaqueDepth(osg::State& state, const GLint viewport[4]);

    /** Draws the quad that covers the viewport under one of the composition StateSets. */
    void compose(osg::RenderInfo& renderInfo, osg::StateSet* stateSet);

    unsigned int _numLayers = 1;
    /** GL_MAX_SHADER_STORAGE_BLOCK_SIZE, once a draw has asked; until then Mesa's and the usual
     * desktop drivers' least. */
    std::atomic<long long> _maxKBufferBytes{1ll << 27};
    /** Whether the context has OpenGL 4.3, once a draw has looked (-1 until then: the cull
     * assumes it, so that every frame of a context draws alike). */
    std::atomic<int> _kBufferSupport{-1};
    DepthPeeling::Method _method = DepthPeeling::PEEL_PASSES;
    Targets _targets;
    osg::ref_ptr<osg::StateSet> _passStateSet;
    osg::ref_ptr<osg::StateSet> _kBufferStateSet;
    osg::ref_ptr<osg::StateSet> _resolveStateSet; // the k-buffer over the target
    osg::ref_ptr<osg::UIntArray> _kBuffer;
    osg::ref_ptr<osg::ShaderStorageBufferBinding> _kBufferBinding;
    osg::ref_ptr<osg::Uniform> _kBufferSize;
    osg::ref_ptr<osg::StateSet> _underStateSet; // a layer under the accumulated layers
    osg::ref_ptr<osg::StateSet> _overStateSet;  // the accumulated layers over the target
    osg::ref_ptr<osg::StateSet> _depthStateSet; // the nearest layer's depth into the target
    osg::ref_ptr<osg::Geometry> _quad;
};

}
}

#endif
