#include "GlyphPicking.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

using namespace osgGlyphs::detail;

namespace
{

/** Where the ray enters and leaves the box (slab test), widened by a relative margin: the boxes
 * are float and the glyphs double. False when it misses the box or the interval [0, maxT]. */
bool crossBox(const osg::BoundingBox& box, const glm::dvec3& origin, const glm::dvec3& direction, double maxT,
              double& tEnter)
{
    double lo = 0.0, hi = maxT;
    for (int axis = 0; axis < 3; ++axis)
    {
        const double margin =
            1e-6 * (double(box._max[axis]) - box._min[axis]) +
            1e-6 * std::max(std::abs(double(box._min[axis])), std::abs(double(box._max[axis])));
        const double min = box._min[axis] - margin, max = box._max[axis] + margin;
        if (direction[axis] == 0.0)
        {
            if (origin[axis] < min || origin[axis] > max)
                return false;
            continue;
        }
        const double t0 = (min - origin[axis]) / direction[axis];
        const double t1 = (max - origin[axis]) / direction[axis];
        lo = std::max(lo, std::min(t0, t1));
        hi = std::min(hi, std::max(t0, t1));
        if (lo > hi)
            return false;
    }
    tEnter = lo;
    return true;
}

}

std::vector<GlyphRayHit> osgGlyphs::detail::castRayThroughChunks(const GlyphChunks& chunks,
                                                                 const GlyphSolidSource& solids,
                                                                 const glm::dvec3& origin,
                                                                 const glm::dvec3& direction, double maxT,
                                                                 bool nearestOnly)
{
    std::vector<std::pair<double, unsigned int>> crossed; // entry distance, chunk
    for (unsigned int index = 0; index < chunks.chunks.size(); ++index)
    {
        double tEnter = 0.0;
        if (crossBox(chunks.chunks[index].box, origin, direction, maxT, tEnter))
            crossed.emplace_back(tEnter, index);
    }
    std::sort(crossed.begin(), crossed.end());

    std::vector<GlyphRayHit> hits;
    GlyphSolid solid;
    for (const auto& [tEnter, index] : crossed)
    {
        if (nearestOnly && !hits.empty() && tEnter > hits.front().t)
            break; // every later chunk starts behind the nearest hit
        const GlyphChunk& chunk = chunks.chunks[index];
        for (unsigned int k = chunk.first; k < chunk.first + chunk.count; ++k)
        {
            GlyphRayHit hit;
            hit.glyph = chunks.ids[k];
            if (!solids(hit.glyph, solid) || !castRay(solid, origin, direction, hit.t, hit.normal) ||
                hit.t > maxT)
                continue;
            if (!nearestOnly)
                hits.push_back(hit);
            else if (hits.empty() || hit.t < hits.front().t)
                hits.assign(1, hit);
        }
    }
    std::sort(hits.begin(), hits.end(),
              [](const GlyphRayHit& a, const GlyphRayHit& b)
              { return a.t < b.t || (a.t == b.t && a.glyph < b.glyph); });
    return hits;
}

std::vector<unsigned int> osgGlyphs::detail::findGlyphsInPolytope(const GlyphChunks& chunks,
                                                                  const osg::Vec3Array& positions,
                                                                  const osg::Polytope& polytope)
{
    std::vector<unsigned int> inside;
    const osg::Polytope::PlaneList& planes = polytope.getPlaneList();
    auto holds = [&](const osg::Vec3& point)
    {
        for (const osg::Plane& plane : planes)
            if (plane.distance(point) < 0.0)
                return false;
        return true;
    };
    for (const GlyphChunk& chunk : chunks.chunks)
    {
        // A box wholly outside one plane holds no glyph point.
        bool outside = false;
        for (const osg::Plane& plane : planes)
            outside = outside || plane.intersect(chunk.box) < 0;
        if (outside)
            continue;
        for (unsigned int k = chunk.first; k < chunk.first + chunk.count; ++k)
        {
            const unsigned int glyph = chunks.ids[k];
            if (holds(positions[glyph]))
                inside.push_back(glyph);
        }
    }
    return inside;
}
