#version 330 compatibility
// osgGlyphsPaper, texture-blend technique: a sprite per sphere, in the glyph's colour.

#include "osgGlyphs/decode.glsl"
#include "sprite.glsl"

flat out vec4 fragColor;

void main()
{
    Glyph glyph = decodeGlyph();
    fragColor = glyph.color;
    placeSprite(glyph);
}
