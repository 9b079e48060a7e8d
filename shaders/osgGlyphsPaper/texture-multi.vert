#version 330 compatibility
// osgGlyphsPaper, texture-multi technique: a sprite per sphere, and the layer of the pre-lit
// sprites in its colour.

#include "osgGlyphs/decode.glsl"
#include "sprite.glsl"

uniform sampler2DArray osgGlyphs_litSprites;

flat out float fragLayer;

/** The layer of the sprites in the glyph's colour: the nearest of the colour map's evenly
  * spaced levels, the nearest colour of the RGB cube (red slowest), or the one colour. */
float litSpriteLayer()
{
    float layers = float(textureSize(osgGlyphs_litSprites, 0).z);
#if defined(OSGGLYPHS_COLOR_SCALAR)
    return floor(colormapCoordinate() * (layers - 1.0) + 0.5);
#elif defined(OSGGLYPHS_COLOR_RGBA)
    float levels = floor(pow(layers, 1.0 / 3.0) + 0.5);
    vec3 level = floor(clamp(osgGlyphs_color.rgb, 0.0, 1.0) * (levels - 1.0) + 0.5);
    return dot(level, vec3(levels * levels, levels, 1.0));
#else
    return 0.0;
#endif
}

void main()
{
    Glyph glyph = decodeGlyph();
    fragLayer = litSpriteLayer();
    placeSprite(glyph);
}
