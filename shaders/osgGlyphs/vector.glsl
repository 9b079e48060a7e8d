// osgGlyphs: cones, arrows and cylinders along an axis, exact: their screen bound and their
// ray intersection, in a frame with the base centre at the origin and the axis along +z.

#ifdef OSGGLYPHS_VECTOR_SHAPE

const float INFINITE_DISTANCE = 1.0e30;

/** The discs (z, radius) whose convex hull contains the shape; returns how many. */
int shapeDiscs(float radius, float len, out vec2 discs[3])
{
#if defined(OSGGLYPHS_SHAPE_CYLINDER)
    discs[0] = vec2(0.0, radius);
    discs[1] = vec2(len, radius);
    return 2;
#elif defined(OSGGLYPHS_SHAPE_CONE)
    discs[0] = vec2(0.0, radius);
    discs[1] = vec2(len, 0.0);
    return 2;
#else
    float headStart = len * (1.0 - osgGlyphs_arrowParams.x);
    discs[0] = vec2(0.0, radius);
    discs[1] = vec2(headStart, radius * max(osgGlyphs_arrowParams.y, 1.0));
    discs[2] = vec2(len, 0.0);
    return 3;
#endif
}

/** Two unit vectors that complete the axis to a right-handed orthonormal frame. */
void axisFrame(vec3 axis, out vec3 u, out vec3 v)
{
    vec3 helper = abs(axis.x) < 0.9 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0);
    u = normalize(cross(helper, axis));
    v = cross(axis, u);
}

/** The range of linear(clip) / clip.w over a circle's projection: the circle's clip-space centre
  * and two orthogonal clip-space radii (w > 0 all round), and a linear form on clip xyz (its w
  * is 0). With k = linear / w, k is reached where (A - kD) + (B - kE) cos + (C - kF) sin = 0 has
  * a solution; the extremes solve a quadratic whose discriminant, in Lagrange's form, keeps
  * its precision for circles far smaller than their distance. */
vec2 projectedRange(vec4 centre, vec4 radiusU, vec4 radiusV, vec4 linear)
{
    float A = dot(linear, centre), B = dot(linear, radiusU), C = dot(linear, radiusV);
    float D = centre.w, E = radiusU.w, F = radiusV.w;
    float a = D * D - E * E - F * F;
    float b = A * D - B * E - C * F;
    float DB_AE = D * B - A * E, DC_AF = D * C - A * F, BF_CE = B * F - C * E;
    float root = sqrt(max(DB_AE * DB_AE + DC_AF * DC_AF - BF_CE * BF_CE, 0.0));
    return vec2(b - root, b + root) / a;
}

/** A screen-space rectangle (four NDC corners, in strip order) that contains the shape: the
  * exact extents of the projected discs that span it, along the projected axis and across it.
  * Returns false for a glyph wholly behind the near plane. */
bool vectorScreenBound(vec3 base, vec3 axis, float len, float radius, out vec2 corners[4], out float nearestNdcZ)
{
    vec2 discs[3];
    int count = shapeDiscs(radius, len, discs);
    float widest = max(discs[0].y, discs[1].y);
    if (count > 2)
        widest = max(widest, discs[2].y);
    vec3 middle = base + axis * (0.5 * len);
    float reach = sqrt(0.25 * len * len + widest * widest);
    float beyondNear = distanceBeyondNearPlane(middle);
    if (beyondNear < -reach)
        return false;
    if (beyondNear <= reach)
    {
        corners = vec2[4](vec2(-1.0, -1.0), vec2(1.0, -1.0), vec2(-1.0, 1.0), vec2(1.0, 1.0));
        nearestNdcZ = -1.0;
        return true;
    }

    // Clip coordinates are linear in eye space, so each disc is a centre and two radii in clip space.
    vec3 u, v;
    axisFrame(axis, u, v);
    vec4 baseClip = gl_ProjectionMatrix * vec4(base, 1.0);
    vec4 axisClip = gl_ProjectionMatrix * vec4(axis, 0.0);
    vec4 uClip = gl_ProjectionMatrix * vec4(u, 0.0);
    vec4 vClip = gl_ProjectionMatrix * vec4(v, 0.0);
    vec4 tipClip = baseClip + axisClip * len;
    vec2 along = tipClip.xy / tipClip.w - baseClip.xy / baseClip.w;
    along = dot(along, along) > 1e-12 ? normalize(along) : vec2(1.0, 0.0);
    vec2 across = vec2(-along.y, along.x);

    vec2 lo = vec2(1e30), hi = vec2(-1e30);
    nearestNdcZ = 1.0;
    for (int disc = 0; disc < count; ++disc)
    {
        vec4 centre = baseClip + axisClip * discs[disc].x;
        vec4 radiusU = uClip * discs[disc].y, radiusV = vClip * discs[disc].y;
        vec2 alongRange = projectedRange(centre, radiusU, radiusV, vec4(along, 0.0, 0.0));
        vec2 acrossRange = projectedRange(centre, radiusU, radiusV, vec4(across, 0.0, 0.0));
        lo = min(lo, vec2(alongRange.x, acrossRange.x));
        hi = max(hi, vec2(alongRange.y, acrossRange.y));
        nearestNdcZ = min(nearestNdcZ, projectedRange(centre, radiusU, radiusV, vec4(0.0, 0.0, 1.0, 0.0)).x);
    }
    corners = vec2[4](along * lo.x + across * lo.y, along * hi.x + across * lo.y, along * lo.x + across * hi.y,
                      along * hi.x + across * hi.y);
    nearestNdcZ = max(nearestNdcZ, -1.0);
    return true;
}

