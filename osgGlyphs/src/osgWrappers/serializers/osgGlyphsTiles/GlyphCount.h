#ifndef OSGGLYPHS_WRAPPERS_GLYPHCOUNT_H
#define OSGGLYPHS_WRAPPERS_GLYPHCOUNT_H

// A whole number of glyphs (a tile archive's or a series' glyph budget) in the osgGlyphsTiles
// wrappers' streams. Private to them.

#include <osgDB/InputStream>
#include <osgDB/OutputStream>

#include <cstddef>
#include <string>

namespace osgGlyphsWrappers
{

/** The largest count a stream may hold: more is a corrupt file. */
const double MAX_GLYPH_COUNT = 1e15;

/** Writes a count as a double in binary streams (exactly, beyond 32 bits), and as its whole digits
 * in text streams, which write doubles with 6 significant digits; readGlyphCount() reads both, as
 * every earlier reader did. */
inline void writeGlyphCount(osgDB::OutputStream& os, std::size_t count)
{
    if (os.isBinary())
        os << static_cast<double>(count);
    else
        os << std::to_string(count);
    os << std::endl;
}

/** Reads a count that writeGlyphCount() wrote; false, count untouched, where the stream holds no
 * number from 0 to MAX_GLYPH_COUNT. */
inline bool readGlyphCount(osgDB::InputStream& is, std::size_t& count)
{
    double value = -1.0;
    is >> value;
    if (!(value >= 0.0 && value <= MAX_GLYPH_COUNT))
        return false;
    count = static_cast<std::size_t>(value);
    return true;
}

}

#endif
