#version 330 compatibility
// osgGlyphs: one vertex per glyph. Decodes the glyph's packed attributes into eye space for
// the geometry shader, which bounds the glyph on screen.

#pragma import_defines(OSGGLYPHS_COLOR_SCALAR, OSGGLYPHS_COLOR_RGBA)

#include "shapes.glsl"
#include "attributes.glsl"

out GlyphVertex
{
    vec4 sphere; // eye-space centre (vector shapes: base), radius (0: skip the glyph)
    vec4 axis;   // vector shapes: unit eye-space axis, length
    vec4 color;
}
glyph;

void main()
{
    vec3 center = (gl_ModelViewMatrix * gl_Vertex).xyz;
    // A glyph scales with the model-view transform (uniform scale assumed).
    float scale = length(gl_ModelViewMatrix[0].xyz);
    glyph.sphere = vec4(center, glyphRadius() * scale);
    glyph.axis = vec4(0.0);
    glyph.color = glyphColor();
#ifdef OSGGLYPHS_VECTOR_SHAPE
    vec3 vector = mat3(gl_ModelViewMatrix) * osgGlyphs_vector;
    float magnitude = length(vector);
    float len = osgGlyphs_vectorParams.y > 0.5 ? osgGlyphs_vectorParams.x * scale : osgGlyphs_vectorParams.x * magnitude;
    if (!(magnitude > 0.0) || !(len > 0.0))
        glyph.sphere.w = 0.0; // no direction: not drawn
    vec3 axis = vector / magnitude;
    glyph.sphere.xyz = center - axis * (len * osgGlyphs_vectorParams.z);
    glyph.axis = vec4(axis, len);
#endif
    gl_Position = vec4(center, 1.0);
}
