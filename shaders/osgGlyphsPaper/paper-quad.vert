#version 330 compatibility
// osgGlyphsPaper, paper-quad technique: the billboard of Aguirre et al. (TPCG 2010), four
// vertices per glyph, each carrying the glyph's attributes and its corner (osgGlyphs_corner).

#include "osgGlyphs/decode.glsl"

flat out vec4 fragSphere;
flat out vec4 fragColor;
flat out vec4 fragAxis;  // cones: the paper's d and h
out vec3 fragLocal;      // billboard coordinates
flat out vec4 fragFrame; // cones: the billboard's eye-space x and y directions

void main()
{
    Glyph glyph = decodeGlyph();
    fragSphere = glyph.sphere;
    fragColor = glyph.color;
    fragAxis = glyph.axis;
    if (!isDrawn(glyph))
    {
        hideVertex();
        return;
    }
    vec3 middle = glyph.sphere.xyz;
    float halfSize = glyph.sphere.w;
#ifdef OSGGLYPHS_VECTOR_SHAPE
    vec3 axis = glyph.axis.xyz;
    float len = glyph.axis.w;
    middle += axis * (0.5 * len);
    halfSize = sqrt(0.25 * len * len + glyph.sphere.w * glyph.sphere.w);
    vec2 up = dot(axis.xy, axis.xy) > 1e-12 ? normalize(axis.xy) : vec2(0.0, 1.0);
    vec2 right = vec2(up.y, -up.x);
    vec2 offset = osgGlyphs_corner * halfSize - (-axis.xy * (0.5 * len)); // from the base centre
    fragLocal = vec3(dot(offset, right), dot(offset, up), 0.0) / glyph.sphere.w;
    fragFrame = vec4(right, up);
    fragAxis = vec4(abs(axis.z), length(axis.xy) * len / glyph.sphere.w, 0.0, 0.0);
#else
    fragLocal = vec3(osgGlyphs_corner, 0.0);
    fragFrame = vec4(0.0);
#endif
    vec4 eye = vec4(middle + vec3(osgGlyphs_corner * halfSize, 0.0), 1.0);
    gl_Position = gl_ProjectionMatrix * eye;
    gl_ClipVertex = eye; // OSG's clip planes cut the billboard where it is, in eye space
}
