// osgglyphviewer: the glyph under a pixel.

#ifndef OSGGLYPHVIEWER_VIEWERPICKING_H
#define OSGGLYPHVIEWER_VIEWERPICKING_H 1

#include <osgGlyphs/GlyphCloud>

#include <osgText/Text>
#include <osgViewer/View>

#include <string>

/** A glyph picked: its cloud, its index in the cloud's arrays (the point's in its frame) and the
 * world point of its surface under the pixel. */
struct GlyphPick
{
    osg::ref_ptr<osgGlyphs::GlyphCloud> cloud;
    unsigned int index = 0;
    osg::Vec3d world;

    bool valid() const { return cloud.valid(); }
};

/** The glyph that the view shows at window point (x, y) (pixels from the bottom left): the
 * nearest surface of content along the ray, if it belongs to a glyph. */
GlyphPick pickGlyph(osgViewer::View& view, osg::Node& content, double x, double y);

/** "pick glyph=<index> x=<x> y=<y> z=<z>" with every digit of the doubles, or "pick none". */
std::string formatPick(const GlyphPick& pick);

/** A HUD of width x height pixels whose text, in the top left corner, shows the picked point. */
osg::ref_ptr<osg::Camera> createPickHud(int width, int height, const osg::Vec4& background,
                                        osgText::Text*& text);

#endif
