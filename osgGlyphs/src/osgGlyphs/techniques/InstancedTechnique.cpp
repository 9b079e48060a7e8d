#include <osgGlyphs/GlyphCloud>
#include <osgGlyphs/ImpostorTechniques>

using namespace osgGlyphs;

std::vector<GlyphShaderFile> InstancedTechnique::getShaderFiles() const
{
    return {{osg::Shader::VERTEX, "osgGlyphs/instanced.vert"},
            {osg::Shader::FRAGMENT, "osgGlyphs/impostor.frag"}};
}

void InstancedTechnique::buildPrimitives(GlyphCloud& cloud, const GlyphArrays& arrays) const
{
    attachGlyphArrays(cloud, arrays, GlyphAttributeRate::PerInstance);
    cloud.setVertexArray(new osg::Vec3Array(4)); // the quad's corners come from gl_VertexID
    cloud.addPrimitiveSet(new osg::DrawArrays(GL_TRIANGLE_STRIP, 0, 4, arrays.count));
}

void InstancedTechnique::configureStateSet(osg::StateSet& stateSet, const GlyphVariant&) const
{
    setInstancedGlyphAttributes(stateSet);
}
