#include "PeelingPasses.h"

#include <osgGlyphs/DepthPeeling>
#include <osgGlyphs/GlyphStateCache>

#include <osg/BlendFunc>
#include <osg/ColorMask>
#include <osg/Depth>
#include <osg/GLExtensions>
#include <osg/Notify>

#include <algorithm>

using namespace osgGlyphs;
using namespace osgGlyphs::detail;

namespace
{

/** A k-buffer slot without a fragment: beyond every depth's float bits (k-buffer.glsl). */
const GLuint EMPTY_LAYER = 0xffffffffu;

osg::ref_ptr<osg::Texture2D> createTarget(int width, int height, GLint internalFormat, GLenum format)
{
    osg::ref_ptr<osg::Texture2D> texture = new osg::Texture2D;
    texture->setTextureSize(width, height);
    texture->setInternalFormat(internalFormat);
    texture->setSourceFormat(format);
    texture->setSourceType(GL_FLOAT);
    texture->setFilter(osg::Texture::MIN_FILTER, osg::Texture::NEAREST);
    texture->setFilter(osg::Texture::MAG_FILTER, osg::Texture::NEAREST);
    texture->setWrap(osg::Texture::WRAP_S, osg::Texture::CLAMP_TO_EDGE);
    texture->setWrap(osg::Texture::WRAP_T, osg::Texture::CLAMP_TO_EDGE);
    return texture;
}

osg::ref_ptr<osg::Texture2D> createDepthTarget(int width, int height)
{
    // Float depth: a layer's depth is compared with the depth its own fragments compute anew.
    return createTarget(width, height, GL_DEPTH_COMPONENT32F, GL_DEPTH_COMPONENT);
}

osg::ref_ptr<osg::Texture2D> createColorTarget(int width, int height)
{
    return createTarget(width, height, GL_RGBA16F_ARB, GL_RGBA);
}

osg::ref_ptr<osg::FrameBufferObject> createFramebuffer(osg::Texture2D* depth, osg::Texture2D* color)
{
    osg::ref_ptr<osg::FrameBufferObject> framebuffer = new osg::FrameBufferObject;
    if (depth)
        framebuffer->setAttachment(osg::Camera::DEPTH_BUFFER, osg::FrameBufferAttachment(depth));
    if (color)
        framebuffer->setAttachment(osg::Camera::COLOR_BUFFER0, osg::FrameBufferAttachment(color));
    return framebuffer;
}

/** Composition draws with the peeled drawables' StateSets still on OSG's stack: its own state
 * is protected from their overrides. */
osg::ref_ptr<osg::StateSet> createCompositionStateSet(osg::BlendFunc* blend, bool premultiply)
{
    const unsigned int ON = osg::StateAttribute::ON | osg::StateAttribute::PROTECTED;
    const unsigned int OFF = osg::StateAttribute::OFF | osg::StateAttribute::PROTECTED;
    osg::ref_ptr<osg::StateSet> stateSet = new osg::StateSet;
    stateSet->setAttributeAndModes(GlyphStateCache::instance()->getPeelingCompositeProgram(), ON);
    stateSet->setAttributeAndModes(blend, ON);
    stateSet->setAttribute(new osg::Depth(osg::Depth::ALWAYS, 0.0, 1.0, false), ON);
    stateSet->setMode(GL_DEPTH_TEST, OFF);
    stateSet->setMode(GL_CULL_FACE, OFF);
    stateSet->addUniform(new osg::Uniform("osgGlyphs_layer", static_cast<int>(PEEL_LAYER_TEXTURE_UNIT)), ON);
    stateSet->addUniform(new osg::Uniform("osgGlyphs_premultiply", premultiply ? 1.0f : 0.0f), ON);
    return stateSet;
}

/** The StateSet above the drawn children: the render bin, the method's define, the depth texture's
 * unit, depth writes, and the blending (off without one), over the children's own. */
osg::ref_ptr<osg::StateSet> createDrawStateSet(const char* name, const char* define, osg::BlendFunc* blend)
{
    const unsigned int OVERRIDE = osg::StateAttribute::ON | osg::StateAttribute::OVERRIDE;
    osg::ref_ptr<osg::StateSet> stateSet = new osg::StateSet;
    stateSet->setName(name);
    stateSet->setRenderBinDetails(DepthPeeling::RENDER_BIN_NUMBER, "RenderBin",
                                  osg::StateSet::OVERRIDE_RENDERBIN_DETAILS);
    stateSet->setNestRenderBins(false);
    stateSet->setDefine(define);
    stateSet->addUniform(new osg::Uniform("osgGlyphs_peelDepth", static_cast<int>(DEPTH_PEEL_TEXTURE_UNIT)));
    if (blend)
        stateSet->setAttributeAndModes(blend, OVERRIDE);
    else
        stateSet->setMode(GL_BLEND, osg::StateAttribute::OFF | osg::StateAttribute::OVERRIDE);
    stateSet->setAttributeAndModes(new osg::Depth(osg::Depth::LESS, 0.0, 1.0, true), OVERRIDE);
    return stateSet;
}

/** Clears and blits obey the write masks and the scissor: opens them, and lets OSG apply its own
 * again afterwards. */
void openWriteMasks(osg::State& state)
{
    glDepthMask(GL_TRUE);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDisable(GL_SCISSOR_TEST);
    state.haveAppliedAttribute(osg::StateAttribute::DEPTH);
    state.haveAppliedAttribute(osg::StateAttribute::COLORMASK);
    state.haveAppliedMode(GL_SCISSOR_TEST);
}

bool isEmpty(const osgUtil::RenderBin& bin)
{
    return bin.getStateGraphList().empty() && bin.getRenderLeafList().empty() &&
           bin.getRenderBinList().empty();
}

}

