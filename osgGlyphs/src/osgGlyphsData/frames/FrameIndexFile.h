/* osgGlyphs - private: the frame index of a trajectory file, persisted beside it or in a cache. */

#ifndef OSGGLYPHS_FRAMES_FRAMEINDEXFILE_H
#define OSGGLYPHS_FRAMES_FRAMEINDEXFILE_H 1

#include "FrameScanner.h"

#include <osgGlyphsData/FrameSource>

#include <cstdint>
#include <string>
#include <vector>

namespace osgGlyphsData
{
namespace frames
{

/** What identifies the file an index was made of: an index is valid for the file whose size,
 * modification time and last bytes are these, and for a file that only grew from it. */
struct FileStamp
{
    uint64_t size = 0;
    int64_t modifiedNanoseconds = 0;
    /** FNV-1a of the file's last (up to) 4 KiB on disk. */
    uint64_t tailHash = 0;

    bool operator==(const FileStamp& other) const
    {
        return size == other.size && modifiedNanoseconds == other.modifiedNanoseconds &&
               tailHash == other.tailHash;
    }
};

/** Stamps path as it is now; false with error when it cannot be read. */
bool stampFile(const std::string& path, FileStamp& stamp, std::string& error);

/** Whether path now holds the file of stamp with bytes appended (same bytes up to stamp.size). */
bool fileGrewFrom(const std::string& path, const FileStamp& stamp);

/** A frame index as stored. */
struct StoredFrameIndex
{
    FileStamp stamp;
    std::string format;
    uint32_t compression = 0;
    /** Where the scan ended: after the last complete frame. */
    ScanPosition end;
    /** Whether the scan reached the end of the file; else a later opening scans on from end. */
    bool complete = true;
    std::vector<FrameInfo> frames;
    std::vector<std::string> warnings;
    /** The compressed stream's restart points (Checkpoints::toBytes()). */
    std::string checkpoints;
};

/** Writes the index to path atomically (a temporary file renamed); false with a one-line error. */
bool writeFrameIndex(const std::string& path, const StoredFrameIndex& index, std::string& error);

/** Reads an index; false with a one-line reason when it is missing, of another version, or
 * corrupt (every count is checked against the file's size, every frame against the last). */
bool readFrameIndex(const std::string& path, StoredFrameIndex& index, std::string& error);

/** Where the index of a file lies: <file>.glyphindex beside it, or in cacheFolder under a name
 * made of the file's absolute path; empty for FrameIndexLocation::None. */
std::string chooseIndexPath(const std::string& file, FrameIndexLocation location,
                            const std::string& cacheFolder);

}
}

#endif
