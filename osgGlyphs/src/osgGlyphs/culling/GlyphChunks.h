/* osgGlyphs - private: glyphs in spatial order, cut into chunks with their bounds. Not installed. */

#ifndef OSGGLYPHS_GLYPHCHUNKS_H
#define OSGGLYPHS_GLYPHCHUNKS_H 1

#include <osg/BoundingBox>
#include <osg/PrimitiveSet>

#include <functional>
#include <vector>

namespace osgGlyphs
{
namespace detail
{

/** A run of the spatial order: glyphs order[first, first + count) and the box that holds them. */
struct GlyphChunk
{
    osg::BoundingBox box;
    unsigned int first = 0;
    unsigned int count = 0;
};

/** The glyphs that are drawn, in Morton order as GL_POINTS indices (the caller's glyph ids; 16-bit
 * for up to 65,536 glyphs), cut along the octree of that order into chunks of at most
 * maxChunkSize glyphs. */
struct GlyphChunks
{
    osg::ref_ptr<osg::DrawElements> order;
    std::vector<GlyphChunk> chunks;
};

/** Sorts the glyphs whose box is valid (the others are not drawn) by the Morton code of their
 * box centre, and cuts the order into chunks of one octree cell each. */
GlyphChunks buildGlyphChunks(unsigned int numGlyphs,
                             const std::function<osg::BoundingBox(unsigned int)>& glyphBox,
                             unsigned int maxChunkSize);

}
}

#endif
