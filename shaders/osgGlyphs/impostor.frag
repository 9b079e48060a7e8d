#version 330 compatibility
#extension GL_ARB_conservative_depth : enable
// osgGlyphs, the impostor techniques' pixels: each fragment ray-casts the glyph's exact surface,
// lights it and writes its true depth, so that glyphs intersect each other and ordinary
// geometry as if they were tessellated exactly.

#include "glyph.glsl"
#include "projection.glsl"
#include "sphere.glsl"
#include "vector.glsl"
#include "lighting.glsl"
#include "varyings.glsl"

out vec4 color;

#ifdef GL_ARB_conservative_depth
// The surface lies at or behind the primitive, which every technique places at the glyph's
// nearest depth: a driver may reject fragments behind the depth buffer before ray-casting them.
layout(depth_greater) out float gl_FragDepth;
#endif

/** The nearest surface point along the ray (t from the near plane) and its unit normal, or
  * false. A glyph entered before the near plane is cut there: the cut faces the viewer. */
bool castRay(vec3 origin, vec3 direction, out float t, out vec3 normal)
{
#ifdef OSGGLYPHS_VECTOR_SHAPE
    vec3 axis = fragAxis.xyz;
    vec3 u, v;
    axisFrame(axis, u, v);
    vec3 relative = origin - fragSphere.xyz;
    if (insideShape(vec3(dot(relative, u), dot(relative, v), dot(relative, axis)), fragSphere.w, fragAxis.w))
    {
        t = 0.0;
        normal = -direction;
        return true;
    }
    // Solve from a point just before the glyph, where the quadratics are well conditioned.
    float reach = fragAxis.w + 2.0 * fragSphere.w * max(osgGlyphs_arrowParams.y, 1.0);
    float start = max(dot(-relative, direction) - reach, 0.0);
    relative += direction * start;
    vec3 o = vec3(dot(relative, u), dot(relative, v), dot(relative, axis));
    vec3 d = vec3(dot(direction, u), dot(direction, v), dot(direction, axis));
    vec3 local;
    intersectShape(o, d, fragSphere.w, fragAxis.w, t, local);
    t += start;
    normal = local.x * u + local.y * v + local.z * axis;
    return t < INFINITE_DISTANCE;
#else
    float tEnter, tLeave;
    if (!intersectSphere(origin, direction, fragSphere, tEnter, tLeave) || tLeave < 0.0)
        return false;
    t = max(tEnter, 0.0);
    normal = tEnter >= 0.0 ? (origin + direction * t - fragSphere.xyz) / fragSphere.w : -direction;
    return true;
#endif
}

/** The eye-space ray through this fragment's centre, from the near plane. */
void rayUnderFragment(out vec3 origin, out vec3 direction)
{
    vec2 ndc = (gl_FragCoord.xy - osgGlyphs_viewport.xy) / osgGlyphs_viewport.zw * 2.0 - 1.0;
    origin = unprojectNdc(vec3(ndc, -1.0));
    direction = normalize(unprojectNdc(vec3(ndc, 1.0)) - origin);
}

void main()
{
    vec3 origin, direction;
    rayUnderFragment(origin, direction);
    float t;
    vec3 normal;
    if (!castRay(origin, direction, t, normal))
        discard;
    vec3 position = origin + direction * t;
    float ndcZ = ndcDepth(position);
    if (ndcZ > 1.0)
        discard; // beyond the far plane, where fixed-function geometry is clipped too
    gl_FragDepth = windowDepth(ndcZ);
    color = vec4(shade(fragColor.rgb, position, normal, -direction), fragColor.a);
}
