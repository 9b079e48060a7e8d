#version 330 compatibility
// osgGlyphs: one vertex per glyph. Decodes the glyph's packed attributes into its eye-space
// centre, radius and colour for the geometry shader, which bounds it on screen.

#pragma import_defines(OSGGLYPHS_COLOR_SCALAR, OSGGLYPHS_COLOR_RGBA)

#include "attributes.glsl"

out GlyphVertex
{
    vec4 sphere; // eye-space centre, radius (0: skip the glyph)
    vec4 color;
}
glyph;

void main()
{
    vec3 center = (gl_ModelViewMatrix * gl_Vertex).xyz;
    // A glyph scales with the model-view transform (uniform scale assumed).
    float scale = length(gl_ModelViewMatrix[0].xyz);
    glyph.sphere = vec4(center, glyphRadius() * scale);
    glyph.color = glyphColor();
    gl_Position = vec4(center, 1.0);
}
