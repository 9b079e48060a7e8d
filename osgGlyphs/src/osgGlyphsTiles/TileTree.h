/* osgGlyphs - private: the glyphs a TileBuilder collects, and the walk along their octree that
 * makes the tiles. Not installed. */

#ifndef OSGGLYPHS_TILETREE_H
#define OSGGLYPHS_TILETREE_H 1

#include "TileArchive.h"
#include "TileOctree.h"
#include "TileThreads.h"

#include <osgGlyphsTiles/TileBuilder>

#include <osg/BoundingBox>

#include <atomic>
#include <mutex>
#include <vector>

namespace osgGlyphsTiles
{
namespace detail
{

/** Glyphs as arrays of equal length (colours, vectors, semi-axes, turns and exponents where used). */
struct TileGlyphs
{
    osg::Vec3d origin;
    std::vector<osg::Vec3f> positions; // relative to origin
    std::vector<float> radii;          // of ellipsoids and superquadrics: a sphere's that holds them
    std::vector<float> scalars;
    std::vector<osg::Vec4ub> colors;
    std::vector<osg::Vec3f> vectors;
    std::vector<osg::Vec3f> semiAxes;
    std::vector<osg::Vec4f> orientations;
    std::vector<osg::Vec2f> exponents;
    float scalarMin = 0.0f, scalarMax = 0.0f;

    /** Calls visit with each array of glyphs, positions first, side by side: visit(a.positions,
     * b.positions, ...), then the radii, and so on (the unused ones empty). */
    template <typename Visit, typename... Glyphs>
    static void forEachArray(const Visit& visit, Glyphs&... glyphs)
    {
        visit(glyphs.positions...);
        visit(glyphs.radii...);
        visit(glyphs.scalars...);
        visit(glyphs.colors...);
        visit(glyphs.vectors...);
        visit(glyphs.semiAxes...);
        visit(glyphs.orientations...);
        visit(glyphs.exponents...);
    }

    std::size_t size() const { return positions.size(); }
    void clear();
    /** Clears the arrays and gives their memory back. */
    void release();
    /** Appends glyph i of other. */
    void append(const TileGlyphs& other, std::size_t i);
    /** Appends every glyph of other. */
    void append(const TileGlyphs& other);
    /** Exchanges the glyphs (not the origin nor the scalar range) with other's. */
    void swapGlyphs(TileGlyphs& other);
};

/** What every tile of a dataset shares (style, octree cube, origin, colour range) and where the
 * tiles go: each inner node's children are written into the archive as it is made, or, without
 * an archive, kept in place. Its calls are safe from the threads of getThreads(), which serialise
 * their tiles side by side. */
class TileWriter
{
public:
    TileWriter(const osgGlyphs::GlyphCloud& style, const TileOptions& options, const OctreeCube& cube,
               const TileGlyphs& dataset, TileArchive* archive, std::size_t totalGlyphs,
               const TileBuilder::ProgressFunction& progress);

    const osgGlyphs::GlyphCloud& getStyle() const { return _style; }
    const TileOptions& getOptions() const { return _options; }
    const OctreeCube& getCube() const { return _cube; }
    /** log2 of TileOptions::cellsPerAxis. */
    unsigned int getCellLevels() const { return _cellLevels; }
    /** The threads that cut subtrees side by side (TileOptions::threads). */
    TileThreads& getThreads() { return _threads; }

    osg::ref_ptr<osgGlyphs::GlyphCloud> createCloud(const TileGlyphs& glyphs) const;

    /** The PagedLOD of an inner node: its representatives until they would be too coarse, then
     * its children (written into the archive now). Null with getError() set when writing fails. */
    osg::ref_ptr<osg::Node> createInnerNode(unsigned int level, uint64_t prefix, osg::Group& children,
                                            const osg::BoundingBoxd& box, const TileGlyphs& representatives);

    /** Counts glyphs into leaves, for the progress. */
    void addDone(std::size_t glyphs);
    /** Reports the progress of work before the leaves (TileStream's passes), which then count
     * from there to the end. */
    void setProgress(double fraction);

    /** Records the first error: every thread then stops. */
    void fail(const std::string& error);
    bool failed() const { return _failed; }
    std::string getError() const;

private:
    const osgGlyphs::GlyphCloud& _style;
    TileOptions _options;
    unsigned int _cellLevels;
    OctreeCube _cube;
    osg::Vec3d _origin;
    float _scalarMin, _scalarMax;
    osg::ref_ptr<osg::StateSet> _tileStateSet; // the style's, in the front-to-back bin
    TileArchive* _archive;
    std::size_t _total;
    TileBuilder::ProgressFunction _progress;
    std::size_t _done = 0;
    double _leavesStart = 0.0;
    std::string _error;
    std::atomic<bool> _failed{false};
    TileThreads _threads;
    mutable std::mutex _progressMutex; // _done, _leavesStart, _error and the progress calls
    mutable std::mutex _styleMutex;    // the style's and the tiles' StateSets' parents
};

/** The octree over glyphs and the tiles made from it. The glyphs are a dataset, or a run of
 * whole octree nodes of one (TileStream). */
class TileTree
{
public:
    /** Puts the glyphs in the order of their octree (Morton order), which the tiles are cut from:
     * every later walk over them reads memory in order. Given runs (the first glyph of each), the
     * glyphs are runs of distinct octree nodes in their octree order, and each run is sorted on
     * its own. */
    TileTree(TileGlyphs& glyphs, TileWriter& writer, std::vector<std::size_t> runs = {});

    std::size_t size() const { return _codes.size(); }

    /** The glyphs of the node at level with prefix: [first, second). */
    std::pair<std::size_t, std::size_t> rangeOf(unsigned int level, uint64_t prefix) const;

    /** The node of the glyphs [begin, end) at level with prefix, its descendants written; null
     * when writing failed (the writer's getError()). */
    osg::ref_ptr<osg::Node> buildNode(unsigned int level, uint64_t prefix, std::size_t begin,
                                      std::size_t end);

    /** Appends the representatives of the cells of a node at level that hold the glyphs
     * [begin, end): whole cells, one representative each. */
    void addRepresentatives(unsigned int level, std::size_t begin, std::size_t end,
                            TileGlyphs& representatives) const;

    /** The box of what the glyphs [begin, end) cover, in the clouds' parent's coordinates. */
    osg::BoundingBoxd boxOf(std::size_t begin, std::size_t end) const;

private:
    /** The radius of the disc whose area is glyph i's mean projected area (its radius for spheres,
     * cones and arrows, which the tiles' coverage takes as theirs). */
    float coveringRadius(std::size_t i) const;
    osg::ref_ptr<osgGlyphs::GlyphCloud> createLeaf(std::size_t begin, std::size_t end) const;

    const TileGlyphs& _glyphs;
    TileWriter& _writer;
    std::vector<uint64_t> _codes; // of the glyphs, in their (sorted) order
};

}
}

#endif
