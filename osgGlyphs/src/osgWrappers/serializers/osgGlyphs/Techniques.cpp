#include <osgGlyphs/ImpostorTechniques>

#include <osgDB/ObjectWrapper>

// A technique is saved by its class; its parameters, where it has any, as its properties. Each
// wrapper has a namespace of its own: the registration macro declares file-scope names.

namespace WrapGlyphTechnique
{
REGISTER_CUSTOM_OBJECT_WRAPPER(osgGlyphs, osgGlyphs_GlyphTechnique, NULL, osgGlyphs::GlyphTechnique,
                               "osg::Object osgGlyphs::GlyphTechnique")
{
}
}

namespace WrapGeometryShaderTechnique
{
REGISTER_CUSTOM_OBJECT_WRAPPER(osgGlyphs, osgGlyphs_GeometryShaderTechnique,
                               new osgGlyphs::GeometryShaderTechnique, osgGlyphs::GeometryShaderTechnique,
                               "osg::Object osgGlyphs::GlyphTechnique osgGlyphs::GeometryShaderTechnique")
{
}
}

namespace WrapInstancedTechnique
{
REGISTER_CUSTOM_OBJECT_WRAPPER(osgGlyphs, osgGlyphs_InstancedTechnique, new osgGlyphs::InstancedTechnique,
                               osgGlyphs::InstancedTechnique,
                               "osg::Object osgGlyphs::GlyphTechnique osgGlyphs::InstancedTechnique")
{
}
}

namespace WrapPointSpriteTechnique
{
REGISTER_CUSTOM_OBJECT_WRAPPER(osgGlyphs, osgGlyphs_PointSpriteTechnique, new osgGlyphs::PointSpriteTechnique,
                               osgGlyphs::PointSpriteTechnique,
                               "osg::Object osgGlyphs::GlyphTechnique osgGlyphs::PointSpriteTechnique")
{
}
}
