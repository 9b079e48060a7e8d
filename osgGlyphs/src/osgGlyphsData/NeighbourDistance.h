/* osgGlyphs - private: the typical spacing of points, for a default glyph size. Not installed. */

#ifndef OSGGLYPHS_NEIGHBOURDISTANCE_H
#define OSGGLYPHS_NEIGHBOURDISTANCE_H 1

#include <osgGlyphsData/PointShare>

#include <osg/Vec3f>

#include <vector>

namespace osgGlyphsData
{
namespace detail
{

/** The median distance from a point to its nearest neighbour, over an evenly spaced sample of at
 * most maxSamples points, found through a uniform grid. Points at the same place as their
 * neighbour and non-finite points are left out. Returns 0 when there are fewer than two distinct
 * finite points. Computed in double: the spacing of float positions may exceed the range of a
 * float. The search of each sample stops after a bounded amount of work, with the nearest
 * neighbour found by then (none: the sample is left out), so that no layout of the points (flat,
 * collinear, coincident, clustered) makes it slow. */
double estimateNeighbourDistance(const std::vector<osg::Vec3f>& positions, unsigned int maxSamples = 2000);

/** The same over the positions of every process of a reduction, each holding its share (in share
 * order): the samples are those of one process holding every point, each process finds their
 * nearest neighbours among its points, the nearest of those is the sample's. The result equals
 * the single-process one unless a search ends on its work bound in one of them. */
double estimateNeighbourDistance(const std::vector<osg::Vec3f>& positions, const ShareReduction& reduction,
                                 unsigned int maxSamples = 2000);

}
}

#endif
