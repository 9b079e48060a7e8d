/* osgGlyphs - private: cutting a dataset larger than memory into tiles. Not installed. */

#ifndef OSGGLYPHS_TILESTREAM_H
#define OSGGLYPHS_TILESTREAM_H 1

#include "TileBuckets.h"

namespace osgGlyphsTiles
{
namespace detail
{

/** The buckets a streamed dataset is first sorted into, in a temporary file at path (isOpen()
 * tells whether it could be made): the nodes 3 levels down the cube (512), or fewer for an inner
 * tile's grid of fewer levels. They count their glyphs into counts, per node at the levels of an
 * inner tile's grid (at most 7: 8^7 counters, 16 MiB), for buildStreamedTree(). */
std::unique_ptr<TileBuckets> createStreamBuckets(const std::string& path, const TileRecordFormat& format,
                                                 const OctreeCube& cube, const TileOptions& options,
                                                 std::vector<std::size_t>& counts);

/** The tile tree of the glyphs in buckets (made by createStreamBuckets(), which counted them into
 * counts) followed by those in tail, holding
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
