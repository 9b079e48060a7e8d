// osgGlyphsPaper: the glyphs of Aguirre, Gutierrez and Perrin (TPCG 2010), kept as a benchmark
// technique: a billboard per glyph, the sphere lit with the orthographic normal and given the
// depth of the paper's equation 1, the cone drawn from a base ellipse and two tangents with
// the billboard's flat depth.

/** Whether a point of the billboard, in units of the base radius with the base centre at the
  * origin and the projected axis along +y, lies on the cone; and its approximate normal
  * (x across, y along the projected axis, z towards the viewer). */
bool paperCone(vec2 p, float d, float h, out vec3 normal)
{
    // The base: the ellipse x^2 + y^2 / d^2 = 1 (equation 2, left).
    float ellipse = p.x * p.x + (d > 1e-6 ? p.y * p.y / (d * d) : (abs(p.y) < 1e-6 ? 0.0 : 2.0));
    // The sides: tangents from the apex (0, h) to the ellipse, touching it at y_t = d^2 / h.
    bool side = false;
    float across = 0.0;
    if (h > d)
    {
        float yt = d * d / h;
        float xt = sqrt(max(1.0 - yt * yt / max(d * d, 1e-12), 0.0));
        float halfWidth = xt * (h - p.y) / (h - yt);
        side = p.y > yt && p.y < h && abs(p.x) < halfWidth; // equation 3
        across = p.x / max(halfWidth, 1e-6);
    }
    if (side)
    {
        normal = normalize(vec3(across, 0.35, sqrt(max(1.0 - across * across, 0.0))));
        return true;
    }
    if (ellipse <= 1.0)
    {
        normal = vec3(0.0, -sqrt(max(1.0 - d * d, 0.0)), d);
        return true;
    }
    return false;
}

/** The paper's glyph at billboard point p: its eye-space normal and (spheres) window depth. */
bool paperGlyph(vec2 p, vec4 sphere, vec4 axis, vec4 frame, out vec3 normal, out float depth)
{
    depth = gl_FragCoord.z;
#ifdef OSGGLYPHS_VECTOR_SHAPE
    vec3 local;
    if (!paperCone(p, axis.x, axis.y, local))
        return false;
    normal = normalize(vec3(local.x * frame.xy + local.y * frame.zw, local.z));
    return true;
#else
    float r2 = dot(p, p);
    if (r2 > 1.0)
        return false;
    normal = vec3(p, sqrt(1.0 - r2)); // the orthographic normal (figure 2)
    // Equation 1, Z = f / (f - n) (1 - n / d), at the distance d of the lit point: the paper
    // prints f n / (f - n) as the factor, which does not reach 1 at the far plane.
    mat4 projection = gl_ProjectionMatrix;
    float n = projection[3][2] / (projection[2][2] - 1.0);
    float f = projection[3][2] / (projection[2][2] + 1.0);
    float d = -(sphere.z + sphere.w * normal.z);
    depth = f / (f - n) * (1.0 - n / d);
    return true;
#endif
}
