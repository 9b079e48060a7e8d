#version 330 compatibility
// osgGlyphs: expands each glyph into a screen-space rectangle that bounds it (exactly, for
// spheres). The fragment shader then ray-casts the glyph's surface inside that rectangle.

layout(points) in;
layout(triangle_strip, max_vertices = 4) out;

#include "shapes.glsl"
#include "projection.glsl"
#include "sphere.glsl"
#include "vector.glsl"

#include "bound.glsl"

in GlyphVertex
{
    vec4 sphere;
    vec4 axis;
    vec4 color;
}
glyphIn[];

#define OSGGLYPHS_VARYING out
#include "varyings.glsl"

void main()
{
    Glyph glyph = Glyph(glyphIn[0].sphere, glyphIn[0].axis, glyphIn[0].color);
    if (!isDrawn(glyph))
        return;
    vec2 corners[4];
    float nearestNdcZ;
    if (!glyphBound(glyph, corners, nearestNdcZ))
        return;
    for (int corner = 0; corner < 4; ++corner)
    {
        fragSphere = glyph.sphere;
        fragAxis = glyph.axis;
        fragColor = glyph.color;
        fragRayNear = unprojectNdc(vec3(corners[corner], -1.0));
        fragRayFar = unprojectNdc(vec3(corners[corner], 1.0));
        gl_Position = vec4(corners[corner], nearestNdcZ, 1.0);
        EmitVertex();
    }
    EndPrimitive();
}
