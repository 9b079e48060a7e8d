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

osg::ref_ptr<osg::Camera> createPickHud(int width, int height, const osg::Vec4& background,
                                        osgText::Text*& text)
{
    osg::ref_ptr<osg::Camera> hud = new osg::Camera;
    hud->setReferenceFrame(osg::Transform::ABSOLUTE_RF);
    hud->setProjectionMatrixAsOrtho2D(0.0, width, 0.0, height);
    hud->setViewMatrix(osg::Matrixd::identity());
    hud->setClearMask(GL_DEPTH_BUFFER_BIT);
    hud->setRenderOrder(osg::Camera::POST_RENDER);
    hud->setAllowEventFocus(false);
    hud->getOrCreateStateSet()->setMode(GL_LIGHTING, osg::StateAttribute::OFF);
    const float luminance = 0.3f * background.r() + 0.6f * background.g() + 0.1f * background.b();
    osg::ref_ptr<osgText::Text> label = new osgText::Text;
    label->setDataVariance(osg::Object::DYNAMIC);
    label->setCharacterSize(14.0f);
    label->setAlignment(osgText::Text::LEFT_TOP);
    label->setPosition(osg::Vec3(10.0f, float(height) - 10.0f, 0.0f));
    label->setColor(luminance > 0.5f ? osg::Vec4(0.0f, 0.0f, 0.0f, 1.0f) : osg::Vec4(1.0f, 1.0f, 1.0f, 1.0f));
    hud->addChild(label.get());
    text = label.get();
    return hud;
}
