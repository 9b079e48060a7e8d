#include <osgGlyphsData/PointReader>

#include "readers/Fields.h"
#include "readers/Readers.h"

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

struct Format
{
    const char* name;
    void (*read)(TextScanner&, PointDataset&);
};

const Format formats[] = {
    {"csv", readCsv}, {"xyz", readXyz}, {"lammps", readLammps}, {"ply", readPly}, {"vtk", readVtk},
};

// Format names and the aliases readPointStream() also takes.
const struct
{
    const char* alias;
    const char* format;
} aliases[] = {
    {"csv", "csv"},          {"xyz", "xyz"},     {"extxyz", "xyz"}, {"lammps", "lammps"},
    {"lammpstrj", "lammps"}, {"dump", "lammps"}, {"ply", "ply"},    {"vtk", "vtk"},
};

std::string canonicalFormat(const std::string& name)
{
    const std::string lower = toLower(name);
    for (const auto& alias : aliases)
    {
        if (lower == alias.alias)
            return alias.format;
    }
    return std::string();
}

std::string formatList()
{
    std::string list;
    for (const Format& format : formats)
        list += (list.empty() ? "" : ", ") + std::string(format.name);
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

std::vector<std::string> osgGlyphsData::getSupportedPointFormats()
{
    std::vector<std::string> names;
    for (const Format& format : formats)
        names.push_back(format.name);
    return names;
}

std::string osgGlyphsData::formatFromExtension(const std::string& path)
{
    const std::filesystem::path file(path);
    const std::string filename = toLower(file.filename().string());
    if (startsWith(filename, "dump."))
        return "lammps";
    std::string extension = toLower(file.extension().string());
    if (extension.empty())
        return std::string();
    extension.erase(0, 1);
    if (extension == "csv")
        return "csv";
    if (extension == "xyz" || extension == "extxyz")
        return "xyz";
    if (extension == "lammpstrj" || extension == "dump" || extension == "lammps")
        return "lammps";
    if (extension == "ply" || extension == "vtk")
        return extension;
    return std::string();
}

osg::ref_ptr<PointDataset> osgGlyphsData::readPointStream(std::istream& stream, const std::string& format,
                                                          const std::string& nameForMessages,
                                                          const PointReadOptions& options, std::string& error)
{
    error.clear();
    const std::string canonical = canonicalFormat(format);
    const Format* reader = nullptr;
    for (const Format& candidate : formats)
    {
        if (canonical == candidate.name)
            reader = &candidate;
    }
    if (!reader)
    {
        error = nameForMessages + ": unknown point format " + quote(format) + " (supported: " + formatList() +
                ")";
        return nullptr;
    }

    const uint64_t size = remainingStreamSize(stream);
    TextScanner scanner(stream, nameForMessages, size, options.progress);
    osg::ref_ptr<PointDataset> dataset = new PointDataset;
    dataset->setFormat(reader->name);
    dataset->setSource(nameForMessages);
    try
    {
        if (scanner.atEnd())
            scanner.failAtLine(1, "the file is empty");
        reader->read(scanner, *dataset);
        for (const osg::ref_ptr<PointData>& frame : dataset->getFrames())
            frame->setSource(nameForMessages);
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
    return readPointStream(stream, format, path, options, error);
}
