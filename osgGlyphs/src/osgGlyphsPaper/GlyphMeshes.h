/* osgGlyphsPaper - private: unit meshes of the glyph shapes for the polygons technique. Not installed. */

#ifndef OSGGLYPHS_GLYPHMESHES_H
#define OSGGLYPHS_GLYPHMESHES_H 1

#include <osgGlyphs/GlyphStyle>

#include <osg/Array>
#include <osg/PrimitiveSet>

namespace osgGlyphsPaper
{
namespace detail
{

/** A triangle mesh with per-vertex normals. */
struct GlyphMesh
{
    osg::ref_ptr<osg::Vec3Array> vertices;
    osg::ref_ptr<osg::Vec3Array> normals;
    osg::ref_ptr<osg::DrawElementsUInt> triangles;
};

/** A sphere of radius 1 about the origin (slices around, stacks from pole to pole), or a
 * vector shape of radius 1 along z from 0 to 1 (slices around; arrows use the head's length
 * ratio and radius ratio), capped. */
GlyphMesh createGlyphMesh(osgGlyphs::GlyphShape shape, unsigned int slices, unsigned int stacks,
                          float headLength, float headRadius);

}
}

#endif
