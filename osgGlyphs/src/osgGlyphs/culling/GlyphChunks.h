/* osgGlyphs - private: glyphs in spatial order, cut into chunks with their bounds. Not installed. */

#ifndef OSGGLYPHS_GLYPHCHUNKS_H
#define OSGGLYPHS_GLYPHCHUNKS_H 1

#include <osg/BoundingBox>

#include <functional>
#include <vector>

namespace osgGlyphs
{
namespace detail
{

/** A run of the spatial order: the glyphs at positions [first, first + count) of the drawn
 * arrays, and the box that holds them. */
struct GlyphChunk
{
    osg::BoundingBox box;
    unsigned int first = 0;
    unsigned int count = 0;
};

/** The glyphs that are drawn, in Morton order, cut along the octree of that order into chunks of
 * at most maxChunkSize glyphs. ids[k] is the caller's id of the glyph the drawn arrays hold at
 * position k. */
struct GlyphChunks
{
    std::vector<unsigned int> ids;
    std::vector<GlyphChunk> chunks;

    /** Whether every drawn glyph is at its own index (those not drawn come after them): the
     * caller's arrays of numGlyphs glyphs can be drawn as they are. */
    bool isIdentity(unsigned int numGlyphs) const;
};

/** Sorts the glyphs whose box is valid (the others are not drawn) by the Morton code of their
 * box centre, and cuts the order into chunks of one octree cell each. */
GlyphChunks buildGlyphChunks(unsigned int numGlyphs,
                             const std::function<osg::BoundingBox(unsigned int)>& glyphBox,
                             unsigned int maxChunkSize);

}
}

#endif
