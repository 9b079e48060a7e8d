#version 330 compatibility
// osgGlyphsPaper, texture-multi technique: one texel of the pre-lit sprite in the glyph's colour.

flat in float fragLayer;

uniform sampler2DArray osgGlyphs_litSprites; // a lit sphere per colour; alpha: the circle

out vec4 color;

void main()
{
    vec4 sprite = texture(osgGlyphs_litSprites, vec3(gl_PointCoord, fragLayer));
    if (sprite.a < 0.5)
        discard;
    color = vec4(sprite.rgb, 1.0);
}
