// osgGlyphs: decodes a glyph's vertex attributes (declared in the generated attributes.glsl)
// into eye space.
//
// osgGlyphs_packed, one 32-bit word per glyph:
//   bits  0..15  radius / osgGlyphs_radiusScale as an IEEE half float (0: skip the glyph)
//   bits 16..31  scalar, quantised to 0..65535 over the data's own range
// osgGlyphs_radiusScalar replaces it with uncompressed attributes (OSGGLYPHS_FLOAT_ATTRIBUTES):
//   radius / osgGlyphs_radiusScale and the scalar in [0, 1] over the data's range, as floats
// osgGlyphs_color: RGBA8 per glyph (OSGGLYPHS_COLOR_RGBA only).
// osgGlyphs_vector: direction and magnitude per glyph (vector shapes only).
// osgGlyphs_axes, osgGlyphs_orientation: per ellipsoid or superquadric, its semi-axes as fractions
//   of its radius (xyz) and the quaternion (x, y, z, w) that turns its body axes into the model's;
//   a superquadric's exponents e1, e2 as the high and low bytes of 16 bits (w), e = byte / 127.
// osgGlyphs_ambientOcclusion: RGBA8 per glyph (OSGGLYPHS_AMBIENT_OCCLUSION only): rgb the model-space
//   direction term of the light reaching the glyph, mapped from [-1, 1], a its mean.
// osgGlyphs_position: the glyph's position, for instanced techniques (else gl_Vertex); with
//   OSGGLYPHS_COMPRESSED_POSITIONS, 16-bit integers q on the grid osgGlyphs_positionGrid:
//   position = offset + q * step (xyz offset, w step; a power of two, so the product is exact).
// Vertex stages only.

#include "glyph.glsl"
#include "attributes.glsl"

uniform float osgGlyphs_radiusScale;
uniform vec4 osgGlyphs_baseColor;
#ifdef OSGGLYPHS_COMPRESSED_POSITIONS
uniform vec4 osgGlyphs_positionGrid;
#endif
#ifdef OSGGLYPHS_COLOR_SCALAR
uniform sampler1D osgGlyphs_colormap;
uniform vec2 osgGlyphs_scalarToColormap; // colormap coordinate = quantised * x + y
#endif

float decodeHalf(uint bits)
{
    uint exponent = (bits >> 10u) & 31u;
    uint mantissa = bits & 1023u;
    if (exponent == 0u)
        return float(mantissa) * (1.0 / 16777216.0);
    return uintBitsToFloat(((bits & 32768u) << 16u) | ((exponent + 112u) << 23u) | (mantissa << 13u));
}

float glyphRadius()
{
#ifdef OSGGLYPHS_FLOAT_ATTRIBUTES
    return osgGlyphs_radiusScalar.x * osgGlyphs_radiusScale;
#else
    return decodeHalf(osgGlyphs_packed & 65535u) * osgGlyphs_radiusScale;
#endif
}

#ifdef OSGGLYPHS_COLOR_SCALAR
/** Where the glyph's scalar falls on the colour map, in [0, 1]. */
float colormapCoordinate()
{
#ifdef OSGGLYPHS_FLOAT_ATTRIBUTES
    float scalar = osgGlyphs_radiusScalar.y;
#else
    float scalar = float(osgGlyphs_packed >> 16u) * (1.0 / 65535.0);
#endif
    return clamp(scalar * osgGlyphs_scalarToColormap.x + osgGlyphs_scalarToColormap.y, 0.0, 1.0);
}
#endif

vec4 glyphColor()
{
#if defined(OSGGLYPHS_COLOR_SCALAR)
    float t = colormapCoordinate();
    // Texel i holds the map at i / (size - 1): sample between the first and last texel centres.
    float size = float(textureSize(osgGlyphs_colormap, 0));
    return texture(osgGlyphs_colormap, (t * (size - 1.0) + 0.5) / size);
#elif defined(OSGGLYPHS_COLOR_RGBA)
    return osgGlyphs_color;
#else
    return osgGlyphs_baseColor;
#endif
}

