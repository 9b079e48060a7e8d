/* osgGlyphs - private: the glyphs a TileBuilder collects, and the walk along their octree that
 * makes the tiles. Not installed. */

#ifndef OSGGLYPHS_TILETREE_H
#define OSGGLYPHS_TILETREE_H 1

#include "TileOctree.h"

#include <osgGlyphsTiles/TileBuilder>

#include <osgDB/Archive>

#include <vector>

namespace osgGlyphsTiles
{
namespace detail
{

/** The glyphs of a dataset, as arrays of equal length (colours and vectors where used). */
struct TileGlyphs
{
    osg::Vec3d origin;
    std::vector<osg::Vec3f> positions; // relative to origin
    std::vector<float> radii;
    std::vector<float> scalars;
    std::vector<osg::Vec4ub> colors;
    std::vector<osg::Vec3f> vectors;
    float scalarMin = 0.0f, scalarMax = 0.0f;
};

/** The octree over a dataset's glyphs and the tiles made from it, root first. */
class TileTree
{
public:
    /** Puts the glyphs in the order of their octree (Morton order), which the tiles are cut from:
     * every later walk over them reads memory in order. */
    TileTree(TileGlyphs& glyphs, const osgGlyphs::GlyphCloud& style, const TileOptions& options);

    /** The root node; with an archive, each inner node's children are written into it as they
     * are made, else kept in place. False with error on a write failure. */
    osg::ref_ptr<osg::Node> build(osgDB::Archive* archive, const TileBuilder::ProgressFunction& progress,
                                  std::string& error);

private:
    osg::ref_ptr<osg::Node> buildNode(unsigned int level, uint64_t prefix, std::size_t begin,
                                      std::size_t end);
    osg::ref_ptr<osgGlyphs::GlyphCloud> createLeaf(std::size_t begin, std::size_t end) const;
    osg::ref_ptr<osgGlyphs::GlyphCloud> createRepresentatives(unsigned int level, std::size_t begin,
                                                              std::size_t end) const;
    osg::ref_ptr<osgGlyphs::GlyphCloud> createCloud(const std::vector<osg::Vec3f>& positions,
                                                    const std::vector<float>& radii,
                                                    const std::vector<float>& scalars,
                                                    const std::vector<osg::Vec4ub>& colors,
                                                    const std::vector<osg::Vec3f>& vectors) const;
    /** The bounding sphere of the glyphs of a range, in the clouds' parent's coordinates. */
    osg::BoundingSphere boundOf(std::size_t begin, std::size_t end) const;

    const TileGlyphs& _glyphs;
    const osgGlyphs::GlyphCloud& _style;
    TileOptions _options;
    unsigned int _cellLevels = 5; // log2 of cellsPerAxis
    OctreeCube _cube;
    std::vector<uint64_t> _codes; // of the glyphs, in their (sorted) order

    osgDB::Archive* _archive = nullptr;
    TileBuilder::ProgressFunction _progress;
    std::size_t _done = 0;
    std::string _error;
};

}
}

#endif
