#version 330 compatibility
// osgGlyphs, ordinary geometry shaded as glyphs are (osgGlyphs::setSurfaceShading): the eye-space
// point and normal of each vertex and its colour.

out vec3 surfacePosition;
out vec3 surfaceNormal;
out vec4 surfaceColor;

void main()
{
    vec4 eye = gl_ModelViewMatrix * gl_Vertex;
    surfacePosition = eye.xyz / eye.w;
    surfaceNormal = gl_NormalMatrix * gl_Normal;
    surfaceColor = gl_Color;
    gl_ClipVertex = eye;
    gl_Position = gl_ProjectionMatrix * eye;
}
