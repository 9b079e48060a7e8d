// osgGlyphs: OSG's clip planes (osg::ClipPlane, osg::ClipNode) cut glyphs along their true
// surface. Vertex stages clip no vertex of a glyph's primitive and drop only glyphs wholly on the
// removed side of a plane; impostor.frag cuts the rest per fragment and, where
// OSGGLYPHS_CLIP_CAPS is defined (setClipCaps), caps the cut with the plane.

// Bit i is set where GL_CLIP_PLANE0 + i is on; the cloud's cull traversal sets it, and defines
// OSGGLYPHS_CLIP_PLANES where any is on, so that glyphs drawn without clip planes pay nothing.
uniform int osgGlyphs_clipPlanes;

// The planes OSG and every GL implementation have: GL_MAX_CLIP_PLANES is at least 8.
const int MAX_CLIP_PLANES = 8;

bool isClipPlaneOn(int i)
{
    return (osgGlyphs_clipPlanes & (1 << i)) != 0;
}

/** Whether an eye-space sphere lies wholly on the removed side of a plane that is on. */
bool isClippedAway(vec4 sphere)
{
#ifdef OSGGLYPHS_CLIP_PLANES
    for (int i = 0; i < MAX_CLIP_PLANES; ++i)
    {
        vec4 plane = gl_ClipPlane[i];
        if (isClipPlaneOn(i) && dot(plane, vec4(sphere.xyz, 1.0)) < -sphere.w * length(plane.xyz))
            return true;
    }
#endif
    return false;
}
