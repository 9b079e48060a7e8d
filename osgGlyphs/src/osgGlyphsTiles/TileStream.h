/* osgGlyphs - private: cutting a dataset larger than memory into tiles. Not installed. */

#ifndef OSGGLYPHS_TILESTREAM_H
#define OSGGLYPHS_TILESTREAM_H 1

#include "TileSpill.h"

namespace osgGlyphsTiles
{
namespace detail
{

/** The tile tree of the glyphs in spill followed by those in tail, holding at most about budget
 * glyphs in memory at a time, as TileTree would make it from all of them at once (the same nodes
 * in the same order, byte for byte).
 *
 * A pass over the glyphs counts them per octree node a few levels down. The largest nodes of at
 * most budget glyphs (or the nodes at that level) are the units; runs of consecutive units of at
 * most budget glyphs together are the partitions, each sorted into a temporary file (named from
 * temporaryPrefix) by a second pass. Each partition is then read and cut into tiles by a TileTree,
 * unit by unit; the nodes above the units (each of more than budget glyphs, so inner nodes) gather
 * their representatives and bounds unit by unit, which is exact because their grid cells are never
 * larger than a unit. Null with error on an I/O failure. */
osg::ref_ptr<osg::Node> buildStreamedTree(TileSpill& spill, const TileGlyphs& tail, TileWriter& writer,
                                          std::size_t budget, const std::string& temporaryPrefix,
                                          std::string& error);

}
}

#endif
