#include "MovieOutput.h"

#ifdef OSGGLYPHVIEWER_MOVIE
#include <osgGlyphsMovie/MovieWriter>
#endif

#include <osgGlyphsData/FrameSource>

#include <osgDB/WriteFile>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>

#include <unistd.h>

namespace
{

/** A bar of the pictures done, with the time left, on stderr: in place on a terminal, else a line
 * every tenth. */
class SequenceProgress
{
public:
    explicit SequenceProgress(std::size_t total)
        : _total(total), _terminal(isatty(fileno(stderr)) != 0), _start(std::chrono::steady_clock::now())
    {
    }

    void done(std::size_t count)
    {
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - _start).count();
        const double left = count ? seconds / count * (_total - count) : 0.0;
        const int percent = static_cast<int>(100 * count / std::max<std::size_t>(_total, 1));
        if (!_terminal && percent / 10 == _lastTenth && count != _total)
            return;
        _lastTenth = percent / 10;
        const int width = 30;
        const int filled = width * percent / 100;
        std::fprintf(stderr, "%s%s: picture %zu of %zu [%s%s] %3d%%, %.1f s left%s", _terminal ? "\r" : "",
                     PROGRAM, count, _total, std::string(filled, '#').c_str(),
                     std::string(width - filled, ' ').c_str(), percent, left,
                     _terminal && count != _total ? "" : "\n");
        std::fflush(stderr);
    }

    double elapsed() const
    {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - _start).count();
    }

private:
    std::size_t _total;
    bool _terminal;
    std::chrono::steady_clock::time_point _start;
    int _lastTenth = -1;
};

/** Where each picture goes: a file of the pattern, a movie, or both. */
class PictureOutputs
{
public:
    bool open(const ViewerOptions& options, std::string& error)
    {
        _pattern = options.output;
        if (options.playback.movie.empty())
            return true;
#ifdef OSGGLYPHVIEWER_MOVIE
        _movie = new osgGlyphsMovie::MovieWriter;
        osgGlyphsMovie::MovieOptions movieOptions;
        movieOptions.framesPerSecond = options.playback.framesPerSecond;
        return _movie->open(options.playback.movie, options.width, options.height, movieOptions, error);
#else
        error = options.playback.movie +
                ": this osgglyphviewer was built without FFmpeg's libraries (install "
                "libavcodec-dev libavformat-dev libswscale-dev and build again)";
        return false;
#endif
    }

    bool write(const osg::Image& image, unsigned long number, std::string& error)
    {
        std::string name;
        if (!_pattern.empty() && osgGlyphsData::formatFramePath(_pattern, number, name) &&
            !osgDB::writeImageFile(image, name))
        {
            error = name + ": cannot write the image";
            return false;
        }
#ifdef OSGGLYPHVIEWER_MOVIE
        if (_movie.valid())
            return _movie->writeFrame(image, error);
#endif
        return true;
    }

    bool close(std::string& error)
    {
#ifdef OSGGLYPHVIEWER_MOVIE
        if (_movie.valid())
        {
            if (!_movie->close(error))
                return false;
            std::cout << PROGRAM << ": wrote " << _movie->getPath() << " (" << _movie->getFramesWritten()
                      << " pictures, " << _movie->getEncoderName() << ")" << std::endl;
        }
#endif
        (void)error;
        return true;
    }

private:
    std::string _pattern;
#ifdef OSGGLYPHVIEWER_MOVIE
    osg::ref_ptr<osgGlyphsMovie::MovieWriter> _movie;
#endif
};

}

std::vector<double> listPictures(const PlaybackOptions& playback, std::size_t numFrames, std::string& error)
{
    std::vector<double> pictures;
    if (numFrames == 0 || playback.range.first >= numFrames)
    {
        error = "--frame-range: no frame " + std::to_string(playback.range.first) + " (the file has " +
                std::to_string(numFrames) + " frames, counted from 0)";
        return pictures;
    }
    const std::size_t last = std::min(playback.range.last, numFrames - 1);
    const std::size_t step = playback.range.step;
    for (std::size_t frame = playback.range.first; frame <= last; frame += step)
    {
        pictures.push_back(static_cast<double>(frame));
        if (frame + step > last)
            break;
        for (unsigned int sub = 1; sub <= playback.subframes; ++sub)
            pictures.push_back(frame + static_cast<double>(step) * sub / (playback.subframes + 1));
    }
    return pictures;
}

int renderPictureSequence(ViewerScene& scene, osgGlyphsHeadless::OffscreenViewer& viewer,
                          const ViewerOptions& options)
{
    osgGlyphsData::FramePlayer* player = scene.getPlayer();
    std::string error;
    if (!player)
    {
        std::cerr << PROGRAM << ": --frame-range and --movie need a file of frames" << std::endl;
        return 1;
    }
    player->waitForIndex();
    PlaybackOptions playback = options.playback;
    if (!playback.hasFrameRange)
        playback.range.last = SIZE_MAX;
    const std::vector<double> pictures = listPictures(playback, player->getNumFrames(), error);
    PictureOutputs outputs;
    if (pictures.empty() || !outputs.open(options, error))
    {
        std::cerr << PROGRAM << ": " << error << std::endl;
        return 1;
    }
    player->setPlaying(false);
    player->setStep(static_cast<int>(playback.range.step));
    player->setRange(playback.range.first, std::min(playback.range.last, player->getNumFrames() - 1));
    player->setLoop(false);
    SequenceProgress progress(pictures.size());
    for (std::size_t i = 0; i < pictures.size(); ++i)
    {
        if (!player->showNow(pictures[i], error))
            std::cerr << PROGRAM << ": warning: picture " << i << " repeats the one before: " << error
                      << std::endl;
        viewer.frame();
        viewer.settlePaging(PAGING_TIMEOUT_SECONDS); // a series of tile archives: every tile in view
        if (!outputs.write(*viewer.getColorImage(), i, error))
        {
            std::cerr << "\n" << PROGRAM << ": " << error << std::endl;
            return 1;
        }
        progress.done(i + 1);
    }
    if (!outputs.close(error))
    {
        std::cerr << PROGRAM << ": " << error << std::endl;
        return 1;
    }
    const osgGlyphsData::FramePlayerStatistics statistics = player->getStatistics();
    std::printf("%s: rendered %zu pictures (%llu interpolated) in %.2f s, %.1f pictures/s\n", PROGRAM,
                pictures.size(), static_cast<unsigned long long>(statistics.interpolated), progress.elapsed(),
                pictures.size() / std::max(progress.elapsed(), 1e-9));
    return 0;
}
