#include <osgGlyphs/DepthPeeling>

#include <osgDB/ObjectWrapper>

REGISTER_CUSTOM_OBJECT_WRAPPER(osgGlyphs, osgGlyphs_DepthPeeling, new osgGlyphs::DepthPeeling,
                               osgGlyphs::DepthPeeling,
                               "osg::Object osg::Node osg::Group osgGlyphs::DepthPeeling")
{
    ADD_UINT_SERIALIZER(NumLayers, osgGlyphs::DepthPeeling::DEFAULT_NUM_LAYERS);
    ADD_BOOL_SERIALIZER(Enabled, true);
    BEGIN_ENUM_SERIALIZER(Method, K_BUFFER);
    ADD_ENUM_VALUE(PEEL_PASSES);
    ADD_ENUM_VALUE(K_BUFFER);
    END_ENUM_SERIALIZER();
}
