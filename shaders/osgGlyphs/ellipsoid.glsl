// osgGlyphs: ellipsoids, exact: the bound of their projection and their ray intersection. An
// ellipsoid is its centre and the matrix A whose columns are its semi-axes, in eye space: the
// points centre + A u with |u| <= 1.

#ifdef OSGGLYPHS_AXES_SHAPE

/** The matrix that takes the ellipsoid to the unit sphere, A^-1: its semi-axes are orthogonal, so
 * its rows are the semi-axes over their squared lengths. */
mat3 inverseSemiAxes(mat3 semiAxes)
{
    return transpose(mat3(semiAxes[0] / dot(semiAxes[0], semiAxes[0]),
                          semiAxes[1] / dot(semiAxes[1], semiAxes[1]),
                          semiAxes[2] / dot(semiAxes[2], semiAxes[2])));
}

/** The 2x2 shape matrix S and centre m of the ellipse {x : (x - m)^T S^-1 (x - m) <= 1} that a
 * projective matrix makes of the ellipsoid in NDC xy, from the ellipsoid's dual quadric
 * Q* = [A A^T - c c^T, -c; -c^T, -1] (c the centre). On clip-space rows i, j and w, with
 * g = row^T A A^T row' and p = row . (c, 1):
 *   m_i = (g_iw - p_i p_w) / (g_ww - p_w^2),
 *   S_ij = (g_iw g_jw - g_ij g_ww + g_ij p_w^2 + p_i p_j g_ww - p_w (g_iw p_j + g_jw p_i))
 *          / (g_ww - p_w^2)^2,
 * the form in which the terms in p_i p_j p_w^2 have cancelled: the ellipse of a glyph far smaller
 * than its distance keeps its precision. Requires the ellipsoid to lie wholly in front of the eye. */
void projectedEllipse(vec3 centre, mat3 semiAxes, out vec2 m, out mat2 S)
{
    mat4 rows = transpose(gl_ProjectionMatrix);
    vec4 c = vec4(centre, 1.0);
    vec3 ax = rows[0].xyz * semiAxes, ay = rows[1].xyz * semiAxes, aw = rows[3].xyz * semiAxes;
    float gxx = dot(ax, ax), gxy = dot(ax, ay), gyy = dot(ay, ay);
    float gxw = dot(ax, aw), gyw = dot(ay, aw), gww = dot(aw, aw);
    float px = dot(rows[0], c), py = dot(rows[1], c), pw = dot(rows[3], c);
    float dww = gww - pw * pw;
    m = vec2(gxw - px * pw, gyw - py * pw) / dww;
    float sxx = gxw * gxw - gxx * gww + gxx * pw * pw + px * px * gww - 2.0 * pw * gxw * px;
    float syy = gyw * gyw - gyy * gww + gyy * pw * pw + py * py * gww - 2.0 * pw * gyw * py;
    float sxy = gxw * gyw - gxy * gww + gxy * pw * pw + px * py * gww - pw * (gxw * py + gyw * px);
    S = mat2(sxx, sxy, sxy, syy) / (dww * dww);
}

/** The smallest NDC depth over the ellipsoid: the plane row_z - s row_w of clip space that touches
 * it nearest, from the same dual quadric (see projectedEllipse). */
float nearestEllipsoidNdcZ(vec3 centre, mat3 semiAxes)
{
    mat4 rows = transpose(gl_ProjectionMatrix);
    vec4 c = vec4(centre, 1.0);
    vec3 az = rows[2].xyz * semiAxes, aw = rows[3].xyz * semiAxes;
    float gzz = dot(az, az), gzw = dot(az, aw), gww = dot(aw, aw);
    float pz = dot(rows[2], c), pw = dot(rows[3], c);
    float dzw = gzw - pz * pw, dww = gww - pw * pw;
    // dzw^2 - dzz dww with the terms in pz^2 pw^2 cancelled.
    float discriminant = gzw * gzw - 2.0 * gzw * pz * pw - gzz * gww + gzz * pw * pw + pz * pz * gww;
    float root = sqrt(max(discriminant, 0.0));
    return min((dzw - root) / dww, (dzw + root) / dww);
}

