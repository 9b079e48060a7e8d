#version 330 compatibility
// osgGlyphs, the full-screen passes of osgGlyphs::ScreenEffects. The composite puts the colour
// and depth its children were drawn into back into the view, with screen-space ambient occlusion
// and outlines, both computed from the depth alone, and writes the children's depth as the view's
// projection has it, so that what is drawn outside the node depth-tests against them. Under
// OSGGLYPHS_SCREEN_OCCLUSION_PASS, the pass before it writes each pixel's occlusion, which the
// composite blurs.

#pragma import_defines(OSGGLYPHS_SCREEN_AMBIENT_OCCLUSION, OSGGLYPHS_SCREEN_OUTLINES, OSGGLYPHS_SCREEN_OCCLUSION_PASS)

uniform sampler2D osgGlyphs_effectsColor;
uniform sampler2D osgGlyphs_effectsDepth;
/** The occlusion pass's output: the light each pixel receives. */
uniform sampler2D osgGlyphs_effectsOcclusion;
/** The view's viewport (x, y, width, height): the textures cover it pixel for pixel. */
uniform vec4 osgGlyphs_effectsViewport;
/** The projection the children were drawn with, and its inverse. */
uniform mat4 osgGlyphs_effectsProjection;
uniform mat4 osgGlyphs_effectsInverseProjection;

uniform float osgGlyphs_occlusionRadius;
uniform float osgGlyphs_occlusionStrength;
uniform int osgGlyphs_occlusionSamples;

uniform float osgGlyphs_outlineWidth;
uniform vec4 osgGlyphs_outlineColor;

out vec4 color;

ivec2 viewSize;

float depthAt(ivec2 pixel)
{
    return texelFetch(osgGlyphs_effectsDepth, clamp(pixel, ivec2(0), viewSize - 1), 0).r;
}

/** The view-space point of window depth depth seen through a point of the texture (in pixels). */
vec3 viewPosition(vec2 point, float depth)
{
    vec4 ndc = vec4(point / vec2(viewSize) * 2.0 - 1.0, depth * 2.0 - 1.0, 1.0);
    vec4 view = osgGlyphs_effectsInverseProjection * ndc;
    return view.xyz / view.w;
}

/** The view-space z of a pixel's centre at a window depth. */
float viewZ(ivec2 pixel, float depth)
{
    return viewPosition(vec2(pixel) + 0.5, depth).z;
}

/** How wide a pixel is in view-space units at view-space depth z. */
float pixelSize(float z)
{
    mat4 p = osgGlyphs_effectsProjection;
    float w = p[2][3] * z + p[3][3];
    return 2.0 * abs(w) / (p[0][0] * float(viewSize.x));
}

#ifdef OSGGLYPHS_SCREEN_AMBIENT_OCCLUSION

/** The surface normal at a pixel from its neighbours' points: on each axis the neighbour whose
 * depth is nearer to the pixel's, so that a silhouette does not bend it. */
vec3 surfaceNormal(ivec2 pixel, vec3 p)
{
    vec3 left = viewPosition(vec2(pixel) + vec2(-0.5, 0.5), depthAt(pixel - ivec2(1, 0)));
    vec3 right = viewPosition(vec2(pixel) + vec2(1.5, 0.5), depthAt(pixel + ivec2(1, 0)));
    vec3 below = viewPosition(vec2(pixel) + vec2(0.5, -0.5), depthAt(pixel - ivec2(0, 1)));
    vec3 above = viewPosition(vec2(pixel) + vec2(0.5, 1.5), depthAt(pixel + ivec2(0, 1)));
    vec3 dx = abs(right.z - p.z) < abs(p.z - left.z) ? right - p : p - left;
    vec3 dy = abs(above.z - p.z) < abs(p.z - below.z) ? above - p : p - below;
    vec3 n = normalize(cross(dx, dy));
    return n.z < 0.0 ? -n : n;
}

/** A value in [0, 1) per pixel, fixed on the screen (it does not flicker): 16 evenly spread
 * values over each 4x4 pixels (a Bayer matrix), which the composite's blur averages. */
float screenNoise(ivec2 pixel)
{
    const int BAYER[16] = int[16](0, 8, 2, 10, 12, 4, 14, 6, 3, 11, 1, 9, 15, 7, 13, 5);
    return (float(BAYER[(pixel.y & 3) * 4 + (pixel.x & 3)]) + 0.5) / 16.0;
}

/** The fraction of the cosine-weighted hemisphere around the normal at p that is open: samples
 * at up to the radius from p that lie behind the surface seen through them are occluded, unless
 * that surface lies more than the radius in front of them (a nearer object, not a neighbour). */
