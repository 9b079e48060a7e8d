// osgglyphviewer: the window.

#ifndef OSGGLYPHVIEWER_INTERACTIVE_H
#define OSGGLYPHVIEWER_INTERACTIVE_H 1

#include "ViewerScene.h"

#include <osg/ApplicationUsage>

/** Adds the keys and mouse bindings of the window (the standard handlers' and the viewer's) to usage. */
void describeViewerKeys(osg::ApplicationUsage& usage);

/** Opens a window of --size with the standard handlers (stats, window size, screen capture,
 * state set, help, trackball) and the viewer's keys, and runs until it is closed; with --frames,
 * renders that many frames on the orbit and prints their times. Returns the exit code. */
int runInteractive(ViewerScene& scene, const ViewerOptions& options, osg::ApplicationUsage* usage);

#endif
