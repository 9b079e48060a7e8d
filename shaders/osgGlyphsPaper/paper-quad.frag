#version 330 compatibility
// osgGlyphsPaper, paper-quad technique: the sphere lit with the orthographic normal at the depth
// of the paper's equation 1; the cone from its base ellipse and tangents, at the billboard's depth.

#include "osgGlyphs/glyph.glsl"
#include "osgGlyphs/lighting.glsl"
#include "paper.glsl"

flat in vec4 fragSphere;
flat in vec4 fragColor;
flat in vec4 fragAxis;
in vec3 fragLocal;
flat in vec4 fragFrame;

out vec4 color;

void main()
{
    vec3 normal;
    float depth;
    if (!paperGlyph(fragLocal.xy, fragSphere, fragAxis, fragFrame, normal, depth))
        discard;
#ifndef OSGGLYPHS_VECTOR_SHAPE
    gl_FragDepth = depth;
#endif
    color = vec4(shade(fragColor.rgb, fragSphere.xyz, normal, vec3(0.0, 0.0, 1.0)), fragColor.a);
}
