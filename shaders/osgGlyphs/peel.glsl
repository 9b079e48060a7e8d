// osgGlyphs: depth peeling (osgGlyphs::DepthPeeling). Each pass of the peeling draws the layer
// behind the previous one: a fragment at or in front of the previous layer's depth is peeled away.

#ifdef OSGGLYPHS_DEPTH_PEEL
// The window depth of the previous layer (0 before the first layer), one texel per pixel.
uniform sampler2D osgGlyphs_peelDepth;

/** Whether a fragment of this window depth, at this pixel (window coordinates), belongs to a
 * layer peeled already. */
bool isPeeledAway(ivec2 pixel, float depth)
{
    return depth <= texelFetch(osgGlyphs_peelDepth, pixel, 0).r;
}
#endif
