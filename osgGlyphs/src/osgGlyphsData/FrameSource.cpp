#include <osgGlyphsData/FrameSource>
#include <osgGlyphsData/PointReader>

#include "FrameTopology.h"
#include "frames/ByteRangeStream.h"
#include "frames/ByteSource.h"
#include "frames/FrameIndexFile.h"
#include "frames/FrameScanner.h"

#include <osg/Notify>

#include <atomic>
#include <cctype>
#include <condition_variable>
#include <cstdlib>
#include <mutex>
#include <thread>

using namespace osgGlyphsData;
using namespace osgGlyphsData::frames;

namespace
{

/** The blocks the index scan reads. */
const std::size_t SCAN_BLOCK_BYTES = std::size_t(4) << 20;

const char* compressionName(Compression compression)
{
    switch (compression)
    {
    case Compression::Gzip:
        return "gzip";
    case Compression::Zstd:
        return "zstd";
    default:
        return "";
    }
}

Compression sniffCompression(const std::string& path)
{
    unsigned char magic[4] = {0, 0, 0, 0};
    FILE* file = std::fopen(path.c_str(), "rb");
    if (!file)
        return Compression::None;
    const std::size_t got = std::fread(magic, 1, sizeof(magic), file);
    std::fclose(file);
    return compressionFromMagic(magic, got);
}

}

struct FrameSource::Impl
{
    FrameSourceOptions options;
    Compression compression = Compression::None;
    std::shared_ptr<Checkpoints> checkpoints;
    /** Of a format read as a FrameFile, which finds its own frames (no index, no scan). */
    osg::ref_ptr<FrameFile> frameFile;
    /** The atoms of FrameSourceOptions::topology, given to every frame. */
    std::unique_ptr<FrameTopology> topology;

    mutable std::mutex mutex; // everything below up to the sources
    mutable std::condition_variable indexed;
    std::vector<FrameInfo> frames;
    std::vector<std::string> warnings;
    ScanPosition scanEnd;
    FileStamp stamp;
    bool complete = false;
    bool singleFrame = false;
    std::string indexPath;

    mutable std::mutex sourcesMutex;
    mutable std::vector<std::unique_ptr<ByteSource>> idleSources;

    std::thread indexThread;
    std::atomic<bool> stopping{false};

    void warn(const std::string& warning)
    {
        {
            std::lock_guard<std::mutex> lock(mutex);
            warnings.push_back(warning);
        }
        if (options.warning)
            options.warning(warning);
        else
            OSG_WARN << warning << std::endl;
    }

    std::unique_ptr<ByteSource> takeSource(const std::string& path, std::string& error) const
    {
        {
            std::lock_guard<std::mutex> lock(sourcesMutex);
            if (!idleSources.empty())
            {
                std::unique_ptr<ByteSource> source = std::move(idleSources.back());
                idleSources.pop_back();
                return source;
            }
        }
        return openByteSource(path, compression, checkpoints, error);
    }

    /** How a frame is read: one frame, this process's share; its warnings are the index's to give. */
    PointReadOptions oneFrame(const std::string& format) const
    {
        PointReadOptions read;
        read.format = format;
        read.maxFrames = 1;
        read.share = options.share;
        read.warning = [](const std::string&) {};
        return read;
    }

    void giveBack(std::unique_ptr<ByteSource> source) const
    {
        std::lock_guard<std::mutex> lock(sourcesMutex);
        idleSources.push_back(std::move(source));
    }
};

FrameSource::FrameSource() : _impl(new Impl) {}

FrameSource::~FrameSource()
{
    _impl->stopping = true;
    if (_impl->indexThread.joinable())
        _impl->indexThread.join();
}

std::string FrameSource::getCompressionName() const
{
    return compressionName(_impl->compression);
}

std::size_t FrameSource::getNumFrames() const
{
    if (_impl->frameFile)
        return _impl->frameFile->getNumFrames();
    std::lock_guard<std::mutex> lock(_impl->mutex);
    return _impl->frames.size();
}

FrameInfo FrameSource::getFrameInfo(std::size_t frame) const
{
    if (_impl->frameFile)
        return _impl->frameFile->getFrameInfo(frame);
    std::lock_guard<std::mutex> lock(_impl->mutex);
    return frame < _impl->frames.size() ? _impl->frames[frame] : FrameInfo();
}

bool FrameSource::isIndexComplete() const
{
    std::lock_guard<std::mutex> lock(_impl->mutex);
    return _impl->complete;
}

