/* osgGlyphs - private: IEEE 754 half floats for packed glyph attributes. Not installed. */

#ifndef OSGGLYPHS_HALFFLOAT_H
#define OSGGLYPHS_HALFFLOAT_H 1

#include <cstdint>

namespace osgGlyphs
{
namespace detail
{

/** The nearest half float to a finite value >= 0; positive values never round to zero and
 * values beyond the half range clamp to its largest finite value. */
uint16_t toHalf(float value);

/** The value of a half float (as the GLSL decodeHalf in shaders/osgGlyphs/attributes.glsl). */
float fromHalf(uint16_t half);

}
}

#endif
