/* osgGlyphs - private: glyphs kept in a temporary file while a dataset larger than memory is
 * cut into tiles. Not installed. */

#ifndef OSGGLYPHS_TILESPILL_H
#define OSGGLYPHS_TILESPILL_H 1

#include "TileTree.h"

#include <cstdio>
#include <functional>
#include <memory>
#include <string>

namespace osgGlyphsTiles
{
namespace detail
{

/** Glyph records, each of one glyph's values (scalars, colours and vectors where the dataset has
 * them), appended to a temporary file that the spill deletes. */
class TileSpill
{
public:
    /** Creates the file at path; isOpen() tells whether that worked. */
    TileSpill(const std::string& path, bool scalars, bool colors, bool vectors);
    ~TileSpill();
    TileSpill(const TileSpill&) = delete;
    TileSpill& operator=(const TileSpill&) = delete;

    /** A new spill of the same kind of records at path. */
    std::unique_ptr<TileSpill> createLike(const std::string& path) const;

    bool isOpen() const { return _file != nullptr; }
    const std::string& getPath() const { return _path; }
    std::size_t size() const { return _count; }

    /** Appends the glyphs [begin, end) of glyphs; false with error naming the file on failure. */
    bool append(const TileGlyphs& glyphs, std::size_t begin, std::size_t end, std::string& error);
    /** Appends the glyphs of glyphs at indices. */
    bool append(const TileGlyphs& glyphs, const std::vector<unsigned int>& indices, std::string& error);

    /** Calls visit with every record, in order, a block at a time (the block's origin and range
     * are not set); stops at the first false from visit. False with error on a read failure. */
    bool read(const std::function<bool(const TileGlyphs& block)>& visit, std::string& error);

private:
    std::size_t recordSize() const;
    /** Appends the glyphs indexOf(0) .. indexOf(count - 1) of glyphs, a buffer at a time. */
    template <typename IndexOf>
    bool appendRecords(const TileGlyphs& glyphs, std::size_t count, const IndexOf& indexOf,
                       std::string& error);
    void pack(const TileGlyphs& glyphs, std::size_t i, unsigned char* record) const;
    bool writeBuffer(std::string& error);

    std::string _path;
    bool _scalars, _colors, _vectors;
    std::FILE* _file = nullptr;
    std::size_t _count = 0;
    std::vector<unsigned char> _buffer;
};

}
}

#endif
