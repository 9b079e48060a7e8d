// This executable links glvnd's libGL before osgGlyphs and libOSMesa: OSG's direct gl* calls
// then reach glvnd, which has no current context under OSMesa. The OSMesa backend must refuse
// to run rather than render nothing, and the default backend must fall back to EGL.

#include "RenderHarness.h"

#include <osgGlyphsHeadless/HeadlessContext>

#include <osg/Geode>
#include <osg/ShapeDrawable>

using namespace osgGlyphsTest;
using osgGlyphsHeadless::HeadlessBackend;

TEST(LinkOrderTrap, OSMesaIsDetectedAsUnreachable)
{
    std::string reason;
    EXPECT_FALSE(osgGlyphsHeadless::HeadlessContext::isOSMesaReachable(reason));
    EXPECT_NE(reason.find("libGL.so"), std::string::npos) << reason;
}

TEST(LinkOrderTrap, ExplicitOSMesaFailsCleanly)
{
    EXPECT_FALSE(osgGlyphsHeadless::HeadlessContext::create(16, 16, HeadlessBackend::OSMesa).valid());
}

TEST(LinkOrderTrap, DefaultFallsBackToEGLAndRenders)
{
    Renderer renderer(32, 32, HeadlessBackend::Default);
    ASSERT_TRUE(renderer.getViewer()->valid());
    EXPECT_EQ(renderer.getViewer()->getContext()->getBackend(), HeadlessBackend::EGL);
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    geode->addDrawable(new osg::ShapeDrawable(new osg::Sphere(osg::Vec3(), 2.0f)));
    const Frame frame = renderer.render(geode.get());
    EXPECT_TRUE(frame.isCovered(16, 16));
    EXPECT_FALSE(frame.isCovered(0, 0));
}
