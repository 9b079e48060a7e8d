/* osgGlyphs - private: the compressed coordinates of GROMACS's XTC frames, decoded. */

#ifndef OSGGLYPHS_FORMATS_XTCCOORDINATES_H
#define OSGGLYPHS_FORMATS_XTCCOORDINATES_H 1

#include <cstddef>
#include <cstdint>
#include <string>

namespace osgGlyphsData
{
namespace formats
{

/** The header of the compressed coordinates of an XTC frame of more than 9 atoms: positions are
 * integers (position * precision, rounded) between minimum and maximum on each axis; smallIndex
 * picks the first size of the small differences between neighbouring atoms. */
struct XtcCompressed
{
    float precision = 0.0f;
    int32_t minimum[3] = {};
    int32_t maximum[3] = {};
    int32_t smallIndex = 0;
};

/** What is wrong with the header: empty when nothing. */
std::string checkXtcCompressed(const XtcCompressed& header);

/** The most bytes that compressed coordinates of this many atoms can take. */
uint64_t maxXtcCompressedBytes(uint64_t atoms);

/** Decodes the positions of atoms into out (x, y and z, atoms values each, in the file's units)
 * from the compressed bytes. Returns an empty string, or what is wrong with byte set to the offset in bytes
 * where decoding found it. The header must have passed checkXtcCompressed(). */
std::string decodeXtcCoordinates(const XtcCompressed& header, const unsigned char* bytes, std::size_t size,
                                 std::size_t atoms, float* const out[3], std::size_t& byte);

} // namespace formats
}

#endif
