/* osgGlyphs - private: the per-glyph ambient occlusion of GlyphCloud::computeOcclusion(). Not
 * installed. */

#ifndef OSGGLYPHS_GLYPHOCCLUSION_H
#define OSGGLYPHS_GLYPHOCCLUSION_H 1

#include <osgGlyphs/GlyphOcclusion>

#include "../picking/GlyphRayCast.h"

#include <osg/Array>

#include <functional>

namespace osgGlyphs
{
namespace detail
{

/** The occlusion values of count glyphs (see GlyphOcclusionSettings), glyph i as solid(i, s)
 * gives it; glyphs for which it returns false neither occlude nor are occluded (value (0.5, 0.5,
 * 0.5, 1): open). */
osg::ref_ptr<osg::Vec4ubArray>
computeGlyphOcclusion(unsigned int count, const std::function<bool(unsigned int, GlyphSolid&)>& solid,
                      const GlyphOcclusionSettings& settings);

}
}

#endif
