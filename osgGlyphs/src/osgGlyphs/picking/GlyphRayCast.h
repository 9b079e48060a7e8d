/* osgGlyphs - private: a glyph's exact surface met by a ray on the CPU, for picking. Not installed.
 *
 * The functions mirror shaders/osgGlyphs/impostor.frag, sphere.glsl, vector.glsl and ellipsoid.glsl, name for
 * name, in double precision: a pick returns the surface the fragment shader draws. */

#ifndef OSGGLYPHS_GLYPHRAYCAST_H
#define OSGGLYPHS_GLYPHRAYCAST_H 1

#include <osgGlyphs/GlyphStyle>

#include <glm/mat3x3.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace osgGlyphs
{
namespace detail
{

/** One glyph as the shaders see it (glyph.glsl's Glyph, with the shape and arrow uniforms). */
struct GlyphSolid
{
    GlyphShape shape = GlyphShape::Sphere;
    glm::dvec3 base = glm::dvec3(0.0); // the sphere's centre; a vector glyph's tail (its base centre)
    double radius = 0.0;
    glm::dvec3 axis = glm::dvec3(0.0, 0.0, 1.0);   // vector glyphs: unit axis
    double length = 0.0;                           // vector glyphs: tail to apex or head tip
    glm::dvec2 arrowParams = glm::dvec2(0.3, 2.0); // head length / length, head radius / radius
    glm::dmat3 semiAxes = glm::dmat3(1.0);         // ellipsoids: the semi-axes as columns
    glm::dvec2 exponents = glm::dvec2(1.0);        // superquadrics: e1, e2
};

/** The nearest surface point along origin + t * direction (unit direction), t >= 0, and its unit
 * normal, or false. A ray that starts inside the glyph meets it at t = 0 with the normal facing
 * back along the ray, as the shader draws a glyph cut by the near plane. */
bool castRay(const GlyphSolid& glyph, const glm::dvec3& origin, const glm::dvec3& direction, double& t,
             glm::dvec3& normal);

}
}

#endif