PeelingPasses::PeelingPasses()
{
    // Each pass keeps the nearest fragment per pixel; the composition blends.
    _passStateSet = createDrawStateSet("osgGlyphs depth peeling", GLYPH_DEPTH_PEEL_DEFINE, nullptr);

    // Front to back: the accumulated colour C and alpha A take a layer (c, a) under them as
    // C + (1 - A) a c and A + (1 - A) a; then over the target's colour T as C + (1 - A) T.
    _underStateSet = createCompositionStateSet(
        new osg::BlendFunc(osg::BlendFunc::ONE_MINUS_DST_ALPHA, osg::BlendFunc::ONE), true);
    _overStateSet = createCompositionStateSet(
        new osg::BlendFunc(osg::BlendFunc::ONE, osg::BlendFunc::ONE_MINUS_SRC_ALPHA), false);

    // The nearest layer's depth (the opaque scene's where it is nearer) goes into the target, as
    // a transparent surface drawn with depth writes would leave it.
    _depthStateSet =
        createCompositionStateSet(new osg::BlendFunc(osg::BlendFunc::ONE, osg::BlendFunc::ZERO), false);
    _depthStateSet->setDefine("OSGGLYPHS_PEEL_NEAREST_DEPTH",
                              osg::StateAttribute::ON | osg::StateAttribute::PROTECTED);
    _depthStateSet->setAttribute(new osg::ColorMask(false, false, false, false),
                                 osg::StateAttribute::ON | osg::StateAttribute::PROTECTED);
    _depthStateSet->setAttribute(new osg::Depth(osg::Depth::ALWAYS, 0.0, 1.0, true),
                                 osg::StateAttribute::ON | osg::StateAttribute::PROTECTED);
    _depthStateSet->setMode(GL_DEPTH_TEST, osg::StateAttribute::ON | osg::StateAttribute::PROTECTED);

    // The k-buffer pass: fragments go into the buffer. Their colour is transparent black, which
    // the blending leaves out of the target (children of other programs draw as they are); their
    // depth is the farthest layer of a full list, which culls what lies behind it.
    _kBufferStateSet = createDrawStateSet(
        "osgGlyphs k-buffer", GLYPH_K_BUFFER_DEFINE,
        new osg::BlendFunc(osg::BlendFunc::SRC_ALPHA, osg::BlendFunc::ONE_MINUS_SRC_ALPHA));
    _kBufferSize = new osg::Uniform("osgGlyphs_kBufferSize", 0, 1);
    _kBufferStateSet->addUniform(_kBufferSize.get());
    _kBufferBinding = new osg::ShaderStorageBufferBinding(K_BUFFER_BINDING);
    _kBufferStateSet->setAttribute(_kBufferBinding.get());

    _resolveStateSet = new osg::StateSet;
    const unsigned int PROTECTED = osg::StateAttribute::ON | osg::StateAttribute::PROTECTED;
    _resolveStateSet->setAttributeAndModes(GlyphStateCache::instance()->getKBufferResolveProgram(),
                                           PROTECTED);
    _resolveStateSet->setAttributeAndModes(
        new osg::BlendFunc(osg::BlendFunc::ONE, osg::BlendFunc::ONE_MINUS_SRC_ALPHA), PROTECTED);
    _resolveStateSet->setAttributeAndModes(new osg::Depth(osg::Depth::ALWAYS, 0.0, 1.0, true), PROTECTED);
    _resolveStateSet->setMode(GL_CULL_FACE, osg::StateAttribute::OFF | osg::StateAttribute::PROTECTED);
    _resolveStateSet->addUniform(_kBufferSize.get(), PROTECTED);
    _resolveStateSet->setAttribute(_kBufferBinding.get(), PROTECTED);

    _quad = osg::createTexturedQuadGeometry(osg::Vec3(-1.0f, -1.0f, 0.0f), osg::Vec3(2.0f, 0.0f, 0.0f),
                                            osg::Vec3(0.0f, 2.0f, 0.0f));
    _quad->setUseDisplayList(false);
    _quad->setUseVertexBufferObjects(true);
}

