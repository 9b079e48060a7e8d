#include <osgGlyphsPaper/Techniques>

using namespace osgGlyphs;
using namespace osgGlyphsPaper;

std::vector<GlyphShaderFile> PointsFloorTechnique::getShaderFiles() const
{
    return {{osg::Shader::VERTEX, "osgGlyphsPaper/points-floor.vert"},
            {osg::Shader::FRAGMENT, "osgGlyphsPaper/points-floor.frag"}};
}
