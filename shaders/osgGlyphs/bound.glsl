// osgGlyphs: the screen-space bound of a glyph, shared by every technique that ray-casts.

#include "occlusion.glsl"
#include "clip.glsl"
#include "peel.glsl"

// True when the framebuffer has one sample per pixel, at its centre (no multisampling).
uniform bool osgGlyphs_singleSample;

/** Whether a rectangle with these NDC corners (in strip order) can cover a sample. Single-sampled,
  * it must hold a pixel centre: most glyphs of a million-point cloud are smaller than a pixel
  * and fall between centres, and skipping them saves the rasteriser their primitives. A
  * rectangle whose bounding box holds at most 2x2 centres has each of them tested, since a
  * slanted one can miss the centres of its box. */
bool coversASample(vec2 corners[4])
{
    if (!osgGlyphs_singleSample)
        return true;
    vec2 toPixels = 0.5 * osgGlyphs_viewport.zw;
    vec2 origin = (corners[0] + 1.0) * toPixels;
    vec2 edge1 = (corners[1] - corners[0]) * toPixels;
    vec2 edge2 = (corners[2] - corners[0]) * toPixels;
    vec2 lo = min(min(origin, origin + edge1), min(origin + edge2, origin + edge1 + edge2));
    vec2 hi = max(max(origin, origin + edge1), max(origin + edge2, origin + edge1 + edge2));
    const float margin = 1e-3; // pixels, for rounding
    vec2 firstCentre = ceil(lo - 0.5 - margin);
    vec2 lastCentre = floor(hi - 0.5 + margin);
    if (any(greaterThan(firstCentre, lastCentre)))
        return false;
    if (any(greaterThan(lastCentre - firstCentre, vec2(1.0))))
        return true;
    // The centre's coordinates along the edges, s and t in [0, 1] inside, scaled by the area.
    float area = edge1.x * edge2.y - edge1.y * edge2.x;
    vec2 areaMargin = margin * vec2(length(edge2), length(edge1));
    for (int k = 0; k < 4; ++k)
    {
        vec2 centre = firstCentre + vec2(k & 1, k >> 1);
        vec2 d = centre + 0.5 - origin;
        vec2 st = vec2(d.x * edge2.y - d.y * edge2.x, edge1.x * d.y - edge1.y * d.x);
        if (all(lessThanEqual(centre, lastCentre)) && all(greaterThanEqual(st, -areaMargin)) &&
            all(lessThanEqual(st, area + areaMargin)))
            return true;
    }
    return false;
}

/** Keeps every vertex of the glyph's primitive from OSG's clip planes: glyphs are cut per
 * fragment (clip.glsl). The last vertex stage calls it. */
void keepVertexFromClipPlanes()
{
    gl_ClipDistance[0] = 1.0;
    gl_ClipDistance[1] = 1.0;
    gl_ClipDistance[2] = 1.0;
    gl_ClipDistance[3] = 1.0;
    gl_ClipDistance[4] = 1.0;
    gl_ClipDistance[5] = 1.0;
    gl_ClipDistance[6] = 1.0;
    gl_ClipDistance[7] = 1.0;
}

#if defined(OSGGLYPHS_DEPTH_PEEL) && !defined(OSGGLYPHS_VECTOR_SHAPE) && !defined(OSGGLYPHS_AXES_SHAPE)
// The most pixel centres per axis that a sphere's rectangle may hold for its vertex stage to
// ray-cast them against the previous layer; larger spheres are left to the fragments.
const float PEEL_TEST_CENTRES = 4.0;

/** Depth peeling: whether a small sphere, inside a rectangle with these NDC corners, is peeled
 * away at every pixel centre it covers, so that it needs no primitive in this layer. The centres
 * are ray-cast as impostor.frag does (from the near plane, the same arithmetic), so the answer is
 * the fragments' own: small glyphs are what rasterising costs, and from the second layer on most
 * of a sparse cloud's are peeled away whole. Clip planes, which move the drawn point, and
 * multisampling leave every glyph to the fragments. */
