#include <osgGlyphsData/PointReader>

#include "PointFormatTable.h"
#include "readers/Fields.h"

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

std::vector<std::string> splitWords(const char* text)
{
    std::vector<std::string_view> fields;
    splitBlanks(text, fields);
    return std::vector<std::string>(fields.begin(), fields.end());
}

bool hasExtension(const PointFormat& format, const std::string& extension)
{
    return std::find(format.extensions.begin(), format.extensions.end(), extension) !=
           format.extensions.end();
}

/** The row of a format name or of one of its extensions, or nullptr. */
const detail::PointFormatRow* findFormat(const std::string& name)
{
    const std::string lower = toLower(name);
    const std::vector<PointFormat>& formats = getPointFormats(); // in the order of the rows
    for (std::size_t i = 0; i < formats.size(); ++i)
    {
        if (lower == formats[i].name || hasExtension(formats[i], lower))
            return &detail::POINT_FORMAT_ROWS[i];
    }
    return nullptr;
}

std::string formatList()
{
    std::string list;
    for (const std::string& name : getSupportedPointFormats())
        list += (list.empty() ? "" : ", ") + name;
    return list;
}

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

const std::vector<PointFormat>& osgGlyphsData::getPointFormats()
{
    static const std::vector<PointFormat> formats = []
    {
        std::vector<PointFormat> list;
        for (const detail::PointFormatRow& row : detail::POINT_FORMAT_ROWS)
            list.push_back({row.name, row.description, splitWords(row.extensions), splitWords(row.prefixes)});
        return list;
    }();
    return formats;
}

std::vector<std::string> osgGlyphsData::getSupportedPointFormats()
{
    std::vector<std::string> names;
    for (const PointFormat& format : getPointFormats())
        names.push_back(format.name);
    return names;
}

std::string osgGlyphsData::formatFromExtension(const std::string& path)
{
    const std::filesystem::path file(path);
    const std::string filename = toLower(file.filename().string());
    std::string extension = toLower(file.extension().string());
    if (!extension.empty())
        extension.erase(0, 1);
    for (const PointFormat& format : getPointFormats())
    {
        for (const std::string& prefix : format.prefixes)
        {
            if (startsWith(filename, prefix))
                return format.name;
        }
    }
    for (const PointFormat& format : getPointFormats())
    {
        if (hasExtension(format, extension))
            return format.name;
    }
    return std::string();
}

osg::ref_ptr<PointDataset> osgGlyphsData::readPointStream(std::istream& stream, const std::string& format,
                                                          const std::string& nameForMessages,
                                                          const PointReadOptions& options, std::string& error)
{
    error.clear();
    const detail::PointFormatRow* reader = findFormat(format);
    if (!reader)
    {
        error = nameForMessages + ": unknown point format " + quote(format) + " (supported: " + formatList() +
                ")";
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
    dataset->setFormat(reader->name);
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
        reader->read(scanner, *dataset, options);
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
            error = path +
                    ": cannot tell the point format from the file name; name it (supported: " + formatList() +
                    ")";
            return nullptr;
        }
    }
    std::error_code code;
    if (std::filesystem::is_directory(path, code))
    {
        error = path + ": is a directory";
        return nullptr;
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
