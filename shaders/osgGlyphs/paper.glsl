// osgGlyphs: the cone of Aguirre, Gutierrez and Perrin (TPCG 2010, section 4), kept as a
// benchmark technique: a billboard on which a base ellipse and two tangent lines are drawn,
// with approximate lighting and the billboard's own depth (no depth correction).

#ifdef OSGGLYPHS_PAPER

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

#endif
