#version 330 compatibility
// osgGlyphsPaper, points-floor technique: a transformed point in the cloud's one colour, nothing
// decoded: the floor of vertex processing.

#include "osgGlyphs/decode.glsl"

flat out vec4 fragColor;

void main()
{
    fragColor = osgGlyphs_baseColor;
    gl_Position = gl_ModelViewProjectionMatrix * glyphPosition();
    gl_ClipVertex = gl_ModelViewMatrix * glyphPosition(); // OSG's clip planes keep or drop a point
    gl_PointSize = 1.0;
}
