#version 330 compatibility
// osgGlyphs, point-sprite technique: a square point sprite over the exact screen bound of each
// glyph, which impostor.frag ray-casts.

#include "decode.glsl"
#include "projection.glsl"
#include "sphere.glsl"
#include "vector.glsl"
#include "ellipsoid.glsl"
#include "superquadric.glsl"
#include "bound.glsl"

#define OSGGLYPHS_VARYINGS_OUT 1
#include "varyings.glsl"

void main()
{
    Glyph glyph = decodeGlyph();
    writeVaryings(glyph);
    keepVertexFromClipPlanes();
    vec2 corners[4];
    float nearestNdcZ;
    if (!isDrawn(glyph) || !glyphBound(glyph, corners, nearestNdcZ))
    {
        hideVertex();
        return;
    }
    vec2 lo = min(min(corners[0], corners[1]), min(corners[2], corners[3]));
    vec2 hi = max(max(corners[0], corners[1]), max(corners[2], corners[3]));
    vec2 pixels = (hi - lo) * 0.5 * osgGlyphs_viewport.zw;
    gl_Position = vec4(0.5 * (lo + hi), nearestNdcZ, 1.0);
    gl_PointSize = ceil(max(pixels.x, pixels.y)) + 1.0;
}
