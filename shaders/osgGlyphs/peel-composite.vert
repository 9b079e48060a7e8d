#version 330 compatibility
// osgGlyphs, the composition of depth peeling's layers (osgGlyphs::DepthPeeling): a quad given in
// normalised device coordinates that covers the viewport.

void main()
{
    gl_Position = gl_Vertex;
}
