// osgGlyphs: Blinn-Phong under OSG's light 0 (the view's headlight or an osg::LightSource).

uniform vec3 osgGlyphs_material; // ambient, specular strength, shininess

#ifdef OSGGLYPHS_SHADOWS
// osgShadow's shadow map and the texture unit whose eye-linear TexGen planes map eye space to it
// (osgGlyphs::setGlyphShadows).
uniform sampler2DShadow osgGlyphs_shadowMap;
uniform int osgGlyphs_shadowUnit;

/** The fraction of light 0 that reaches a surface point (eye space, unit normal): 1 lit, 0 in
  * shadow. The point is looked up moved out along its normal by two shadow-map texels, so that a
  * glyph does not shadow itself where the map holds its own surface. */
float lightReaching(vec3 position, vec3 normal)
{
    int unit = osgGlyphs_shadowUnit;
    vec4 s = gl_EyePlaneS[unit], t = gl_EyePlaneT[unit], q = gl_EyePlaneQ[unit];
    vec4 point = vec4(position, 1.0);
    float w = dot(q, point);
    // Eye-space length of a texel: the gradients of the map's s/q and t/q at the point.
    vec3 sRate = (s.xyz * w - q.xyz * dot(s, point)) / (w * w);
    vec3 tRate = (t.xyz * w - q.xyz * dot(t, point)) / (w * w);
    vec2 size = vec2(textureSize(osgGlyphs_shadowMap, 0));
    float texel = max(1.0 / (size.x * length(sRate)), 1.0 / (size.y * length(tRate)));
    point.xyz += normal * (2.0 * texel);
    vec4 coord = vec4(dot(s, point), dot(t, point), dot(gl_EyePlaneR[unit], point), dot(q, point));
    return textureProj(osgGlyphs_shadowMap, coord);
}
#endif

/** The lit colour of a surface point; normal and toEye are unit eye-space vectors; ambientLight is
 * the fraction of ambient and diffuse light that occluders let through (1: none occluded). */
vec3 shade(vec3 base, vec3 position, vec3 normal, vec3 toEye, float ambientLight)
{
#ifdef OSGGLYPHS_LIT
    vec4 light = gl_LightSource[0].position;
    vec3 toLight = light.w == 0.0 ? normalize(light.xyz) : normalize(light.xyz - position);
    float diffuse = max(dot(normal, toLight), 0.0);
    float specular = 0.0;
    if (diffuse > 0.0)
        specular = pow(max(dot(normal, normalize(toLight + toEye)), 0.0), osgGlyphs_material.z);
#ifdef OSGGLYPHS_SHADOWS
    if (diffuse > 0.0)
    {
        float reaching = lightReaching(position, normal);
        diffuse *= reaching;
        specular *= reaching;
    }
#endif
    vec3 ambient = vec3(osgGlyphs_material.x) + gl_LightSource[0].ambient.rgb;
    return base * ambientLight * (ambient + diffuse * gl_LightSource[0].diffuse.rgb) +
           osgGlyphs_material.y * specular * gl_LightSource[0].specular.rgb;
#else
    return base;
#endif
}

vec3 shade(vec3 base, vec3 position, vec3 normal, vec3 toEye)
{
    return shade(base, position, normal, toEye, 1.0);
}
