#include "TileOctree.h"

#include <osg/Math>

#include <algorithm>
#include <cmath>

using namespace osgGlyphsTiles::detail;

namespace
{

/** The bits of v spread to every third bit. */
uint64_t spread(uint64_t v)
{
    v &= 0x1fffff;
    v = (v | v << 32) & 0x1f00000000ffffULL;
    v = (v | v << 16) & 0x1f0000ff0000ffULL;
    v = (v | v << 8) & 0x100f00f00f00f00fULL;
    v = (v | v << 4) & 0x10c30c30c30c30c3ULL;
    v = (v | v << 2) & 0x1249249249249249ULL;
    return v;
}

const double MORTON_STEPS = double(1u << MORTON_LEVELS);

uint64_t quantise(double value, double min, double stepsPerUnit)
{
    // floor() clamped to the steps, without a call: the conversion truncates, which is floor()
    // from 0 on.
    const double q = (value - min) * stepsPerUnit;
    if (!(q > 0.0))
        return 0;
    return q < MORTON_STEPS - 1.0 ? static_cast<uint64_t>(q) : static_cast<uint64_t>(MORTON_STEPS - 1.0);
}

}

uint64_t OctreeCube::code(const osg::Vec3d& point) const
{
    const double stepsPerUnit = MORTON_STEPS / size;
    return spread(quantise(point.x(), min.x(), stepsPerUnit)) |
           spread(quantise(point.y(), min.y(), stepsPerUnit)) << 1 |
           spread(quantise(point.z(), min.z(), stepsPerUnit)) << 2;
}

OctreeCube OctreeCube::node(unsigned int level, uint64_t prefix) const
{
    OctreeCube cube;
    cube.min = min;
    cube.size = size;
    for (unsigned int i = 0; i < level; ++i)
    {
        const unsigned int octant = static_cast<unsigned int>(prefix >> (3 * (level - 1 - i))) & 7u;
        cube.size *= 0.5;
        for (unsigned int axis = 0; axis < 3; ++axis)
            if (octant & (1u << axis))
                cube.min[axis] += cube.size;
    }
    return cube;
}

OctreeCube osgGlyphsTiles::detail::cubeAround(const osg::BoundingBoxd& box)
{
    OctreeCube cube;
    if (box.valid())
    {
        cube.min = box._min;
        const double extent =
            std::max({box.xMax() - box.xMin(), box.yMax() - box.yMin(), box.zMax() - box.zMin()});
        // A little wider than the points, so that the farthest ones quantise inside.
        cube.size = extent > 0.0 ? extent * (1.0 + 1e-6) : 1.0;
    }
    return cube;
}

unsigned int osgGlyphsTiles::detail::gridLevels(unsigned int cellsPerAxis)
{
    unsigned int levels = 0;
    while ((2u << levels) <= cellsPerAxis)
        ++levels;
    return levels;
}

uint64_t osgGlyphsTiles::detail::firstCode(unsigned int level, uint64_t prefix)
{
    return prefix << (3 * (MORTON_LEVELS - level));
}

uint64_t osgGlyphsTiles::detail::endCode(unsigned int level, uint64_t prefix)
{
    return (prefix + 1) << (3 * (MORTON_LEVELS - level));
}

void CellCoverage::add(const osg::Vec3d& position, float radius)
{
    const double weight = double(radius) * radius;
    if (_count++ == 0)
        _firstPosition = position;
    _weight += weight;
    _weightedPosition += position * weight;
    _area += osg::PI * weight;
    _maxRadius = std::max(_maxRadius, radius);
}

osg::Vec3d CellCoverage::getCentroid() const
{
    return _weight > 0.0 ? _weightedPosition / _weight : _firstPosition;
}

float CellCoverage::getRadius(double cellSize) const
{
    const double cellArea = cellSize * cellSize;
    const double covered = cellArea * -std::expm1(-_area / cellArea);
    return std::max(_maxRadius, static_cast<float>(std::sqrt(covered / osg::PI)));
}
