#version 330 compatibility
// osgGlyphs, geometry-shader technique: expands each glyph into a screen-space rectangle that
// bounds it (exactly, for spheres), inside which impostor.frag ray-casts the glyph's surface.

layout(points) in;
layout(triangle_strip, max_vertices = 4) out;

#include "glyph.glsl"
#include "projection.glsl"
#include "sphere.glsl"
#include "vector.glsl"
#include "ellipsoid.glsl"
#include "superquadric.glsl"

#include "bound.glsl"

const float SMALL_GLYPH_PIXELS = 3.0;

in GlyphVertex
{
    vec4 sphere;
    vec4 axis;
    vec4 color;
    vec4 occlusion;
#ifdef OSGGLYPHS_AXES_SHAPE
    mat3 semiAxes;
#endif
#ifdef OSGGLYPHS_SHAPE_SUPERQUADRIC
    vec2 exponents;
#endif
}
glyphIn[];

#define OSGGLYPHS_VARYINGS_OUT 1
#include "varyings.glsl"

void main()
{
    Glyph glyph;
    glyph.sphere = glyphIn[0].sphere;
    glyph.axis = glyphIn[0].axis;
    glyph.color = glyphIn[0].color;
    glyph.occlusion = glyphIn[0].occlusion;
#ifdef OSGGLYPHS_AXES_SHAPE
    glyph.semiAxes = glyphIn[0].semiAxes;
#endif
#ifdef OSGGLYPHS_SHAPE_SUPERQUADRIC
    glyph.exponents = glyphIn[0].exponents;
#endif
    if (!isDrawn(glyph))
        return;
    vec2 corners[4];
    float nearestNdcZ;
    if (!glyphBound(glyph, corners, nearestNdcZ))
        return;
    // A glyph of a few pixels gets one triangle of twice the rectangle's area, right-angled at its
    // first corner: rasterising primitives, not shading fragments, is what small glyphs cost.
    int numCorners = 4;
    vec2 toPixels = 0.5 * osgGlyphs_viewport.zw;
    float longestSide = max(length((corners[1] - corners[0]) * toPixels), length((corners[2] - corners[0]) * toPixels));
    if (longestSide < SMALL_GLYPH_PIXELS)
    {
        corners[1] = 2.0 * corners[1] - corners[0];
        corners[2] = 2.0 * corners[2] - corners[0];
        numCorners = 3;
    }
    GlyphVaryings varyings = glyphVaryings(glyph);
    for (int corner = 0; corner < numCorners; ++corner)
    {
        writeVaryings(varyings);
        gl_Position = vec4(corners[corner], nearestNdcZ, 1.0);
        keepVertexFromClipPlanes();
        EmitVertex();
    }
    EndPrimitive();
}
