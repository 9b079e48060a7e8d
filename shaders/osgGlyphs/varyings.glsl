// osgGlyphs: what the impostor techniques hand the ray-casting fragment shader. The stage that
// writes them defines OSGGLYPHS_VARYINGS_OUT before including this file. A software rasteriser
// carries every one through each vertex of each glyph's primitive: they are kept few.

#ifdef OSGGLYPHS_VARYINGS_OUT
#define OSGGLYPHS_VARYING out
#else
#define OSGGLYPHS_VARYING in
#endif

#if defined(OSGGLYPHS_AXES_SHAPE) && !defined(OSGGLYPHS_SHAPE_SUPERQUADRIC)
#define OSGGLYPHS_QUADRIC_SHAPE 1
#endif

flat OSGGLYPHS_VARYING vec4 fragSphere; // eye-space centre (vector shapes: base), radius
flat OSGGLYPHS_VARYING vec4 fragColor;
#ifdef OSGGLYPHS_VECTOR_SHAPE
flat OSGGLYPHS_VARYING vec4 fragAxis; // unit axis, length
#endif
#ifdef OSGGLYPHS_AMBIENT_OCCLUSION
flat OSGGLYPHS_VARYING vec4 fragOcclusion; // Glyph.occlusion
#endif
#ifdef OSGGLYPHS_QUADRIC_SHAPE
flat OSGGLYPHS_VARYING vec3 fragQuadricDiagonal; // ellipsoidQuadric()
flat OSGGLYPHS_VARYING vec3 fragQuadricOffDiagonal;
#endif
#ifdef OSGGLYPHS_SHAPE_SUPERQUADRIC
flat OSGGLYPHS_VARYING mat3 fragInverseSemiAxes; // takes the semi-axes to the unit ones
flat OSGGLYPHS_VARYING vec4 fragSuperquadricPowers; // superquadricPowers()
#endif

#ifdef OSGGLYPHS_VARYINGS_OUT
/** The varyings of one glyph, computed once and written for each of its vertices. */
struct GlyphVaryings
{
    vec4 sphere;
    vec4 color;
    vec4 axis;
    vec4 occlusion;
#ifdef OSGGLYPHS_QUADRIC_SHAPE
    vec3 quadricDiagonal;
    vec3 quadricOffDiagonal;
#endif
#ifdef OSGGLYPHS_SHAPE_SUPERQUADRIC
    mat3 inverseSemiAxes;
    vec4 superquadricPowers;
#endif
};

GlyphVaryings glyphVaryings(Glyph glyph)
{
    GlyphVaryings varyings;
    varyings.sphere = glyph.sphere;
    varyings.color = glyph.color;
    varyings.axis = glyph.axis;
    varyings.occlusion = glyph.occlusion;
#ifdef OSGGLYPHS_QUADRIC_SHAPE
    ellipsoidQuadric(glyph.semiAxes, varyings.quadricDiagonal, varyings.quadricOffDiagonal);
#endif
#ifdef OSGGLYPHS_SHAPE_SUPERQUADRIC
    varyings.inverseSemiAxes = inverseSemiAxes(glyph.semiAxes);
    varyings.superquadricPowers = superquadricPowers(glyph.exponents);
#endif
    return varyings;
}

void writeVaryings(GlyphVaryings varyings)
{
    fragSphere = varyings.sphere;
    fragColor = varyings.color;
#ifdef OSGGLYPHS_VECTOR_SHAPE
    fragAxis = varyings.axis;
#endif
#ifdef OSGGLYPHS_AMBIENT_OCCLUSION
    fragOcclusion = varyings.occlusion;
#endif
#ifdef OSGGLYPHS_QUADRIC_SHAPE
    fragQuadricDiagonal = varyings.quadricDiagonal;
    fragQuadricOffDiagonal = varyings.quadricOffDiagonal;
#endif
#ifdef OSGGLYPHS_SHAPE_SUPERQUADRIC
    fragInverseSemiAxes = varyings.inverseSemiAxes;
    fragSuperquadricPowers = varyings.superquadricPowers;
#endif
}

void writeVaryings(Glyph glyph)
{
    writeVaryings(glyphVaryings(glyph));
}
#endif
