#include <osgGlyphs/GlyphAttributes>

#include "GlyphDefines.h"

#include <osgGlyphs/GlyphStateCache>

#include <osg/VertexAttribDivisor>

using namespace osgGlyphs;

namespace
{

std::string defined(const char* define)
{
    return std::string("defined(") + define + ")";
}

}

std::vector<GlyphAttributeBinding> osgGlyphs::getGlyphAttributeBindings(GlyphAttributeRate positionRate)
{
    std::vector<GlyphAttributeBinding> bindings;
    if (positionRate == GlyphAttributeRate::PerInstance)
        bindings.push_back({"osgGlyphs_position", POSITION_ATTRIBUTE, "vec3", ""});
    bindings.push_back({"osgGlyphs_packed", RADIUS_SCALAR_ATTRIBUTE, "uint",
                        "!" + defined(detail::FLOAT_ATTRIBUTES_DEFINE)});
    bindings.push_back({"osgGlyphs_radiusScalar", RADIUS_SCALAR_ATTRIBUTE, "vec2",
                        defined(detail::FLOAT_ATTRIBUTES_DEFINE)});
    bindings.push_back({"osgGlyphs_color", COLOR_ATTRIBUTE, "vec4", defined(detail::COLOR_RGBA_DEFINE)});
    bindings.push_back({"osgGlyphs_vector", VECTOR_ATTRIBUTE, "vec3", defined(detail::VECTOR_SHAPE_DEFINE)});
    bindings.push_back(
        {"osgGlyphs_ambientOcclusion", OCCLUSION_ATTRIBUTE, "vec4", defined(GLYPH_AMBIENT_OCCLUSION_DEFINE)});
    bindings.push_back({"osgGlyphs_axes", AXES_ATTRIBUTE, "vec4", defined(detail::AXES_SHAPE_DEFINE)});
    bindings.push_back(
        {"osgGlyphs_orientation", ORIENTATION_ATTRIBUTE, "vec4", defined(detail::AXES_SHAPE_DEFINE)});
    return bindings;
}

void osgGlyphs::attachGlyphArrays(osg::Geometry& geometry, const GlyphArrays& arrays, GlyphAttributeRate rate)
{
    auto attach = [&](unsigned int location, osg::Array* array)
    {
        if (array)
            array->setBinding(osg::Array::BIND_PER_VERTEX);
        geometry.setVertexAttribArray(location, array);
    };
    if (rate == GlyphAttributeRate::PerVertex)
        geometry.setVertexArray(arrays.positions);
    else
        attach(POSITION_ATTRIBUTE, arrays.positions);
    attach(RADIUS_SCALAR_ATTRIBUTE, arrays.radiusScalar);
    attach(COLOR_ATTRIBUTE, arrays.colors);
    attach(VECTOR_ATTRIBUTE, arrays.vectors);
    attach(OCCLUSION_ATTRIBUTE, arrays.occlusion);
    attach(AXES_ATTRIBUTE, arrays.axes);
    attach(ORIENTATION_ATTRIBUTE, arrays.orientations);
}

void osgGlyphs::setInstancedGlyphAttributes(osg::StateSet& stateSet)
{
    for (const GlyphAttributeBinding& binding : getGlyphAttributeBindings(GlyphAttributeRate::PerInstance))
        stateSet.setAttribute(new osg::VertexAttribDivisor(binding.location, 1));
}
