// osgGlyphs: what reaches the fragment shader. OSGGLYPHS_VARYING is "out" in the stage that
// writes these and "in" in the fragment shader.

flat OSGGLYPHS_VARYING vec4 fragSphere; // eye-space centre (vector shapes: base), radius
flat OSGGLYPHS_VARYING vec4 fragAxis;   // vector shapes: unit axis, length
flat OSGGLYPHS_VARYING vec4 fragColor;
#ifdef OSGGLYPHS_RAYCAST
#ifdef OSGGLYPHS_TECHNIQUE_SPRITE
flat OSGGLYPHS_VARYING vec4 fragSprite; // NDC centre and half size of the point sprite
#else
noperspective OSGGLYPHS_VARYING vec3 fragRayNear; // eye-space point on the near plane under this fragment
noperspective OSGGLYPHS_VARYING vec3 fragRayFar;  // and on the far plane
#endif
#endif
#if defined(OSGGLYPHS_TECHNIQUE_PAPER) || defined(OSGGLYPHS_TECHNIQUE_POLYGONS)
OSGGLYPHS_VARYING vec3 fragLocal; // paper: billboard coordinates; polygons: eye-space normal
flat OSGGLYPHS_VARYING vec4 fragFrame; // paper cones: the billboard's eye-space x and y directions
#endif
#ifdef OSGGLYPHS_TECHNIQUE_TEXTURE_MULTI
flat OSGGLYPHS_VARYING float fragLayer; // the layer of the glyph's pre-lit sprite
#endif
