// osgglyphviewer: views point data files as GPU shader glyphs, in a window or headless.

#include <osgGlyphs/OffscreenViewer>
#include <osgGlyphs/Version>

#include <osg/ArgumentParser>
#include <osg/Geode>
#include <osg/ShapeDrawable>
#include <osgDB/WriteFile>

#include <chrono>
#include <iostream>

namespace
{

/** The built-in default scene. */
osg::ref_ptr<osg::Node> createDefaultScene()
{
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    auto add = [&](osg::Shape* shape, const osg::Vec4& color)
    {
        osg::ref_ptr<osg::ShapeDrawable> drawable = new osg::ShapeDrawable(shape);
        drawable->setColor(color);
        geode->addDrawable(drawable.get());
    };
    add(new osg::Sphere(osg::Vec3(-1.2f, 0.0f, 0.0f), 1.0f), osg::Vec4(0.27f, 0.51f, 0.71f, 1.0f));
    add(new osg::Box(osg::Vec3(1.2f, 0.0f, 0.0f), 1.5f), osg::Vec4(0.85f, 0.55f, 0.2f, 1.0f));
    return geode;
}

} // namespace

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
    viewer->getCamera()->setViewMatrixAsLookAt(osg::Vec3d(0.0, -9.0, 3.0), osg::Vec3d(0.0, 0.0, 0.0),
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
