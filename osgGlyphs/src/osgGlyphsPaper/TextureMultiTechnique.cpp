#include <osgGlyphsPaper/Techniques>

#include "SpriteTextures.h"

#include <osg/Uniform>

using namespace osgGlyphs;
using namespace osgGlyphsPaper;

std::vector<GlyphShaderFile> TextureMultiTechnique::getShaderFiles() const
{
    return {{osg::Shader::VERTEX, "osgGlyphsPaper/texture-multi.vert"},
            {osg::Shader::FRAGMENT, "osgGlyphsPaper/texture-multi.frag"}};
}

void TextureMultiTechnique::configureStateSet(osg::StateSet& stateSet, const GlyphVariant& variant) const
{
    SpriteTechnique::configureStateSet(stateSet, variant);
    stateSet.setTextureAttribute(
        LIT_SPRITES_TEXTURE_UNIT,
        detail::createLitSprites(variant.colorMode, variant.colorMap.get(), variant.color));
    stateSet.addUniform(new osg::Uniform("osgGlyphs_litSprites", static_cast<int>(LIT_SPRITES_TEXTURE_UNIT)));
}
