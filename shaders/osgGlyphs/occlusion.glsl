// osgGlyphs: occlusion culling of single glyphs against a depth pyramid of what is drawn
// already. A cloud that culls draws its chunks in rounds, nearest first; before each round after
// the first, it reads back the depth and fills this pyramid, and glyphs whose nearest point lies
// behind the farthest depth over their screen rectangle make no primitive at all.

// The farthest window depth over blocks of pixels, one level of the pyramid in each rectangle of
// this one-level atlas: rectangle j (x, y, width, height) holds blocks of 2^(j+1) pixels, the last
// column and row also holding the pixels left over (see DepthPyramid).
uniform sampler2D osgGlyphs_depthPyramid;
uniform ivec4 osgGlyphs_pyramidLevels[16];
// x: 1 while a round is tested against the pyramid, else 0; y: the pyramid's levels; z: the
// depth margin that a glyph must lie beyond.
uniform vec3 osgGlyphs_occlusion;

float farthestDepth(ivec2 texel, int level)
{
    return texelFetch(osgGlyphs_depthPyramid, osgGlyphs_pyramidLevels[level].xy + texel, 0).r;
}

/** Whether the glyph, in a rectangle with these NDC corners and whose nearest point has this NDC
  * depth, lies wholly behind what is drawn. */
bool isOccluded(vec2 corners[4], float nearestNdcZ)
{
    if (osgGlyphs_occlusion.x == 0.0)
        return false;
    vec2 toPixels = 0.5 * osgGlyphs_viewport.zw;
    vec2 lo = (min(min(corners[0], corners[1]), min(corners[2], corners[3])) + 1.0) * toPixels;
    vec2 hi = (max(max(corners[0], corners[1]), max(corners[2], corners[3])) + 1.0) * toPixels;
    ivec2 first = ivec2(max(floor(lo), vec2(0.0)));
    ivec2 last = ivec2(min(floor(hi), osgGlyphs_viewport.zw - 1.0));
    if (any(greaterThan(first, last)))
        return false;
    // The finest level at which the rectangle spans at most 4x4 texels: random packings leave
    // narrow gaps that show far into a cloud, and a tight bound sees past fewer of them.
    int shift = 1;
    while (any(greaterThan((last >> shift) - (first >> shift), ivec2(3))))
        ++shift;
    int level = min(shift - 1, int(osgGlyphs_occlusion.y) - 1);
    ivec2 size = osgGlyphs_pyramidLevels[level].zw;
    ivec2 t0 = min(first >> (level + 1), size - 1);
    ivec2 t1 = min(last >> (level + 1), size - 1);
    float nearest = windowDepth(nearestNdcZ) - osgGlyphs_occlusion.z;
    for (int y = t0.y; y <= t1.y; ++y)
        for (int x = t0.x; x <= t1.x; ++x)
            if (farthestDepth(ivec2(x, y), level) >= nearest)
                return false;
    return true;
}
