// osgGlyphs: which shape and which technique this program variant draws, from the define list.

#pragma import_defines(OSGGLYPHS_SHAPE_CONE, OSGGLYPHS_SHAPE_ARROW, OSGGLYPHS_SHAPE_CYLINDER)
#pragma import_defines(OSGGLYPHS_TECHNIQUE_INSTANCED, OSGGLYPHS_TECHNIQUE_SPRITE, OSGGLYPHS_TECHNIQUE_PAPER)
#pragma import_defines(OSGGLYPHS_TECHNIQUE_POLYGONS, OSGGLYPHS_TECHNIQUE_TEXTURE_BLEND, OSGGLYPHS_TECHNIQUE_TEXTURE_MULTI)
#pragma import_defines(OSGGLYPHS_TECHNIQUE_POINTS)

#if defined(OSGGLYPHS_SHAPE_CONE) || defined(OSGGLYPHS_SHAPE_ARROW) || defined(OSGGLYPHS_SHAPE_CYLINDER)
#define OSGGLYPHS_VECTOR_SHAPE 1
#endif

// The paper's texture techniques: a textured point sprite the size of the projected bounding sphere.
#if defined(OSGGLYPHS_TECHNIQUE_TEXTURE_BLEND) || defined(OSGGLYPHS_TECHNIQUE_TEXTURE_MULTI)
#define OSGGLYPHS_TEXTURED_SPRITE 1
#endif

// The exact impostor: bounded by a geometry shader (no technique define), an instanced quad
// or a point sprite, and ray-cast in the fragment shader.
#if !defined(OSGGLYPHS_TECHNIQUE_PAPER) && !defined(OSGGLYPHS_TECHNIQUE_POLYGONS) &&                          \
    !defined(OSGGLYPHS_TEXTURED_SPRITE) && !defined(OSGGLYPHS_TECHNIQUE_POINTS)
#define OSGGLYPHS_RAYCAST 1
#endif

// Instanced techniques read the glyph's position from a per-instance attribute.
#if defined(OSGGLYPHS_TECHNIQUE_INSTANCED) || defined(OSGGLYPHS_TECHNIQUE_POLYGONS)
#define OSGGLYPHS_PER_INSTANCE 1
#endif

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
    vec4 sphere; // centre (vector shapes: the tail's base centre), radius (0: not drawn)
    vec4 axis;   // vector shapes: unit axis, length
    vec4 color;
};

bool isDrawn(Glyph glyph)
{
    return glyph.sphere.w > 0.0 && !any(isnan(glyph.sphere)) && !any(isinf(glyph.sphere)) && !any(isnan(glyph.axis));
}
