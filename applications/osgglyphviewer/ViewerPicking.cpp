#include "ViewerPicking.h"

#include <iomanip>
#include <limits>
#include <sstream>

GlyphPick pickGlyph(osgViewer::View& view, osg::Node& content, double x, double y)
{
    GlyphPick pick;
    osgUtil::LineSegmentIntersector::Intersections hits;
    osg::NodePath path{&content};
    if (!view.computeIntersections(view.getCamera(), osgUtil::Intersector::WINDOW, float(x), float(y), path,
                                   hits))
        return pick;
    const osgUtil::LineSegmentIntersector::Intersection& nearest = *hits.begin();
    pick.cloud = dynamic_cast<osgGlyphs::GlyphCloud*>(nearest.drawable.get());
    pick.index = nearest.primitiveIndex;
    pick.world = nearest.getWorldIntersectPoint();
    return pick;
}

std::string formatPick(const GlyphPick& pick)
{
    if (!pick.valid())
        return "pick none";
    std::ostringstream text;
    text << std::setprecision(std::numeric_limits<double>::max_digits10) << "pick glyph=" << pick.index
         << " x=" << pick.world.x() << " y=" << pick.world.y() << " z=" << pick.world.z();
    return text.str();
}
