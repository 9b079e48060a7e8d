/* osgGlyphs - private: the point formats, those of PointFormats.cmake and those registered since. */

#ifndef OSGGLYPHS_FORMATREGISTRY_H
#define OSGGLYPHS_FORMATREGISTRY_H 1

#include <osgGlyphsData/FrameFile>
#include <osgGlyphsData/PointReader>

#include "readers/TextScanner.h"

namespace osgGlyphsData
{
namespace detail
{

/** A format and how it is read: from a stream (read), or as a FrameFile (open). */
struct FormatEntry
{
    PointFormat format;
    void (*read)(readers::TextScanner&, PointDataset&, const PointReadOptions&) = nullptr;
    FrameFileOpener open;
};

/** The format of a name or of one of its extensions, case-insensitively; false when none. */
bool findFormatEntry(const std::string& nameOrExtension, FormatEntry& entry);

/** "csv, xyz, lammps, ...": the format names, for messages. */
std::string listFormatNames();

} // namespace detail
}

#endif
