#include "DatasetLoading.h"

#include "ViewerOptions.h"

#include <osgGlyphsData/PointReader>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <iostream>

#include <unistd.h>

ProgressIndicator::ProgressIndicator(const std::string& file)
    : _file(file), _terminal(isatty(fileno(stderr)) != 0), _start(std::chrono::steady_clock::now())
{
}

void ProgressIndicator::update(uint64_t bytesRead, uint64_t totalBytes)
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

void ProgressIndicator::finish(std::size_t frames, std::size_t points)
{
    if (_lineOpen)
        std::fputc('\n', stderr);
    _lineOpen = false;
    if (!_shown || frames == 0)
        return;
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - _start).count();
    std::fprintf(stderr, "%s: read %.1f MB in %.2f s (%.1f MB/s): %zu frame%s, %zu points\n", PROGRAM,
                 _bytes / 1e6, seconds, seconds > 0.0 ? _bytes / 1e6 / seconds : 0.0, frames,
                 frames == 1 ? "" : "s", points);
}

void ProgressIndicator::finish(const osgGlyphsData::PointDataset* dataset)
{
    std::size_t points = 0;
    for (std::size_t i = 0; dataset && i < dataset->getNumFrames(); ++i)
        points += dataset->getFrame(i)->getNumPoints();
    finish(dataset ? dataset->getNumFrames() : 0, points);
}

osg::ref_ptr<osgGlyphsData::PointDataset> loadDataset(const std::string& file, const std::string& format,
                                                      bool growing, const osgGlyphsData::PointShare& share,
                                                      std::string& error,
                                                      const std::vector<std::string>& datasets)
{
    ProgressIndicator progress(file);
    osgGlyphsData::PointReadOptions options;
    options.format = format;
    options.datasets = datasets;
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
