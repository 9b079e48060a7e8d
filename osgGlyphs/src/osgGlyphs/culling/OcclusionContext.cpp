#include "OcclusionContext.h"

#include <osg/GLExtensions>

#include <algorithm>
#include <cstring>

using namespace osgGlyphs::detail;

OcclusionContext::OcclusionContext(unsigned int contextID)
    : ContextRelease("osgGlyphs::OcclusionContext", contextID), _image(new osg::Image),
      _texture(new osg::Texture2D)
{
    _texture->setImage(_image.get());
    _texture->setInternalFormat(GL_R32F);
    _texture->setResizeNonPowerOfTwoHint(false);
    _texture->setUseHardwareMipMapGeneration(false);
    _texture->setFilter(osg::Texture::MIN_FILTER, osg::Texture::NEAREST);
    _texture->setFilter(osg::Texture::MAG_FILTER, osg::Texture::NEAREST);
    _texture->setWrap(osg::Texture::WRAP_S, osg::Texture::CLAMP_TO_EDGE);
    _texture->setWrap(osg::Texture::WRAP_T, osg::Texture::CLAMP_TO_EDGE);
}

bool OcclusionContext::readDepth(osg::State& state, const osg::Viewport& viewport)
{
    const int width = static_cast<int>(viewport.width()), height = static_cast<int>(viewport.height());
    if (width <= 0 || height <= 0)
        return false;
    float* depth = _pyramid.resetImage(width, height);
    state.unbindPixelBufferObject();
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    while (glGetError() != GL_NO_ERROR)
    {
    }
    glReadPixels(static_cast<GLint>(viewport.x()), static_cast<GLint>(viewport.y()), width, height,
                 GL_DEPTH_COMPONENT, GL_FLOAT, depth);
    if (glGetError() != GL_NO_ERROR)
    {
        _pyramid.clear();
        _atlasCurrent = false;
        return false;
    }
    _pyramid.buildLevels();
    _atlasCurrent = false;
    return true;
}

bool OcclusionContext::recordDraw(osg::RenderInfo& renderInfo)
{
    const osg::FrameStamp* frameStamp = renderInfo.getState()->getFrameStamp();
    if (!frameStamp)
        return false;
    const osg::Camera* camera = renderInfo.getCurrentCamera();
    const unsigned int frame = frameStamp->getFrameNumber();
    const bool drawnBefore = camera && camera == _lastCamera && frame == _lastFrame;
    _lastCamera = camera;
    _lastFrame = frame;
    return drawnBefore;
}

int OcclusionContext::applyPyramidTexture(osg::State& state)
{
    const int levels = std::min(_pyramid.getNumLevels() - 1, MAX_PYRAMID_TEXTURE_LEVELS);
    if (levels <= 0)
        return 0;
    if (_atlasCurrent)
    {
        state.setActiveTextureUnit(DEPTH_PYRAMID_TEXTURE_UNIT);
        _texture->apply(state);
        state.haveAppliedTextureAttribute(DEPTH_PYRAMID_TEXTURE_UNIT, _texture.get());
        return levels;
    }
    _atlasCurrent = true;
    // Level 1 at the origin, the levels above it stacked in a column to its right.
    _atlasLevels.clear();
    int width = _pyramid.getWidth(1), height = _pyramid.getHeight(1), columnHeight = 0;
    for (int level = 1; level <= levels; ++level)
    {
        const bool first = level == 1;
        _atlasLevels.insert(_atlasLevels.end(), {first ? 0 : _pyramid.getWidth(1), first ? 0 : columnHeight,
                                                 _pyramid.getWidth(level), _pyramid.getHeight(level)});
        if (!first)
        {
            columnHeight += _pyramid.getHeight(level);
            width = std::max(width, _pyramid.getWidth(1) + _pyramid.getWidth(level));
        }
    }
    height = std::max(height, columnHeight);
    if (_image->s() != width || _image->t() != height)
        _image->allocateImage(width, height, 1, GL_RED, GL_FLOAT);
    float* atlas = reinterpret_cast<float*>(_image->data());
    for (int level = 1; level <= levels; ++level)
    {
        const GLint* rect = &_atlasLevels[4 * (level - 1)];
        const std::vector<float>& texels = _pyramid.getLevel(level);
        for (int y = 0; y < rect[3]; ++y)
            std::memcpy(atlas + size_t(rect[1] + y) * width + rect[0], texels.data() + size_t(y) * rect[2],
                        size_t(rect[2]) * sizeof(float));
    }
    _image->dirty();
    // Applied directly: State skips an attribute it applied last, and this one changes in between.
    state.setActiveTextureUnit(DEPTH_PYRAMID_TEXTURE_UNIT);
    _texture->apply(state);
    state.haveAppliedTextureAttribute(DEPTH_PYRAMID_TEXTURE_UNIT, _texture.get());
    return levels;
}

void OcclusionContext::releaseContext()
{
    osg::ref_ptr<osg::State> state = new osg::State;
    state->setContextID(getContextID());
    _texture->releaseGLObjects(state.get());
    // Kept if the context's data outlives it: a later context with this ID starts afresh (its first
    // camera may come at the address, and its first frame with the number, of this one's last).
    _pyramid.clear();
    _atlasCurrent = false;
    _lastCamera = nullptr;
    _lastFrame = 0;
}
