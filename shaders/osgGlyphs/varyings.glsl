// osgGlyphs: what reaches the fragment shader. OSGGLYPHS_VARYING is "out" in the stage that
// writes these and "in" in the fragment shader.

flat OSGGLYPHS_VARYING vec4 fragSphere; // eye-space centre (vector shapes: base), radius
flat OSGGLYPHS_VARYING vec4 fragColor;
#if defined(OSGGLYPHS_VECTOR_SHAPE) || !defined(OSGGLYPHS_RAYCAST)
#define OSGGLYPHS_AXIS_VARYING 1
flat OSGGLYPHS_VARYING vec4 fragAxis; // vector shapes: unit axis, length
#endif
#if defined(OSGGLYPHS_TECHNIQUE_PAPER) || defined(OSGGLYPHS_TECHNIQUE_POLYGONS)
OSGGLYPHS_VARYING vec3 fragLocal; // paper: billboard coordinates; polygons: eye-space normal
flat OSGGLYPHS_VARYING vec4 fragFrame; // paper cones: the billboard's eye-space x and y directions
#endif
#ifdef OSGGLYPHS_TECHNIQUE_TEXTURE_MULTI
flat OSGGLYPHS_VARYING float fragLayer; // the layer of the glyph's pre-lit sprite
#endif
