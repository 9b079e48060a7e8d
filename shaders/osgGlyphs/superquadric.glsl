// osgGlyphs: superquadrics (Barr's superellipsoids), exact: their ray intersection. A superquadric
// is an ellipsoid's centre and semi-axes (ellipsoid.glsl) and two exponents, e1 along its z axis
// and e2 around it, each in [0.1, 2]: in the frame where the semi-axes are unit, it is the unit
// ball of the norm
//   N(p) = ((|x|^q + |y|^q)^(s/q) + |z|^s)^(1/s),  q = 2 / e2, s = 2 / e1,
// an L^s norm of an L^q norm: convex (q, s >= 1), 1 on the surface, within the unit cube.

#ifdef OSGGLYPHS_SHAPE_SUPERQUADRIC

/** A scale of the semi-axes whose ellipsoid holds the superquadric: 2^((1 - e)/2) per exponent
 * below 1 (the L^2 norm over an L^p norm of two components, p >= 2), at most sqrt(3) (the cube). */
float superquadricBoundScale(vec2 exponents)
{
    vec2 excess = max(1.0 - exponents, 0.0);
    return min(exp2(0.5 * (excess.x + excess.y)), 1.7320508);
}

/** The radius of a sphere inside the superquadric: 2^(-(e - 1)/2) per exponent above 1 (an L^p norm
 * of two components, p <= 2, is at most 2^(1/p - 1/2) times their L^2 norm, so N(p) <= |p| / it);
 * 1 for exponents at most 1 (N <= the L^2 norm). */
float superquadricInnerScale(vec2 exponents)
{
    vec2 excess = max(exponents - 1.0, 0.0);
    return exp2(-0.5 * (excess.x + excess.y));
}

/** Four NDC corners (triangle-strip order) of a rectangle that contains the superquadric, and the
 * NDC depth of its nearest point, as ellipsoidScreenBound() gives them for the ellipsoid that holds
 * it; where the screen rectangle of the eight corners of its box (the superquadric lies in the box
 * of its semi-axes) is smaller, as for boxes, that one. */
bool superquadricScreenBound(vec3 centre, mat3 semiAxes, vec2 exponents, out vec2 corners[4], out float nearestNdcZ)
{
    if (!ellipsoidScreenBound(centre, semiAxes * superquadricBoundScale(exponents), corners, nearestNdcZ))
        return false;
    if (nearestNdcZ <= -1.0)
        return true; // across the near plane: the whole view
    vec2 low = vec2(1.0e30), high = vec2(-1.0e30);
    for (int i = 0; i < 8; ++i)
    {
        vec3 signs = vec3((i & 1) != 0 ? 1.0 : -1.0, (i & 2) != 0 ? 1.0 : -1.0, (i & 4) != 0 ? 1.0 : -1.0);
        vec4 clip = gl_ProjectionMatrix * vec4(centre + semiAxes * signs, 1.0);
        if (!(clip.w > 0.0))
            return true; // a corner behind the eye: the ellipse's rectangle
        low = min(low, clip.xy / clip.w);
        high = max(high, clip.xy / clip.w);
    }
    float ellipseArea = length(corners[1] - corners[0]) * length(corners[2] - corners[0]);
    if ((high.x - low.x) * (high.y - low.y) < ellipseArea)
        corners = vec2[4](low, vec2(high.x, low.y), vec2(low.x, high.y), high);
    return true;
}

/** N(p) and its gradient (N is homogeneous of degree 1: the gradient is that of p / max|p_i|,
 * where every power is at most 1). */
float superquadricNorm(vec3 p, vec2 exponents, out vec3 gradient)
{
    vec3 a = abs(p);
    float largest = max(max(a.x, a.y), a.z);
    if (!(largest > 0.0))
    {
        gradient = vec3(0.0);
        return 0.0;
    }
    a = max(a / largest, vec3(1e-20));
    float q = 2.0 / exponents.y, s = 2.0 / exponents.x;
    float xq = pow(a.x, q), yq = pow(a.y, q);
    float rq = xq + yq;        // rho^q, rho the L^q norm of (x, y)
    float rs = pow(rq, s / q); // rho^s
    float zs = pow(a.z, s);
    float ns = rs + zs; // N^s, at least 1 here
    float n = pow(ns, 1.0 / s);
    // dN/dz = N^(1-s) z^(s-1); dN/dx = N^(1-s) rho^(s-q) x^(q-1), which goes to 0 with rho (s >= 1);
    // powers as quotients.
    float outer = n / ns;
    float across = rq > 0.0 ? outer * rs / rq : 0.0;
    gradient = sign(p) * vec3(across * xq / a.x, across * yq / a.y, outer * zs / a.z);
    return largest * n;
}

/** H(t) = N(o + t d) - 1 along a ray in the unit frame, its derivative, and N's gradient there. */
float superquadricAlong(vec3 o, vec3 d, float t, vec2 exponents, out float slope, out vec3 gradient)
{
    float h = superquadricNorm(o + t * d, exponents, gradient) - 1.0;
    slope = dot(gradient, d);
    return h;
}

