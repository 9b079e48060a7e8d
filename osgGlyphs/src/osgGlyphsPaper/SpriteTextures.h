/* osgGlyphsPaper - private: the sprite textures of the texture techniques. Not installed. */

#ifndef OSGGLYPHS_SPRITETEXTURES_H
#define OSGGLYPHS_SPRITETEXTURES_H 1

#include <osgGlyphs/ColorMap>
#include <osgGlyphs/GlyphStyle>
#include <osgGlyphsPaper/Techniques>

#include <osg/Texture2D>
#include <osg/Texture2DArray>

#include <mutex>
#include <vector>

namespace osgGlyphsPaper
{
namespace detail
{

/** The modes of the texture techniques' point sprites: sizes from the vertex shader, and
 * gl_PointCoord across each sprite. */
void setSpriteModes(osg::StateSet& stateSet);

/** texture-blend's textures: the circle mask (white inside the circle), or the sphere lit by
 * a headlight in grey. Alpha is the circle in both. */
osg::ref_ptr<osg::Texture2D> createSpriteTexture(bool lighting);

/** texture-multi's textures: one layer per colour, each texture-blend's lit sphere in that
 * colour (RGB the lit colour, alpha the circle). Sprites made from a colour map follow the
 * map: after ColorMap::setColors() the layers are refilled the next time the texture is
 * applied. */
class LitSpriteArray : public osg::Texture2DArray
{
public:
    LitSpriteArray();
    /** One layer per colour of a palette. */
    explicit LitSpriteArray(const std::vector<osg::Vec4>& palette);
    /** levels layers, of the map's colours at 0, 1 / (levels - 1), ..., 1, filled when first applied. */
    LitSpriteArray(const osgGlyphs::ColorMap* colorMap, unsigned int levels);
    LitSpriteArray(const LitSpriteArray& other, const osg::CopyOp& copyop = osg::CopyOp::SHALLOW_COPY);
    META_StateAttribute(osgGlyphsPaper, LitSpriteArray, TEXTURE);

    void apply(osg::State& state) const override;

protected:
    ~LitSpriteArray() override = default;

    void allocateLayers(unsigned int count);
    void fillLayers(const std::vector<osg::Vec4>& palette) const;
    void fillFromColorMap() const;
    /** Refills the layers from the colour map, if it changed since they were filled. */
    void followColorMap() const;

    std::vector<osg::ref_ptr<osg::Image>> _layers;
    osg::ref_ptr<const osgGlyphs::ColorMap> _colorMap;
    unsigned int _levels = 0;
    mutable unsigned int _colorMapModifiedCount = 0;
    mutable std::mutex _mutex;
};

/** texture-multi's sprites for a colour mode: TEXTURE_MULTI_COLORMAP_LEVELS levels of the
 * colour map (Scalar), the RGB cube of TEXTURE_MULTI_CUBE_LEVELS levels per channel, red
 * slowest (RGBA), or the one colour (Uniform). */
osg::ref_ptr<LitSpriteArray> createLitSprites(osgGlyphs::GlyphColorMode colorMode,
                                              const osgGlyphs::ColorMap* colorMap, const osg::Vec4& color);

}
}

#endif