float ambientLight(ivec2 pixel, vec3 p)
{
    vec3 n = surfaceNormal(pixel, p);
    vec3 helper = abs(n.z) < 0.999 ? vec3(0.0, 0.0, 1.0) : vec3(1.0, 0.0, 0.0);
    vec3 t = normalize(cross(helper, n));
    vec3 b = cross(n, t);
    float noise = screenNoise(pixel);
    float turn = 6.2831853 * noise;
    float radius = osgGlyphs_occlusionRadius;
    float bias = 0.02 * radius + 2.0 * pixelSize(p.z);
    int samples = osgGlyphs_occlusionSamples;
    float occluded = 0.0;
    for (int i = 0; i < samples; ++i)
    {
        float k = (float(i) + 0.5) / float(samples);
        float sinTheta = sqrt(k), cosTheta = sqrt(1.0 - k);
        float phi = float(i) * 2.3999632 + turn;
        vec3 direction = (t * cos(phi) + b * sin(phi)) * sinTheta + n * cosTheta;
        float reach = radius * mix(0.15, 1.0, fract(float(i) * 0.618034 + noise));
        vec3 s = p + direction * reach;
        vec4 clip = osgGlyphs_effectsProjection * vec4(s, 1.0);
        vec2 point = (clip.xy / clip.w * 0.5 + 0.5) * vec2(viewSize);
        if (any(lessThan(point, vec2(0.0))) || any(greaterThanEqual(point, vec2(viewSize))))
            continue;
        float depth = depthAt(ivec2(point));
        if (depth >= 1.0)
            continue;
        float seen = viewPosition(floor(point) + 0.5, depth).z;
        float inFront = seen - s.z;
        occluded += inFront >= bias ? 1.0 - smoothstep(radius, 2.0 * radius, inFront) : 0.0;
    }
    return 1.0 - occluded / float(samples);
}

/** The light of the occlusion pass averaged over the 4x4 pixels of the sample pattern around
 * the pixel, over those whose surface lies within a tenth of the radius of the pixel's (across a
 * silhouette the light of another surface does not bleed). */
float blurredAmbientLight(ivec2 pixel, float z)
{
    float tolerance = max(0.1 * osgGlyphs_occlusionRadius, 2.0 * pixelSize(z));
    float sum = 0.0, count = 0.0;
    for (int y = -2; y < 2; ++y)
    {
        for (int x = -2; x < 2; ++x)
        {
            ivec2 neighbour = clamp(pixel + ivec2(x, y), ivec2(0), viewSize - 1);
            float depth = depthAt(neighbour);
            if (depth >= 1.0 || abs(viewZ(neighbour, depth) - z) > tolerance)
                continue;
            sum += texelFetch(osgGlyphs_effectsOcclusion, neighbour, 0).r;
            count += 1.0;
        }
    }
    return count > 0.0 ? sum / count : 1.0;
}

#endif

#ifdef OSGGLYPHS_SCREEN_OUTLINES

/** How much a pixel belongs to an outline, from 0 to 1. Along four axes through the pixel, the
 * chord between its neighbours at the outline's width, interpolated in window depth (exact for
 * planes under both projections), is compared with the pixel's depth: a pixel in front of the
 * chord is at a silhouette or a convex edge, one behind it at a crease where surfaces meet,
 * unless the chord lies so far in front that it passes over an occluder's silhouette. */
float outline(ivec2 pixel, float depth, vec3 p)
{
    const float CREASE = 0.3, RIDGE = 1.5, JUMP = 4.0;
    float width = osgGlyphs_outlineWidth;
    float footprint = width * pixelSize(p.z);
    const vec2 AXES[4] = vec2[4](vec2(1.0, 0.0), vec2(0.0, 1.0), vec2(0.7071068, 0.7071068),
                                 vec2(0.7071068, -0.7071068));
    float edge = 0.0;
    for (int i = 0; i < 4; ++i)
    {
        ivec2 offset = ivec2(round(AXES[i] * width));
        float chord = 0.5 * (depthAt(pixel + offset) + depthAt(pixel - offset));
        float ahead = (p.z - viewZ(pixel, chord)) / footprint;
        edge = max(edge, smoothstep(RIDGE, 2.0 * RIDGE, ahead));
        edge = max(edge, smoothstep(CREASE, 2.0 * CREASE, -ahead) * (1.0 - smoothstep(JUMP, 2.0 * JUMP, -ahead)));
    }
    return edge;
}

#endif

#ifdef OSGGLYPHS_SCREEN_OCCLUSION_PASS

void main()
{
    viewSize = ivec2(osgGlyphs_effectsViewport.zw);
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    float depth = depthAt(pixel);
    color = vec4(depth >= 1.0 ? 1.0 : ambientLight(pixel, viewPosition(vec2(pixel) + 0.5, depth)));
}

#else

void main()
{
    viewSize = ivec2(osgGlyphs_effectsViewport.zw);
    ivec2 pixel = ivec2(gl_FragCoord.xy - osgGlyphs_effectsViewport.xy);
    float depth = depthAt(pixel);
    if (depth >= 1.0)
        discard;
    vec3 p = viewPosition(vec2(pixel) + 0.5, depth);
    color = texelFetch(osgGlyphs_effectsColor, pixel, 0);
#ifdef OSGGLYPHS_SCREEN_AMBIENT_OCCLUSION
    color.rgb *= mix(1.0, blurredAmbientLight(pixel, p.z), osgGlyphs_occlusionStrength);
#endif
#ifdef OSGGLYPHS_SCREEN_OUTLINES
    // Over the pixel, which may be transparent (premultiplied): an outline covers what is behind.
    float cover = osgGlyphs_outlineColor.a * outline(pixel, depth, p);
    color = vec4(osgGlyphs_outlineColor.rgb * cover, cover) + color * (1.0 - cover);
#endif
    vec4 clip = gl_ProjectionMatrix * vec4(p, 1.0);
    gl_FragDepth = 0.5 * (gl_DepthRange.diff * clip.z / clip.w + gl_DepthRange.near + gl_DepthRange.far);
}

#endif
