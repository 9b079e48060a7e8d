#include <osgGlyphsPaper/Techniques>

#include "SpriteTextures.h"

#include <osg/Uniform>

using namespace osgGlyphs;
using namespace osgGlyphsPaper;

std::vector<GlyphShaderFile> TextureBlendTechnique::getShaderFiles() const
{
    return {{osg::Shader::VERTEX, "osgGlyphsPaper/texture-blend.vert"},
            {osg::Shader::FRAGMENT, "osgGlyphsPaper/texture-blend.frag"}};
}

void TextureBlendTechnique::configureStateSet(osg::StateSet& stateSet, const GlyphVariant& variant) const
{
    SpriteTechnique::configureStateSet(stateSet, variant);
    stateSet.setTextureAttribute(MASK_TEXTURE_UNIT, detail::createSpriteTexture(false));
    stateSet.setTextureAttribute(LIGHTING_TEXTURE_UNIT, detail::createSpriteTexture(true));
    stateSet.addUniform(new osg::Uniform("osgGlyphs_maskTexture", static_cast<int>(MASK_TEXTURE_UNIT)));
    stateSet.addUniform(
        new osg::Uniform("osgGlyphs_lightingTexture", static_cast<int>(LIGHTING_TEXTURE_UNIT)));
}
