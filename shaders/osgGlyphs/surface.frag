#version 330 compatibility
#extension GL_ARB_shader_storage_buffer_object : enable
#extension GL_ARB_shading_language_420pack : enable
#extension GL_ARB_shading_language_packing : enable
#extension GL_ARB_shader_image_load_store : enable
// osgGlyphs, ordinary geometry shaded as glyphs are (osgGlyphs::setSurfaceShading): the glyphs'
// lighting, and their shadow look-up where setGlyphShadows turns it on.

#include "defines.glsl"
#include "projection.glsl"
#include "lighting.glsl"
#include "peel.glsl"
#include "k-buffer-insert.glsl"

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
#ifdef OSGGLYPHS_K_BUFFER
    if (isBehindKBuffer(ivec2(gl_FragCoord.xy), gl_FragCoord.z))
        discard;
#endif
    vec3 normal = normalize(gl_FrontFacing ? surfaceNormal : -surfaceNormal);
    vec3 toEye = isOrthographic() ? vec3(0.0, 0.0, 1.0) : normalize(-surfacePosition);
    color = vec4(shade(surfaceColor.rgb, surfacePosition, normal, toEye), surfaceColor.a);
#ifdef OSGGLYPHS_K_BUFFER
    gl_FragDepth = insertIntoKBuffer(ivec2(gl_FragCoord.xy), gl_FragCoord.z, color);
    color = vec4(0.0);
#endif
}
