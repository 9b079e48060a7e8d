// osgGlyphs: what the impostor techniques hand the ray-casting fragment shader. The stage that
// writes them defines OSGGLYPHS_VARYINGS_OUT before including this file.

#ifdef OSGGLYPHS_VARYINGS_OUT
#define OSGGLYPHS_VARYING out
#else
#define OSGGLYPHS_VARYING in
#endif

flat OSGGLYPHS_VARYING vec4 fragSphere; // eye-space centre (vector shapes: base), radius
flat OSGGLYPHS_VARYING vec4 fragColor;
#ifdef OSGGLYPHS_VECTOR_SHAPE
flat OSGGLYPHS_VARYING vec4 fragAxis; // unit axis, length
#endif
#ifdef OSGGLYPHS_AMBIENT_OCCLUSION
flat OSGGLYPHS_VARYING vec4 fragOcclusion; // Glyph.occlusion
#endif
#ifdef OSGGLYPHS_AXES_SHAPE
flat OSGGLYPHS_VARYING mat3 fragInverseSemiAxes; // takes the ellipsoid to the unit sphere
#endif
#ifdef OSGGLYPHS_SHAPE_SUPERQUADRIC
flat OSGGLYPHS_VARYING vec2 fragExponents;
flat OSGGLYPHS_VARYING vec4 fragSuperquadricPowers;
#endif

#ifdef OSGGLYPHS_VARYINGS_OUT
void writeVaryings(Glyph glyph)
{
    fragSphere = glyph.sphere;
    fragColor = glyph.color;
#ifdef OSGGLYPHS_VECTOR_SHAPE
    fragAxis = glyph.axis;
#endif
#ifdef OSGGLYPHS_AMBIENT_OCCLUSION
    fragOcclusion = glyph.occlusion;
#endif
#ifdef OSGGLYPHS_AXES_SHAPE
    fragInverseSemiAxes = inverseSemiAxes(glyph.semiAxes);
#endif
#ifdef OSGGLYPHS_SHAPE_SUPERQUADRIC
    fragExponents = glyph.exponents;
    fragSuperquadricPowers = superquadricPowers(glyph.exponents);
#endif
}
#endif
