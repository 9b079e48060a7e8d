#version 330 compatibility
// osgGlyphs, the full-screen pass of osgGlyphs::ScreenEffects: one triangle that covers the
// viewport, given in normalised device coordinates.

void main()
{
    gl_Position = vec4(gl_Vertex.xy, 0.0, 1.0);
}
