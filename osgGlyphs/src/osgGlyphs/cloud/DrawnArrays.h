/* osgGlyphs - private: a culling cloud's GPU arrays in its chunks' spatial order. Not installed. */

#ifndef OSGGLYPHS_DRAWNARRAYS_H
#define OSGGLYPHS_DRAWNARRAYS_H 1

#include "../culling/GlyphChunks.h"

#include <osgGlyphs/GlyphAttributes>

#include <memory>

namespace osgGlyphs
{
namespace detail
{

/** into, of source's type and flags, holding source's elements at ids in turn. */
void gatherElements(const osg::Array& source, const std::vector<unsigned int>& ids, osg::Array& into);

/** Reorders array in place (its type, flags and user values kept): element k becomes the one
 * at order[k]; order holds each index of the array once. */
void permuteElements(osg::Array& array, const std::vector<unsigned int>& order);

/** The arrays a culling technique draws: each chunk one range of them, so that a chunk is read
 * from memory in order and drawn without an index buffer. Where the chunks' order is the
 * caller's own, the caller's arrays; else copies in that order, gathered again only where their
 * source, its contents (modified count) or the order changed. */
class DrawnArrays
{
public:
    /** The glyph arrays of source in the order of chunks (made for source's glyphs). */
    GlyphArrays update(const GlyphArrays& source, const std::shared_ptr<const GlyphChunks>& chunks);

    /** Frees the copies. */
    void clear() { *this = DrawnArrays(); }

    /** Whether the drawn arrays are copies in another order than the caller's. */
    bool isReordered() const { return _reordered; }

private:
    /** One array gathered in the chunks' order, and what it was gathered from. */
    struct Copy
    {
        osg::ref_ptr<osg::Array> array;
        const osg::Array* source = nullptr;
        unsigned int modifiedCount = 0;
    };

    osg::Array* gather(Copy& copy, const osg::Array* source, bool orderChanged);

    Copy _positions, _radiusScalar, _colors, _vectors, _occlusion, _axes, _orientations;
    std::shared_ptr<const GlyphChunks> _chunks;
    bool _reordered = false;
};

}
}

#endif
