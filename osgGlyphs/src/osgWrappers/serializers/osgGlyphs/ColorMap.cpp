#include <osgGlyphs/ColorMap>

#include <osgDB/InputStream>
#include <osgDB/ObjectWrapper>
#include <osgDB/OutputStream>

static bool checkColors(const osgGlyphs::ColorMap& map)
{
    return !map.getColors().empty();
}

static bool readColors(osgDB::InputStream& is, osgGlyphs::ColorMap& map)
{
    unsigned int count = is.readSize();
    std::vector<osg::Vec4> colors;
    is >> is.BEGIN_BRACKET;
    for (unsigned int i = 0; i < count && is.getException() == nullptr; ++i)
    {
        osg::Vec4 color;
        is >> color;
        colors.push_back(color);
    }
    is >> is.END_BRACKET;
    map.setColors(colors);
    return true;
}

static bool writeColors(osgDB::OutputStream& os, const osgGlyphs::ColorMap& map)
{
    os.writeSize(map.getColors().size());
    os << os.BEGIN_BRACKET << std::endl;
    for (const osg::Vec4& color : map.getColors())
        os << color << std::endl;
    os << os.END_BRACKET << std::endl;
    return true;
}

REGISTER_CUSTOM_OBJECT_WRAPPER(osgGlyphs, osgGlyphs_ColorMap, new osgGlyphs::ColorMap, osgGlyphs::ColorMap,
                               "osg::Object osgGlyphs::ColorMap")
{
    ADD_USER_SERIALIZER(Colors);
}
