// osgglyphviewer: a point file read frame by frame and played (osgGlyphsData::FrameSource).

#ifndef OSGGLYPHVIEWER_TRAJECTORYSCENE_H
#define OSGGLYPHVIEWER_TRAJECTORYSCENE_H 1

#include "ViewerScene.h"

/** The scene of a point file in one process: the file opened through a FrameSource (its first
 * frame read, the others indexed on a worker thread), mapped to one GlyphCloud that a
 * TrajectoryPlayer shows the frames in (ViewerScene::getPlayer()). The colour range is taken
 * over --range-sample frames (default: the first frame alone, so that the first picture waits
 * for no other frame; for --frame-range and --movie, 8 frames). Returns nullptr with a one-line
 * error. */
osg::ref_ptr<ViewerScene> createTrajectoryScene(const ViewerOptions& options, std::string& error);

#endif
