// osgglyphviewer: rendering without a display.

#ifndef OSGGLYPHVIEWER_HEADLESS_H
#define OSGGLYPHVIEWER_HEADLESS_H 1

#include "ViewerScene.h"

#include <osgGlyphsHeadless/FrameCapture>

#include <chrono>
#include <functional>
#include <string>

/** What renderOffscreen does differently in one of several processes that each draw a share of
 * the scene (mpirun): by default, nothing. */
struct OffscreenSharing
{
    /** The camera's post-draw callback that composites the processes' pictures
     * (osgGlyphsComposite::ImageCompositor); in the output process its images are the composite. */
    osg::ref_ptr<osgGlyphsHeadless::FrameCapture> compositor;
    /** Whether this process writes the outputs and prints what it did (rank 0). */
    bool output = true;
    /** How this process names itself where every process prints ("rank 2 of 3"); empty alone. */
    std::string processName;
    /** Collective: whether every process succeeded, else the first failure's error in all. */
    std::function<bool(bool ok, std::string& error)> agree;
    /** Collective, after each frame: one line on where the frame's time went. */
    std::function<std::string(double frameMilliseconds)> describeFrame;
};

/** Renders the scene through an osgGlyphsHeadless::OffscreenViewer and writes --output (PNG) and
 * --depth-output (eye-space depth, PFM) from the first frame; with --frames, renders that many
 * frames on the orbit and prints their times. Prints what it wrote and the time since start.
 * Returns the exit code: 1, with one line and nothing written, when a glyph program fails to
 * compile or link. */
int renderOffscreen(ViewerScene& scene, const ViewerOptions& options,
                    std::chrono::steady_clock::time_point start,
                    const OffscreenSharing& sharing = OffscreenSharing());

#endif
