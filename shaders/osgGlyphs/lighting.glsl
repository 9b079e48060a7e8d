// osgGlyphs: Blinn-Phong under OSG's light 0 (the view's headlight or an osg::LightSource).

uniform vec3 osgGlyphs_material; // ambient, specular strength, shininess

/** The lit colour of a surface point; normal and toEye are unit eye-space vectors. */
vec3 shade(vec3 base, vec3 position, vec3 normal, vec3 toEye)
{
#ifdef OSGGLYPHS_LIT
    vec4 light = gl_LightSource[0].position;
    vec3 toLight = light.w == 0.0 ? normalize(light.xyz) : normalize(light.xyz - position);
    float diffuse = max(dot(normal, toLight), 0.0);
    float specular = 0.0;
    if (diffuse > 0.0)
        specular = pow(max(dot(normal, normalize(toLight + toEye)), 0.0), osgGlyphs_material.z);
    vec3 ambient = vec3(osgGlyphs_material.x) + gl_LightSource[0].ambient.rgb;
    return base * (ambient + diffuse * gl_LightSource[0].diffuse.rgb) +
           osgGlyphs_material.y * specular * gl_LightSource[0].specular.rgb;
#else
    return base;
#endif
}
