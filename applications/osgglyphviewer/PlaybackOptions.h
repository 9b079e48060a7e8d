// osgglyphviewer: the options that play a trajectory, in a window or into pictures and movies.

#ifndef OSGGLYPHVIEWER_PLAYBACKOPTIONS_H
#define OSGGLYPHVIEWER_PLAYBACKOPTIONS_H 1

#include <osgGlyphsData/FramePlayer>
#include <osgGlyphsData/FrameSource>

#include <osg/ApplicationUsage>
#include <osg/ArgumentParser>

#include <cstddef>
#include <string>

/** How a trajectory plays. */
struct PlaybackOptions
{
    bool play = false;               // --play: start playing in the window
    double framesPerSecond = 10.0;   // --fps: pictures per second (and of --movie)
    unsigned int subframes = 0;      // --interpolate n: pictures between two stored frames
    bool smooth = false;             // --smooth: Catmull-Rom instead of straight lines
    int step = 1;                    // --step n: every n-th frame
    bool loop = true;                // --no-loop: stop at the end
    bool hasFrameRange = false;      // --frame-range a:b[:step]: offscreen, a picture per frame
    osgGlyphsData::FrameRange range; // "a:" runs to the last frame
    std::string movie;               // --movie out.mp4
    unsigned int rangeSample = 0; // --range-sample n: frames the colour range is taken over; 0: the default
    std::size_t cacheMegabytes = 256; // --cache-mb
};

void describePlaybackOptions(osg::ApplicationUsage& usage);

/** Reads the options above; false with a one-line error on a bad value. */
bool readPlaybackOptions(osg::ArgumentParser& arguments, PlaybackOptions& options, std::string& error);

/** Sets a player's rate, sub-frames, step and loop as the options ask, and its errors to go to the
 * console. */
void applyPlaybackOptions(const PlaybackOptions& options, osgGlyphsData::FramePlayer& player);

#endif