void FrameSource::waitForIndex() const
{
    std::unique_lock<std::mutex> lock(_impl->mutex);
    _impl->indexed.wait(lock, [this] { return _impl->complete; });
}

std::vector<std::string> FrameSource::getWarnings() const
{
    std::lock_guard<std::mutex> lock(_impl->mutex);
    return _impl->warnings;
}

std::string FrameSource::getIndexPath() const
{
    std::lock_guard<std::mutex> lock(_impl->mutex);
    return _impl->indexPath;
}

uint64_t FrameSource::getFileSize() const
{
    std::lock_guard<std::mutex> lock(_impl->mutex);
    return _impl->stamp.size;
}

namespace
{

/** Reads frames from a range of a source with the point reader. */
osg::ref_ptr<PointDataset> readRange(ByteSource& source, uint64_t begin, uint64_t end,
                                     const std::string& format, const std::string& name,
                                     const PointReadOptions& options, std::string& error)
{
    ByteRangeStream stream(source, begin, end);
    osg::ref_ptr<PointDataset> dataset = readPointStream(stream, format, name, options, error);
    const SourceError* failure = stream.getError();
    // The stream reads ahead of the frames: a failure past their end leaves them whole.
    const bool beyond = failure && dataset.valid() && dataset->getNumFrames() > 0 &&
                        stream.getErrorOffset() >= dataset->getEndOfCompleteFrames().offset;
    if (failure && !beyond)
    {
        error = failure->message;
        return nullptr;
    }
    return dataset;
}

}

osg::ref_ptr<PointData> FrameSource::readFrame(std::size_t frame, std::string& error) const
{
    osg::ref_ptr<PointData> data = readFileFrame(frame, error);
    if (data && _impl->topology && !_impl->topology->apply(*data, _impl->options.share, _path, frame, error))
        return nullptr;
    return data;
}

osg::ref_ptr<PointData> FrameSource::readFileFrame(std::size_t frame, std::string& error) const
{
    if (_impl->frameFile)
    {
        if (frame >= _impl->frameFile->getNumFrames())
        {
            error = _path + ": no frame " + std::to_string(frame) + " (" +
                    std::to_string(_impl->frameFile->getNumFrames()) + " frames)";
            return nullptr;
        }
        osg::ref_ptr<PointData> data = _impl->frameFile->readFrame(frame, _impl->options.share, error);
        if (data)
            data->setSource(_path);
        return data;
    }
    if (_impl->singleFrame)
    {
        if (frame == 0)
            return _firstFrame;
        error = _path + ": no frame " + std::to_string(frame) + " (the file has one frame, 0)";
        return nullptr;
    }
    FrameInfo info;
    {
        std::lock_guard<std::mutex> lock(_impl->mutex);
        if (frame >= _impl->frames.size())
        {
            error = _path + ": no frame " + std::to_string(frame) + " (" +
                    std::to_string(_impl->frames.size()) + " frames known" +
                    (_impl->complete ? "" : " so far") + ")";
            return nullptr;
        }
        info = _impl->frames[frame];
    }
    std::unique_ptr<ByteSource> source = _impl->takeSource(_path, error);
    if (!source)
        return nullptr;
    PointReadOptions options = _impl->oneFrame(_format);
    options.start = {info.offset, info.line, info.fileFrame};
    osg::ref_ptr<PointDataset> dataset =
        readRange(*source, info.offset, info.end, _format, _path, options, error);
    _impl->giveBack(std::move(source));
    if (!dataset)
        return nullptr;
    if (dataset->getNumFrames() == 0)
    {
        error = _path + ":" + std::to_string(info.line + 1) + ": frame " +
                std::to_string(info.fileFrame + 1) + " holds no complete frame" +
                (dataset->getWarnings().empty() ? std::string() : ": " + dataset->getWarnings().front());
        return nullptr;
    }
    return dataset->getFrame(0);
}

namespace
{

/** Scans a source from a position to its current end, appending the frames to the source's list. */
bool scanFrames(ByteSource& source, const std::string& format, const ScanPosition& start, bool growing,
                const std::atomic<bool>& stopping, const FrameScanner::FrameHandler& onFrame,
                const FrameScanner::WarningHandler& onWarning, ScanPosition& end)
{
    FrameScanner scanner(format, source.getName(), start, onFrame, onWarning);
    std::vector<char> block(SCAN_BLOCK_BYTES);
    uint64_t offset = start.offset;
    bool ok = true;
    while (!stopping)
    {
        std::unique_ptr<SourceError> failure;
        const std::size_t got = readBeforeFailure(source, offset, block.data(), block.size(), failure);
        if (got == 0 && failure)
        {
            if (!(growing && failure->endOfInput))
                onWarning(failure->message + ": the frames after line " +
                          std::to_string(scanner.getEndOfFrames().line) + " cannot be indexed");
            ok = !failure->endOfInput || growing;
            break;
        }
        if (got == 0)
            break;
        scanner.feed(block.data(), got);
        offset += got;
    }
    scanner.finish(growing || !ok);
    end = scanner.getEndOfFrames();
    return ok;
}

}

