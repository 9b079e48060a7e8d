/* osgGlyphs - private: cutting a dataset larger than memory into tiles. Not installed. */

#ifndef OSGGLYPHS_TILESTREAM_H
#define OSGGLYPHS_TILESTREAM_H 1

#include "TileBuckets.h"

namespace osgGlyphsTiles
{
namespace detail
{

/** The level of the octree a streamed dataset's glyphs are counted at: the levels of an inner
 * tile's grid, at most 7 (8^7 counters, 16 MiB). */
unsigned int streamCountLevel(const TileOptions& options);

/** The buckets a streamed dataset is first sorted into: the nodes 3 levels down (512), or at the
 * count level when that is less deep. */
unsigned int streamBucketLevel(const TileOptions& options);

/** The tile tree of the glyphs in buckets (the nodes at streamBucketLevel() of the writer's cube,
 * their glyphs counted per node at streamCountLevel() in counts) followed by those in tail, holding
 * at most about budget glyphs in memory at a time, as TileTree would make it from all of them at
 * once (the same nodes in the same order, byte for byte).
 *
 * The largest nodes of at most budget glyphs (or the nodes at the count level) are the units; runs
 * of consecutive units of at most budget glyphs together are the partitions. A bucket of more than
 * budget glyphs is first sorted into the buckets of its nodes a few levels down (a temporary file
 * named from temporaryPrefix). Each partition is read from the buckets that hold its glyphs and cut
 * into tiles by a TileTree, unit by unit; the nodes above the units (each of more than budget
 * glyphs, so inner nodes) gather their representatives and bounds unit by unit, which is exact
 * because their grid cells are never larger than a unit. Null with error on an I/O failure. */
osg::ref_ptr<osg::Node> buildStreamedTree(TileBuckets& buckets, std::vector<std::size_t> counts,
                                          const TileGlyphs& tail, TileWriter& writer, std::size_t budget,
                                          const std::string& temporaryPrefix, std::string& error);

}
}

#endif
