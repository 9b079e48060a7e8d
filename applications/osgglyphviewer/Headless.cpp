#include "Headless.h"

#include "DatasetLoading.h"
#include "MovieOutput.h"
#include "ViewerCamera.h"
#include "ViewerPicking.h"

#include <osgGlyphs/GlyphStateCache>
#include <osgGlyphsHeadless/DepthImage>
#include <osgGlyphsHeadless/OffscreenViewer>

#include <osgDB/WriteFile>

#include <iostream>
#include <sstream>
#include <thread>
#include <vector>

namespace
{

double millisecondsSince(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

/** Writes the outputs of the frame just rendered; depth comes from sceneCapture, which read it
 * before the legend was drawn, with the projection the scene was drawn with. */
bool writeOutputs(osgGlyphsHeadless::OffscreenViewer& viewer,
                  const osgGlyphsHeadless::FrameCapture* sceneCapture, const ViewerOptions& options,
                  std::string& error)
{
    if (!options.output.empty() && !osgDB::writeImageFile(*viewer.getColorImage(), options.output))
    {
        error = options.output + ": cannot write the image";
        return false;
    }
    if (!options.depthOutput.empty())
    {
        osg::ref_ptr<osg::Image> distance = osgGlyphsHeadless::createEyeDistanceImage(
            *sceneCapture->getDepthImage(), sceneCapture->getProjectionMatrix());
        if (!distance.valid() || !osgGlyphsHeadless::writePFM(*distance, options.depthOutput, error))
        {
            error = options.depthOutput + ": " + (error.empty() ? "cannot convert the depth image" : error);
            return false;
        }
    }
    return true;
}

/** Waits for the followed file to complete a frame, then shows its newest frame. */
bool showNextFrame(ViewerScene& scene, double timeout, std::string& error)
{
    const auto start = std::chrono::steady_clock::now();
    for (;;)
    {
        std::size_t added = 0;
        if (!scene.followFile(added, error))
            return false;
        if (added > 0)
            break;
        if (millisecondsSince(start) > timeout * 1000.0)
        {
            error = "no new frame for " + std::to_string(static_cast<int>(timeout)) + " s of --follow";
            return false;
        }
        std::this_thread::sleep_for(std::chrono::duration<double>(FOLLOW_POLL_SECONDS));
    }
    const std::size_t newest = scene.getNumFrames() - 1;
    if (!scene.setFrame(newest, error))
        return false;
    std::cout << PROGRAM << ": frame " << newest << " completed" << std::endl;
    return true;
}

/** The --camera option that gives this view again: for pictures of one trajectory rendered in pieces. */
void printCameraOption(const CameraView& view)
{
    std::ostringstream line;
    line.precision(9);
    for (const osg::Vec3d& v : {view.eye, view.center, view.up})
        line << " " << v.x() << " " << v.y() << " " << v.z();
    std::cout << PROGRAM << ": camera:" << line.str() << std::endl;
}

}

int renderOffscreen(ViewerScene& scene, const ViewerOptions& options,
                    std::chrono::steady_clock::time_point start, const OffscreenSharing& sharing)
{
    const auto agree = [&sharing](bool ok, std::string& error)
    { return sharing.agree ? sharing.agree(ok, error) : ok; };
    osg::ref_ptr<osgGlyphsHeadless::OffscreenViewer> viewer = new osgGlyphsHeadless::OffscreenViewer(
        options.width, options.height, options.backend, options.eglDevice);
    std::string contextError = viewer->getContextError();
    if (!agree(viewer->valid(), contextError))
    {
        if (sharing.output)
            std::cerr << PROGRAM << ": " << contextError << std::endl;
        return 1;
    }
    std::cout << PROGRAM << (sharing.processName.empty() ? "" : " (" + sharing.processName + ")")
              << ": OpenGL through " << viewer->getContext()->getRendererInfo().describe() << std::endl;
    const double aspect = static_cast<double>(options.width) / options.height;
    osg::Camera* camera = viewer->getCamera();
    camera->setClearColor(options.background);
    scene.addLegend(camera, options.background);
    viewer->setSceneData(scene.getRoot());
    if (scene.hasOwnLight())
        viewer->setLightingMode(osg::View::NO_LIGHT);

    // The legend is drawn after the scene: depth and projection are read before it.
    osg::ref_ptr<osgGlyphsHeadless::FrameCapture> sceneCapture = sharing.compositor;
    if (sceneCapture.valid())
        camera->setPostDrawCallback(sceneCapture.get());
    else if (!options.depthOutput.empty())
    {
        sceneCapture = new osgGlyphsHeadless::FrameCapture;
        camera->setPostDrawCallback(sceneCapture.get());
    }
    viewer->getFrameCapture()->setCaptureDepth(false);

    const CameraView home = options.hasCamera ? options.camera : scene.getHomeView(options.fov, aspect);
    setProjectionForView(*camera, options.fov, aspect, home);
    if (sharing.output && !options.hasCamera)
        printCameraOption(home);
    if (!sharing.compositor.valid()) // a share may well be out of view
        warnIfGlyphsHidden(*scene.getContent(), *camera, home);
    if (options.playback.hasFrameRange || !options.playback.movie.empty())
    {
        camera->setViewMatrixAsLookAt(home.eye, home.center, home.up);
        return renderPictureSequence(scene, *viewer, options);
    }
    const unsigned int frames = options.frames > 0 ? options.frames : 1;
    std::vector<double> times;
    for (unsigned int frame = 0; frame < frames; ++frame)
    {
        std::string error;
        if (scene.isFollowing() && frame > 0 && !showNextFrame(scene, options.followTimeout, error))
        {
            std::cerr << PROGRAM << ": " << error << std::endl;
            return 1;
        }
        // Following a file, each picture shows a new frame of the data from the same place.
        const double degrees = scene.isFollowing() ? 0.0 : frame * ORBIT_DEGREES_PER_FRAME;
        const CameraView view = orbit(home, degrees);
        camera->setViewMatrixAsLookAt(view.eye, view.center, view.up);
        const auto frameStart = std::chrono::steady_clock::now();
        viewer->frame();
        times.push_back(millisecondsSince(frameStart));
        if (frame == 0)
        {
            const double firstPicture = millisecondsSince(start);
            const auto pagingStart = std::chrono::steady_clock::now();
            if (const unsigned int pagingFrames = viewer->settlePaging(PAGING_TIMEOUT_SECONDS))
                std::cout << PROGRAM << ": the first picture took " << firstPicture
                          << " ms from the start; paged in tiles over " << pagingFrames << " more frames in "
                          << millisecondsSince(pagingStart) << " ms" << std::endl;
        }
        error = osgGlyphs::GlyphStateCache::instance()->getProgramError();
        if (!agree(error.empty(), error))
        {
            if (sharing.output)
                std::cerr << PROGRAM << ": " << error << std::endl;
            return 1;
        }
        if (sharing.describeFrame)
        {
            const std::string line = sharing.describeFrame(times.back());
            if (sharing.output && options.frames > 0)
                std::cout << PROGRAM << ": frame " << frame << ": " << line << std::endl;
        }
        if (frame > 0 && !scene.isFollowing())
            continue;

        const bool written = !sharing.output || writeOutputs(*viewer, sceneCapture.get(), options, error);
        if (!agree(written, error))
        {
            if (sharing.output)
                std::cerr << PROGRAM << ": " << error << std::endl;
            return 1;
        }
        if (!sharing.output)
            continue;
        const std::string size =
            std::to_string(options.width) + "x" + std::to_string(options.height) + ", " +
            osgGlyphsHeadless::getHeadlessBackendName(viewer->getContext()->getBackend());
        const double ms = millisecondsSince(start);
        if (!options.output.empty())
            std::cout << PROGRAM << ": wrote " << options.output << " (" << size << ") in " << ms << " ms"
                      << std::endl;
        if (!options.depthOutput.empty())
            std::cout << PROGRAM << ": wrote " << options.depthOutput << " (eye-space depth, " << size
                      << ") in " << ms << " ms" << std::endl;
        if (options.output.empty() && options.depthOutput.empty())
            std::cout << PROGRAM << ": rendered " << size << " in " << ms << " ms" << std::endl;
        if (options.hasPick)
        {
            // Through the pixel's centre; window rows count from the bottom.
            const double x = options.pickX + 0.5, y = options.height - (options.pickY + 0.5);
            std::cout << formatPick(pickGlyph(*viewer, *scene.getContent(), x, y)) << std::endl;
        }
    }
    if (options.frames > 0 && sharing.output)
        std::cout << formatFrameTimes(times) << std::endl;
    return 0;
}