void FrameSource::startIndexThread(const ScanPosition& start)
{
    _impl->indexThread = std::thread(
        [this, start]
        {
            Impl& impl = *_impl;
            std::string error;
            std::unique_ptr<ByteSource> source =
                openByteSource(_path, impl.compression, impl.checkpoints, error);
            ScanPosition end = start;
            if (!source)
                impl.warn(error);
            else
                scanFrames(
                    *source, _format, start, impl.options.growing, impl.stopping,
                    [&impl](const FrameInfo& frame)
                    {
                        std::lock_guard<std::mutex> lock(impl.mutex);
                        impl.frames.push_back(frame);
                    },
                    [&impl](const std::string& warning) { impl.warn(warning); }, end);
            {
                std::lock_guard<std::mutex> lock(impl.mutex);
                impl.scanEnd = end;
            }
            // Written before the index counts as complete: a source closed at once still keeps it.
            // Closed while scanning, the frames found so far are kept, and the next opening goes on.
            writeIndex(!impl.stopping);
            {
                std::lock_guard<std::mutex> lock(impl.mutex);
                impl.complete = true;
            }
            impl.indexed.notify_all();
        });
}

void FrameSource::writeIndex(bool complete)
{
    StoredFrameIndex index;
    index.complete = complete;
    std::string path;
    {
        std::lock_guard<std::mutex> lock(_impl->mutex);
        path = _impl->indexPath;
        index.stamp = _impl->stamp;
        index.format = _format;
        index.compression = static_cast<uint32_t>(_impl->compression);
        index.end = _impl->scanEnd;
        index.frames = _impl->frames;
        index.warnings = _impl->warnings;
    }
    if (_impl->checkpoints)
        index.checkpoints = _impl->checkpoints->toBytes();
    std::string error;
    if (path.empty() || writeFrameIndex(path, index, error))
        return;
    // A folder that cannot be written after all: the cache instead.
    const std::string cached = chooseIndexPath(_path, FrameIndexLocation::Cache, _impl->options.cacheFolder);
    if (cached == path || !writeFrameIndex(cached, index, error))
    {
        OSG_INFO << "osgGlyphs: the frame index of " << _path << " is not kept: " << error << std::endl;
        return;
    }
    std::lock_guard<std::mutex> lock(_impl->mutex);
    _impl->indexPath = cached;
}

bool FrameSource::reuseIndex(ScanPosition& resumeAt)
{
    const std::string indexPath = getIndexPath();
    if (indexPath.empty())
        return false;
    StoredFrameIndex stored;
    std::string reason;
    if (!readFrameIndex(indexPath, stored, reason))
    {
        if (reason != "no index file")
            _impl->warn(indexPath + ": " + reason + "; the index is built again");
        return false;
    }
    const bool sameKind = stored.format == _format && stored.compression == uint32_t(_impl->compression);
    const bool same = sameKind && stored.stamp == _impl->stamp;
    const bool grew = sameKind && !same && fileGrewFrom(_path, stored.stamp);
    if ((!same && !grew) || (_impl->checkpoints && !stored.checkpoints.empty() &&
                             !_impl->checkpoints->fromBytes(stored.checkpoints)))
    {
        _impl->warn(indexPath + ": made for " +
                    (sameKind ? "an earlier version of the file" : "another format") +
                    "; the index is built again");
        return false;
    }
    std::lock_guard<std::mutex> lock(_impl->mutex);
    _impl->frames = std::move(stored.frames);
    _impl->warnings = std::move(stored.warnings);
    _impl->scanEnd = stored.end;
    _impl->complete = same && stored.complete;
    resumeAt = stored.end;
    _indexReused = true;
    return true;
}

