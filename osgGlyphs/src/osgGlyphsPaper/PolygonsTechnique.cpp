#include <osgGlyphsPaper/Techniques>

#include "GlyphMeshes.h"

#include <osgGlyphs/GlyphCloud>

using namespace osgGlyphs;
using namespace osgGlyphsPaper;

std::vector<GlyphShaderFile> PolygonsTechnique::getShaderFiles() const
{
    return {{osg::Shader::VERTEX, "osgGlyphsPaper/polygons.vert"},
            {osg::Shader::FRAGMENT, "osgGlyphsPaper/polygons.frag"}};
}

void PolygonsTechnique::setResolution(unsigned int slices, unsigned int stacks)
{
    _slices = slices;
    _stacks = stacks;
}

void PolygonsTechnique::buildPrimitives(GlyphCloud& cloud, const GlyphArrays& arrays) const
{
    // One instance of the unit mesh per glyph: the per-glyph arrays advance once per instance.
    const detail::GlyphMesh mesh = detail::createGlyphMesh(
        cloud.getShape(), _slices, _stacks, cloud.getArrowHeadLengthRatio(), cloud.getArrowHeadRadiusRatio());
    attachGlyphArrays(cloud, arrays, GlyphAttributeRate::PerInstance);
    cloud.setVertexArray(mesh.vertices.get());
    cloud.setNormalArray(mesh.normals.get(), osg::Array::BIND_PER_VERTEX);
    mesh.triangles->setNumInstances(arrays.count);
    cloud.addPrimitiveSet(mesh.triangles.get());
}

void PolygonsTechnique::configureStateSet(osg::StateSet& stateSet, const GlyphVariant&) const
{
    setInstancedGlyphAttributes(stateSet);
}
