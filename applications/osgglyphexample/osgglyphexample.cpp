// osgglyphexample: the smallest complete osgGlyphs program, meant to be read and copied.
//
// It builds a helix of spheres from plain arrays, colours them by height through a colour map,
// puts them next to an ordinary OSG box that they cut through, and shows the scene:
//
//   osgglyphexample                          in a window (osgViewer::Viewer)
//   osgglyphexample --output helix.png       one frame rendered headless, written as a PNG
//   osgglyphexample --output helix.png --size 640 480

#include <osgGlyphs/ColorMap>
#include <osgGlyphs/GlyphCloud>
#include <osgGlyphsHeadless/OffscreenViewer>

#include <osg/ArgumentParser>
#include <osg/Group>
#include <osg/ShapeDrawable>
#include <osgDB/WriteFile>
#include <osgGA/TrackballManipulator>
#include <osgViewer/Viewer>

#include <cmath>
#include <iostream>

// Where both modes look from (z is up).
const osg::Vec3d EYE(0.0, -10.0, 4.5), CENTER(0.0, 0.0, -0.2), UP(0.0, 0.0, 1.0);

// 100 spheres on three turns of a helix around the z axis, rising from z = -1.5 at the front
// (towards the camera) to z = 1.5.
osg::ref_ptr<osgGlyphs::GlyphCloud> createHelix()
{
    // A GlyphCloud takes ordinary OSG arrays, one entry per glyph.
    osg::ref_ptr<osg::Vec3Array> positions = new osg::Vec3Array;
    osg::ref_ptr<osg::FloatArray> radii = new osg::FloatArray;
    osg::ref_ptr<osg::FloatArray> heights = new osg::FloatArray; // the scalar we colour by
    const int count = 100;
    for (int i = 0; i < count; ++i)
    {
        const float t = static_cast<float>(i) / (count - 1); // 0 .. 1 along the helix
        const float angle = t * 3.0f * 2.0f * osg::PIf - osg::PI_2f;
        const osg::Vec3 p(1.5f * std::cos(angle), 1.5f * std::sin(angle), -1.5f + 3.0f * t);
        positions->push_back(p);
        radii->push_back(0.15f + 0.07f * t); // spheres grow towards the top
        heights->push_back(p.z());
    }

    osg::ref_ptr<osgGlyphs::GlyphCloud> cloud = new osgGlyphs::GlyphCloud;
    cloud->setPositions(positions.get()); // required: the sphere centres
    cloud->setRadii(radii.get());         // or cloud->setRadius(0.1f) for one radius
    cloud->setScalars(heights.get());     // a float per glyph, mapped to a colour on the GPU
    cloud->setColorMap(osgGlyphs::ColorMap::getBuiltin("coolwarm")); // blue (low) to red (high)
    cloud->setScalarRange(-1.5f, 1.5f); // heights outside the range clamp to its ends
    return cloud;
}

// The helix next to fixed-function geometry: a flat box the lowest turn sinks into. Glyphs
// write their exact depth, so the box hides the sunk parts and the spheres hide the box.
osg::ref_ptr<osg::Node> createScene()
{
    osg::ref_ptr<osg::ShapeDrawable> box =
        new osg::ShapeDrawable(new osg::Box(osg::Vec3(0.0f, 0.0f, -1.45f), 4.5f, 4.5f, 0.3f));
    box->setColor(osg::Vec4(0.8f, 0.8f, 0.75f, 1.0f));

    // A GlyphCloud is an osg::Geometry: it goes into a Group like any other drawable (a Geode
    // would draw it too, but OSG's intersectors would not pick its glyphs there).
    osg::ref_ptr<osg::Group> group = new osg::Group;
    group->addChild(createHelix().get());
    group->addChild(box.get());
    return group;
}

// Headless: an OffscreenViewer is an osgViewer::Viewer that renders into an off-screen
// OpenGL context (OSMesa or EGL, no display or GPU needed) and reads every frame back.
int renderToFile(osg::Node* scene, const std::string& path, int width, int height)
{
    osg::ref_ptr<osgGlyphsHeadless::OffscreenViewer> viewer =
        new osgGlyphsHeadless::OffscreenViewer(width, height);
    if (!viewer->valid())
    {
        std::cerr << "osgglyphexample: " << viewer->getContextError() << std::endl;
        return 1;
    }
    viewer->setSceneData(scene);
    viewer->getCamera()->setClearColor(osg::Vec4(0.15f, 0.15f, 0.2f, 1.0f));
    viewer->getCamera()->setViewMatrixAsLookAt(EYE, CENTER, UP); // no manipulator: a fixed view
    viewer->frame();                                             // render one frame...
    if (!osgDB::writeImageFile(*viewer->getColorImage(), path))  // ...and save its colour
    {
        std::cerr << "osgglyphexample: cannot write " << path << std::endl;
        return 1;
    }
    std::cout << "osgglyphexample: wrote " << path << " (" << width << "x" << height << ")" << std::endl;
    return 0;
}

int main(int argc, char** argv)
{
    osg::ArgumentParser arguments(&argc, argv);
    std::string output;
    int width = 800, height = 600;
    arguments.read("--output", output);
    if (arguments.read("--size", width, height) && (width <= 0 || height <= 0))
    {
        std::cerr << "osgglyphexample: --size needs a positive width and height" << std::endl;
        return 1;
    }

    osg::ref_ptr<osg::Node> scene = createScene();
    if (!output.empty())
        return renderToFile(scene.get(), output, width, height);

    // Interactive: a plain osgViewer::Viewer; glyphs need nothing special from it. The viewer's
    // headlight lights the spheres and the box alike.
    osgViewer::Viewer viewer(arguments);
    viewer.setSceneData(scene.get());
    osg::ref_ptr<osgGA::TrackballManipulator> manipulator = new osgGA::TrackballManipulator;
    manipulator->setHomePosition(EYE, CENTER, UP);
    viewer.setCameraManipulator(manipulator.get());
    return viewer.run();
}
