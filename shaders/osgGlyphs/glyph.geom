#version 330 compatibility
// osgGlyphs: expands each glyph into the screen-space rectangle that bounds it exactly.
// The fragment shader then ray-casts the glyph's surface inside that rectangle.

layout(points) in;
layout(triangle_strip, max_vertices = 4) out;

#include "projection.glsl"
#include "sphere.glsl"

in GlyphVertex
{
    vec4 sphere;
    vec4 color;
}
glyph[];

flat out vec4 fragSphere;
flat out vec4 fragColor;
noperspective out vec3 fragRayNear; // eye-space point on the near plane under this fragment
noperspective out vec3 fragRayFar;  // and on the far plane

void main()
{
    vec4 sphere = glyph[0].sphere;
    if (!(sphere.w > 0.0) || any(isnan(sphere)) || any(isinf(sphere)))
        return;
    vec4 box;
    float nearestNdcZ;
    if (!sphereScreenBound(sphere.xyz, sphere.w, box, nearestNdcZ))
        return;
    for (int corner = 0; corner < 4; ++corner)
    {
        vec2 ndc = vec2((corner & 1) == 0 ? box.x : box.z, (corner & 2) == 0 ? box.y : box.w);
        fragSphere = sphere;
        fragColor = glyph[0].color;
        fragRayNear = unprojectNdc(vec3(ndc, -1.0));
        fragRayFar = unprojectNdc(vec3(ndc, 1.0));
        gl_Position = vec4(ndc, nearestNdcZ, 1.0);
        EmitVertex();
    }
    EndPrimitive();
}
