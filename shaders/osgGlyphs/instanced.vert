#version 330 compatibility
// osgGlyphs, instanced technique: the four vertices of each instance span the exact screen
// bound of its glyph, which impostor.frag ray-casts.

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
    gl_Position = vec4(corners[gl_VertexID & 3], nearestNdcZ, 1.0);
}
