// osgGlyphs: the exact sphere, its screen-space bound and its ray intersection.

/** The two values of x/z (or y/z) of the planes through the eye that touch the sphere,
  * in the 2D section (lateral, z); requires the sphere to lie wholly in front of the eye. */
vec2 tangentSlopes(float lateral, float z, float radius)
{
    float a = z * z - radius * radius;
    float b = lateral * z;
    float root = radius * sqrt(max(lateral * lateral + z * z - radius * radius, 0.0));
    return vec2(b - root, b + root) / a;
}

/** Whether the projection is an axis-aligned orthographic or perspective one (glFrustum, glOrtho,
  * their shears included), for which the eye's z is the depth. Light-space perspective shadow
  * maps (osgShadow's ViewDependentShadowMap) are not. */
bool isAxisAlignedProjection()
{
    mat4 p = gl_ProjectionMatrix;
    bool standardW = isOrthographic() ? p[3][3] == 1.0 : p[3][3] == 0.0 && p[2][3] == -1.0;
    return p[0][1] == 0.0 && p[1][0] == 0.0 && p[0][3] == 0.0 && p[1][3] == 0.0 && standardW;
}

/** The two values s of the planes row - s * w of clip space that touch the sphere: the extent of
  * the sphere along that row's coordinate in NDC, for any projective matrix, through the sphere's
  * dual quadric [r^2 I - c c^T, -c; -c^T, -1]. The sphere must lie wholly in front of the eye. */
vec2 tangentRange(vec4 row, vec4 w, vec3 center, float radius)
{
    float r2 = radius * radius;
    vec4 c = vec4(center, 1.0);
    float rowRow = r2 * dot(row.xyz, row.xyz) - dot(row, c) * dot(row, c);
    float rowW = r2 * dot(row.xyz, w.xyz) - dot(row, c) * dot(w, c);
    float wW = r2 * dot(w.xyz, w.xyz) - dot(w, c) * dot(w, c);
    float root = sqrt(max(rowW * rowW - rowRow * wW, 0.0));
    vec2 s = vec2(rowW - root, rowW + root) / wW;
    return vec2(min(s.x, s.y), max(s.x, s.y));
}

/** sphereScreenBound under any projective matrix: the NDC box and nearest NDC depth. */
bool projectiveSphereBound(vec3 center, float radius, out vec4 box, out float nearestNdcZ)
{
    mat4 rows = transpose(gl_ProjectionMatrix);
    vec2 xs = tangentRange(rows[0], rows[3], center, radius);
    vec2 ys = tangentRange(rows[1], rows[3], center, radius);
    box = vec4(xs.x, ys.x, xs.y, ys.y);
    nearestNdcZ = max(tangentRange(rows[2], rows[3], center, radius).x, -1.0);
    return true;
}

/** The exact NDC rectangle (xmin, ymin, xmax, ymax) of the sphere's projection, and the NDC
  * depth of its nearest point. A sphere that crosses the near plane covers the whole view, so
  * its cut is drawn; one wholly behind the near plane returns false. */
bool sphereScreenBound(vec3 center, float radius, out vec4 box, out float nearestNdcZ)
{
    float beyondNear = distanceBeyondNearPlane(center);
    if (beyondNear < -radius)
        return false;
    if (beyondNear <= radius)
    {
        box = vec4(-1.0, -1.0, 1.0, 1.0);
        nearestNdcZ = -1.0;
        return true;
    }
    mat4 p = gl_ProjectionMatrix;
    if (!isAxisAlignedProjection())
        return projectiveSphereBound(center, radius, box, nearestNdcZ);
    if (isOrthographic())
    {
        vec4 lo = p * vec4(center - vec3(radius, radius, 0.0), 1.0);
        vec4 hi = p * vec4(center + vec3(radius, radius, 0.0), 1.0);
        box = vec4(min(lo.xy, hi.xy), max(lo.xy, hi.xy));
    }
    else
    {
        // x_ndc = -(p00 * x/z + p20) on a plane x = k z through the eye.
        vec2 xs = -(p[0][0] * tangentSlopes(center.x, center.z, radius) + p[2][0]);
        vec2 ys = -(p[1][1] * tangentSlopes(center.y, center.z, radius) + p[2][1]);
        box = vec4(min(xs.x, xs.y), min(ys.x, ys.y), max(xs.x, xs.y), max(ys.x, ys.y));
    }
    nearestNdcZ = ndcDepth(vec3(0.0, 0.0, center.z + radius));
    return true;
}

/** Where the ray origin + t * direction (unit) enters and leaves the sphere; false if it misses. */
bool intersectSphere(vec3 origin, vec3 direction, vec4 sphere, out float tEnter, out float tLeave)
{
    vec3 m = origin - sphere.xyz;
    float b = dot(m, direction);
    vec3 closest = m - b * direction; // numerically stable for small, distant spheres
    float h2 = sphere.w * sphere.w - dot(closest, closest);
    if (h2 < 0.0)
        return false;
    float h = sqrt(h2);
    tEnter = -b - h;
    tLeave = -b + h;
    return true;
}
