// osgGlyphs: eye space <-> normalised device coordinates <-> window depth, for any
// perspective or orthographic projection in gl_ProjectionMatrix.

bool isOrthographic()
{
    return gl_ProjectionMatrix[2][3] == 0.0;
}

vec3 unprojectNdc(vec3 ndc)
{
    vec4 eye = gl_ProjectionMatrixInverse * vec4(ndc, 1.0);
    return eye.xyz / eye.w;
}

float ndcDepth(vec3 eye)
{
    vec4 clip = gl_ProjectionMatrix * vec4(eye, 1.0);
    return clip.z / clip.w;
}

/** The window depth fixed-function geometry would get at this eye-space point. */
float windowDepth(float ndcZ)
{
    return 0.5 * (gl_DepthRange.diff * ndcZ + gl_DepthRange.near + gl_DepthRange.far);
}

/** Signed distance of an eye-space point in front of the near plane. */
float distanceBeyondNearPlane(vec3 eye)
{
    mat4 p = gl_ProjectionMatrix;
    vec4 plane = vec4(p[0][2] + p[0][3], p[1][2] + p[1][3], p[2][2] + p[2][3], p[3][2] + p[3][3]);
    return dot(plane, vec4(eye, 1.0)) / length(plane.xyz);
}
