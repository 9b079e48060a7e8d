#include "Interactive.h"

#include "ScreenEffectsOptions.h"
#include "Timeline.h"
#include "ViewerCamera.h"
#include "ViewerEventHandler.h"
#include "ViewerPicking.h"

#include <osgGA/StateSetManipulator>
#include <osgGA/TrackballManipulator>
#include <osgViewer/Viewer>
#include <osgViewer/ViewerEventHandlers>
#include <osgViewer/config/SingleWindow>

#include <chrono>
#include <iostream>
#include <vector>

namespace
{

/** The screenshots of key c: osgglyphviewer-screenshot_<context>_<n>.png in the working folder. */
const char* const SCREENSHOT_PREFIX = "osgglyphviewer-screenshot";

/** The viewer's keys and the standard handlers, in the order they see events. The viewer's own
 * handler goes before the StateSetManipulator, so that l toggles both glyph and OpenGL lighting. */
std::vector<osg::ref_ptr<osgGA::GUIEventHandler>>
createHandlers(ViewerEventHandler* keys, osg::StateSet* cameraState, osg::ApplicationUsage* usage)
{
    osg::ref_ptr<osgViewer::ScreenCaptureHandler> capture = new osgViewer::ScreenCaptureHandler(
        new osgViewer::ScreenCaptureHandler::WriteToFile(SCREENSHOT_PREFIX, "png"));
    return {keys,
            new osgGA::StateSetManipulator(cameraState),
            new osgViewer::StatsHandler,
            new osgViewer::WindowSizeHandler,
            capture,
            new osgViewer::HelpHandler(usage)};
}

}

void describeViewerKeys(osg::ApplicationUsage& usage)
{
    osg::ref_ptr<osg::StateSet> stateSet = new osg::StateSet;
    for (const auto& handler : createHandlers(new ViewerEventHandler(nullptr), stateSet.get(), nullptr))
        handler->getUsage(usage);
    osg::ref_ptr<osgGA::TrackballManipulator> trackball = new osgGA::TrackballManipulator;
    trackball->getUsage(usage);
    usage.addKeyboardMouseBinding("Mouse left", "Drag to rotate about the centre");
    usage.addKeyboardMouseBinding("Mouse middle", "Drag to pan");
    usage.addKeyboardMouseBinding("Mouse right", "Drag up and down to zoom (or the wheel)");
    usage.addKeyboardMouseBinding("c", std::string("Save a screenshot as ") + SCREENSHOT_PREFIX +
                                           "_<context>_<n>.png in the working folder");
    // The viewer's keys last: they replace the standard description of l.
    osg::ref_ptr<ViewerEventHandler> keys = new ViewerEventHandler(nullptr);
    keys->getUsage(usage);
    osg::ref_ptr<ScreenEffectsKeys> effectKeys = new ScreenEffectsKeys(nullptr);
    effectKeys->getUsage(usage);
}

int runInteractive(ViewerScene& scene, const ViewerOptions& options, osg::ApplicationUsage* usage)
{
    osg::ref_ptr<osgViewer::Viewer> viewer = new osgViewer::Viewer;
    // One thread: keys replace the scene's content and shaders between frames.
    viewer->setThreadingModel(osgViewer::ViewerBase::SingleThreaded);
    viewer->apply(new osgViewer::SingleWindow(50, 50, options.width, options.height));
    osg::Camera* camera = viewer->getCamera();
    if (!camera->getGraphicsContext() || !camera->getGraphicsContext()->valid())
    {
        std::cerr << PROGRAM
                  << ": cannot open a window (is DISPLAY set?); render without one with --offscreen"
                  << std::endl;
        return 1;
    }
    if (osgViewer::GraphicsWindow* window =
            dynamic_cast<osgViewer::GraphicsWindow*>(camera->getGraphicsContext()))
        window->setWindowName(std::string(PROGRAM) + (options.file.empty() ? "" : ": " + options.file));
    const double aspect = static_cast<double>(options.width) / options.height;
    camera->setClearColor(options.background);
    scene.addLegend(camera, options.background);
    viewer->setSceneData(scene.getRoot());
    if (scene.hasOwnLight())
        viewer->setLightingMode(osg::View::NO_LIGHT);
    osg::ref_ptr<ViewerEventHandler> keys = new ViewerEventHandler(&scene);
    osgText::Text* pickText = nullptr;
    scene.getRoot()->addChild(createPickHud(options.width, options.height, options.background, pickText));
    keys->setPickText(pickText);
    if (osgGlyphsData::FramePlayer* player = scene.getPlayer())
    {
        // Before the other handlers: a click on the bar seeks instead of picking or turning.
        osg::ref_ptr<Timeline> timeline = new Timeline(player, camera, options.background);
        scene.getRoot()->addChild(timeline->getHud());
        viewer->addEventHandler(timeline.get());
    }
    for (const auto& handler : createHandlers(keys.get(), camera->getOrCreateStateSet(), usage))
        viewer->addEventHandler(handler.get());
    viewer->addEventHandler(new ScreenEffectsKeys(scene.getScreenEffects()));

    const CameraView home = options.hasCamera ? options.camera : scene.getHomeView(options.fov, aspect);
    setProjectionForView(*camera, options.fov, aspect, home);
    warnIfGlyphsHidden(*scene.getContent(), *camera, home);
    osg::ref_ptr<osgGA::TrackballManipulator> trackball = new osgGA::TrackballManipulator;
    trackball->setAutoComputeHomePosition(false);
    trackball->setHomePosition(home.eye, home.center, home.up);
    viewer->setCameraManipulator(trackball.get());

    if (options.frames == 0)
    {
        viewer->run();
        return keys->getExitCode();
    }

    viewer->realize();
    std::vector<double> times;
    for (unsigned int frame = 0; frame < options.frames && !viewer->done(); ++frame)
    {
        const CameraView view = orbit(home, frame * ORBIT_DEGREES_PER_FRAME);
        trackball->setTransformation(view.eye, view.center, view.up);
        const auto start = std::chrono::steady_clock::now();
        viewer->frame();
        times.push_back(
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    }
    if (keys->getExitCode() != 0)
        return keys->getExitCode();
    std::cout << formatFrameTimes(times) << std::endl;
    return 0;
}
