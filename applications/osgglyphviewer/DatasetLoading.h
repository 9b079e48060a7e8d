// osgglyphviewer: reading a point file, with progress on stderr.

#ifndef OSGGLYPHVIEWER_DATASETLOADING_H
#define OSGGLYPHVIEWER_DATASETLOADING_H 1

#include <osgGlyphsData/PointData>
#include <osgGlyphsData/PointShare>

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <string>

/** The progress of reading one file on stderr: from PROGRESS_MIN_BYTES on, a line updated in place
 * on a terminal, and at the end a line of the bytes, time and throughput. */
class ProgressIndicator
{
public:
    explicit ProgressIndicator(const std::string& file);
    /** For osgGlyphsData::PointReadOptions::progress. */
    void update(uint64_t bytesRead, uint64_t totalBytes);
    /** Ends the line with what was read (nothing when it failed: frames 0). */
    void finish(std::size_t frames, std::size_t points);
    void finish(const osgGlyphsData::PointDataset* dataset);

private:
    std::string _file;
    bool _terminal;
    std::chrono::steady_clock::time_point _start;
    uint64_t _bytes = 0;
    bool _shown = false;
    bool _lineOpen = false;
    int _percent = -2;
};

/** Reads every frame of a point file through osgGlyphsData::readPointFile, in the named format or the
 * one of its extension. Files of PROGRESS_MIN_BYTES or more show a progress indicator on stderr
 * (a line updated in place on a terminal) and end with a line of the bytes, time and throughput.
 * Returns nullptr with the reader's one-line error ("<file>:<line>: <what>"). A growing file (a
 * dump being written) may end in a frame half written and may hold no frame yet. */
osg::ref_ptr<osgGlyphsData::PointDataset> loadDataset(const std::string& file, const std::string& format,
                                                      bool growing, const osgGlyphsData::PointShare& share,
                                                      std::string& error,
                                                      const std::vector<std::string>& datasets = {});

/** Appends to a dataset the frames its file completed since it was read (osgglyphviewer --follow). */
class DatasetFollower
{
public:
    DatasetFollower(const std::string& file, const std::string& format, osgGlyphsData::PointDataset* dataset);

    /** Reads on from where the complete frames ended; returns false with a one-line error when the
     * new part of the file is malformed. added: the frames appended. */
    bool poll(std::size_t& added, std::string& error);

private:
    std::string _file;
    std::string _format;
    osg::ref_ptr<osgGlyphsData::PointDataset> _dataset;
};

/** How often --follow reads a growing file again, in seconds. */
const double FOLLOW_POLL_SECONDS = 0.25;

/** The size from which loading shows its progress: 16 MiB. */
const unsigned long long PROGRESS_MIN_BYTES = 16ull << 20;

#endif