bool FrameSource::openFrameFile(std::string& error)
{
    if (_impl->compression != Compression::None)
    {
        error = _path + ": " + _format + " files are read by seeking in them; a " +
                compressionName(_impl->compression) + "-compressed one cannot be: decompress it first";
        return false;
    }
    std::string shareError;
    if (!checkPointShare(_impl->options.share, shareError))
    {
        error = _path + ": " + shareError;
        return false;
    }
    FrameFileOptions options;
    options.datasets = _impl->options.datasets;
    _impl->frameFile = osgGlyphsData::openFrameFile(_path, _format, options, error);
    if (!_impl->frameFile)
        return false;
    for (const std::string& warning : _impl->frameFile->getWarnings())
        _impl->warn(warning);
    if (_impl->frameFile->getNumFrames() == 0)
    {
        error = _path + ": no frames";
        return false;
    }
    _impl->complete = true;
    _firstFrame = readFrame(0, error);
    return _firstFrame.valid();
}

bool FrameSource::openSingleFrame(std::string& error)
{
    PointReadOptions options;
    options.format = _format;
    options.share = _impl->options.share;
    options.progress = _impl->options.progress;
    options.warning = _impl->options.warning;
    osg::ref_ptr<PointDataset> dataset;
    if (_impl->compression == Compression::None)
        dataset = readPointFile(_path, options, error);
    else if (std::unique_ptr<ByteSource> source = _impl->takeSource(_path, error))
        dataset = readRange(*source, 0, UINT64_MAX, _format, _path, options, error);
    if (!dataset)
        return false;
    if (dataset->getNumFrames() == 0)
    {
        error = _path + ": no points";
        return false;
    }
    _firstFrame = dataset->getFrame(0);
    _impl->singleFrame = true;
    _impl->complete = true;
    _impl->frames.push_back(FrameInfo());
    _impl->frames.back().points = _firstFrame->getFilePointCount();
    _impl->frames.back().timestep = _firstFrame->getTimestep();
    return true;
}

bool FrameSource::openFirstFrame(std::string& error)
{
    if (getNumFrames() > 0)
    {
        _firstFrame = readFrame(0, error);
        return _firstFrame.valid();
    }
    std::unique_ptr<ByteSource> source = _impl->takeSource(_path, error);
    if (!source)
        return false;
    PointReadOptions options = _impl->oneFrame(_format);
    options.growing = _impl->options.growing;
    const uint64_t end = _impl->compression == Compression::None ? _impl->stamp.size : UINT64_MAX;
    osg::ref_ptr<PointDataset> dataset = readRange(*source, 0, end, _format, _path, options, error);
    _impl->giveBack(std::move(source));
    if (!dataset)
        return false;
    if (dataset->getNumFrames() == 0)
    {
        error = _path + ": no complete frame yet";
        return false;
    }
    _firstFrame = dataset->getFrame(0);
    return true;
}

osg::ref_ptr<FrameSource> FrameSource::open(const std::string& path, const FrameSourceOptions& options,
                                            std::string& error)
{
    osg::ref_ptr<FrameSource> source = openFile(path, options, error);
    if (source && !options.topology.empty() && !source->attachTopology(error))
        return nullptr;
    return source;
}

bool FrameSource::attachTopology(std::string& error)
{
    const FrameSourceOptions& options = _impl->options;
    _impl->topology = FrameTopology::read(
        options.topology, options.topologyFormat,
        [this](const std::string& warning) { _impl->warn(warning); }, error);
    return _impl->topology && _impl->topology->apply(*_firstFrame, options.share, _path, 0, error);
}

osg::ref_ptr<FrameSource> FrameSource::openFile(const std::string& path, const FrameSourceOptions& options,
                                                std::string& error)
{
    osg::ref_ptr<FrameSource> source = new FrameSource;
    Impl& impl = *source->_impl;
    impl.options = options;
    source->_path = path;
    std::string stripped;
    impl.compression = compressionFromName(path, stripped);
    if (impl.compression == Compression::None)
        impl.compression = sniffCompression(path);
    source->_format = options.format.empty() ? formatFromExtension(stripped) : options.format;
    if (source->_format.empty())
    {
        error = path + ": cannot tell the point format from the file name; name it";
        return nullptr;
    }
    if (!stampFile(path, impl.stamp, error))
        return nullptr;
    if (isFrameFileFormat(source->_format))
        return source->openFrameFile(error) ? source : nullptr;
    if (impl.compression != Compression::None)
    {
        std::unique_ptr<ByteSource> first = openByteSource(path, impl.compression, nullptr, error);
        if (!first)
            return nullptr;
        impl.checkpoints = first->getCheckpoints();
        impl.giveBack(std::move(first));
    }
    if (!FrameScanner::supportsFormat(source->_format))
        return source->openSingleFrame(error) ? source : nullptr;

    impl.indexPath = chooseIndexPath(path, options.indexLocation, options.cacheFolder);
    ScanPosition resumeAt;
    const bool reused = source->reuseIndex(resumeAt);
    if (!source->openFirstFrame(error))
        return nullptr;
    if (!reused || !impl.complete)
        source->startIndexThread(resumeAt);
    return source;
}

