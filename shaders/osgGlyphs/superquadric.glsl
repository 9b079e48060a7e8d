// osgGlyphs: superquadrics (Barr's superellipsoids), exact: their ray intersection. A superquadric
// is an ellipsoid's centre and semi-axes (ellipsoid.glsl) and two exponents, e1 along its z axis
// and e2 around it, each in [0.1, 2]: in the frame where the semi-axes are unit, it is the unit
// ball of the norm
//   N(p) = ((|x|^q + |y|^q)^(s/q) + |z|^s)^(1/s),  q = 2 / e2, s = 2 / e1,
// an L^s norm of an L^q norm: convex (q, s >= 1), 1 on the surface, within the unit cube.

#ifdef OSGGLYPHS_SHAPE_SUPERQUADRIC

/** The scale of the semi-axes whose ellipsoid holds the superquadric, touching it: the largest
 * |p|_2 where N(p) = 1. Over the L^q unit circle, |(x, y)|_2 is at most k = 2^(1/2 - 1/q) for
 * q >= 2 (on the diagonals), else 1; then, by Hoelder's inequality, k^2 u^2 + v^2 with
 * u^s + v^s = 1 (s > 2) is at most (k^2r + 1)^(1/r), r = s / (s - 2) = 1 / (1 - e1), and at most
 * k^2 for s <= 2. In logarithms, so that k^2r cannot overflow as e1 approaches 1; 1e-4 wider,
 * so that rounding cannot cut the points where it touches. */
