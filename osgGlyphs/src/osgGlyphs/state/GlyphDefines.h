/* osgGlyphs - private: the defines that select program variants, and the GLSL generated from
 * them and from the attribute table. Not installed. */

#ifndef OSGGLYPHS_GLYPHDEFINES_H
#define OSGGLYPHS_GLYPHDEFINES_H 1

#include <osgGlyphs/GlyphTechnique>

#include <string>
#include <vector>

namespace osgGlyphs
{
namespace detail
{

extern const char* const FLOAT_ATTRIBUTES_DEFINE;
extern const char* const COLOR_RGBA_DEFINE;
extern const char* const VECTOR_SHAPE_DEFINE;
extern const char* const AXES_SHAPE_DEFINE;
/** Set by a cloud (not a variant) whose positions are 16-bit integers on a grid. */
extern const char* const COMPRESSED_POSITIONS_DEFINE;
/** Set by the cull traversal (not a variant) where any of OSG's clip planes is on. */
extern const char* const CLIP_PLANES_DEFINE;

/** Every define of the glyph programs that a StateSet sets: the one table from which every stage's
 * #pragma import_defines is generated (generateDefinesGlsl). A define missing here is never seen
 * by the shaders; test_shader_defines fails on a stage that tests one. */
const std::vector<const char*>& getGlyphProgramDefines();

/** The defines of a variant, as its StateSet sets them. */
std::vector<std::string> getVariantDefines(const GlyphVariant& variant);

/** GLSL every stage includes (osgGlyphs/defines.glsl): the variant defines OSG may set, and
 * what follows from them. */
std::string generateDefinesGlsl();

/** GLSL the vertex stage includes (osgGlyphs/attributes.glsl): the technique's attributes, each
 * declared under its condition. */
std::string generateAttributesGlsl(const GlyphTechnique& technique);

/** Every attribute of the technique's program: the glyph attributes and its own. */
std::vector<GlyphAttributeBinding> getProgramAttributes(const GlyphTechnique& technique);

}
}

#endif
