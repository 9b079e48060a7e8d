#include <osgGlyphsPaper/Techniques>

#include <osgDB/InputStream>
#include <osgDB/ObjectWrapper>
#include <osgDB/OutputStream>

using osgGlyphsPaper::PolygonsTechnique;

static bool checkResolution(const PolygonsTechnique&)
{
    return true;
}

static bool readResolution(osgDB::InputStream& is, PolygonsTechnique& technique)
{
    unsigned int slices = 0, stacks = 0;
    is >> slices >> stacks;
    technique.setResolution(slices, stacks);
    return true;
}

static bool writeResolution(osgDB::OutputStream& os, const PolygonsTechnique& technique)
{
    os << technique.getSlices() << technique.getStacks() << std::endl;
    return true;
}

namespace WrapPolygonsTechnique
{
REGISTER_CUSTOM_OBJECT_WRAPPER(osgGlyphs, osgGlyphsPaper_PolygonsTechnique,
                               new osgGlyphsPaper::PolygonsTechnique, osgGlyphsPaper::PolygonsTechnique,
                               "osg::Object osgGlyphs::GlyphTechnique osgGlyphsPaper::PolygonsTechnique")
{
    ADD_USER_SERIALIZER(Resolution);
}
}

/** The wrapper of a technique without parameters, in a namespace of its own (the macro declares
 * file-scope names). */
#define OSGGLYPHSPAPER_WRAPPER(ClassName)                                                                    \
    namespace Wrap##ClassName                                                                                \
    {                                                                                                        \
        REGISTER_CUSTOM_OBJECT_WRAPPER(osgGlyphs, osgGlyphsPaper_##ClassName, new osgGlyphsPaper::ClassName, \
                                       osgGlyphsPaper::ClassName,                                            \
                                       "osg::Object osgGlyphs::GlyphTechnique osgGlyphsPaper::" #ClassName)  \
        {                                                                                                    \
        }                                                                                                    \
    }

OSGGLYPHSPAPER_WRAPPER(PaperQuadTechnique)
OSGGLYPHSPAPER_WRAPPER(TextureBlendTechnique)
OSGGLYPHSPAPER_WRAPPER(TextureMultiTechnique)
OSGGLYPHSPAPER_WRAPPER(PointsFloorTechnique)