bool isPeeledAwaySphere(vec4 sphere, vec2 corners[4])
{
    if (osgGlyphs_clipPlanes != 0 || !osgGlyphs_singleSample)
        return false;
    vec2 toPixels = 0.5 * osgGlyphs_viewport.zw;
    vec2 lo = (min(min(corners[0], corners[1]), min(corners[2], corners[3])) + 1.0) * toPixels;
    vec2 hi = (max(max(corners[0], corners[1]), max(corners[2], corners[3])) + 1.0) * toPixels;
    const float margin = 1e-2; // pixels: centres on the rectangle's edge are tested too
    vec2 firstCentre = ceil(lo - 0.5 - margin);
    vec2 lastCentre = floor(hi - 0.5 + margin);
    if (any(greaterThan(lastCentre - firstCentre, vec2(PEEL_TEST_CENTRES - 1.0))))
        return false;
    for (float y = firstCentre.y; y <= lastCentre.y; ++y)
        for (float x = firstCentre.x; x <= lastCentre.x; ++x)
        {
            vec2 window = osgGlyphs_viewport.xy + vec2(x, y) + 0.5;
            vec2 ndc = (window - osgGlyphs_viewport.xy) / osgGlyphs_viewport.zw * 2.0 - 1.0;
            vec3 origin = unprojectNdc(vec3(ndc, -1.0));
            vec3 direction = normalize(unprojectNdc(vec3(ndc, 1.0)) - origin);
            float tEnter, tLeave;
            if (!intersectSphere(origin, direction, sphere, tEnter, tLeave))
                continue;
            float t = max(tEnter, 0.0);
            if (t > tLeave)
                continue;
            float ndcZ = ndcDepth(origin + direction * t);
            if (ndcZ <= 1.0 && !isPeeledAway(ivec2(window), windowDepth(ndcZ)))
                return false;
        }
    return true;
}
#endif

#ifdef OSGGLYPHS_AXES_SHAPE
/** The axis-aligned box of the ellipse inscribed in a rectangle (NDC corners in strip order): its
 * half extents are those of S = a a^T + b b^T, a and b the rectangle's half sides. Ellipsoids lie
 * in that ellipse, and superquadrics too (their rectangle is their bounding ellipsoid's, or
 * axis-aligned, when the box is the rectangle): the occlusion test of a turned ellipse reads fewer
 * of the pyramid's texels than over its rectangle's box (5% fewer fragments at 300k dense
 * ellipsoids). */
vec2[4] inscribedEllipseBox(vec2 corners[4])
{
    vec2 middle = 0.5 * (corners[0] + corners[3]);
    vec2 halfSide = 0.5 * (corners[1] - corners[0]), otherHalfSide = 0.5 * (corners[2] - corners[0]);
    vec2 reach = sqrt(halfSide * halfSide + otherHalfSide * otherHalfSide);
    return vec2[4](middle - reach, vec2(middle.x + reach.x, middle.y - reach.y),
                   vec2(middle.x - reach.x, middle.y + reach.y), middle + reach);
}
#endif

/** Four NDC corners (in triangle-strip order) of a rectangle that contains the glyph, and the
  * NDC depth of its nearest point; false when the glyph is wholly behind the near plane or on
  * the removed side of a clip plane, covers no sample or lies behind what is drawn (isOccluded). */
bool glyphBound(Glyph glyph, out vec2 corners[4], out float nearestNdcZ)
{
#ifdef OSGGLYPHS_VECTOR_SHAPE
    vec4 enclosing = vectorBoundingSphere(glyph.sphere.xyz, glyph.axis.xyz, glyph.axis.w, glyph.sphere.w);
#else
    vec4 enclosing = glyph.sphere;
#endif
    if (isClippedAway(enclosing))
        return false;
#ifdef OSGGLYPHS_VECTOR_SHAPE
    if (!vectorScreenBound(glyph.sphere.xyz, glyph.axis.xyz, glyph.axis.w, glyph.sphere.w, corners, nearestNdcZ))
        return false;
#elif defined(OSGGLYPHS_SHAPE_SUPERQUADRIC)
    if (!superquadricScreenBound(glyph.sphere.xyz, glyph.semiAxes, glyph.exponents, corners, nearestNdcZ))
        return false;
#elif defined(OSGGLYPHS_AXES_SHAPE)
    if (!ellipsoidScreenBound(glyph.sphere.xyz, glyph.semiAxes, corners, nearestNdcZ))
        return false;
#else
    vec4 box;
    if (!sphereScreenBound(glyph.sphere.xyz, glyph.sphere.w, box, nearestNdcZ))
        return false;
    corners = vec2[4](box.xy, box.zy, box.xw, box.zw);
#endif
    vec2 occlusionBox[4] = corners;
#ifdef OSGGLYPHS_AXES_SHAPE
    occlusionBox = inscribedEllipseBox(corners);
#endif
    if (!coversASample(corners) || isOccluded(occlusionBox, nearestNdcZ))
        return false;
#if defined(OSGGLYPHS_DEPTH_PEEL) && !defined(OSGGLYPHS_VECTOR_SHAPE) && !defined(OSGGLYPHS_AXES_SHAPE)
    if (isPeeledAwaySphere(glyph.sphere, corners))
        return false;
#endif
    return true;
}
