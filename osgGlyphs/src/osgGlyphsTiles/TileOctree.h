/* osgGlyphs - private: the octree of the tiles, as ranges of glyphs sorted by Morton code, and
 * the glyph that stands for the glyphs of one cell. Not installed. */

#ifndef OSGGLYPHS_TILEOCTREE_H
#define OSGGLYPHS_TILEOCTREE_H 1

#include <osg/BoundingBox>
#include <osg/Vec3d>

#include <cstdint>

namespace osgGlyphsTiles
{
namespace detail
{

/** Bits of each coordinate in a Morton code: 63 bits in all, 21 octree levels. */
const unsigned int MORTON_LEVELS = 21;

/** A cube with its corner at min, and the Morton codes of the points in it. */
struct OctreeCube
{
    osg::Vec3d min;
    double size = 1.0;

    /** The code of a point: its coordinates quantised to 2^21 steps per side, interleaved (x
     * lowest); points outside are clamped to the cube. */
    uint64_t code(const osg::Vec3d& point) const;

    /** The cube of the node at this level whose codes start with prefix (3 * level bits). */
    OctreeCube node(unsigned int level, uint64_t prefix) const;
};

/** The cube that quantises every point of box inside it (of side 1 for no point). */
OctreeCube cubeAround(const osg::BoundingBoxd& box);

/** The octree levels of a grid of cellsPerAxis cells per axis (a power of two): its log2. */
unsigned int gridLevels(unsigned int cellsPerAxis);

/** The first code of the node at level with prefix, and the first code after it. */
uint64_t firstCode(unsigned int level, uint64_t prefix);
uint64_t endCode(unsigned int level, uint64_t prefix);

/** What stands for the glyphs of one grid cell from afar: one of them (a representative subset
 * keeps the distribution of scalars and colours, which averaging would pull to the middle of
 * the colour map), the one nearest their area-weighted centroid, drawn with a radius that
 * covers what they cover. */
class CellCoverage
{
public:
    void add(const osg::Vec3d& position, float radius);

    /** The glyphs' area-weighted centroid (the first glyph's where every radius is 0). */
    osg::Vec3d getCentroid() const;

    /** The radius for a cell cellSize wide: the largest of the glyphs' radii, or that of a disc
     * covering the fraction 1 - exp(-A / cellSize^2) of the cell, A being their summed projected
     * area (random overlap), whichever is larger. */
    float getRadius(double cellSize) const;

private:
    unsigned long _count = 0;
    double _weight = 0.0;
    osg::Vec3d _weightedPosition;
    osg::Vec3d _firstPosition;
    double _area = 0.0;
    float _maxRadius = 0.0f;
};

}
}

#endif
