#version 330 compatibility
// osgGlyphsPaper, texture-blend technique: the circle mask and a lit grey sphere, modulated by
// the glyph's colour (paper section 3.1).

flat in vec4 fragColor;

uniform sampler2D osgGlyphs_maskTexture;     // the circle
uniform sampler2D osgGlyphs_lightingTexture; // a lit grey sphere

out vec4 color;

void main()
{
    if (texture(osgGlyphs_maskTexture, gl_PointCoord).a < 0.5)
        discard;
    color = vec4(fragColor.rgb * texture(osgGlyphs_lightingTexture, gl_PointCoord).rgb, fragColor.a);
}
