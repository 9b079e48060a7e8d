#include "SpriteTextures.h"

#include <algorithm>
#include <cmath>

using namespace osgGlyphs;

namespace
{

/** Texels per side of every sprite texture (the paper's 256 px^2). */
const int SPRITE_SIZE = 256;

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

}

osg::ref_ptr<osg::Texture2D> osgGlyphs::detail::createSpriteTexture(bool lighting)
{
    osg::ref_ptr<osg::Image> image = allocateSpriteImage();
    fillSpriteImage(*image, osg::Vec4(1.0f, 1.0f, 1.0f, 1.0f), lighting);
    osg::ref_ptr<osg::Texture2D> texture = new osg::Texture2D(image.get());
    setSpriteSampling(*texture);
    return texture;
}
