#version 330 compatibility
// osgGlyphs: decodes a glyph's packed attributes into eye space. With a geometry shader (the
// default technique) it hands the glyph on; otherwise it places this vertex of the glyph's
// instanced quad, point sprite, billboard or mesh itself.

#pragma import_defines(OSGGLYPHS_COLOR_SCALAR, OSGGLYPHS_COLOR_RGBA)

#include "shapes.glsl"
#include "attributes.glsl"
#include "projection.glsl"
#include "sphere.glsl"
#include "vector.glsl"
#include "bound.glsl"

#if defined(OSGGLYPHS_RAYCAST) && !defined(OSGGLYPHS_TECHNIQUE_INSTANCED) && !defined(OSGGLYPHS_TECHNIQUE_SPRITE)
out GlyphVertex
{
    vec4 sphere;
    vec4 axis;
    vec4 color;
}
glyphOut;
#else
#define OSGGLYPHS_VARYING out
#include "varyings.glsl"
#endif

#ifdef OSGGLYPHS_TECHNIQUE_PAPER
in vec2 osgGlyphs_corner; // this vertex's corner of the glyph's billboard, (+-1, +-1)
#endif

void hide()
{
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0); // outside the clip volume
    gl_PointSize = 0.0;
}

void main()
{
#ifdef OSGGLYPHS_TECHNIQUE_POINTS
    // The floor of vertex processing: a transformed point in the cloud's one colour, nothing decoded.
    fragColor = osgGlyphs_baseColor;
    gl_Position = gl_ModelViewProjectionMatrix * glyphPosition();
    gl_PointSize = 1.0;
    return;
#endif
    Glyph glyph = decodeGlyph();
#if defined(OSGGLYPHS_RAYCAST) && !defined(OSGGLYPHS_TECHNIQUE_INSTANCED) && !defined(OSGGLYPHS_TECHNIQUE_SPRITE)
    glyphOut.sphere = glyph.sphere;
    glyphOut.axis = glyph.axis;
    glyphOut.color = glyph.color;
    gl_Position = vec4(glyph.sphere.xyz, 1.0);
#else
    fragSphere = glyph.sphere;
    fragColor = glyph.color;
#ifdef OSGGLYPHS_AXIS_VARYING
    fragAxis = glyph.axis;
#endif
    if (!isDrawn(glyph))
    {
        hide();
        return;
    }
#if defined(OSGGLYPHS_TECHNIQUE_INSTANCED)
    // One instance per glyph: vertex 0..3 of a triangle strip over the exact bound.
    vec2 corners[4];
    float nearestNdcZ;
    if (!glyphBound(glyph, corners, nearestNdcZ))
    {
        hide();
        return;
    }
    gl_Position = vec4(corners[gl_VertexID & 3], nearestNdcZ, 1.0);
#elif defined(OSGGLYPHS_TECHNIQUE_SPRITE)
    // A square point sprite over the exact bound.
    vec2 corners[4];
    float nearestNdcZ;
    if (!glyphBound(glyph, corners, nearestNdcZ))
    {
        hide();
        return;
    }
    vec2 lo = min(min(corners[0], corners[1]), min(corners[2], corners[3]));
    vec2 hi = max(max(corners[0], corners[1]), max(corners[2], corners[3]));
    vec2 pixels = (hi - lo) * 0.5 * osgGlyphs_viewport.zw;
    float size = ceil(max(pixels.x, pixels.y)) + 1.0;
    gl_Position = vec4(0.5 * (lo + hi), nearestNdcZ, 1.0);
    gl_PointSize = size;
#elif defined(OSGGLYPHS_TECHNIQUE_PAPER)
    // The paper's billboard: four vertices per glyph, each carrying the glyph's attributes.
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
    fragAxis = vec4(abs(axis.z), length(axis.xy) * len / glyph.sphere.w, 0.0, 0.0); // the paper's d and h
#else
    fragLocal = vec3(osgGlyphs_corner, 0.0);
    fragFrame = vec4(0.0);
#endif
    gl_Position = gl_ProjectionMatrix * vec4(middle + vec3(osgGlyphs_corner * halfSize, 0.0), 1.0);
#elif defined(OSGGLYPHS_TECHNIQUE_POLYGONS)
    // A unit mesh (gl_Vertex, gl_Normal) per instance: a sphere of radius 1, or a vector shape
    // of radius 1 along z from 0 to 1.
#ifdef OSGGLYPHS_VECTOR_SHAPE
    vec3 u, v;
    axisFrame(glyph.axis.xyz, u, v);
    vec3 extent = vec3(glyph.sphere.w, glyph.sphere.w, glyph.axis.w);
    vec3 local = gl_Vertex.xyz * extent;
    vec3 position = glyph.sphere.xyz + u * local.x + v * local.y + glyph.axis.xyz * local.z;
    vec3 n = gl_Normal / extent;
    fragLocal = normalize(u * n.x + v * n.y + glyph.axis.xyz * n.z);
#else
    vec3 position = glyph.sphere.xyz + gl_Vertex.xyz * glyph.sphere.w;
    fragLocal = gl_Normal;
#endif
    fragFrame = vec4(position, 0.0);
    gl_Position = gl_ProjectionMatrix * vec4(position, 1.0);
#elif defined(OSGGLYPHS_TEXTURED_SPRITE)
    // A sprite the size of the glyph's projected bounding sphere, textured.
#ifdef OSGGLYPHS_TECHNIQUE_TEXTURE_MULTI
    fragLayer = litSpriteLayer();
#endif
    float reach = glyph.sphere.w;
#ifdef OSGGLYPHS_VECTOR_SHAPE
    reach = sqrt(0.25 * glyph.axis.w * glyph.axis.w + glyph.sphere.w * glyph.sphere.w);
    glyph.sphere.xyz += glyph.axis.xyz * (0.5 * glyph.axis.w);
#endif
    gl_Position = gl_ProjectionMatrix * vec4(glyph.sphere.xyz, 1.0);
    float pixelsPerUnit = isOrthographic() ? gl_ProjectionMatrix[1][1] : gl_ProjectionMatrix[1][1] / -glyph.sphere.z;
    gl_PointSize = max(2.0 * reach * pixelsPerUnit * 0.5 * osgGlyphs_viewport.w, 1.0);
#endif
#endif
}
