#version 330 compatibility
// osgGlyphs, geometry-shader technique: decodes each glyph into eye space and hands it to
// geometry-shader.geom, which bounds it on screen.

#include "decode.glsl"

out GlyphVertex
{
    vec4 sphere;
    vec4 axis;
    vec4 color;
    vec4 occlusion;
#ifdef OSGGLYPHS_AXES_SHAPE
    mat3 semiAxes;
#endif
#ifdef OSGGLYPHS_SHAPE_SUPERQUADRIC
    vec2 exponents;
#endif
}
glyphOut;

void main()
{
    Glyph glyph = decodeGlyph();
    glyphOut.sphere = glyph.sphere;
    glyphOut.axis = glyph.axis;
    glyphOut.color = glyph.color;
    glyphOut.occlusion = glyph.occlusion;
#ifdef OSGGLYPHS_AXES_SHAPE
    glyphOut.semiAxes = glyph.semiAxes;
#endif
#ifdef OSGGLYPHS_SHAPE_SUPERQUADRIC
    glyphOut.exponents = glyph.exponents;
#endif
    gl_Position = vec4(glyph.sphere.xyz, 1.0);
}
