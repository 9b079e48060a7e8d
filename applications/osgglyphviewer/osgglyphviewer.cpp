// osgglyphviewer: views point data files as GPU shader glyphs, in a window or headless.

#include <osgGlyphs/GlyphCloud>
#include <osgGlyphs/OffscreenViewer>
#include <osgGlyphs/Version>

#include <osg/ArgumentParser>
#include <osg/Geode>
#include <osg/ShapeDrawable>
#include <osgDB/WriteFile>

#include <chrono>
#include <iostream>
#include <random>

namespace
{

/** The built-in default scene: a seeded random cloud of spheres coloured by a scalar,
 * intersecting a fixed-function box and sphere. */
osg::ref_ptr<osg::Node> createDefaultScene()
{
    const unsigned int count = 2000;
    std::mt19937 random(7);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    osg::ref_ptr<osg::Vec3Array> positions = new osg::Vec3Array;
    osg::ref_ptr<osg::FloatArray> radii = new osg::FloatArray;
    osg::ref_ptr<osg::FloatArray> scalars = new osg::FloatArray;
    for (unsigned int i = 0; i < count; ++i)
    {
        const osg::Vec3 p(2.0f * unit(random), 2.0f * unit(random), 2.0f * unit(random));
        positions->push_back(p);
        radii->push_back(0.06f + 0.05f * (unit(random) + 1.0f));
        scalars->push_back(p.z());
    }
    osg::ref_ptr<osgGlyphs::GlyphCloud> cloud = new osgGlyphs::GlyphCloud;
    cloud->setPositions(positions.get());
    cloud->setRadii(radii.get());
    cloud->setScalars(scalars.get());

    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    geode->addDrawable(cloud.get());
    osg::ref_ptr<osg::ShapeDrawable> box =
        new osg::ShapeDrawable(new osg::Box(osg::Vec3(0.0f, 0.0f, -1.0f), 3.0f, 3.0f, 0.2f));
    box->setColor(osg::Vec4(0.75f, 0.75f, 0.75f, 1.0f));
    geode->addDrawable(box.get());
    osg::ref_ptr<osg::ShapeDrawable> sphere =
        new osg::ShapeDrawable(new osg::Sphere(osg::Vec3(0.0f, 0.0f, 0.3f), 0.8f));
    sphere->setColor(osg::Vec4(0.85f, 0.3f, 0.25f, 1.0f));
    geode->addDrawable(sphere.get());
    return geode;
}

}

int main(int argc, char** argv)
{
    osg::ArgumentParser arguments(&argc, argv);
    osg::ApplicationUsage* usage = arguments.getApplicationUsage();
    usage->setApplicationName(arguments.getApplicationName());
    usage->setDescription(arguments.getApplicationName() +
                          " renders point datasets as GPU shader glyphs (osgGlyphs " + osgGlyphsGetVersion() +
                          ").");
    usage->setCommandLineUsage(arguments.getApplicationName() + " [options] [file]");
    usage->addCommandLineOption("--offscreen",
                                "Render without a display (OSMesa by default, see --headless).");
    usage->addCommandLineOption("--headless <osmesa|egl>", "The headless GL backend used by --offscreen.");
    usage->addCommandLineOption("--output <file.png>", "Write the rendered colour image.");
    usage->addCommandLineOption("--size <w> <h>", "Image size in pixels (default 800 600).");
    usage->addCommandLineOption("-h or --help", "Display this help.");

    if (arguments.read("-h") || arguments.read("--help"))
    {
        usage->write(std::cout, osg::ApplicationUsage::COMMAND_LINE_OPTION);
        return 0;
    }

    int width = 800, height = 600;
    arguments.read("--size", width, height);
    std::string output = "osgglyphviewer.png";
    arguments.read("--output", output);
    std::string backendName = "default";
    arguments.read("--headless", backendName);
    osgGlyphs::HeadlessBackend backend;
    if (!osgGlyphs::parseHeadlessBackend(backendName, backend))
    {
        std::cerr << "osgglyphviewer: unknown headless backend '" << backendName << "' (osmesa or egl)"
                  << std::endl;
        return 1;
    }
    arguments.read("--offscreen");

    arguments.reportRemainingOptionsAsUnrecognized();
    if (arguments.errors())
    {
        arguments.writeErrorMessages(std::cerr);
        return 1;
    }

    const auto start = std::chrono::steady_clock::now();
    osg::ref_ptr<osgGlyphs::OffscreenViewer> viewer = new osgGlyphs::OffscreenViewer(width, height, backend);
    if (!viewer->valid())
        return 1;
    viewer->setSceneData(createDefaultScene());
    viewer->getCamera()->setClearColor(osg::Vec4(1.0f, 1.0f, 1.0f, 1.0f));
    viewer->getCamera()->setViewMatrixAsLookAt(osg::Vec3d(2.5, -9.0, 4.0), osg::Vec3d(0.0, 0.0, 0.0),
                                               osg::Vec3d(0.0, 0.0, 1.0));
    viewer->frame();
    if (!osgDB::writeImageFile(*viewer->getColorImage(), output))
    {
        std::cerr << "osgglyphviewer: cannot write " << output << std::endl;
        return 1;
    }
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    std::cout << "osgglyphviewer: wrote " << output << " (" << width << "x" << height << ", "
              << osgGlyphs::getHeadlessBackendName(viewer->getContext()->getBackend()) << ") in " << ms
              << " ms" << std::endl;
    return 0;
}
