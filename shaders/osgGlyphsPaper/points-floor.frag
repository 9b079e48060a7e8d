#version 330 compatibility
// osgGlyphsPaper, points-floor technique: the point's one colour.

flat in vec4 fragColor;

out vec4 color;

void main()
{
    color = fragColor;
}
