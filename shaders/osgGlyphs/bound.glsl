// osgGlyphs: the screen-space bound of a glyph, shared by every technique that ray-casts.

// True when the framebuffer has one sample per pixel, at its centre (no multisampling).
uniform bool osgGlyphs_singleSample;

/** Whether a rectangle with these NDC corners can cover a sample. Single-sampled, it must hold a
  * pixel centre: most glyphs of a million-point cloud are smaller than a pixel and fall between
  * centres, and skipping them saves the rasteriser their primitives. */
bool coversASample(vec2 corners[4])
{
    if (!osgGlyphs_singleSample)
        return true;
    vec2 lo = min(min(corners[0], corners[1]), min(corners[2], corners[3]));
    vec2 hi = max(max(corners[0], corners[1]), max(corners[2], corners[3]));
    const float margin = 1e-3; // pixels, for rounding
    vec2 firstCentre = ceil((lo * 0.5 + 0.5) * osgGlyphs_viewport.zw - 0.5 - margin);
    vec2 lastCentre = floor((hi * 0.5 + 0.5) * osgGlyphs_viewport.zw - 0.5 + margin);
    return all(lessThanEqual(firstCentre, lastCentre));
}

/** Four NDC corners (in triangle-strip order) of a rectangle that contains the glyph, and the
  * NDC depth of its nearest point; false when the glyph is wholly behind the near plane or
  * covers no sample. */
bool glyphBound(Glyph glyph, out vec2 corners[4], out float nearestNdcZ)
{
#ifdef OSGGLYPHS_VECTOR_SHAPE
    if (!vectorScreenBound(glyph.sphere.xyz, glyph.axis.xyz, glyph.axis.w, glyph.sphere.w, corners, nearestNdcZ))
        return false;
#else
    vec4 box;
    if (!sphereScreenBound(glyph.sphere.xyz, glyph.sphere.w, box, nearestNdcZ))
        return false;
    corners = vec2[4](box.xy, box.zy, box.xw, box.zw);
#endif
    return coversASample(corners);
}
