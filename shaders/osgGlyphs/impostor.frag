#version 330 compatibility
#extension GL_ARB_conservative_depth : enable
#extension GL_ARB_shader_storage_buffer_object : enable
#extension GL_ARB_shading_language_420pack : enable
#extension GL_ARB_shading_language_packing : enable
#extension GL_ARB_shader_image_load_store : enable
// osgGlyphs, the impostor techniques' pixels: each fragment ray-casts the glyph's exact surface,
// lights it and writes its true depth, so that glyphs intersect each other and ordinary
// geometry as if they were tessellated exactly.

#include "glyph.glsl"
#include "projection.glsl"
#include "sphere.glsl"
#include "vector.glsl"
#include "ellipsoid.glsl"
#include "superquadric.glsl"
#include "lighting.glsl"
#include "varyings.glsl"
#include "clip.glsl"
#include "peel.glsl"
#include "k-buffer-insert.glsl"

out vec4 color;

// GlyphCloud::setOpacity, which scales every glyph's alpha.
uniform float osgGlyphs_opacity;

// The selection's pass (GlyphCloud::setSelection): a tint and its strength; 0 otherwise.
uniform vec4 osgGlyphs_highlight;

#ifdef GL_ARB_conservative_depth
// The surface lies at or behind the primitive, which every technique places at the glyph's
// nearest depth: a driver may reject fragments behind the depth buffer before ray-casting them.
layout(depth_greater) out float gl_FragDepth;
#endif

/** Moves t and normal to the first drawn point of the span where that is nearer than t. The span
 * is cut at the near plane (t = 0: the cut faces the viewer) and by the clip planes that are on:
 * a cut shows as a cap facing the viewer where OSGGLYPHS_CLIP_CAPS is defined, else the solid's
 * far side shows from within. */
void keepNearerDrawnPoint(vec3 origin, vec3 direction, Span span, inout float t, inout vec3 normal)
{
    float first = span.tEnter;
    vec3 firstNormal = span.nEnter;
    if (first < 0.0)
    {
        first = 0.0;
        firstNormal = -direction;
    }
    float last = span.tLeave;
    bool entryCut = false, exitCut = false;
#ifdef OSGGLYPHS_CLIP_PLANES
    // Up to the highest plane that is on: a software rasteriser runs every branch it meets.
    for (int i = 0; i < MAX_CLIP_PLANES && (osgGlyphs_clipPlanes >> i) != 0; ++i)
    {
        if (!isClipPlaneOn(i))
            continue;
        vec4 plane = gl_ClipPlane[i];
        float atOrigin = dot(plane, vec4(origin, 1.0));
        float rate = dot(plane.xyz, direction);
        if (rate == 0.0)
        {
            if (atOrigin < 0.0)
                return;
            continue;
        }
        float crossing = -atOrigin / rate;
        if (rate > 0.0 && crossing > first)
        {
            first = crossing;
            firstNormal = -normalize(plane.xyz);
            entryCut = true;
        }
        else if (rate < 0.0 && crossing < last)
        {
            last = crossing;
            exitCut = true;
        }
    }
#endif
    if (first > last)
        return;
#ifndef OSGGLYPHS_CLIP_CAPS
    if (entryCut)
    {
        if (exitCut)
            return;
        first = span.tLeave;
        firstNormal = -span.nLeave;
    }
#endif
    if (first < t)
    {
        t = first;
        normal = firstNormal;
    }
}

/** The nearest point drawn along the ray (eye space, unit direction, from the near plane) and its
 * unit normal, or false. The glyph's convex parts are spans of the ray, held in variables of
 * their own: arrays indexed in loops cost a software rasteriser memory traffic per fragment. */
