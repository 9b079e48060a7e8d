// osgglyphviewer: a trajectory rendered offscreen, picture by picture, into files and a movie.

#ifndef OSGGLYPHVIEWER_MOVIEOUTPUT_H
#define OSGGLYPHVIEWER_MOVIEOUTPUT_H 1

#include "ViewerScene.h"

#include <osgGlyphsHeadless/OffscreenViewer>

#include <vector>

/** The positions (in stored frames) of the pictures of --frame-range a:b:step (every frame for a
 * --movie without one), with --interpolate's pictures between stored frames; b is clamped to the
 * last frame. Empty, with error set, when a is past the last frame. */
std::vector<double> listPictures(const PlaybackOptions& playback, std::size_t numFrames, std::string& error);

/** Renders the pictures of --frame-range or --movie with viewer, from its camera as it is: each
 * one shown through the scene's player (waiting for its frames), written to --output's pattern
 * (out%04d.png, numbered from 0) and encoded into --movie at --fps. A progress bar with the time
 * left goes to stderr. Returns the exit code: 1 with one line when a picture cannot be made or
 * written (a frame that cannot be read is a warning: the picture before it is repeated). */
int renderPictureSequence(ViewerScene& scene, osgGlyphsHeadless::OffscreenViewer& viewer,
                          const ViewerOptions& options);

#endif
