// osgGlyphs: cones, arrows and cylinders along an axis, exact: their screen bound and their
// ray intersection, in a frame with the base centre at the origin and the axis along +z.

#ifdef OSGGLYPHS_VECTOR_SHAPE

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

/** A sphere (centre, radius) that contains the shape. */
vec4 vectorBoundingSphere(vec3 base, vec3 axis, float len, float radius)
{
    vec2 discs[3];
    int count = shapeDiscs(radius, len, discs);
    float widest = max(discs[0].y, discs[1].y);
    if (count > 2)
        widest = max(widest, discs[2].y);
    return vec4(base + axis * (0.5 * len), sqrt(0.25 * len * len + widest * widest));
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

// The fewest pixels along a vector glyph's rectangle for a trapezoid to pay (measured on cones).
const float SLOPED_SIDES_PIXELS = 3.0;

/** The support line of the shape's projection with this slope on the far side of across: the q of
  * across = slope * along + q that bounds every disc (sign 1: from above, -1: from below). */
float supportOffset(vec4 baseClip, vec4 axisClip, vec4 uClip, vec4 vClip, vec2 discs[3], int count,
                    vec2 along, vec2 across, float slope, float side)
{
    vec4 linear = vec4(side * (across - slope * along), 0.0, 0.0);
    float q = -1e30;
    for (int disc = 0; disc < count; ++disc)
    {
        vec4 centre = baseClip + axisClip * discs[disc].x;
        q = max(q, projectedRange(centre, uClip * discs[disc].y, vClip * discs[disc].y, linear).y);
    }
    return side * q;
}

/** A screen-space quadrilateral (four NDC corners, in strip order) that contains the shape. Its
  * ends are the exact extents of the projected discs along the projected axis; its sides are the
  * exact extents across it (a rectangle) or, where that is smaller, the support lines sloped from
  * the first disc's projection to the second's (a trapezoid: a cone seen from the side fills
  * about half of its rectangle). The wider end comes first, so that the corners' parallelogram
  * (corners[1] + corners[2] - corners[0]) contains the quadrilateral.
  * Returns false for a glyph wholly behind the near plane. */
bool vectorScreenBound(vec3 base, vec3 axis, float len, float radius, out vec2 corners[4], out float nearestNdcZ)
{
    vec2 discs[3];
    int count = shapeDiscs(radius, len, discs);
    vec4 enclosing = vectorBoundingSphere(base, axis, len, radius);
    float beyondNear = distanceBeyondNearPlane(enclosing.xyz);
    if (beyondNear < -enclosing.w)
        return false;
    if (beyondNear <= enclosing.w)
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
    // The first two discs' centres along the axis and extents across it, for the sloped sides.
    vec2 centreAlong;
    vec4 edgeAcross;
    for (int disc = 0; disc < count; ++disc)
    {
        vec4 centre = baseClip + axisClip * discs[disc].x;
        vec4 radiusU = uClip * discs[disc].y, radiusV = vClip * discs[disc].y;
        vec2 alongRange = projectedRange(centre, radiusU, radiusV, vec4(along, 0.0, 0.0));
        vec2 acrossRange = projectedRange(centre, radiusU, radiusV, vec4(across, 0.0, 0.0));
        lo = min(lo, vec2(alongRange.x, acrossRange.x));
        hi = max(hi, vec2(alongRange.y, acrossRange.y));
        nearestNdcZ = min(nearestNdcZ, projectedRange(centre, radiusU, radiusV, vec4(0.0, 0.0, 1.0, 0.0)).x);
        if (disc < 2)
        {
            centreAlong[disc] = dot(centre.xy / centre.w, along);
            edgeAcross[disc] = acrossRange.x;
            edgeAcross[disc + 2] = acrossRange.y;
        }
    }
    nearestNdcZ = max(nearestNdcZ, -1.0);
    // Rectangle: across = lo.y and hi.y at both ends, lo.x and hi.x.
    vec2 lower = vec2(lo.y), upper = vec2(hi.y);
#ifndef OSGGLYPHS_SHAPE_CYLINDER
    // (A cylinder's sides are parallel but for perspective: its rectangle is as tight.) Glyphs of
    // a few pixels cost their primitive, not their fragments, and keep the rectangle.
    float separation = centreAlong.y - centreAlong.x;
    vec2 toPixels = 0.5 * osgGlyphs_viewport.zw;
    float longestSide = max(length(along * toPixels) * (hi.x - lo.x), length(across * toPixels) * (hi.y - lo.y));
    if (abs(separation) > 0.25 * (hi.x - lo.x) && longestSide >= SLOPED_SIDES_PIXELS)
    {
        float lowerSlope = (edgeAcross.y - edgeAcross.x) / separation;
        float upperSlope = (edgeAcross.w - edgeAcross.z) / separation;
        // A side may run along a straight edge of the silhouette, which rounding must not move
        // inside: the sides are moved out by a sixteenth of a pixel.
        float margin = 0.125 / max(osgGlyphs_viewport.z, osgGlyphs_viewport.w);
        float lowerQ = supportOffset(baseClip, axisClip, uClip, vClip, discs, count, along, across, lowerSlope, -1.0) -
                       margin * sqrt(1.0 + lowerSlope * lowerSlope);
        float upperQ = supportOffset(baseClip, axisClip, uClip, vClip, discs, count, along, across, upperSlope, 1.0) +
                       margin * sqrt(1.0 + upperSlope * upperSlope);
        vec2 sloped0 = vec2(lowerSlope, upperSlope) * lo.x + vec2(lowerQ, upperQ);
        vec2 sloped1 = vec2(lowerSlope, upperSlope) * hi.x + vec2(lowerQ, upperQ);
        // Both ends hold a point of the shape, so the sides cross only by rounding.
        float width0 = max(sloped0.y - sloped0.x, 0.0), width1 = max(sloped1.y - sloped1.x, 0.0);
        if (width0 + width1 < 2.0 * (hi.y - lo.y))
        {
            lower = vec2(sloped0.x, sloped1.x);
            upper = vec2(sloped0.x + width0, sloped1.x + width1);
        }
    }
#endif
    vec2 ends = vec2(lo.x, hi.x);
    if (upper.y - lower.y > upper.x - lower.x)
    {
        // The frame turned half round, which keeps the winding.
        along = -along;
        across = -across;
        ends = -ends.yx;
        vec2 turnedLower = -upper.yx;
        upper = -lower.yx;
        lower = turnedLower;
    }
    corners = vec2[4](along * ends.x + across * lower.x, along * ends.y + across * lower.y,
                      along * ends.x + across * upper.x, along * ends.y + across * upper.y);
    return true;
}

/** Where the ray o + t d (unit d) runs inside the solid of revolution of radius r0 at z0 changing
 * linearly to r1 at z1 (both >= 0): between the end planes and inside the side. False if it misses. */
bool frustumSpan(vec3 o, vec3 d, float z0, float r0, float z1, float r1, out Span span)
{
    span = Span(-INFINITE_DISTANCE, INFINITE_DISTANCE, vec3(0.0), vec3(0.0));
    if (abs(d.z) < 1e-12)
    {
        if (o.z < z0 || o.z > z1)
            return false;
    }
    else
    {
        float t0 = (z0 - o.z) / d.z, t1 = (z1 - o.z) / d.z;
        float up = sign(d.z);
        span = Span(min(t0, t1), max(t0, t1), vec3(0.0, 0.0, -up), vec3(0.0, 0.0, up));
    }
    // Inside the side: x^2 + y^2 <= rho^2, rho = r0 + slope (z - z0) >= 0, and rho = rho0 + rate t
    // along the ray: q(t) = a t^2 + 2 b t + c <= 0.
    float slope = (r1 - r0) / (z1 - z0);
    float rho0 = r0 + slope * (o.z - z0);
    float rate = slope * d.z;
    float a = dot(d.xy, d.xy) - rate * rate;
    float b = dot(o.xy, d.xy) - rho0 * rate;
    float c = dot(o.xy, o.xy) - rho0 * rho0;
    float sideEnter = -INFINITE_DISTANCE, sideLeave = INFINITE_DISTANCE;
    float discriminant = b * b - a * c;
    if (abs(a) < 1e-12)
    {
        // Along a generator of the side (or the axis of a cylinder): q is linear.
        if (abs(b) < 1e-12)
        {
            if (c > 0.0)
                return false;
        }
        else if (b > 0.0)
            sideLeave = -c / (2.0 * b);
        else
            sideEnter = -c / (2.0 * b);
    }
    else if (a > 0.0)
    {
        // Inside between the roots; beyond the end planes the other nappe of the cone is cut off.
        if (discriminant < 0.0)
            return false;
        float s = sqrt(discriminant);
        sideEnter = (-b - s) / a;
        sideLeave = (-b + s) / a;
    }
    else
    {
        // Steeper than the side: inside before the first root and after the second (everywhere
        // without roots), on the nappe where rho >= 0, which begins at the apex.
        float s = sqrt(max(discriminant, 0.0));
        float apex = -rho0 / rate;
        if (rate > 0.0)
            sideEnter = discriminant >= 0.0 ? (-b - s) / a : apex;
        else
            sideLeave = discriminant >= 0.0 ? (-b + s) / a : apex;
    }
    if (sideEnter > span.tEnter)
    {
        vec3 p = o + d * sideEnter;
        span.tEnter = sideEnter;
        span.nEnter = normalize(vec3(p.xy, -slope * (r0 + slope * (p.z - z0))));
    }
    if (sideLeave < span.tLeave)
    {
        vec3 p = o + d * sideLeave;
        span.tLeave = sideLeave;
        span.nLeave = normalize(vec3(p.xy, -slope * (r0 + slope * (p.z - z0))));
    }
    return span.tEnter <= span.tLeave;
}

/** The spans of the ray inside the shape's convex parts; returns how many (first, then second).
 * An arrow's shaft and head make one span where the ray goes from one into the other. */
int shapeSpans(vec3 o, vec3 d, float radius, float len, out Span first, out Span second)
{
    second = Span(INFINITE_DISTANCE, -INFINITE_DISTANCE, vec3(0.0), vec3(0.0));
#if defined(OSGGLYPHS_SHAPE_CYLINDER)
    return frustumSpan(o, d, 0.0, radius, len, radius, first) ? 1 : 0;
#elif defined(OSGGLYPHS_SHAPE_CONE)
    return frustumSpan(o, d, 0.0, radius, len, 0.0, first) ? 1 : 0;
#else
    float headStart = len * (1.0 - osgGlyphs_arrowParams.x);
    Span shaft, head;
    bool hitsShaft = frustumSpan(o, d, 0.0, radius, headStart, radius, shaft);
    bool hitsHead = frustumSpan(o, d, headStart, radius * osgGlyphs_arrowParams.y, len, 0.0, head);
    first = hitsShaft ? shaft : head;
    if (!hitsShaft || !hitsHead)
        return hitsShaft || hitsHead ? 1 : 0;
    if (max(shaft.tEnter, head.tEnter) <= min(shaft.tLeave, head.tLeave))
    {
        bool shaftFirst = shaft.tEnter <= head.tEnter, shaftLast = shaft.tLeave >= head.tLeave;
        first = Span(shaftFirst ? shaft.tEnter : head.tEnter, shaftLast ? shaft.tLeave : head.tLeave,
                     shaftFirst ? shaft.nEnter : head.nEnter, shaftLast ? shaft.nLeave : head.nLeave);
        return 1;
    }
    second = head;
    return 2;
#endif
}

#endif