void PeelingPasses::Targets::releaseGLObjects(osg::State* state) const
{
    for (const osg::Texture2D* texture : {opaqueDepth.get(), layerDepth.get(), previousDepth.get(),
                                          nearestDepth.get(), layerColor.get(), accumulatedColor.get()})
        if (texture)
            texture->releaseGLObjects(state);
    for (const osg::FrameBufferObject* framebuffer :
         {opaque.get(), layer.get(), previous.get(), nearest.get(), accumulated.get()})
        if (framebuffer)
            framebuffer->releaseGLObjects(state);
}

void PeelingPasses::resizeTargets(osg::State& state, int width, int height)
{
    _targets.releaseGLObjects(&state);
    Targets& t = _targets;
    t.width = width;
    t.height = height;
    t.opaqueDepth = createDepthTarget(width, height);
    t.layerDepth = createDepthTarget(width, height);
    t.previousDepth = createDepthTarget(width, height);
    t.nearestDepth = createDepthTarget(width, height);
    t.layerColor = createColorTarget(width, height);
    t.accumulatedColor = createColorTarget(width, height);
    t.opaque = createFramebuffer(t.opaqueDepth.get(), nullptr);
    t.layer = createFramebuffer(t.layerDepth.get(), t.layerColor.get());
    t.previous = createFramebuffer(t.previousDepth.get(), nullptr);
    t.nearest = createFramebuffer(t.nearestDepth.get(), nullptr);
    t.accumulated = createFramebuffer(nullptr, t.accumulatedColor.get());
    // Made here, on a unit of ours: a framebuffer object would make its textures on whichever
    // unit is active, behind OSG's back, and the next drawable would sample the wrong one.
    for (osg::Texture2D* texture : {t.opaqueDepth.get(), t.layerDepth.get(), t.previousDepth.get(),
                                    t.nearestDepth.get(), t.layerColor.get(), t.accumulatedColor.get()})
        state.applyTextureAttribute(PEEL_LAYER_TEXTURE_UNIT, texture);
    state.haveAppliedTextureAttribute(PEEL_LAYER_TEXTURE_UNIT, osg::StateAttribute::TEXTURE);
    _passStateSet->setTextureAttribute(DEPTH_PEEL_TEXTURE_UNIT, t.previousDepth.get());
    _kBufferStateSet->setTextureAttribute(DEPTH_PEEL_TEXTURE_UNIT, t.opaqueDepth.get());
    const unsigned int PROTECTED = osg::StateAttribute::ON | osg::StateAttribute::PROTECTED;
    _underStateSet->setTextureAttribute(PEEL_LAYER_TEXTURE_UNIT, t.layerColor.get(), PROTECTED);
    _overStateSet->setTextureAttribute(PEEL_LAYER_TEXTURE_UNIT, t.accumulatedColor.get(), PROTECTED);
    _depthStateSet->setTextureAttribute(PEEL_LAYER_TEXTURE_UNIT, t.nearestDepth.get(), PROTECTED);
}

