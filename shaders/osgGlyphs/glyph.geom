#version 330 compatibility
// osgGlyphs: expands each glyph into a screen-space rectangle that bounds it (exactly, for
// spheres). The fragment shader then ray-casts the glyph's surface inside that rectangle.

layout(points) in;
layout(triangle_strip, max_vertices = 4) out;

#include "shapes.glsl"
#include "projection.glsl"
#include "sphere.glsl"
#include "vector.glsl"

in GlyphVertex
{
    vec4 sphere;
    vec4 axis;
    vec4 color;
}
glyph[];

flat out vec4 fragSphere;
flat out vec4 fragAxis;
flat out vec4 fragColor;
noperspective out vec3 fragRayNear; // eye-space point on the near plane under this fragment
noperspective out vec3 fragRayFar;  // and on the far plane
#ifdef OSGGLYPHS_PAPER
out vec2 fragBillboard;           // the paper's billboard coordinates, in base radii
flat out vec4 fragBillboardFrame; // its eye-space x (across) and y (along the axis) directions
#endif

void emitCorner(vec2 ndc, float ndcZ)
{
    fragSphere = glyph[0].sphere;
    fragAxis = glyph[0].axis;
    fragColor = glyph[0].color;
    fragRayNear = unprojectNdc(vec3(ndc, -1.0));
    fragRayFar = unprojectNdc(vec3(ndc, 1.0));
    gl_Position = vec4(ndc, ndcZ, 1.0);
    EmitVertex();
}

void main()
{
    vec4 sphere = glyph[0].sphere;
    if (!(sphere.w > 0.0) || any(isnan(sphere)) || any(isinf(sphere)) || any(isnan(glyph[0].axis)))
        return;
#if defined(OSGGLYPHS_PAPER)
    // A camera-facing square around the glyph's middle, in the paper's 2D frame.
    vec3 axis = glyph[0].axis.xyz;
    float len = glyph[0].axis.w;
    vec3 middle = sphere.xyz + axis * (0.5 * len);
    float halfSize = sqrt(0.25 * len * len + sphere.w * sphere.w);
    vec2 up = dot(axis.xy, axis.xy) > 1e-12 ? normalize(axis.xy) : vec2(0.0, 1.0);
    vec2 right = vec2(up.y, -up.x);
    vec2 baseOffset = -axis.xy * (0.5 * len); // the base centre, seen orthographically
    for (int corner = 0; corner < 4; ++corner)
    {
        vec2 offset = vec2((corner & 1) == 0 ? -halfSize : halfSize, (corner & 2) == 0 ? -halfSize : halfSize);
        fragSphere = sphere;
        fragAxis = vec4(abs(axis.z), length(axis.xy) * len / sphere.w, 0.0, 0.0); // the paper's d and h
        fragColor = glyph[0].color;
        fragBillboard = vec2(dot(offset - baseOffset, right), dot(offset - baseOffset, up)) / sphere.w;
        fragBillboardFrame = vec4(right, up);
        gl_Position = gl_ProjectionMatrix * vec4(middle + vec3(offset, 0.0), 1.0);
        EmitVertex();
    }
#elif defined(OSGGLYPHS_VECTOR_SHAPE)
    vec2 corners[4];
    float nearestNdcZ;
    if (!vectorScreenBound(sphere.xyz, glyph[0].axis.xyz, glyph[0].axis.w, sphere.w, corners, nearestNdcZ))
        return;
    for (int corner = 0; corner < 4; ++corner)
        emitCorner(corners[corner], nearestNdcZ);
#else
    vec4 box;
    float nearestNdcZ;
    if (!sphereScreenBound(sphere.xyz, sphere.w, box, nearestNdcZ))
        return;
    for (int corner = 0; corner < 4; ++corner)
        emitCorner(vec2((corner & 1) == 0 ? box.x : box.z, (corner & 2) == 0 ? box.y : box.w), nearestNdcZ);
#endif
    EndPrimitive();
}
