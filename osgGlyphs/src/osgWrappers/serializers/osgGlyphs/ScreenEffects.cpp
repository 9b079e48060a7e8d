#include <osgGlyphs/ScreenEffects>

#include <osgDB/ObjectWrapper>

REGISTER_CUSTOM_OBJECT_WRAPPER(osgGlyphs, osgGlyphs_ScreenEffects, new osgGlyphs::ScreenEffects,
                               osgGlyphs::ScreenEffects,
                               "osg::Object osg::Node osg::Group osgGlyphs::ScreenEffects")
{
    ADD_BOOL_SERIALIZER(AmbientOcclusion, false);
    ADD_FLOAT_SERIALIZER(OcclusionRadius, 0.0f);
    ADD_FLOAT_SERIALIZER(OcclusionStrength, 1.0f);
    ADD_UINT_SERIALIZER(OcclusionSamples, 16u);
    ADD_BOOL_SERIALIZER(Outlines, false);
    ADD_FLOAT_SERIALIZER(OutlineWidth, 1.5f);
    ADD_VEC4_SERIALIZER(OutlineColor, osg::Vec4(0.0f, 0.0f, 0.0f, 1.0f));
}
