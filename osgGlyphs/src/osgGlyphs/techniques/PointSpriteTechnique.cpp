#include <osgGlyphs/ImpostorTechniques>

#include <osg/PointSprite>

using namespace osgGlyphs;

std::vector<GlyphShaderFile> PointSpriteTechnique::getShaderFiles() const
{
    return {{osg::Shader::VERTEX, "osgGlyphs/point-sprite.vert"},
            {osg::Shader::FRAGMENT, "osgGlyphs/impostor.frag"}};
}

void PointSpriteTechnique::configureStateSet(osg::StateSet& stateSet, const GlyphVariant&) const
{
    stateSet.setMode(GL_VERTEX_PROGRAM_POINT_SIZE, osg::StateAttribute::ON);
    stateSet.setTextureAttributeAndModes(0, new osg::PointSprite, osg::StateAttribute::ON);
}
