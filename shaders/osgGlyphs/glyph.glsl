// osgGlyphs: a glyph in eye space, and the uniforms every technique's stages share.

#include "defines.glsl"

// Vector glyphs: x = length scale, y = 1 for one length for all glyphs (x), z = anchor
// (0 tail, 0.5 centre, 1 head on the data point); arrows: x = head length / length,
// y = head radius / shaft radius.
uniform vec3 osgGlyphs_vectorParams;
uniform vec2 osgGlyphs_arrowParams;

// The viewport (x, y, width, height) in pixels: rays through fragments, sizes of point sprites.
uniform vec4 osgGlyphs_viewport;

/** A glyph in eye space. */
struct Glyph
{
    vec4 sphere; // centre (vector shapes: the tail's base centre), radius (ellipsoids: the largest
                 // semi-axis, superquadrics: a bound of their extent; 0: not drawn)
    vec4 axis;   // vector shapes: unit axis, length
    vec4 color;
    // Per-glyph ambient occlusion (GlyphCloud::setOcclusion): the light reaching a surface point of
    // unit eye-space normal n is clamp(occlusion.w + dot(occlusion.xyz, n), 0, 1); (0, 0, 0, 1) without.
    vec4 occlusion;
#ifdef OSGGLYPHS_AXES_SHAPE
    mat3 semiAxes; // ellipsoids and superquadrics: the semi-axes as columns
#endif
#ifdef OSGGLYPHS_SHAPE_SUPERQUADRIC
    vec2 exponents; // superquadrics: e1 along the third semi-axis, e2 around it
#endif
};

const float INFINITE_DISTANCE = 1.0e30;

/** Where a ray runs inside a convex solid: from tEnter to tLeave (possibly infinite), with the
 * solid's unit outward normals there. */
struct Span
{
    float tEnter;
    float tLeave;
    vec3 nEnter;
    vec3 nLeave;
};

bool isDrawn(Glyph glyph)
{
    return glyph.sphere.w > 0.0 && !any(isnan(glyph.sphere)) && !any(isinf(glyph.sphere)) && !any(isnan(glyph.axis));
}