/** The four NDC corners (in strip order) of the rectangle along the axes of the ellipsoid's
 * projected ellipse that touches it on all four sides, and the NDC depth of its nearest point,
 * under any projective matrix. An ellipsoid that crosses the near plane covers the whole view, so
 * its cut is drawn; one wholly behind it returns false. */
bool ellipsoidScreenBound(vec3 centre, mat3 semiAxes, out vec2 corners[4], out float nearestNdcZ)
{
    mat4 p = gl_ProjectionMatrix;
    vec3 nearNormal = vec3(p[0][2] + p[0][3], p[1][2] + p[1][3], p[2][2] + p[2][3]);
    float reach = length(normalize(nearNormal) * semiAxes); // the half extent across the near plane
    float beyondNear = distanceBeyondNearPlane(centre);
    if (beyondNear < -reach)
        return false;
    if (beyondNear <= reach)
    {
        corners = vec2[4](vec2(-1.0, -1.0), vec2(1.0, -1.0), vec2(-1.0, 1.0), vec2(1.0, 1.0));
        nearestNdcZ = -1.0;
        return true;
    }
    vec2 m;
    mat2 S;
    projectedEllipse(centre, semiAxes, m, S);
    // The ellipse's axes: the eigenvectors of S, and its half extents along them.
    float angle = 0.5 * atan(2.0 * S[0][1], S[0][0] - S[1][1]);
    vec2 major = vec2(cos(angle), sin(angle)), minor = vec2(-major.y, major.x);
    vec2 halfMajor = major * sqrt(max(dot(major, S * major), 0.0));
    vec2 halfMinor = minor * sqrt(max(dot(minor, S * minor), 0.0));
    corners = vec2[4](m - halfMajor - halfMinor, m + halfMajor - halfMinor, m - halfMajor + halfMinor,
                      m + halfMajor + halfMinor);
    nearestNdcZ = max(nearestEllipsoidNdcZ(centre, semiAxes), -1.0);
    return true;
}

/** The ellipsoid's quadric Q = A^-T A^-1, which holds the points x with (x - centre)^T Q
 * (x - centre) <= 1: its diagonal and its elements xy, xz and yz. Six numbers, where A^-1 takes nine:
 * what a glyph hands its fragments costs a software rasteriser for each vertex. */
void ellipsoidQuadric(mat3 semiAxes, out vec3 diagonal, out vec3 offDiagonal)
{
    mat3 inverse = inverseSemiAxes(semiAxes);
    mat3 q = transpose(inverse) * inverse;
    diagonal = vec3(q[0][0], q[1][1], q[2][2]);
    offDiagonal = vec3(q[1][0], q[2][0], q[2][1]);
}

/** Where the ray origin + t * direction (unit) runs inside the ellipsoid (centre, ellipsoidQuadric()),
 * with the unit outward normals there; false if it misses. Solved from the point of the ray nearest
 * the centre in the quadric's metric. */
bool ellipsoidSpan(vec3 origin, vec3 direction, vec3 centre, vec3 diagonal, vec3 offDiagonal, out Span span)
{
    mat3 q = mat3(diagonal.x, offDiagonal.x, offDiagonal.y, offDiagonal.x, diagonal.y, offDiagonal.z, offDiagonal.y,
                  offDiagonal.z, diagonal.z);
    vec3 qd = q * direction;
    float a = dot(direction, qd), b = dot(origin - centre, qd) / a;
    vec3 closest = origin - centre - b * direction;
    // The gradient of (x - centre)^T Q (x - centre) / 2, Q (x - centre), is linear along the ray.
    vec3 qClosest = q * closest;
    float h2 = 1.0 - dot(closest, qClosest);
    if (h2 < 0.0)
        return false;
    float h = sqrt(h2 / a);
    // The far side's normal is shown only through a clip plane's cut.
    span = Span(-b - h, -b + h, normalize(qClosest - h * qd), vec3(0.0));
#ifdef OSGGLYPHS_CLIP_PLANES
    span.nLeave = normalize(qClosest + h * qd);
#endif
    return true;
}

#endif