vec4 glyphPosition()
{
#ifdef OSGGLYPHS_PER_INSTANCE
    vec3 position = osgGlyphs_position;
#else
    vec3 position = gl_Vertex.xyz;
#endif
#ifdef OSGGLYPHS_COMPRESSED_POSITIONS
    position = osgGlyphs_positionGrid.xyz + position * osgGlyphs_positionGrid.w;
#endif
    return vec4(position, 1.0);
}

#ifdef OSGGLYPHS_AXES_SHAPE
/** The rotation of a unit quaternion (x, y, z, w). */
mat3 rotationOf(vec4 q)
{
    vec3 twice = 2.0 * q.xyz;
    float xx = q.x * twice.x, yy = q.y * twice.y, zz = q.z * twice.z;
    float xy = q.x * twice.y, xz = q.x * twice.z, yz = q.y * twice.z;
    float wx = q.w * twice.x, wy = q.w * twice.y, wz = q.w * twice.z;
    return mat3(1.0 - yy - zz, xy + wz, xz - wy, xy - wz, 1.0 - xx - zz, yz + wx, xz + wy, yz - wx, 1.0 - xx - yy);
}
#endif

#ifdef OSGGLYPHS_SHAPE_SUPERQUADRIC
/** The exponents (e1, e2) of a superquadric, packed as two bytes in 16 bits of its axes attribute. */
vec2 unpackExponents(float packedWord)
{
    float word = floor(packedWord * 65535.0 + 0.5);
    float high = floor(word / 256.0);
    return vec2(high, word - 256.0 * high) / 127.0;
}
#endif

Glyph decodeGlyph()
{
    Glyph glyph;
    vec3 center = (gl_ModelViewMatrix * glyphPosition()).xyz;
    // A glyph scales with the model-view transform (uniform scale assumed).
    float scale = length(gl_ModelViewMatrix[0].xyz);
    glyph.sphere = vec4(center, glyphRadius() * scale);
    glyph.axis = vec4(0.0);
    glyph.color = glyphColor();
    glyph.occlusion = vec4(0.0, 0.0, 0.0, 1.0);
#ifdef OSGGLYPHS_AMBIENT_OCCLUSION
    glyph.occlusion = vec4(mat3(gl_ModelViewMatrix) * (osgGlyphs_ambientOcclusion.xyz * 2.0 - 1.0) / scale,
                           osgGlyphs_ambientOcclusion.w);
#endif
#ifdef OSGGLYPHS_VECTOR_SHAPE
    vec3 vector = mat3(gl_ModelViewMatrix) * osgGlyphs_vector;
    float magnitude = length(vector);
    float len = osgGlyphs_vectorParams.y > 0.5 ? osgGlyphs_vectorParams.x * scale : osgGlyphs_vectorParams.x * magnitude;
    if (!(magnitude > 0.0) || !(len > 0.0))
        glyph.sphere.w = 0.0; // no direction: not drawn
    vec3 axis = vector / magnitude;
    glyph.sphere.xyz = center - axis * (len * osgGlyphs_vectorParams.z);
    glyph.axis = vec4(axis, len);
#endif
#ifdef OSGGLYPHS_AXES_SHAPE
    float rotationLength = length(osgGlyphs_orientation);
    if (!(rotationLength > 0.0))
        glyph.sphere.w = 0.0; // no rotation: not drawn
    vec3 semiAxes = osgGlyphs_axes.xyz * glyphRadius();
    glyph.semiAxes = mat3(gl_ModelViewMatrix) * rotationOf(osgGlyphs_orientation / rotationLength) *
                     mat3(semiAxes.x, 0.0, 0.0, 0.0, semiAxes.y, 0.0, 0.0, 0.0, semiAxes.z);
#endif
#ifdef OSGGLYPHS_SHAPE_SUPERQUADRIC
    glyph.exponents = unpackExponents(osgGlyphs_axes.w);
#endif
    return glyph;
}

/** Puts this vertex outside the clip volume, so that its primitive draws nothing. */
void hideVertex()
{
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
    gl_PointSize = 0.0;
}
