/* osgGlyphs - private: glyphs kept in temporary files while a dataset larger than memory is cut
 * into tiles. Not installed. */

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

/** The bytes of one glyph in a temporary file: its position and radius, then a value of each
 * other array the dataset uses (scalar, colour, vector, semi-axes, turn, exponents). */
class TileRecordFormat
{
public:
    /** The records of glyphs like these. */
    explicit TileRecordFormat(const TileGlyphs& like);

    std::size_t size() const { return _size; }
    /** Writes glyph i of glyphs at record. */
    void pack(const TileGlyphs& glyphs, std::size_t i, unsigned char* record) const;
    /** Makes room for count glyphs in the arrays these records fill. */
    void reserve(TileGlyphs& glyphs, std::size_t count) const;
    /** Sets glyphs to the count records at bytes. */
    void unpack(const unsigned char* bytes, std::size_t count, TileGlyphs& glyphs) const;

private:
    /** Calls visit with each array of glyphs that a record holds a value of, in the record's order. */
    template <typename Glyphs, typename Visit>
    void forEachArray(Glyphs& glyphs, const Visit& visit) const
    {
        unsigned int index = 0;
        TileGlyphs::forEachArray(
            [&](auto& values)
            {
                if (_used >> index++ & 1u)
                    visit(values);
            },
            glyphs);
    }

    unsigned int _used = 0; // a bit for each array, in the order of TileGlyphs::forEachArray
    std::size_t _size = 0;
};

/** Glyph records appended to a temporary file that the spill deletes. */
class TileSpill
{
public:
    /** Creates the file at path; isOpen() tells whether that worked. */
    TileSpill(const std::string& path, const TileRecordFormat& format);
    ~TileSpill();
    TileSpill(const TileSpill&) = delete;
    TileSpill& operator=(const TileSpill&) = delete;

    bool isOpen() const { return _file != nullptr; }
    const std::string& getPath() const { return _path; }
    const TileRecordFormat& getFormat() const { return _format; }
    std::size_t size() const { return _count; }

    /** Appends the glyphs [begin, end) of glyphs; false with error naming the file on failure. */
    bool append(const TileGlyphs& glyphs, std::size_t begin, std::size_t end, std::string& error);

    /** Calls visit with every record, in order, a block at a time (the block's origin and range
     * are not set); stops at the first false from visit. False with error on a read failure. */
    bool read(const std::function<bool(const TileGlyphs& block)>& visit, std::string& error);

private:
    bool writeBuffer(std::string& error);

    std::string _path;
    TileRecordFormat _format;
    std::FILE* _file = nullptr;
    std::size_t _count = 0;
    std::vector<unsigned char> _buffer;
};

}
}

#endif