float superquadricBoundScale(vec2 exponents)
{
    float logK = 0.5 * max(1.0 - exponents.y, 0.0);
    float inverseR = max(1.0 - exponents.x, 0.0);
    float logScale = logK;
    if (inverseR > 0.0)
        logScale += 0.5 * inverseR * log2(1.0 + exp2(-2.0 * logK / inverseR));
    return 1.0001 * exp2(logScale);
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

/** What ray-casting a glyph of these exponents needs, computed once a glyph: the norm's powers q,
 * s and s / q, and superquadricBoundScale(). */
vec4 superquadricPowers(vec2 exponents)
{
    float q = 2.0 / exponents.y, s = 2.0 / exponents.x;
    return vec4(q, s, s / q, superquadricBoundScale(exponents));
}

/** L(t) = ln N(o + t d) along a ray in the unit frame, its derivative, and the gradient of ln N
 * there, for the norm's powers (q, s, s / q, 1 / s), at points where N is about 1 or more:
 * ln N = log2(N^s) ln 2 / s and its gradient is that of N^s over s N^s, so that N itself, one more
 * power, is never needed. */
float superquadricLogAlong(vec3 o, vec3 d, float t, vec4 powers, out float slope, out vec3 gradient)
{
    vec3 p = o + t * d;
    vec3 a = max(abs(p), vec3(1e-20));
    float xq = pow(a.x, powers.x), yq = pow(a.y, powers.x);
    float rq = max(xq + yq, 1e-30);  // rho^q, rho the L^q norm of (x, y)
    float rs = pow(rq, powers.z);     // rho^s
    float zs = pow(a.z, powers.y);
    float ns = rs + zs;               // N^s
    // d(N^s)/dx over s: rho^(s-q) x^(q-1), bounded since s >= 1; as rho^s (x^q / rho^q) / x, whose
    // factors stay in range where rho^(s-q) alone would overflow near the z axis.
    gradient = sign(p) * vec3(rs * (xq / rq) / a.x, rs * (yq / rq) / a.y, zs / a.z) / ns;
    slope = dot(gradient, d);
    return log2(ns) * (0.69314718 * powers.w);
}

/** Where the ray origin + t * direction runs inside the superquadric (centre, A^-1 and
 * superquadricPowers()), with the unit outward normals there; false if it misses.
 *
 * H = N - 1 is convex along the ray, so its tangent lies below it: Newton's steps from the near
 * end of the ray's span through the bounds, where H > 0, never pass the entry point, and each
 * lands where H >= 0. They converge to the entry monotonically (quadratically once near it), or
 * reach a point where H > 0 no longer falls, beyond which it cannot fall to 0: a certain miss. The
 * exit is found the same way from the far end. A ray that grazes the surface closer than 24 steps
 * tell is taken as a miss. H is solved to 1e-5 of the glyph's size.
 *
 * The steps are taken from L = ln N, which costs a power less than N: Newton's step for H is
 * (1 - e^-L) / -L', and (L - L^2/2) / -L' is a little shorter (by a term in L^3, so convergence
 * stays quadratic) and so cannot pass the entry either.
 *
 * Each pass of the one loop evaluates L once, at whatever point the ray asks for: the rays that a
 * SIMD machine shades together, some seeking their entry and some their exit, share passes. */
bool superquadricSpan(vec3 origin, vec3 direction, vec3 centre, mat3 inverseAxes, vec4 powers, out Span span)
{
    float bound = powers.w;
    vec4 normPowers = vec4(powers.xyz, 1.0 / powers.y);
    vec3 d = inverseAxes * direction;
    // The ray from its point nearest the centre, t = 0 there: a glyph far smaller than its
    // distance would otherwise leave t too few digits for L to reach the tolerance.
    vec3 fromCentre = inverseAxes * (origin - centre);
    float a = dot(d, d), shift = -dot(fromCentre, d) / a;
    vec3 o = fromCentre + shift * d;
    // The span through the unit cube, which holds the superquadric, and the sphere that does.
    vec3 safe = mix(d, vec3(1e-30), lessThan(abs(d), vec3(1e-30)));
    vec3 tA = (-1.0 - o) / safe, tB = (1.0 - o) / safe;
    vec3 tNear = min(tA, tB), tFar = max(tA, tB);
    float h2 = bound * bound - dot(o, o);
    if (h2 < 0.0)
        return false; // most rays that miss stop here
    float h = sqrt(h2 / a);
    float lo = max(max(max(tNear.x, tNear.y), tNear.z), -h), hi = min(min(min(tFar.x, tFar.y), tFar.z), h);
    if (!(lo < hi))
        return false;
    // Where the ray leaves matters to a clip plane's cut, and to a ray that starts inside (then
    // keepNearerDrawnPoint draws the near plane's cut); elsewhere the span's far end will do.
#ifdef OSGGLYPHS_CLIP_PLANES
    bool exitMatters = true;
#else
    bool exitMatters = lo < -shift;
#endif
    const float tolerance = 1e-5;
    vec3 gradientLo = vec3(0.0), gradientHi = vec3(0.0);
    bool seekingExit = false, found = false, missed = false;
    float t = lo;
    for (int steps = 0, pass = 0; pass < 40 && !found && !missed; ++pass)
    {
        float slope;
        vec3 gradient;
        float value = superquadricLogAlong(o, d, t, normPowers, slope, gradient);
        ++steps;
        if (!seekingExit)
        {
            lo = t;
            gradientLo = gradient;
            bool entered = value <= tolerance;
            if (!entered)
            {
                missed = !(slope < 0.0) || steps >= 24;
                t -= (value - 0.5 * value * value) / slope;
                missed = missed || t > hi;
                // Newton's error after the step is about H''/2 (H / H')^2: with H'' below 20 |d|^2
                // (the shapes' curvature), within the tolerance where H < 1e-3 |H'| / |d|, which
                // L < 1e-3 |L'| / |d| implies (H <= L N, H' = N L'). The entry is then taken
                // without evaluating L there, its normal from this point's gradient (within 2%);
                // rays that graze the surface, with small L', are excluded.
                entered = !missed && value < -1e-3 * slope * inversesqrt(a);
                lo = entered ? t : lo;
            }
            if (entered)
            {
                seekingExit = exitMatters;
                found = !exitMatters;
                steps = 0;
                t = hi;
            }
        }
        else
        {
            hi = t;
            gradientHi = gradient;
            found = value <= tolerance || !(slope > 0.0) || steps >= 16;
            t -= (value - 0.5 * value * value) / slope;
        }
    }
    if (!found)
        return false;
    mat3 toNormal = transpose(inverseAxes);
    span = Span(lo + shift, hi + shift, normalize(toNormal * gradientLo), vec3(0.0));
#ifdef OSGGLYPHS_CLIP_PLANES // the far side's normal is shown only through a clip plane's cut
    span.nLeave = normalize(toNormal * gradientHi);
#endif
    return true;
}

#endif