void hitDisc(vec3 o, vec3 d, float z, float radius, float facing, inout float tBest, inout vec3 nBest)
{
    if (abs(d.z) < 1e-12)
        return;
    float t = (z - o.z) / d.z;
    vec2 p = o.xy + d.xy * t;
    if (t >= 0.0 && t < tBest && dot(p, p) <= radius * radius)
    {
        tBest = t;
        nBest = vec3(0.0, 0.0, facing);
    }
}

/** The side of a cylinder or truncated cone: radius r0 at z0 shrinking linearly to r1 at z1. */
void hitSide(vec3 o, vec3 d, float z0, float r0, float z1, float r1, inout float tBest, inout vec3 nBest)
{
    // x^2 + y^2 = (r0 + slope (z - z0))^2, with slope = (r1 - r0) / (z1 - z0).
    float slope = (r1 - r0) / (z1 - z0);
    float radiusAtOrigin = r0 + slope * (o.z - z0);
    float a = dot(d.xy, d.xy) - slope * slope * d.z * d.z;
    float b = dot(o.xy, d.xy) - slope * radiusAtOrigin * d.z;
    float c = dot(o.xy, o.xy) - radiusAtOrigin * radiusAtOrigin;
    float roots[2];
    if (abs(a) < 1e-12)
    {
        if (abs(b) < 1e-12)
            return;
        roots[0] = roots[1] = -c / (2.0 * b);
    }
    else
    {
        float discriminant = b * b - a * c;
        if (discriminant < 0.0)
            return;
        float s = sqrt(discriminant);
        roots[0] = min((-b - s) / a, (-b + s) / a);
        roots[1] = max((-b - s) / a, (-b + s) / a);
    }
    for (int i = 0; i < 2; ++i)
    {
        float t = roots[i];
        float z = o.z + d.z * t;
        float radiusAtHit = r0 + slope * (z - z0);
        if (t >= 0.0 && t < tBest && z >= z0 && z <= z1 && radiusAtHit >= 0.0)
        {
            vec2 p = o.xy + d.xy * t;
            tBest = t;
            nBest = normalize(vec3(p, -slope * radiusAtHit));
            return;
        }
    }
}

/** Whether a point (in the shape's frame) lies inside the solid. */
bool insideSide(vec3 p, float z0, float r0, float z1, float r1)
{
    float r = mix(r0, r1, (p.z - z0) / (z1 - z0));
    return p.z >= z0 && p.z <= z1 && dot(p.xy, p.xy) < r * r;
}

bool insideShape(vec3 p, float radius, float len)
{
#if defined(OSGGLYPHS_SHAPE_CYLINDER)
    return insideSide(p, 0.0, radius, len, radius);
#elif defined(OSGGLYPHS_SHAPE_CONE)
    return insideSide(p, 0.0, radius, len, 0.0);
#else
    float headStart = len * (1.0 - osgGlyphs_arrowParams.x);
    return insideSide(p, 0.0, radius, headStart, radius) ||
           insideSide(p, headStart, radius * osgGlyphs_arrowParams.y, len, 0.0);
#endif
}

/** The nearest hit (t >= 0) of a ray with the shape, and its normal; tBest stays infinite on a miss. */
void intersectShape(vec3 o, vec3 d, float radius, float len, out float tBest, out vec3 normal)
{
    tBest = INFINITE_DISTANCE;
    normal = vec3(0.0, 0.0, 1.0);
#if defined(OSGGLYPHS_SHAPE_CYLINDER)
    hitSide(o, d, 0.0, radius, len, radius, tBest, normal);
    hitDisc(o, d, 0.0, radius, -1.0, tBest, normal);
    hitDisc(o, d, len, radius, 1.0, tBest, normal);
#elif defined(OSGGLYPHS_SHAPE_CONE)
    hitSide(o, d, 0.0, radius, len, 0.0, tBest, normal);
    hitDisc(o, d, 0.0, radius, -1.0, tBest, normal);
#else
    float headStart = len * (1.0 - osgGlyphs_arrowParams.x);
    float headRadius = radius * osgGlyphs_arrowParams.y;
    hitSide(o, d, 0.0, radius, headStart, radius, tBest, normal);
    hitDisc(o, d, 0.0, radius, -1.0, tBest, normal);
    hitSide(o, d, headStart, headRadius, len, 0.0, tBest, normal);
    hitDisc(o, d, headStart, headRadius, -1.0, tBest, normal);
#endif
}

#endif
