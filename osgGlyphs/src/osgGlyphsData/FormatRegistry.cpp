#include "FormatRegistry.h"

#include "PointFormatTable.h"
#include "readers/Fields.h"

#include <algorithm>
#include <filesystem>
#include <mutex>

using namespace osgGlyphsData;
using namespace osgGlyphsData::detail;

namespace
{

std::vector<std::string> splitWords(const char* text)
{
    std::vector<std::string_view> fields;
    readers::splitBlanks(text, fields);
    return std::vector<std::string>(fields.begin(), fields.end());
}

bool hasExtension(const PointFormat& format, const std::string& extension)
{
    return std::find(format.extensions.begin(), format.extensions.end(), extension) !=
           format.extensions.end();
}

/** The formats of the table, then those registered, in that order; guarded by registryMutex(). */
std::vector<FormatEntry>& registry()
{
    static std::vector<FormatEntry> entries = []
    {
        std::vector<FormatEntry> table;
        for (const PointFormatRow& row : POINT_FORMAT_ROWS)
        {
            FormatEntry entry;
            entry.format = {row.name, row.description, splitWords(row.extensions), splitWords(row.prefixes)};
            entry.read = row.read;
            if (row.open)
                entry.open = row.open;
            table.push_back(entry);
        }
        return table;
    }();
    return entries;
}

std::mutex& registryMutex()
{
    static std::mutex mutex;
    return mutex;
}

}

bool detail::findFormatEntry(const std::string& nameOrExtension, FormatEntry& entry)
{
    const std::string lower = readers::toLower(nameOrExtension);
    std::lock_guard<std::mutex> lock(registryMutex());
    for (const FormatEntry& candidate : registry())
    {
        if (lower == candidate.format.name || hasExtension(candidate.format, lower))
        {
            entry = candidate;
            return true;
        }
    }
    return false;
}

std::string detail::listFormatNames()
{
    std::string list;
    for (const std::string& name : getSupportedPointFormats())
        list += (list.empty() ? "" : ", ") + name;
    return list;
}

std::vector<PointFormat> osgGlyphsData::getPointFormats()
{
    std::lock_guard<std::mutex> lock(registryMutex());
    std::vector<PointFormat> formats;
    for (const FormatEntry& entry : registry())
        formats.push_back(entry.format);
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
    const std::string filename = readers::toLower(file.filename().string());
    std::string extension = readers::toLower(file.extension().string());
    if (!extension.empty())
        extension.erase(0, 1);
    // A known extension first: data.csv is a CSV file, dump.xyz an XYZ file; data.peptide is not.
    const std::vector<PointFormat> formats = getPointFormats();
    for (const PointFormat& format : formats)
    {
        if (hasExtension(format, extension))
            return format.name;
    }
    for (const PointFormat& format : formats)
    {
        for (const std::string& prefix : format.prefixes)
        {
            if (readers::startsWith(filename, prefix))
                return format.name;
        }
    }
    return std::string();
}

void osgGlyphsData::registerFrameFileFormat(const PointFormat& format, FrameFileOpener opener)
{
    FormatEntry entry;
    entry.format = format;
    entry.open = std::move(opener);
    std::lock_guard<std::mutex> lock(registryMutex());
    std::vector<FormatEntry>& entries = registry();
    auto same =
        std::find_if(entries.begin(), entries.end(),
                     [&format](const FormatEntry& known) { return known.format.name == format.name; });
    if (same != entries.end())
        *same = std::move(entry);
    else
        entries.push_back(std::move(entry));
}

bool osgGlyphsData::isFrameFileFormat(const std::string& nameOrExtension)
{
    FormatEntry entry;
    return findFormatEntry(nameOrExtension, entry) && entry.open;
}

osg::ref_ptr<FrameFile> osgGlyphsData::openFrameFile(const std::string& path, const std::string& format,
                                                     const FrameFileOptions& options, std::string& error)
{
    const std::string name = format.empty() ? formatFromExtension(path) : format;
    FormatEntry entry;
    if (name.empty() || !findFormatEntry(name, entry))
    {
        error = path + ": " +
                (name.empty() ? "cannot tell the point format from the file name; name it"
                              : "unknown point format \"" + name + "\"") +
                " (supported: " + listFormatNames() + ")";
        return nullptr;
    }
    if (!entry.open)
    {
        error = path + ": " + entry.format.name + " files are text, read as a stream, not as a frame file";
        return nullptr;
    }
    std::error_code code;
    if (!std::filesystem::is_directory(path, code) && std::filesystem::file_size(path, code) == 0 && !code)
    {
        error = path + ": the file is empty";
        return nullptr;
    }
    return entry.open(path, options, error);
}
