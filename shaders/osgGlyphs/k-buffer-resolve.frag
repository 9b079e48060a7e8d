#version 330 compatibility
#extension GL_ARB_shader_storage_buffer_object : require
#extension GL_ARB_shader_image_load_store : require
#extension GL_ARB_shading_language_420pack : require
#extension GL_ARB_shading_language_packing : require
// osgGlyphs, the resolve of osgGlyphs::DepthPeeling's k-buffer: the pixel's list blended front to
// back into one premultiplied colour, which the blending puts over the target, and the nearest
// layer's depth, written into the target's depth buffer. The list is emptied for the next frame.

#include "k-buffer.glsl"

out vec4 color;

void main()
{
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec3 sum = vec3(0.0);
    float transmittance = 1.0;
    float nearest = 1.0;
    for (int layer = 0; layer < osgGlyphs_kBufferSize.y; ++layer)
    {
        uint depthSlot = kBufferDepthSlot(pixel, layer);
        uint key = osgGlyphs_kBuffer[depthSlot];
        if (key == EMPTY_LAYER)
            break;
        vec4 layerColor = unpackUnorm4x8(osgGlyphs_kBuffer[kBufferColorSlot(pixel, layer)]);
        sum += transmittance * layerColor.a * layerColor.rgb;
        transmittance *= 1.0 - layerColor.a;
        if (layer == 0)
            nearest = uintBitsToFloat(key);
        osgGlyphs_kBuffer[depthSlot] = EMPTY_LAYER;
    }
    if (nearest == 1.0)
        discard;
    gl_FragDepth = nearest;
    color = vec4(sum, 1.0 - transmittance);
}