void PeelingPasses::compose(osg::RenderInfo& renderInfo, osg::StateSet* stateSet)
{
    osg::State& state = *renderInfo.getState();
    state.apply(stateSet);
    _quad->draw(renderInfo);
    // Back to the state of the last drawable, which the next leaf of its StateGraph expects.
    state.apply();
}

namespace
{

/** A frame's draw of the bin, by the method that was culled. */
class PeelingDraw : public osgUtil::RenderBin::DrawCallback
{
public:
    PeelingDraw(PeelingPasses* passes, bool kBuffer, unsigned int layers)
        : _passes(passes), _kBuffer(kBuffer), _layers(layers)
    {
    }

    void drawImplementation(osgUtil::RenderBin* bin, osg::RenderInfo& renderInfo,
                            osgUtil::RenderLeaf*& previous) override
    {
        if (isEmpty(*bin))
            return;
        if (_kBuffer)
            _passes->drawKBuffer(bin, renderInfo, previous, _layers);
        else
            _passes->drawPeelPasses(bin, renderInfo, previous, _layers);
    }

private:
    osg::ref_ptr<PeelingPasses> _passes;
    bool _kBuffer;
    unsigned int _layers;
};

/** Whether a context has what the k-buffer needs. */
bool supportsKBuffer(const osg::GLExtensions& ext)
{
    return ext.glVersion >= 4.3f && ext.glMemoryBarrier && ext.isFrameBufferObjectSupported;
}

/** The bytes of a k-buffer for a viewport (from the window's origin) and a number of layers. */
long long kBufferBytes(double rowPixels, double rows, unsigned int layers)
{
    return static_cast<long long>(rowPixels * rows * (1.0 + 2.0 * layers) * sizeof(GLuint));
}

}

void PeelingPasses::setMethod(DepthPeeling::Method method, const osg::Viewport* viewport)
{
    bool kBuffer = method == DepthPeeling::K_BUFFER && _kBufferSupport != 0;
    if (kBuffer && viewport)
        kBuffer = kBufferBytes(viewport->x() + viewport->width(), viewport->y() + viewport->height(),
                               _numLayers) <= _maxKBufferBytes;
    _method = kBuffer ? DepthPeeling::K_BUFFER : DepthPeeling::PEEL_PASSES;
}

osg::StateSet* PeelingPasses::getPassStateSet()
{
    return _method == DepthPeeling::K_BUFFER ? _kBufferStateSet.get() : _passStateSet.get();
}

osg::ref_ptr<osgUtil::RenderBin::DrawCallback> PeelingPasses::getDrawCallback()
{
    return new PeelingDraw(this, _method == DepthPeeling::K_BUFFER, _numLayers);
}

bool PeelingPasses::copyOpaqueDepth(osg::State& state, const GLint viewport[4])
{
    const GLint x0 = viewport[0], y0 = viewport[1], x1 = viewport[0] + viewport[2],
                y1 = viewport[1] + viewport[3];
    if (x1 != _targets.width || y1 != _targets.height)
        resizeTargets(state, x1, y1);
    // A copy rather than a blit: the target's depth format may differ. A multisampled target
    // cannot be copied.
    state.applyTextureAttribute(PEEL_LAYER_TEXTURE_UNIT, _targets.opaqueDepth.get());
    while (glGetError() != GL_NO_ERROR)
    {
    }
    glCopyTexSubImage2D(GL_TEXTURE_2D, 0, x0, y0, x0, y0, x1 - x0, y1 - y0);
    return glGetError() == GL_NO_ERROR;
}

