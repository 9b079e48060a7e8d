/* osgGlyphs - private: writing an OSG archive (.osga) from several threads at once. Not
 * installed. */

#ifndef OSGGLYPHS_TILEARCHIVE_H
#define OSGGLYPHS_TILEARCHIVE_H 1

#include <osg/Node>

#include <cstdint>
#include <cstdio>
#include <mutex>
#include <string>
#include <vector>

namespace osgGlyphsTiles
{
namespace detail
{

/** An OSG archive being written, laid out as osgDB's osga plugin writes one (and reads it): a
 * header, then the files, with the index blocks that name them placed between the files as they
 * fill. Unlike osgDB::Archive, whose writeNode() serialises straight into its file, one at a time,
 * writeNode() serialises into memory on the caller's thread and only appends the bytes under a
 * lock, so that threads serialise their tiles side by side. */
class TileArchive
{
public:
    TileArchive() = default;
    ~TileArchive();
    TileArchive(const TileArchive&) = delete;
    TileArchive& operator=(const TileArchive&) = delete;

    /** Creates the file at path; false with error when that fails. Errors do not name the
     * archive: the caller does. */
    bool create(const std::string& path, std::string& error);

    /** Writes node as the file name, through the ReaderWriter of name's extension, as
     * osgDB::Archive::writeNode() does. Safe from several threads. A name written again replaces
     * the earlier file for readers (the index's last entry of a name wins). */
    bool writeNode(const osg::Node& node, const std::string& name, std::string& error);

    /** Writes the index and closes the file; false with error on failure. */
    bool close(std::string& error);

private:
    struct IndexBlock
    {
        uint64_t position = 0; // of the block in the file
        uint64_t next = 0;     // position of the next block; 0 for the last
        std::vector<char> entries;
    };

    bool append(const std::string& name, const std::string& bytes, std::string& error);
    bool writeBlock(const IndexBlock& block);
    bool writeAt(uint64_t position, const void* data, std::size_t size);

    std::FILE* _file = nullptr;
    uint64_t _end = 0;
    std::vector<IndexBlock> _blocks;
    std::mutex _mutex; // _file, _end, _blocks
};

}
}

#endif
