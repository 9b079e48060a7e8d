#include "PlaybackOptions.h"
#include "ViewerOptions.h"

#include <iostream>

void describePlaybackOptions(osg::ApplicationUsage& usage)
{
    usage.addCommandLineOption("--play", "Play a trajectory from the start (space plays and pauses).");
    usage.addCommandLineOption("--fps <f>", "Pictures per second while playing and of --movie (default 10).");
    usage.addCommandLineOption("--interpolate <n>",
                               "n pictures between two stored frames, atoms matched by id and moved the "
                               "short way across periodic boundaries (default 0).");
    usage.addCommandLineOption("--smooth", "With --interpolate: Catmull-Rom curves through the frames "
                                           "around instead of straight lines.");
    usage.addCommandLineOption("--step <n>", "Play every n-th frame (default 1; negative: backwards).");
    usage.addCommandLineOption("--no-loop", "Stop at the last frame instead of starting again.");
    usage.addCommandLineOption("--frame-range <a:b[:step]>",
                               "Offscreen: render frames a to b (a: to the last), every step-th, with "
                               "--interpolate's pictures between, each to --output's pattern "
                               "(out%04d.png, numbered from 0) and/or into --movie.");
    usage.addCommandLineOption("--movie <file.mp4>",
                               "Offscreen: encode the pictures of --frame-range (default: every frame) "
                               "as a movie at --fps (H.264 through FFmpeg's libraries where available).");
    usage.addCommandLineOption(
        "--range-sample <n>",
        "Take the colour range over n frames spread over the trajectory (default: 1, "
        "the first frame, in a window; 8 for --frame-range and --movie). --range fixes it.");
    usage.addCommandLineOption("--cache-mb <m>", "The decoded frames kept for playback, in MiB (default 256; "
                                                 "at least two frames).");
}

bool readPlaybackOptions(osg::ArgumentParser& arguments, PlaybackOptions& options, std::string& error)
{
    while (arguments.read("--play"))
        options.play = true;
    while (arguments.read("--smooth"))
        options.smooth = true;
    while (arguments.read("--no-loop"))
        options.loop = false;
    if (arguments.read("--fps", options.framesPerSecond) &&
        !(options.framesPerSecond > 0.0 && options.framesPerSecond <= 1000.0))
    {
        error = "--fps needs a rate from above 0 to 1000 pictures per second";
        return false;
    }
    int value = 0;
    if (arguments.read("--interpolate", value))
    {
        if (value < 0 || value > 1000)
        {
            error = "--interpolate needs a number of pictures from 0 to 1000";
            return false;
        }
        options.subframes = static_cast<unsigned int>(value);
    }
    if (arguments.read("--step", value))
    {
        if (value == 0 || value > 1000000 || value < -1000000)
        {
            error = "--step needs a non-zero number of frames";
            return false;
        }
        options.step = value;
    }
    std::string range;
    if (arguments.read("--frame-range", range) &&
        !(options.hasFrameRange = osgGlyphsData::parseFrameRange(range, options.range)))
    {
        error = "--frame-range '" + range +
                "': expected first:last or first:last:step (first: to the last "
                "frame), frames counted from 0";
        return false;
    }
    arguments.read("--movie", options.movie);
    if (arguments.read("--range-sample", value))
    {
        if (value < 1 || value > 10000)
        {
            error = "--range-sample needs a number of frames from 1 to 10000";
            return false;
        }
        options.rangeSample = static_cast<unsigned int>(value);
    }
    if (arguments.read("--cache-mb", value))
    {
        if (value < 1)
        {
            error = "--cache-mb needs a positive number of MiB";
            return false;
        }
        options.cacheMegabytes = static_cast<std::size_t>(value);
    }
    return true;
}

void applyPlaybackOptions(const PlaybackOptions& options, osgGlyphsData::FramePlayer& player)
{
    player.setFramesPerSecond(options.framesPerSecond);
    player.setSubframes(options.subframes);
    player.setStep(options.step);
    player.setLoop(options.loop);
    player.setErrorHandler([](const std::string& message)
                           { std::cerr << PROGRAM << ": " << message << std::endl; });
}