bool castRay(vec3 origin, vec3 direction, out float t, out vec3 normal)
{
    t = INFINITE_DISTANCE;
    normal = -direction;
#ifdef OSGGLYPHS_VECTOR_SHAPE
    vec3 axis = fragAxis.xyz;
    vec3 u, v;
    axisFrame(axis, u, v);
    vec3 relative = origin - fragSphere.xyz;
    // Solve from a point just before the glyph, where the quadratics are well conditioned.
    float reach = fragAxis.w + 2.0 * fragSphere.w * max(osgGlyphs_arrowParams.y, 1.0);
    float start = max(dot(-relative, direction) - reach, 0.0);
    relative += direction * start;
    vec3 o = vec3(dot(relative, u), dot(relative, v), dot(relative, axis));
    vec3 d = vec3(dot(direction, u), dot(direction, v), dot(direction, axis));
    Span first, second;
    int count = shapeSpans(o, d, fragSphere.w, fragAxis.w, first, second);
    mat3 toEye = mat3(u, v, axis);
    if (count > 0)
        keepNearerDrawnPoint(origin, direction,
                             Span(first.tEnter + start, first.tLeave + start, toEye * first.nEnter,
                                  toEye * first.nLeave),
                             t, normal);
    if (count > 1)
        keepNearerDrawnPoint(origin, direction,
                             Span(second.tEnter + start, second.tLeave + start, toEye * second.nEnter,
                                  toEye * second.nLeave),
                             t, normal);
#elif defined(OSGGLYPHS_SHAPE_SUPERQUADRIC)
    Span span;
    if (superquadricSpan(origin, direction, fragSphere.xyz, fragInverseSemiAxes, fragSuperquadricPowers, span))
        keepNearerDrawnPoint(origin, direction, span, t, normal);
#elif defined(OSGGLYPHS_AXES_SHAPE)
    Span span;
    if (ellipsoidSpan(origin, direction, fragSphere.xyz, fragQuadricDiagonal, fragQuadricOffDiagonal, span))
        keepNearerDrawnPoint(origin, direction, span, t, normal);
#else
    float tEnter, tLeave;
    if (intersectSphere(origin, direction, fragSphere, tEnter, tLeave))
    {
        vec3 centre = fragSphere.xyz;
        keepNearerDrawnPoint(origin, direction,
                             Span(tEnter, tLeave, (origin + direction * tEnter - centre) / fragSphere.w,
                                  (origin + direction * tLeave - centre) / fragSphere.w),
                             t, normal);
    }
#endif
    return t < INFINITE_DISTANCE;
}

/** The eye-space ray through this fragment's centre, from the near plane. */
void rayUnderFragment(out vec3 origin, out vec3 direction)
{
    vec2 ndc = (gl_FragCoord.xy - osgGlyphs_viewport.xy) / osgGlyphs_viewport.zw * 2.0 - 1.0;
    // unprojectNdc at NDC z = -1 and z = 1, sharing the product of x and y.
    vec4 middle = gl_ProjectionMatrixInverse * vec4(ndc, 0.0, 1.0);
    vec4 nearPoint = middle - gl_ProjectionMatrixInverse[2];
    vec4 farPoint = middle + gl_ProjectionMatrixInverse[2];
    origin = nearPoint.xyz / nearPoint.w;
    direction = normalize(farPoint.xyz / farPoint.w - origin);
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
#ifdef OSGGLYPHS_DEPTH_PEEL
    if (isPeeledAway(ivec2(gl_FragCoord.xy), gl_FragDepth))
        discard;
#endif
#ifdef OSGGLYPHS_K_BUFFER
    if (isBehindKBuffer(ivec2(gl_FragCoord.xy), gl_FragDepth))
        discard;
#endif
    float ambientLight = 1.0;
#ifdef OSGGLYPHS_AMBIENT_OCCLUSION
    ambientLight = clamp(fragOcclusion.w + dot(fragOcclusion.xyz, normal), 0.0, 1.0);
#endif
    color = vec4(shade(fragColor.rgb, position, normal, -direction, ambientLight),
                 fragColor.a * osgGlyphs_opacity);
    color.rgb = mix(color.rgb, osgGlyphs_highlight.rgb, osgGlyphs_highlight.a);
#ifdef OSGGLYPHS_K_BUFFER
    gl_FragDepth = insertIntoKBuffer(ivec2(gl_FragCoord.xy), gl_FragDepth, color);
    color = vec4(0.0);
#endif
}
