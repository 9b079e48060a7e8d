#include "SpriteTextures.h"

#include <osg/PointSprite>

#include <algorithm>
#include <cmath>
#include <limits>

using namespace osgGlyphs;
using namespace osgGlyphsPaper;
using namespace osgGlyphsPaper::detail;

namespace
{

/** Texels per side of every sprite texture (the paper's 256 px^2). */
const int SPRITE_SIZE = 256;

/** A layer's modified count under a context that has not loaded it. */
const unsigned int NOT_LOADED = std::numeric_limits<unsigned int>::max();

/** A texel of the sprite: the grey level of the sphere under it and whether it is inside the circle. */
struct SpriteTexel
{
    float shade;
    bool inside;
};

/** Every texel of the sprite, row by row, top row first (gl_PointCoord's origin is the upper
 * left). The sphere is lit by Blinn-Phong under a headlight with GlyphCloud's default
 * material; outside the circle the shade continues at the silhouette's level, so that
 * filtering does not darken the edge. */
const std::vector<SpriteTexel>& getSpriteTexels()
{
    static const std::vector<SpriteTexel> texels = []
    {
        std::vector<SpriteTexel> result;
        result.reserve(SPRITE_SIZE * SPRITE_SIZE);
        for (int t = 0; t < SPRITE_SIZE; ++t)
        {
            for (int s = 0; s < SPRITE_SIZE; ++s)
            {
                const float x = (s + 0.5f) / SPRITE_SIZE * 2.0f - 1.0f;
                const float y = 1.0f - (t + 0.5f) / SPRITE_SIZE * 2.0f;
                const float r2 = x * x + y * y;
                const float nz = std::sqrt(std::max(1.0f - r2, 0.0f));
                const float halfway = std::max((nz + 1.0f) / std::sqrt(2.0f * (1.0f + nz)), 0.0f);
                const float shade = std::min(0.2f + nz + 0.4f * std::pow(halfway, 48.0f), 1.0f);
                result.push_back({shade, r2 <= 1.0f});
            }
        }
        return result;
    }();
    return texels;
}

unsigned char toByte(float value)
{
    return static_cast<unsigned char>(std::lround(std::clamp(value, 0.0f, 1.0f) * 255.0f));
}

/** Fills an allocated sprite image: RGB the colour, times the shade if lit; alpha the circle. */
void fillSpriteImage(osg::Image& image, const osg::Vec4& color, bool lit)
{
    const std::vector<SpriteTexel>& texels = getSpriteTexels();
    for (int t = 0; t < SPRITE_SIZE; ++t)
    {
        for (int s = 0; s < SPRITE_SIZE; ++s)
        {
            const SpriteTexel& texel = texels[t * SPRITE_SIZE + s];
            const float shade = lit ? texel.shade : 1.0f;
            unsigned char* data = image.data(s, t);
            for (int c = 0; c < 3; ++c)
                data[c] = toByte(color[c] * shade);
            data[3] = texel.inside ? 255 : 0;
        }
    }
    image.dirty();
}

osg::ref_ptr<osg::Image> allocateSpriteImage()
{
    osg::ref_ptr<osg::Image> image = new osg::Image;
    image->allocateImage(SPRITE_SIZE, SPRITE_SIZE, 1, GL_RGBA, GL_UNSIGNED_BYTE);
    return image;
}

/** Trilinear filtering, clamped: both texture techniques sample their sprites alike. */
void setSpriteSampling(osg::Texture& texture)
{
    texture.setFilter(osg::Texture::MIN_FILTER, osg::Texture::LINEAR_MIPMAP_LINEAR);
    texture.setFilter(osg::Texture::MAG_FILTER, osg::Texture::LINEAR);
    texture.setWrap(osg::Texture::WRAP_S, osg::Texture::CLAMP_TO_EDGE);
    texture.setWrap(osg::Texture::WRAP_T, osg::Texture::CLAMP_TO_EDGE);
}

std::vector<osg::Vec4> sampleColorMap(const ColorMap& colorMap, unsigned int levels)
{
    std::vector<osg::Vec4> palette;
    for (unsigned int i = 0; i < levels; ++i)
        palette.push_back(colorMap.getColor(static_cast<float>(i) / static_cast<float>(levels - 1)));
    return palette;
}

std::vector<osg::Vec4> createColorCube(unsigned int levels)
{
    std::vector<osg::Vec4> palette;
    const float step = 1.0f / static_cast<float>(levels - 1);
    for (unsigned int r = 0; r < levels; ++r)
        for (unsigned int g = 0; g < levels; ++g)
            for (unsigned int b = 0; b < levels; ++b)
                palette.emplace_back(r * step, g * step, b * step, 1.0f);
    return palette;
}

}

