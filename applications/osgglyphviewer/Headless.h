// osgglyphviewer: rendering without a display.

#ifndef OSGGLYPHVIEWER_HEADLESS_H
#define OSGGLYPHVIEWER_HEADLESS_H 1

#include "ViewerScene.h"

#include <chrono>

/** Renders the scene through an osgGlyphsHeadless::OffscreenViewer and writes --output (PNG) and
 * --depth-output (eye-space depth, PFM) from the first frame; with --frames, renders that many
 * frames on the orbit and prints their times. Prints what it wrote and the time since start.
 * Returns the exit code: 1, with one line and nothing written, when a glyph program fails to
 * compile or link. */
int renderOffscreen(ViewerScene& scene, const ViewerOptions& options,
                    std::chrono::steady_clock::time_point start);

#endif
