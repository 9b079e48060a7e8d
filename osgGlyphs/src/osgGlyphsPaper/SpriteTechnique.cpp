#include <osgGlyphsPaper/Techniques>

#include "SpriteTextures.h"

using namespace osgGlyphs;
using namespace osgGlyphsPaper;

bool SpriteTechnique::supportsShape(GlyphShape shape) const
{
    return shape == GlyphShape::Sphere; // the paper's textures are of spheres
}

void SpriteTechnique::configureStateSet(osg::StateSet& stateSet, const GlyphVariant&) const
{
    detail::setSpriteModes(stateSet);
}
