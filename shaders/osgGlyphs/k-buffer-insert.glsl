// osgGlyphs: the fragments of osgGlyphs::DepthPeeling's k-buffer pass. The pass inserts every
// fragment in front of the opaque scene into its pixel's list (k-buffer.glsl) and draws nothing
// itself: its colour is transparent black, which the pass's blending leaves out. A shader that
// includes this enables the extensions k-buffer.glsl names, at its top.

#ifdef OSGGLYPHS_K_BUFFER
#include "k-buffer.glsl"

// The window depth of the opaque scene that the camera drew before, one texel per pixel.
uniform sampler2D osgGlyphs_peelDepth;

/** Whether a fragment of this window depth cannot enter its pixel's list: it is behind the opaque
 * scene, or behind every layer of a full list (read without the lock: the last layer only moves
 * nearer, so a stale value lets a fragment through that the insertion then drops). */
bool isBehindKBuffer(ivec2 pixel, float depth)
{
    return depth >= texelFetch(osgGlyphs_peelDepth, pixel, 0).r ||
           floatBitsToUint(depth) >= osgGlyphs_kBuffer[kBufferDepthSlot(pixel, osgGlyphs_kBufferSize.y - 1)];
}

/** Inserts a fragment into its pixel's list, in depth order; the farthest falls off a full list.
 * Fragments of one pixel may run at once: the list is changed under the pixel's lock. Returns the
 * depth of the farthest layer if the list is full, else 1: the pass writes it as the fragment's
 * depth, so that its depth buffer holds what hides a glyph from the list, which occlusion culling
 * reads back between its rounds. */
float insertIntoKBuffer(ivec2 pixel, float depth, vec4 color)
{
    uint last = EMPTY_LAYER;
    uint lock = kBufferLock(pixel);
    uint key = floatBitsToUint(depth);
    uint value = packUnorm4x8(clamp(color, 0.0, 1.0));
    bool inserted = false;
    while (!inserted)
    {
        if (atomicCompSwap(osgGlyphs_kBuffer[lock], 0u, 1u) == 0u)
        {
            for (int layer = 0; layer < osgGlyphs_kBufferSize.y && key != EMPTY_LAYER; ++layer)
            {
                uint depthSlot = kBufferDepthSlot(pixel, layer);
                uint layerKey = osgGlyphs_kBuffer[depthSlot];
                if (key < layerKey)
                {
                    uint colorSlot = kBufferColorSlot(pixel, layer);
                    uint layerValue = osgGlyphs_kBuffer[colorSlot];
                    osgGlyphs_kBuffer[depthSlot] = key;
                    osgGlyphs_kBuffer[colorSlot] = value;
                    key = layerKey;
                    value = layerValue;
                }
            }
            last = osgGlyphs_kBuffer[kBufferDepthSlot(pixel, osgGlyphs_kBufferSize.y - 1)];
            memoryBarrier();
            atomicExchange(osgGlyphs_kBuffer[lock], 0u);
            inserted = true;
        }
    }
    return last == EMPTY_LAYER ? 1.0 : uintBitsToFloat(last);
}
#endif