void osgGlyphsPaper::detail::setSpriteModes(osg::StateSet& stateSet)
{
    stateSet.setMode(GL_VERTEX_PROGRAM_POINT_SIZE, osg::StateAttribute::ON);
    stateSet.setTextureAttributeAndModes(MASK_TEXTURE_UNIT, new osg::PointSprite, osg::StateAttribute::ON);
}

osg::ref_ptr<osg::Texture2D> osgGlyphsPaper::detail::createSpriteTexture(bool lighting)
{
    osg::ref_ptr<osg::Image> image = allocateSpriteImage();
    fillSpriteImage(*image, osg::Vec4(1.0f, 1.0f, 1.0f, 1.0f), lighting);
    osg::ref_ptr<osg::Texture2D> texture = new osg::Texture2D(image.get());
    setSpriteSampling(*texture);
    return texture;
}

LitSpriteArray::LitSpriteArray()
{
    setSpriteSampling(*this);
}

LitSpriteArray::LitSpriteArray(const std::vector<osg::Vec4>& palette)
{
    setSpriteSampling(*this);
    allocateLayers(static_cast<unsigned int>(palette.size()));
    fillLayers(palette);
}

LitSpriteArray::LitSpriteArray(const ColorMap* colorMap, unsigned int levels)
    : _colorMap(colorMap), _levels(levels), _colorMapModifiedCount(NOT_LOADED)
{
    // Filled when first applied: a variant that is made but never drawn costs no filling.
    setSpriteSampling(*this);
    allocateLayers(levels);
}

LitSpriteArray::LitSpriteArray(const LitSpriteArray& other, const osg::CopyOp& copyop)
    : osg::Texture2DArray(other, copyop), _colorMap(other._colorMap), _levels(other._levels),
      _colorMapModifiedCount(other._colorMapModifiedCount)
{
    for (int layer = 0; layer < getTextureDepth(); ++layer)
        _layers.push_back(getImage(layer));
}

void LitSpriteArray::allocateLayers(unsigned int count)
{
    setTextureSize(SPRITE_SIZE, SPRITE_SIZE, static_cast<int>(count));
    _layers.clear();
    for (unsigned int layer = 0; layer < count; ++layer)
    {
        _layers.push_back(allocateSpriteImage());
        setImage(layer, _layers.back().get());
    }
}

void LitSpriteArray::fillLayers(const std::vector<osg::Vec4>& palette) const
{
    for (size_t layer = 0; layer < _layers.size() && layer < palette.size(); ++layer)
        fillSpriteImage(*_layers[layer], palette[layer], true);
}

void LitSpriteArray::fillFromColorMap() const
{
    _colorMapModifiedCount = _colorMap->getModifiedCount();
    fillLayers(sampleColorMap(*_colorMap, _levels));
}

void LitSpriteArray::followColorMap() const
{
    std::lock_guard<std::mutex> lock(_mutex);
    if (_colorMap->getModifiedCount() != _colorMapModifiedCount)
        fillFromColorMap();
}

void LitSpriteArray::apply(osg::State& state) const
{
    if (_colorMap.valid())
        followColorMap();
    const unsigned int contextID = state.getContextID();
    if (!getTextureObject(contextID))
    {
        // Texture2DArray remembers which layers it loaded under a context ID even after their
        // texture object is released: a later context with that ID must load every layer.
        for (unsigned int layer = 0; layer < _layers.size(); ++layer)
            getModifiedCount(layer, contextID) = NOT_LOADED;
    }
    else if (isDirty(contextID))
    {
        // It reloads only the base level of a refilled layer: the mipmaps must follow.
        _texMipmapGenerationDirtyList[contextID] = 1;
    }
    osg::Texture2DArray::apply(state);
}

osg::ref_ptr<LitSpriteArray> osgGlyphsPaper::detail::createLitSprites(GlyphColorMode colorMode,
                                                                      const ColorMap* colorMap,
                                                                      const osg::Vec4& color)
{
    switch (colorMode)
    {
    case GlyphColorMode::Scalar:
        return new LitSpriteArray(colorMap, TEXTURE_MULTI_COLORMAP_LEVELS);
    case GlyphColorMode::RGBA:
        return new LitSpriteArray(createColorCube(TEXTURE_MULTI_CUBE_LEVELS));
    default:
        return new LitSpriteArray(std::vector<osg::Vec4>{color});
    }
}
