#version 330 compatibility
// osgGlyphs, full-screen passes (osgGlyphs::ScreenEffects, the composition of osgGlyphs::DepthPeeling's
// layers): primitives that cover the viewport, given in normalised device coordinates.

void main()
{
    gl_Position = vec4(gl_Vertex.xy, 0.0, 1.0);
}