void PeelingPasses::drawPeelPasses(osgUtil::RenderBin* bin, osg::RenderInfo& renderInfo,
                                   osgUtil::RenderLeaf*& previous, unsigned int numLayers)
{
    osg::State& state = *renderInfo.getState();
    osg::GLExtensions* ext = state.get<osg::GLExtensions>();
    _kBufferSupport = supportsKBuffer(*ext) ? 1 : 0;
    if (!ext->isFrameBufferObjectSupported || !ext->glBlitFramebuffer)
    {
        bin->drawImplementation(renderInfo, previous);
        return;
    }

    GLint targetDraw = 0, targetRead = 0, viewport[4] = {0, 0, 0, 0};
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &targetDraw);
    glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &targetRead);
    glGetIntegerv(GL_VIEWPORT, viewport);
    const GLint x0 = viewport[0], y0 = viewport[1], x1 = viewport[0] + viewport[2],
                y1 = viewport[1] + viewport[3];
    if (viewport[2] <= 0 || viewport[3] <= 0)
        return;

    // The depth of what the stage drew, which hides the layers behind it; the children are drawn
    // unsorted where it cannot be copied.
    if (!copyOpaqueDepth(state, viewport))
    {
        bin->drawImplementation(renderInfo, previous);
        return;
    }

    openWriteMasks(state);
    GLfloat clearColor[4];
    GLfloat clearDepth = 1.0f;
    glGetFloatv(GL_COLOR_CLEAR_VALUE, clearColor);
    glGetFloatv(GL_DEPTH_CLEAR_VALUE, &clearDepth);
    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);

    // Before the first layer nothing is peeled.
    _targets.previous->apply(state, osg::FrameBufferObject::DRAW_FRAMEBUFFER);
    glClearDepth(0.0);
    glClear(GL_DEPTH_BUFFER_BIT);
    glClearDepth(1.0);
    _targets.accumulated->apply(state, osg::FrameBufferObject::DRAW_FRAMEBUFFER);
    glClear(GL_COLOR_BUFFER_BIT);

    for (unsigned int layer = 0; layer < numLayers; ++layer)
    {
        openWriteMasks(state);
        _targets.opaque->apply(state, osg::FrameBufferObject::READ_FRAMEBUFFER);
        _targets.layer->apply(state, osg::FrameBufferObject::DRAW_FRAMEBUFFER);
        ext->glBlitFramebuffer(x0, y0, x1, y1, x0, y0, x1, y1, GL_DEPTH_BUFFER_BIT, GL_NEAREST);
        glClear(GL_COLOR_BUFFER_BIT);
        // Read and draw: occlusion culling reads the pass's depth back.
        _targets.layer->apply(state, osg::FrameBufferObject::READ_DRAW_FRAMEBUFFER);
        bin->drawImplementation(renderInfo, previous);

        // The layer's depth: the first for the target, each but the last for the next pass.
        const auto keepDepth = [&](osg::FrameBufferObject* target)
        {
            openWriteMasks(state);
            target->apply(state, osg::FrameBufferObject::DRAW_FRAMEBUFFER);
            // Again: making a framebuffer object binds it for reading too.
            _targets.layer->apply(state, osg::FrameBufferObject::READ_FRAMEBUFFER);
            ext->glBlitFramebuffer(x0, y0, x1, y1, x0, y0, x1, y1, GL_DEPTH_BUFFER_BIT, GL_NEAREST);
        };
        if (layer == 0)
            keepDepth(_targets.nearest.get());
        if (layer + 1 < numLayers)
            keepDepth(_targets.previous.get());

        _targets.accumulated->apply(state, osg::FrameBufferObject::READ_DRAW_FRAMEBUFFER);
        compose(renderInfo, _underStateSet.get());
    }

    ext->glBindFramebuffer(GL_DRAW_FRAMEBUFFER_EXT, targetDraw);
    ext->glBindFramebuffer(GL_READ_FRAMEBUFFER_EXT, targetRead);
    compose(renderInfo, _overStateSet.get());
    compose(renderInfo, _depthStateSet.get());
    glClearColor(clearColor[0], clearColor[1], clearColor[2], clearColor[3]);
    glClearDepth(clearDepth);
}

