#include "TileStream.h"

#include <algorithm>
#include <memory>

using namespace osgGlyphsTiles::detail;

namespace
{

/** The deepest level the glyphs are counted at: 8^7 counters, 16 MiB. */
const unsigned int MAX_COUNT_LEVEL = 7;

/** An octree node cut into tiles from memory at once. */
struct Unit
{
    unsigned int level;
    uint64_t prefix;
    std::size_t glyphs;
};

/** A node above the units, gathering what its units give it. */
struct OpenNode
{
    OpenNode(unsigned int nodeLevel, uint64_t nodePrefix) : level(nodeLevel), prefix(nodePrefix) {}

    unsigned int level;
    uint64_t prefix;
    osg::ref_ptr<osg::Group> children = new osg::Group;
    osg::BoundingBoxd box;
    TileGlyphs representatives;

    bool contains(const Unit& unit) const
    {
        return level < unit.level && unit.prefix >> 3 * (unit.level - level) == prefix;
    }
};

/** The share of the progress of the passes over every glyph that come before the tiles: counting,
 * then sorting into partitions (measured: about a tenth of the time, mostly the sorting). */
const double COUNTED = 0.02, DISTRIBUTED = 0.12;

/** The glyphs of the spill, then the tail, a block at a time, reporting progress from first to
 * last of the writer's. */
bool readGlyphs(TileSpill& spill, const TileGlyphs& tail, TileWriter& writer, double first, double last,
                const std::function<void(const TileGlyphs& block)>& visit, std::string& error)
{
    const double total = double(spill.size() + tail.size());
    std::size_t done = 0;
    if (!spill.read(
            [&](const TileGlyphs& block)
            {
                visit(block);
                done += block.size();
                writer.setProgress(first + (last - first) * done / total);
                return true;
            },
            error))
        return false;
    visit(tail);
    writer.setProgress(last);
    return true;
}

class StreamedTree
{
public:
    StreamedTree(TileWriter& writer, std::size_t budget)
        : _writer(writer), _budget(std::max<std::size_t>(budget, writer.getOptions().maxGlyphsPerTile)),
          _countLevel(std::min(writer.getCellLevels(), MAX_COUNT_LEVEL))
    {
    }

    bool count(TileSpill& spill, const TileGlyphs& tail, std::string& error)
    {
        std::vector<std::size_t> counts[2];
        for (auto& half : counts)
            half.assign(std::size_t(1) << 3 * _countLevel, 0);
        const unsigned int shift = 3 * (MORTON_LEVELS - _countLevel);
        if (!readGlyphs(
                spill, tail, _writer, 0.0, COUNTED,
                [&](const TileGlyphs& block)
                {
                    forEachCode(block, [&](unsigned int half, std::size_t, uint64_t code)
                                { ++counts[half][code >> shift]; });
                },
                error))
            return false;
        _before.assign(counts[0].size() + 1, 0);
        for (std::size_t i = 0; i < counts[0].size(); ++i)
            _before[i + 1] = _before[i] + counts[0][i] + counts[1][i];
        findUnits(0, 0);
        return true;
    }

    /** Runs of consecutive units of at most the budget together. */
    void partition()
    {
        std::size_t glyphs = 0;
        for (std::size_t i = 0; i < _units.size(); ++i)
        {
            if (i == 0 || glyphs + _units[i].glyphs > _budget)
            {
                // A glyph belongs to the last partition whose first code is not after its code:
                // the units hold every glyph.
                _partitionStarts.push_back(i);
                _partitionCodes.push_back(firstCode(_units[i].level, _units[i].prefix));
                glyphs = 0;
            }
            glyphs += _units[i].glyphs;
        }
        _partitionStarts.push_back(_units.size());
    }

    bool distribute(TileSpill& spill, const TileGlyphs& tail, const std::string& prefix, std::string& error)
    {
        for (std::size_t p = 0; p + 1 < _partitionStarts.size(); ++p)
        {
            _partitions.push_back(spill.createLike(prefix + "-" + std::to_string(p)));
            if (!_partitions.back()->isOpen())
            {
                error = _partitions.back()->getPath() + ": cannot create a temporary file";
                return false;
            }
        }
        std::vector<std::vector<unsigned int>> indices(_partitions.size());
        std::vector<unsigned int> partitionOf;
        bool written = true;
        if (!readGlyphs(
                spill, tail, _writer, COUNTED, DISTRIBUTED,
                [&](const TileGlyphs& block)
                {
                    for (auto& list : indices)
                        list.clear();
                    partitionOf.resize(block.size());
                    forEachCode(
                        block,
                        [&](unsigned int, std::size_t i, uint64_t code)
                        {
                            partitionOf[i] = static_cast<unsigned int>(
                                std::upper_bound(_partitionCodes.begin(), _partitionCodes.end(), code) -
                                _partitionCodes.begin() - 1);
                        });
                    for (std::size_t i = 0; i < block.size(); ++i)
                        indices[partitionOf[i]].push_back(static_cast<unsigned int>(i));
                    for (std::size_t p = 0; p < indices.size() && written; ++p)
                        written = _partitions[p]->append(block, indices[p], error);
                },
                error))
            return false;
        return written;
    }

