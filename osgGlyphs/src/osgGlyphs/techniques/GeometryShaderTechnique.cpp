#include <osgGlyphs/ImpostorTechniques>

using namespace osgGlyphs;

std::vector<GlyphShaderFile> GeometryShaderTechnique::getShaderFiles() const
{
    return {{osg::Shader::VERTEX, "osgGlyphs/geometry-shader.vert"},
            {osg::Shader::GEOMETRY, "osgGlyphs/geometry-shader.geom"},
            {osg::Shader::FRAGMENT, "osgGlyphs/impostor.frag"}};
}
