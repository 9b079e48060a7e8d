// Renders a small scene headless through the installed osgGlyphs and checks what it drew.

#include <osgGlyphs/OffscreenViewer>
#include <osgGlyphs/Version>

#include <osg/Geode>
#include <osg/ShapeDrawable>

#include <iostream>

int main()
{
    osg::ref_ptr<osgGlyphs::OffscreenViewer> viewer = new osgGlyphs::OffscreenViewer(64, 64);
    if (!viewer->valid())
        return 1;
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    geode->addDrawable(new osg::ShapeDrawable(new osg::Sphere(osg::Vec3(), 1.0f)));
    viewer->setSceneData(geode.get());
    viewer->getCamera()->setClearColor(osg::Vec4(0.0f, 0.0f, 0.0f, 1.0f));
    viewer->getCamera()->setViewMatrixAsLookAt(osg::Vec3d(0.0, -6.0, 0.0), osg::Vec3d(),
                                               osg::Vec3d(0.0, 0.0, 1.0));
    viewer->frame();

    const float centerDepth = *reinterpret_cast<const float*>(viewer->getDepthImage()->data(32, 32));
    const float cornerDepth = *reinterpret_cast<const float*>(viewer->getDepthImage()->data(0, 0));
    const unsigned char* center = viewer->getColorImage()->data(32, 32);
    const bool ok = centerDepth < 1.0f && cornerDepth == 1.0f && center[0] > 64;
    std::cout << "osgGlyphs " << osgGlyphsGetVersion() << " consumer: centre depth " << centerDepth
              << ", corner depth " << cornerDepth << ", centre red " << int(center[0])
              << (ok ? ": ok" : ": WRONG") << std::endl;
    return ok ? 0 : 1;
}
