#version 330 compatibility
// osgGlyphsPaper, polygons technique: the tessellated glyph, lit per fragment.

#include "osgGlyphs/glyph.glsl"
#include "osgGlyphs/projection.glsl"
#include "osgGlyphs/lighting.glsl"

flat in vec4 fragColor;
in vec3 fragNormal;
flat in vec3 fragPosition;

out vec4 color;

void main()
{
    vec3 toEye = isOrthographic() ? vec3(0.0, 0.0, 1.0) : normalize(-fragPosition);
    color = vec4(shade(fragColor.rgb, fragPosition, normalize(fragNormal), toEye), fragColor.a);
}