bool FrameSource::poll(std::size_t& added, std::string& error)
{
    added = 0;
    if (_impl->singleFrame || !isIndexComplete())
        return true;
    FileStamp now;
    if (!stampFile(_path, now, error))
        return false;
    FileStamp before;
    ScanPosition start;
    std::size_t known = 0;
    {
        std::lock_guard<std::mutex> lock(_impl->mutex);
        before = _impl->stamp;
        start = _impl->scanEnd;
        known = _impl->frames.size();
    }
    if (now == before)
        return true;
    if (!fileGrewFrom(_path, before))
    {
        error = _path + ": the file shrank or was rewritten while followed (" + std::to_string(before.size) +
                " bytes before, " + std::to_string(now.size) + " now)";
        return false;
    }
    std::unique_ptr<ByteSource> source = _impl->takeSource(_path, error);
    if (!source)
        return false;
    std::vector<FrameInfo> found;
    ScanPosition end;
    scanFrames(
        *source, _format, start, true, _impl->stopping,
        [&found](const FrameInfo& frame) { found.push_back(frame); },
        [this](const std::string& warning) { _impl->warn(warning); }, end);
    _impl->giveBack(std::move(source));
    {
        std::lock_guard<std::mutex> lock(_impl->mutex);
        _impl->frames.insert(_impl->frames.end(), found.begin(), found.end());
        _impl->scanEnd = end;
        _impl->stamp = now;
        added = _impl->frames.size() - known;
    }
    if (added > 0)
        writeIndex(true);
    return true;
}

bool osgGlyphsData::formatFramePath(const std::string& pattern, uint64_t number, std::string& name)
{
    name.clear();
    const std::size_t percent = pattern.find('%');
    if (percent == std::string::npos)
    {
        name = pattern;
        return true;
    }
    // %[0][width]d, width up to two digits, and no other '%' after it.
    std::size_t at = percent + 1;
    const bool zeros = at < pattern.size() && pattern[at] == '0';
    at += zeros ? 1 : 0;
    int width = 0;
    for (int digits = 0;
         digits < 2 && at < pattern.size() && std::isdigit(static_cast<unsigned char>(pattern[at]));
         ++digits, ++at)
        width = 10 * width + (pattern[at] - '0');
    if (at >= pattern.size() || pattern[at] != 'd' || pattern.find('%', at) != std::string::npos)
        return false;
    std::string digits = std::to_string(number);
    if (static_cast<int>(digits.size()) < width)
        digits.insert(0, static_cast<std::size_t>(width) - digits.size(), zeros ? '0' : ' ');
    name = pattern.substr(0, percent) + digits + pattern.substr(at + 1);
    return true;
}

namespace
{

/** The largest step, so that frame + step cannot overflow. */
const unsigned long long MAX_FRAME_STEP = 1000000;

bool parseCount(const std::string& text, unsigned long long& value)
{
    if (text.empty() || text.size() > 18 || text.find_first_not_of("0123456789") != std::string::npos)
        return false;
    value = std::strtoull(text.c_str(), nullptr, 10);
    return true;
}

}

bool osgGlyphsData::parseFrameRange(const std::string& text, FrameRange& range)
{
    const std::size_t colon = text.find(':');
    if (colon == std::string::npos)
        return false;
    const std::size_t second = text.find(':', colon + 1);
    const std::string last =
        text.substr(colon + 1, second == std::string::npos ? std::string::npos : second - colon - 1);
    unsigned long long first = 0, end = 0, step = 1;
    if (!parseCount(text.substr(0, colon), first) || (!last.empty() && !parseCount(last, end)) ||
        (second != std::string::npos && !parseCount(text.substr(second + 1), step)))
        return false;
    if (step == 0 || step > MAX_FRAME_STEP || (!last.empty() && end < first))
        return false;
    range.first = static_cast<std::size_t>(first);
    range.last = last.empty() ? SIZE_MAX : static_cast<std::size_t>(end);
    range.step = static_cast<std::size_t>(step);
    return true;
}
