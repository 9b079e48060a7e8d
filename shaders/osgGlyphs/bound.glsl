// osgGlyphs: the screen-space bound of a glyph, shared by every technique that ray-casts.

/** Four NDC corners (in triangle-strip order) of a rectangle that contains the glyph, and the
  * NDC depth of its nearest point; false when the glyph is wholly behind the near plane. */
bool glyphBound(Glyph glyph, out vec2 corners[4], out float nearestNdcZ)
{
#ifdef OSGGLYPHS_VECTOR_SHAPE
    return vectorScreenBound(glyph.sphere.xyz, glyph.axis.xyz, glyph.axis.w, glyph.sphere.w, corners, nearestNdcZ);
#else
    vec4 box;
    if (!sphereScreenBound(glyph.sphere.xyz, glyph.sphere.w, box, nearestNdcZ))
        return false;
    corners = vec2[4](box.xy, box.zy, box.xw, box.zw);
    return true;
#endif
}
