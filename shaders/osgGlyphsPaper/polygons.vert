#version 330 compatibility
// osgGlyphsPaper, polygons technique: a unit mesh (gl_Vertex, gl_Normal) per instance: a sphere
// of radius 1, or a vector shape of radius 1 along z from 0 to 1.

#include "osgGlyphs/decode.glsl"
#include "osgGlyphs/projection.glsl"
#include "osgGlyphs/vector.glsl"

flat out vec4 fragColor;
out vec3 fragNormal;        // eye space
flat out vec3 fragPosition; // eye space, of the provoking vertex

void main()
{
    Glyph glyph = decodeGlyph();
    fragColor = glyph.color;
    if (!isDrawn(glyph))
    {
        hideVertex();
        return;
    }
#ifdef OSGGLYPHS_VECTOR_SHAPE
    vec3 u, v;
    axisFrame(glyph.axis.xyz, u, v);
    vec3 extent = vec3(glyph.sphere.w, glyph.sphere.w, glyph.axis.w);
    vec3 local = gl_Vertex.xyz * extent;
    vec3 position = glyph.sphere.xyz + u * local.x + v * local.y + glyph.axis.xyz * local.z;
    vec3 n = gl_Normal / extent;
    fragNormal = normalize(u * n.x + v * n.y + glyph.axis.xyz * n.z);
#else
    vec3 position = glyph.sphere.xyz + gl_Vertex.xyz * glyph.sphere.w;
    fragNormal = gl_Normal;
#endif
    fragPosition = position;
    gl_Position = gl_ProjectionMatrix * vec4(position, 1.0);
    gl_ClipVertex = vec4(position, 1.0); // OSG's clip planes cut the mesh as any mesh
}
