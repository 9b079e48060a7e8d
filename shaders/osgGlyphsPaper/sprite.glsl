// osgGlyphsPaper: the texture techniques' sprite, a GL point the size of the sphere's projection.

#include "osgGlyphs/projection.glsl"

/** Places this vertex's point sprite over the sphere, or hides it. */
void placeSprite(Glyph glyph)
{
    if (!isDrawn(glyph))
    {
        hideVertex();
        return;
    }
    gl_Position = gl_ProjectionMatrix * vec4(glyph.sphere.xyz, 1.0);
    gl_ClipVertex = vec4(glyph.sphere.xyz, 1.0); // OSG's clip planes keep or drop a whole sprite
    float pixelsPerUnit = isOrthographic() ? gl_ProjectionMatrix[1][1] : gl_ProjectionMatrix[1][1] / -glyph.sphere.z;
    gl_PointSize = max(2.0 * glyph.sphere.w * pixelsPerUnit * 0.5 * osgGlyphs_viewport.w, 1.0);
}