void PeelingPasses::resizeKBuffer(osg::State& state, unsigned int pixels, unsigned int layers)
{
    if (_kBuffer)
        _kBuffer->releaseGLObjects(&state);
    const unsigned int stride = 1 + 2 * layers;
    _kBuffer = new osg::UIntArray(pixels * stride, 0u);
    for (unsigned int pixel = 0; pixel < pixels; ++pixel)
        std::fill_n(_kBuffer->begin() + pixel * stride + 1, layers, EMPTY_LAYER);
    _kBuffer->setBufferObject(new osg::ShaderStorageBufferObject);
    _kBufferBinding->setBufferData(_kBuffer.get());
    _kBufferBinding->setOffset(0);
    _kBufferBinding->setSize(static_cast<GLsizeiptr>(_kBuffer->getTotalDataSize()));
}

void PeelingPasses::drawKBuffer(osgUtil::RenderBin* bin, osg::RenderInfo& renderInfo,
                                osgUtil::RenderLeaf*& previous, unsigned int numLayers)
{
    osg::State& state = *renderInfo.getState();
    osg::GLExtensions* ext = state.get<osg::GLExtensions>();
    _kBufferSupport = supportsKBuffer(*ext) ? 1 : 0;
    if (!_kBufferSupport)
    {
        // Only before a draw told the cull: the next frame peels in passes.
        OSG_WARN << "osgGlyphs::DepthPeeling: the k-buffer needs OpenGL 4.3; transparent children are "
                    "left out of this frame"
                 << std::endl;
        return;
    }
    GLint viewport[4] = {0, 0, 0, 0};
    glGetIntegerv(GL_VIEWPORT, viewport);
    if (viewport[2] <= 0 || viewport[3] <= 0)
        return;
    if (!copyOpaqueDepth(state, viewport))
    {
        bin->drawImplementation(renderInfo, previous);
        return;
    }
    GLint maxBytes = 0;
    glGetIntegerv(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &maxBytes);
    _maxKBufferBytes = maxBytes;
    if (kBufferBytes(viewport[0] + viewport[2], viewport[1] + viewport[3], numLayers) > maxBytes)
    {
        // Only before the cull knew the limit: the next frame peels in passes.
        OSG_WARN << "osgGlyphs::DepthPeeling: the k-buffer exceeds GL_MAX_SHADER_STORAGE_BLOCK_SIZE; "
                    "transparent children are left out of this frame"
                 << std::endl;
        return;
    }
    const int rowPixels = viewport[0] + viewport[2];
    const int layers = static_cast<int>(numLayers);
    const unsigned int pixels = static_cast<unsigned int>(rowPixels * (viewport[1] + viewport[3]));
    int previousRow = 0, previousLayers = 0;
    _kBufferSize->get(previousRow, previousLayers);
    if (!_kBuffer || previousRow != rowPixels || previousLayers != layers ||
        _kBuffer->size() != pixels * (1 + 2 * numLayers))
    {
        resizeKBuffer(state, pixels, numLayers);
        _kBufferSize->set(rowPixels, layers);
    }

    bin->drawImplementation(renderInfo, previous);
    ext->glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    openWriteMasks(state);
    compose(renderInfo, _resolveStateSet.get());
    // The lists are empty again for the next frame's fragments.
    ext->glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

void PeelingPasses::releaseGLObjects(osg::State* state)
{
    _targets.releaseGLObjects(state);
    _targets = Targets(); // made anew on the next draw
    _passStateSet->releaseGLObjects(state);
    _underStateSet->releaseGLObjects(state);
    _overStateSet->releaseGLObjects(state);
    _depthStateSet->releaseGLObjects(state);
    _kBufferStateSet->releaseGLObjects(state);
    _resolveStateSet->releaseGLObjects(state);
    if (_kBuffer)
        _kBuffer->releaseGLObjects(state);
    _quad->releaseGLObjects(state);
}
