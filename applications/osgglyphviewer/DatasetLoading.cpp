#include "DatasetLoading.h"

#include "ViewerOptions.h"

#include <osgGlyphsData/PointReader>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <iostream>

#include <unistd.h>

namespace
{

/** The progress of one file on stderr. */
class ProgressIndicator
{
public:
    explicit ProgressIndicator(const std::string& file)
        : _file(file), _terminal(isatty(fileno(stderr)) != 0), _start(std::chrono::steady_clock::now())
    {
    }

    void update(uint64_t bytesRead, uint64_t totalBytes)
    {
        _bytes = bytesRead;
        if (!_shown && std::max(bytesRead, totalBytes) < PROGRESS_MIN_BYTES)
            return;
        if (!_shown && !_terminal)
            std::fprintf(stderr, "%s: reading %s (%.1f MB)\n", PROGRAM, _file.c_str(), totalBytes / 1e6);
        _shown = true;
        const int percent = totalBytes ? static_cast<int>(100 * bytesRead / totalBytes) : -1;
        if (!_terminal || percent == _percent)
            return;
        _percent = percent;
        if (totalBytes)
            std::fprintf(stderr, "\r%s: reading %s %3d%% (%.1f of %.1f MB)", PROGRAM, _file.c_str(), percent,
                         bytesRead / 1e6, totalBytes / 1e6);
        else
            std::fprintf(stderr, "\r%s: reading %s %.1f MB", PROGRAM, _file.c_str(), bytesRead / 1e6);
        std::fflush(stderr);
        _lineOpen = true;
    }

    void finish(const osgGlyphsData::PointDataset* dataset)
    {
        if (_lineOpen)
            std::fputc('\n', stderr);
        if (!_shown || !dataset)
            return;
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - _start).count();
        std::size_t points = 0;
        for (const auto& frame : dataset->getFrames())
            points += frame->getNumPoints();
        std::fprintf(stderr, "%s: read %.1f MB in %.2f s (%.1f MB/s): %zu frame%s, %zu points\n", PROGRAM,
                     _bytes / 1e6, seconds, seconds > 0.0 ? _bytes / 1e6 / seconds : 0.0,
                     dataset->getNumFrames(), dataset->getNumFrames() == 1 ? "" : "s", points);
    }

private:
    std::string _file;
    bool _terminal;
    std::chrono::steady_clock::time_point _start;
    uint64_t _bytes = 0;
    bool _shown = false;
    bool _lineOpen = false;
    int _percent = -2;
};

}

osg::ref_ptr<osgGlyphsData::PointDataset> loadDataset(const std::string& file, const std::string& format,
                                                      bool growing, const osgGlyphsData::PointShare& share,
                                                      std::string& error)
{
    ProgressIndicator progress(file);
    osgGlyphsData::PointReadOptions options;
    options.format = format;
    options.growing = growing;
    options.share = share;
    options.progress = [&progress](uint64_t bytesRead, uint64_t totalBytes)
    { progress.update(bytesRead, totalBytes); };
    osg::ref_ptr<osgGlyphsData::PointDataset> dataset = osgGlyphsData::readPointFile(file, options, error);
    progress.finish(dataset.get());
    if (dataset.valid() && dataset->getNumFrames() == 0 && !growing)
    {
        error = file + ": no points";
        return nullptr;
    }
    return dataset;
}

DatasetFollower::DatasetFollower(const std::string& file, const std::string& format,
                                 osgGlyphsData::PointDataset* dataset)
    : _file(file), _format(format), _dataset(dataset)
{
}

bool DatasetFollower::poll(std::size_t& added, std::string& error)
{
    added = 0;
    osgGlyphsData::PointReadOptions options;
    options.format = _format;
    options.growing = true;
    options.start = _dataset->getEndOfCompleteFrames();
    options.warning = [](const std::string& warning)
    { std::cerr << PROGRAM << ": warning: " << warning << std::endl; };
    osg::ref_ptr<osgGlyphsData::PointDataset> grown = osgGlyphsData::readPointFile(_file, options, error);
    if (!grown)
        return false;
    for (const osg::ref_ptr<osgGlyphsData::PointData>& frame : grown->getFrames())
        _dataset->addFrame(frame.get());
    added = grown->getNumFrames();
    _dataset->setEndOfCompleteFrames(grown->getEndOfCompleteFrames());
    return true;
}