/** Where the ray origin + t * direction runs inside the superquadric (centre, A^-1, exponents),
 * with the unit outward normals there; false if it misses. H is convex along the ray. A ray through
 * the sphere inside (superquadricInnerScale) has its points inside at once; for the others, the
 * minimum of H over the ray's span of the unit cube is bracketed by tangents (Kelley's cutting
 * planes, which also bound H from below: a bound above 0 is a certain miss). Once points inside
 * are known, Newton's steps from the outside point on each side converge monotonically to the
 * surface, never past it. */
bool superquadricSpan(vec3 origin, vec3 direction, vec3 centre, mat3 inverseAxes, vec2 exponents,
                      out Span span)
{
    vec3 o = inverseAxes * (origin - centre), d = inverseAxes * direction;
    vec3 safe = mix(d, vec3(1e-30), lessThan(abs(d), vec3(1e-30)));
    vec3 tA = (-1.0 - o) / safe, tB = (1.0 - o) / safe;
    vec3 tNear = min(tA, tB), tFar = max(tA, tB);
    float lo = max(max(tNear.x, tNear.y), tNear.z), hi = min(min(tFar.x, tFar.y), tFar.z);
    // Within the sphere of the bound too (superquadricBoundScale): most rays that miss stop here.
    float a = dot(d, d), b = dot(o, d) / a, bound = superquadricBoundScale(exponents);
    vec3 closest = o - b * d;
    float h2 = bound * bound - dot(closest, closest);
    if (h2 < 0.0)
        return false;
    float h = sqrt(h2 / a);
    lo = max(lo, -b - h);
    hi = min(hi, -b + h);
    if (!(lo < hi))
        return false;
    float gLo, gHi;
    vec3 gradLo, gradHi = vec3(0.0);
    float hLo = superquadricAlong(o, d, lo, exponents, gLo, gradLo);
    float hHi = 0.0; // evaluated by the search, or for the way out: only they need it
    // The points inside nearest each end: the inner sphere's span, or the one the search finds.
    float insideFirst, insideLast;
    float inner = superquadricInnerScale(exponents);
    float innerH2 = inner * inner - dot(closest, closest);
    if (innerH2 > 0.0)
    {
        float innerH = sqrt(innerH2 / a);
        insideFirst = -b - innerH;
        insideLast = -b + innerH;
    }
    else
    {
        hHi = superquadricAlong(o, d, hi, exponents, gHi, gradHi);
        float inside = hLo <= 0.0 ? lo : (hHi <= 0.0 ? hi : -1.0e30);
        for (int i = 0; i < 24 && inside == -1.0e30; ++i)
        {
            if (!(gLo < 0.0) || !(gHi > 0.0))
                return false; // the minimum at an end, where H > 0
            // The tangents at both ends meet at tx, where they bound H from below.
            float tx = (hHi - hLo + gLo * lo - gHi * hi) / (gLo - gHi);
            if (hLo + gLo * (tx - lo) > 0.0)
                return false;
            float t = (i % 3 == 2) ? 0.5 * (lo + hi) : clamp(tx, lo, hi);
            float g;
            vec3 grad;
            float h = superquadricAlong(o, d, t, exponents, g, grad);
            if (h <= 0.0)
                inside = t;
            else if (g < 0.0)
            {
                lo = t;
                hLo = h;
                gLo = g;
                gradLo = grad;
            }
            else
            {
                hi = t;
                hHi = h;
                gHi = g;
                gradHi = grad;
            }
        }
        if (inside == -1.0e30)
            return false; // a ray that grazes it closer than the steps tell
        insideFirst = insideLast = inside;
    }
    float enter = lo, leave = hi;
    for (int i = 0; i < 16 && hLo > 1e-5 && gLo < 0.0; ++i)
    {
        enter = min(enter - hLo / gLo, insideFirst);
        hLo = superquadricAlong(o, d, enter, exponents, gLo, gradLo);
    }
    // Where the ray leaves matters to a clip plane's cut, and to a ray that starts inside (then
    // keepNearerDrawnPoint draws the near plane's cut); elsewhere the bracket's end will do.
#ifndef OSGGLYPHS_CLIP_PLANES
    if (enter < 0.0)
#endif
    {
        if (innerH2 > 0.0) // no search ran
            hHi = superquadricAlong(o, d, hi, exponents, gHi, gradHi);
        for (int i = 0; i < 16 && hHi > 1e-5 && gHi > 0.0; ++i)
        {
            leave = max(leave - hHi / gHi, insideLast);
            hHi = superquadricAlong(o, d, leave, exponents, gHi, gradHi);
        }
    }
    mat3 toNormal = transpose(inverseAxes);
    span = Span(enter, leave, normalize(toNormal * gradLo), vec3(0.0));
#ifdef OSGGLYPHS_CLIP_PLANES // the far side's normal is shown only through a clip plane's cut
    span.nLeave = normalize(toNormal * gradHi);
#endif
    return true;
}

#endif