    osg::ref_ptr<osg::Node> build(const osg::Vec3d& origin, std::string& error)
    {
        for (std::size_t p = 0; p < _partitions.size(); ++p)
        {
            TileGlyphs glyphs;
            glyphs.origin = origin;
            const std::size_t count = _partitions[p]->size();
            if (!_partitions[p]->read(
                    [&glyphs, count](const TileGlyphs& block)
                    {
                        if (glyphs.positions.capacity() < count)
                            glyphs.reserve(count, block);
                        glyphs.append(block);
                        return true;
                    },
                    error))
                return nullptr;
            _partitions[p].reset();
            TileTree tree(glyphs, _writer);
            for (std::size_t u = _partitionStarts[p]; u < _partitionStarts[p + 1]; ++u)
                if (!addUnit(tree, _units[u]))
                {
                    error = _writer.getError();
                    return nullptr;
                }
        }
        while (!_open.empty())
            if (!close())
            {
                error = _writer.getError();
                return nullptr;
            }
        return _root;
    }

private:
    /** Calls visit(half, i, code) with the Morton code of each glyph i of block: on two threads,
     * one for each half (0, 1) of the block. */
    template <typename Visit>
    void forEachCode(const TileGlyphs& block, const Visit& visit)
    {
        const OctreeCube& cube = _writer.getCube();
        const auto visitRange = [&](unsigned int half, std::size_t first, std::size_t last)
        {
            for (std::size_t i = first; i < last; ++i)
                visit(half, i, cube.code(osg::Vec3d(block.positions[i])));
        };
        _writer.getThreads().runHalves(block.size(), visitRange);
    }

    std::size_t glyphsIn(unsigned int level, uint64_t prefix) const
    {
        const unsigned int shift = 3 * (_countLevel - level);
        return _before[(prefix + 1) << shift] - _before[prefix << shift];
    }

    void findUnits(unsigned int level, uint64_t prefix)
    {
        const std::size_t glyphs = glyphsIn(level, prefix);
        if (glyphs == 0)
            return;
        if (glyphs <= _budget || level == _countLevel)
        {
            _units.push_back({level, prefix, glyphs});
            return;
        }
        for (uint64_t octant = 0; octant < 8; ++octant)
            findUnits(level + 1, prefix << 3 | octant);
    }

    bool addUnit(TileTree& tree, const Unit& unit)
    {
        while (!_open.empty() && !_open.back().contains(unit))
            if (!close())
                return false;
        for (unsigned int level = _open.empty() ? 0 : _open.back().level + 1; level < unit.level; ++level)
            _open.emplace_back(level, unit.prefix >> 3 * (unit.level - level));
        const auto range = tree.rangeOf(unit.level, unit.prefix);
        // What the unit gives the nodes above it, beside its own tiles: both only read the glyphs.
        osg::ref_ptr<osg::Node> node;
        _writer.getThreads().runBoth(
            [&]
            {
                const osg::BoundingBoxd box = tree.boxOf(range.first, range.second);
                for (OpenNode& open : _open)
                {
                    open.box.expandBy(box);
                    tree.addRepresentatives(open.level, range.first, range.second, open.representatives);
                }
            },
            [&] { node = tree.buildNode(unit.level, unit.prefix, range.first, range.second); });
        if (!node)
            return false;
        attach(node.get());
        return true;
    }

    bool close()
    {
        OpenNode node = std::move(_open.back());
        _open.pop_back();
        osg::ref_ptr<osg::Node> inner =
            _writer.createInnerNode(node.level, node.prefix, *node.children, node.box, node.representatives);
        if (!inner)
            return false;
        attach(inner.get());
        return true;
    }

    void attach(osg::Node* node)
    {
        if (_open.empty())
            _root = node;
        else
            _open.back().children->addChild(node);
    }

    TileWriter& _writer;
    std::size_t _budget;
    unsigned int _countLevel;
    std::vector<std::size_t> _before; // glyphs before each node of the count level
    std::vector<Unit> _units;         // in octree order
    std::vector<std::size_t> _partitionStarts;
    std::vector<uint64_t> _partitionCodes;
    std::vector<std::unique_ptr<TileSpill>> _partitions;
    std::vector<OpenNode> _open; // the nodes above the current unit, root first
    osg::ref_ptr<osg::Node> _root;
};

}

osg::ref_ptr<osg::Node> osgGlyphsTiles::detail::buildStreamedTree(TileSpill& spill, const TileGlyphs& tail,
                                                                  TileWriter& writer, std::size_t budget,
                                                                  const std::string& temporaryPrefix,
                                                                  std::string& error)
{
    StreamedTree tree(writer, budget);
    if (!tree.count(spill, tail, error))
        return nullptr;
    tree.partition();
    if (!tree.distribute(spill, tail, temporaryPrefix, error))
        return nullptr;
    return tree.build(tail.origin, error);
}
