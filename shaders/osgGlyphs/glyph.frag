#version 330 compatibility
// osgGlyphs: ray-casts the glyph's exact surface, lights it and writes its true depth, so that
// glyphs intersect each other and ordinary geometry as if they were tessellated exactly.

#include "projection.glsl"
#include "sphere.glsl"
#include "lighting.glsl"

flat in vec4 fragSphere;
flat in vec4 fragColor;
noperspective in vec3 fragRayNear;
noperspective in vec3 fragRayFar;

out vec4 color;

void main()
{
    vec3 origin = fragRayNear;
    vec3 direction = normalize(fragRayFar - fragRayNear);
    float tEnter, tLeave;
    if (!intersectSphere(origin, direction, fragSphere, tEnter, tLeave) || tLeave < 0.0)
        discard;

    // The ray starts on the near plane: a sphere entered before it is cut there, and the cut
    // face is drawn at the near plane, facing the viewer.
    vec3 position = origin + direction * max(tEnter, 0.0);
    vec3 normal = tEnter >= 0.0 ? (position - fragSphere.xyz) / fragSphere.w : -direction;

    float ndcZ = ndcDepth(position);
    if (ndcZ > 1.0)
        discard; // beyond the far plane, where fixed-function geometry is clipped too
    gl_FragDepth = windowDepth(ndcZ);
    color = vec4(shade(fragColor.rgb, position, normal, -direction), fragColor.a);
}
