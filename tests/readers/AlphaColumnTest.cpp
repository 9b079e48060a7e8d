// Colours with an alpha column: red, green, blue and alpha columns (PLY's names) give RGBA glyph
// colours, the alpha on the colours' scale; without the alpha column the glyphs are opaque.

#include "ReaderTestUtil.h"

#include <osgGlyphsData/GlyphMapping>

#include <osgGlyphs/GlyphCloud>

using namespace osgGlyphsData;
using namespace readertest;

namespace
{

osg::ref_ptr<osgGlyphs::GlyphCloud> mapCsv(const std::string& text)
{
    std::string error;
    osg::ref_ptr<PointDataset> dataset = readString(text, "csv", error, "colours.csv");
    EXPECT_TRUE(dataset.valid()) << error;
    if (!dataset)
        return nullptr;
    GlyphMappingOptions options;
    options.radius = 0.1f;
    GlyphMapper mapper(options);
    EXPECT_TRUE(mapper.prepare(*dataset, 0, error)) << error;
    osg::ref_ptr<osgGlyphs::GlyphCloud> cloud = mapper.createCloud(*dataset->getFrame(0), error);
    EXPECT_TRUE(cloud.valid()) << error;
    return cloud;
}

}

TEST(AlphaColumn, GivesTheColoursTheirAlpha)
{
    const osg::ref_ptr<osgGlyphs::GlyphCloud> cloud =
        mapCsv("x,y,z,red,green,blue,alpha\n0,0,0,255,0,0,128\n1,0,0,0,255,0,255\n2,0,0,0,0,255,0\n");
    ASSERT_TRUE(cloud.valid());
    ASSERT_NE(cloud->getColors(), nullptr);
    ASSERT_EQ(cloud->getColors()->size(), 3u);
    EXPECT_EQ((*cloud->getColors())[0], osg::Vec4ub(255, 0, 0, 128));
    EXPECT_EQ((*cloud->getColors())[1], osg::Vec4ub(0, 255, 0, 255));
    EXPECT_EQ((*cloud->getColors())[2], osg::Vec4ub(0, 0, 255, 0));
}

TEST(AlphaColumn, OnTheScaleOfUnitColours)
{
    const osg::ref_ptr<osgGlyphs::GlyphCloud> cloud =
        mapCsv("x,y,z,red,green,blue,alpha\n0,0,0,1,0.5,0,0.25\n");
    ASSERT_TRUE(cloud.valid());
    ASSERT_NE(cloud->getColors(), nullptr);
    EXPECT_EQ((*cloud->getColors())[0], osg::Vec4ub(255, 128, 0, 64));
}

TEST(AlphaColumn, WithoutItTheGlyphsAreOpaque)
{
    const osg::ref_ptr<osgGlyphs::GlyphCloud> cloud = mapCsv("x,y,z,red,green,blue\n0,0,0,255,0,0\n");
    ASSERT_TRUE(cloud.valid());
    ASSERT_NE(cloud->getColors(), nullptr);
    EXPECT_EQ((*cloud->getColors())[0], osg::Vec4ub(255, 0, 0, 255));
}

TEST(AlphaColumn, SixteenBitColoursAsLasStoresThem)
{
    const osg::ref_ptr<osgGlyphs::GlyphCloud> cloud =
        mapCsv("x,y,z,red,green,blue\n0,0,0,65535,32896,0\n1,0,0,256,0,65535\n");
    ASSERT_TRUE(cloud.valid());
    ASSERT_NE(cloud->getColors(), nullptr);
    EXPECT_EQ((*cloud->getColors())[0], osg::Vec4ub(255, 128, 0, 255));
    EXPECT_EQ((*cloud->getColors())[1], osg::Vec4ub(1, 0, 255, 255));
}
