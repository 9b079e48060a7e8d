// osgGlyphs: which glyph shape this program variant draws, from the define list.

#pragma import_defines(OSGGLYPHS_SHAPE_CONE, OSGGLYPHS_SHAPE_ARROW, OSGGLYPHS_SHAPE_CYLINDER, OSGGLYPHS_PAPER)

#if defined(OSGGLYPHS_SHAPE_CONE) || defined(OSGGLYPHS_SHAPE_ARROW) || defined(OSGGLYPHS_SHAPE_CYLINDER)
#define OSGGLYPHS_VECTOR_SHAPE 1
#endif

// Vector glyphs: x = length scale, y = 1 for one length for all glyphs (x), z = anchor
// (0 tail, 0.5 centre, 1 head on the data point); arrows: x = head length / length,
// y = head radius / shaft radius.
uniform vec3 osgGlyphs_vectorParams;
uniform vec2 osgGlyphs_arrowParams;
