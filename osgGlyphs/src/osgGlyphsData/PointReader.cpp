#include <osgGlyphsData/PointReader>

#include "FormatRegistry.h"
#include "readers/Fields.h"
#include "readers/Readers.h"

#include <osg/Notify>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <istream>
#include <new>
#include <stdexcept>

using namespace osgGlyphsData;
using namespace osgGlyphsData::readers;

namespace
{

// What is left in the stream from its current position, 0 when it cannot seek.
uint64_t remainingStreamSize(std::istream& stream)
{
    const std::istream::pos_type start = stream.tellg();
    if (start == std::istream::pos_type(-1))
    {
        stream.clear();
        return 0;
    }
    stream.seekg(0, std::ios::end);
    const std::istream::pos_type end = stream.tellg();
    stream.clear();
    stream.seekg(start);
    if (end == std::istream::pos_type(-1) || end < start)
        return 0;
    return static_cast<uint64_t>(end - start);
}

} // namespace

namespace
{

/** Reads the frames of a FrameFile in order, as a PointDataset. */
osg::ref_ptr<PointDataset> readFrameFile(const std::string& path, const detail::FormatEntry& entry,
                                         const PointReadOptions& options, std::string& error)
{
    FrameFileOptions open;
    open.datasets = options.datasets;
    osg::ref_ptr<FrameFile> file = openFrameFile(path, entry.format.name, open, error);
    if (!file)
        return nullptr;
    osg::ref_ptr<PointDataset> dataset = new PointDataset;
    dataset->setFormat(entry.format.name);
    dataset->setSource(path);
    for (const std::string& warning : file->getWarnings())
    {
        dataset->addWarning(warning);
        if (options.warning)
            options.warning(warning);
        else
            OSG_WARN << warning << std::endl;
    }
    const std::size_t frames = file->getNumFrames();
    std::size_t frame = static_cast<std::size_t>(std::min<uint64_t>(options.start.frame, frames));
    for (; frame < frames && (options.maxFrames == 0 || dataset->getNumFrames() < options.maxFrames); ++frame)
    {
        osg::ref_ptr<PointData> data = file->readFrame(frame, options.share, error);
        if (!data)
            return nullptr;
        data->setSource(path);
        dataset->addFrame(data.get());
        if (options.progress)
            options.progress(file->getFrameInfo(frame).end, 0);
    }
    dataset->setEndOfCompleteFrames({file->getFrameInfo(frame == 0 ? 0 : frame - 1).end, 0, frame});
    if (dataset->getNumFrames() == 0 && !readers::mayReadNothing(options))
    {
        error = path + ": no frames";
        return nullptr;
    }
    return dataset;
}

}

osg::ref_ptr<PointDataset> osgGlyphsData::readPointStream(std::istream& stream, const std::string& format,
                                                          const std::string& nameForMessages,
                                                          const PointReadOptions& options, std::string& error)
{
    error.clear();
    detail::FormatEntry reader;
    if (!detail::findFormatEntry(format, reader))
    {
        error = nameForMessages + ": unknown point format " + quote(format) +
                " (supported: " + detail::listFormatNames() + ")";
        return nullptr;
    }
    if (!reader.read)
    {
        error = nameForMessages + ": " + reader.format.name +
                " files are read by seeking in them: give a file, not a stream";
        return nullptr;
    }

    std::string shareError;
    if (!checkPointShare(options.share, shareError))
    {
        error = nameForMessages + ": " + shareError;
        return nullptr;
    }
    const uint64_t size = remainingStreamSize(stream);
    TextScanner scanner(stream, nameForMessages, size, options.progress, options.start.offset,
                        options.start.line);
    osg::ref_ptr<PointDataset> dataset = new PointDataset;
    dataset->setFormat(reader.format.name);
    dataset->setSource(nameForMessages);
    dataset->setEndOfCompleteFrames(options.start);
    try
    {
        if (scanner.atEnd())
        {
            if (mayReadNothing(options))
                return dataset;
            scanner.failAtLine(1, "the file is empty");
        }
        reader.read(scanner, *dataset, options);
        for (const osg::ref_ptr<PointData>& frame : dataset->getFrames())
            frame->setSource(nameForMessages);
        for (const std::string& warning : dataset->getWarnings())
        {
            if (options.warning)
                options.warning(warning);
            else
                OSG_WARN << warning << std::endl;
        }
        scanner.reportProgress();
        return dataset;
    }
    catch (const ReadError& failure)
    {
        error = failure.message;
    }
    catch (const std::bad_alloc&)
    {
        error = nameForMessages + ": out of memory while reading byte " + std::to_string(scanner.getOffset());
    }
    catch (const std::length_error&)
    {
        error = nameForMessages + ": out of memory while reading byte " + std::to_string(scanner.getOffset());
    }
    return nullptr;
}

osg::ref_ptr<PointDataset> osgGlyphsData::readPointFile(const std::string& path,
                                                        const PointReadOptions& options, std::string& error)
{
    std::string format = options.format;
    if (format.empty())
    {
        format = formatFromExtension(path);
        if (format.empty())
        {
            error = path + ": cannot tell the point format from the file name; name it (supported: " +
                    detail::listFormatNames() + ")";
            return nullptr;
        }
    }
    std::error_code code;
    if (std::filesystem::is_directory(path, code))
    {
        error = path + ": is a directory";
        return nullptr;
    }
    detail::FormatEntry entry;
    if (detail::findFormatEntry(format, entry) && entry.open)
    {
        std::string shareError;
        if (!checkPointShare(options.share, shareError))
        {
            error = path + ": " + shareError;
            return nullptr;
        }
        return readFrameFile(path, entry, options, error);
    }
    std::ifstream stream(path, std::ios::binary);
    if (!stream)
    {
        error = path + ": cannot open: " + std::strerror(errno);
        return nullptr;
    }
    if (options.start.offset > 0 && !stream.seekg(static_cast<std::streamoff>(options.start.offset)))
    {
        error = path + ": cannot seek to byte " + std::to_string(options.start.offset);
        return nullptr;
    }
    return readPointStream(stream, format, path, options, error);
}
