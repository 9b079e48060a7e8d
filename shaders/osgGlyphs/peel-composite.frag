#version 330 compatibility
// osgGlyphs, the composition of depth peeling's layers (osgGlyphs::DepthPeeling): the layer's
// pixel under this one, as a premultiplied colour that the blending puts under or over what the
// target holds. Under OSGGLYPHS_PEEL_NEAREST_DEPTH, the nearest layer's depth instead, written
// into the target's depth buffer.

#pragma import_defines(OSGGLYPHS_PEEL_NEAREST_DEPTH)

// A layer (or, for the depth, the nearest layer's depth), one texel per pixel.
uniform sampler2D osgGlyphs_layer;
// 1 where the layer's colour is still to be multiplied by its alpha, 0 where it is already.
uniform float osgGlyphs_premultiply;

out vec4 color;

void main()
{
#ifdef OSGGLYPHS_PEEL_NEAREST_DEPTH
    gl_FragDepth = texelFetch(osgGlyphs_layer, ivec2(gl_FragCoord.xy), 0).r;
    color = vec4(0.0);
#else
    // Clamped as a fixed-point target clamps what blending takes: a highlight's colour may exceed 1.
    vec4 layer = clamp(texelFetch(osgGlyphs_layer, ivec2(gl_FragCoord.xy), 0), 0.0, 1.0);
    color = vec4(layer.rgb * mix(1.0, layer.a, osgGlyphs_premultiply), layer.a);
#endif
}
