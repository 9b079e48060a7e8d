/* osgGlyphs - private: the glyphs a ray meets or a polytope holds, found through the chunks of the
 * spatial order. Not installed. */

#ifndef OSGGLYPHS_GLYPHPICKING_H
#define OSGGLYPHS_GLYPHPICKING_H 1

#include "../culling/GlyphChunks.h"
#include "GlyphRayCast.h"

#include <osg/Array>
#include <osg/Polytope>

#include <functional>
#include <vector>

namespace osgGlyphs
{
namespace detail
{

/** Glyph i as drawn, relative to the cloud's origin; false for a glyph that is not drawn. */
typedef std::function<bool(unsigned int i, GlyphSolid& solid)> GlyphSolidSource;

/** A glyph met by a ray: the distance along it, and the surface normal there. */
struct GlyphRayHit
{
    unsigned int glyph = 0;
    double t = 0.0;
    glm::dvec3 normal;
};

/** The glyphs the ray origin + t * direction (unit direction) meets for t in [0, maxT], each at
 * its nearest point, nearest first; only the nearest one when nearestOnly. The chunks' boxes
 * are the spatial index: the ray visits the chunks it crosses, nearest first. */
std::vector<GlyphRayHit> castRayThroughChunks(const GlyphChunks& chunks, const GlyphSolidSource& solids,
                                              const glm::dvec3& origin, const glm::dvec3& direction,
                                              double maxT, bool nearestOnly);

/** The glyphs whose point (positions[i]) lies inside the polytope, in spatial order. */
std::vector<unsigned int> findGlyphsInPolytope(const GlyphChunks& chunks, const osg::Vec3Array& positions,
                                               const osg::Polytope& polytope);

}
}

#endif
