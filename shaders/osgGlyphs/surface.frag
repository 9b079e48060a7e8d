#version 330 compatibility
// osgGlyphs, ordinary geometry shaded as glyphs are (osgGlyphs::setSurfaceShading): the glyphs'
// lighting, and their shadow look-up where setGlyphShadows turns it on.

#include "defines.glsl"
#include "projection.glsl"
#include "lighting.glsl"
#include "peel.glsl"

in vec3 surfacePosition;
in vec3 surfaceNormal;
in vec4 surfaceColor;

out vec4 color;

void main()
{
#ifdef OSGGLYPHS_DEPTH_PEEL
    if (isPeeledAway(ivec2(gl_FragCoord.xy), gl_FragCoord.z))
        discard;
#endif
    vec3 normal = normalize(gl_FrontFacing ? surfaceNormal : -surfaceNormal);
    vec3 toEye = isOrthographic() ? vec3(0.0, 0.0, 1.0) : normalize(-surfacePosition);
    color = vec4(shade(surfaceColor.rgb, surfacePosition, normal, toEye), surfaceColor.a);
}
