#include "TileStream.h"

#include <algorithm>
#include <memory>

using namespace osgGlyphsTiles::detail;

namespace
{

/** The deepest level the glyphs are counted at: 8^7 counters, 16 MiB. */
const unsigned int MAX_COUNT_LEVEL = 7;

/** Levels from a node to its buckets: 512 of them. */
const unsigned int BUCKET_LEVELS = 3;

unsigned int countLevelOf(const osgGlyphsTiles::TileOptions& options)
{
    return std::min(gridLevels(options.cellsPerAxis), MAX_COUNT_LEVEL);
}

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

/** A bucket that partitions read their glyphs from. */
struct Source
{
    TileBuckets* buckets;
    std::size_t bucket;
    unsigned int level;
    uint64_t prefix;
};

class StreamedTree
{
public:
    StreamedTree(TileWriter& writer, const TileRecordFormat& format, std::size_t budget,
                 const std::string& temporaryPrefix)
        : _writer(writer), _format(format),
          _budget(std::max<std::size_t>(budget, writer.getOptions().maxGlyphsPerTile)),
          _countLevel(countLevelOf(writer.getOptions())), _temporaryPrefix(temporaryPrefix)
    {
    }

    /** Finds the units from the counts of the glyphs in buckets and those of the tail. */
    void count(std::vector<std::size_t>& counts, const TileGlyphs& tail)
    {
        const OctreeCube& cube = _writer.getCube();
        const unsigned int shift = 3 * (MORTON_LEVELS - _countLevel);
        _tailCodes.resize(tail.size());
        for (std::size_t i = 0; i < tail.size(); ++i)
        {
            _tailCodes[i] = cube.code(osg::Vec3d(tail.positions[i]));
            ++counts[_tailCodes[i] >> shift];
        }
        _before.assign(counts.size() + 1, 0);
        for (std::size_t i = 0; i < counts.size(); ++i)
            _before[i + 1] = _before[i] + counts[i];
        findUnits(0, 0);
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
        _partitionCodes.push_back(endCode(0, 0));
    }

    /** The buckets in octree order, those of more than the budget sorted into smaller ones. */
    bool findSources(TileBuckets& buckets, std::string& error)
    {
        for (std::size_t b = 0; b < buckets.getNumBuckets(); ++b)
        {
            const unsigned int bucketLevel = buckets.getBucketLevel();
            const uint64_t prefix = buckets.getBucketPrefix(b);
            if (buckets.getBucketSize(b) <= _budget || bucketLevel >= _countLevel)
            {
                if (buckets.getBucketSize(b))
                    _sources.push_back({&buckets, b, bucketLevel, prefix});
                continue;
            }
            _splits.push_back(std::make_unique<TileBuckets>(
                _temporaryPrefix + "-" + std::to_string(_splits.size()), buckets.getFormat(),
                _writer.getCube(), bucketLevel, prefix, std::min(bucketLevel + BUCKET_LEVELS, _countLevel)));
            TileBuckets& split = *_splits.back();
            if (!split.isOpen())
            {
                error = split.getPath() + ": cannot create a temporary file";
                return false;
            }
            bool added = true;
            if (!buckets.read(
                    b,
                    [&](const TileGlyphs& block) { return added = split.add(block, 0, block.size(), error); },
                    error) ||
                !added || !findSources(split, error))
                return false;
        }
        return true;
    }

    osg::ref_ptr<osg::Node> build(const TileGlyphs& tail, std::string& error)
    {
        for (std::size_t p = 0; p + 1 < _partitionStarts.size(); ++p)
        {
            TileGlyphs glyphs;
            glyphs.origin = tail.origin;
            std::size_t count = 0;
            for (std::size_t u = _partitionStarts[p]; u < _partitionStarts[p + 1]; ++u)
                count += _units[u].glyphs;
            _format.reserve(glyphs, count);
            std::vector<std::size_t> runs;
            if (!gather(_partitionCodes[p], _partitionCodes[p + 1], tail, glyphs, runs, error))
                return nullptr;
            TileTree tree(glyphs, _writer, runs);
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
    /** Appends the glyphs with codes in [begin, end) to glyphs: those of the buckets, in octree
     * order, then those of the tail, each in the order they came. A bucket lies in one unit (a
     * unit is the largest node of at most the budget, or a node at the count level, and a bucket
     * is a node of at most the budget, or at the count level), so in one partition. Without a
     * tail, runs are where the buckets' glyphs start (else none: the tail's glyphs may lie
     * anywhere). */
    bool gather(uint64_t begin, uint64_t end, const TileGlyphs& tail, TileGlyphs& glyphs,
                std::vector<std::size_t>& runs, std::string& error)
    {
        for (; _nextSource < _sources.size(); ++_nextSource)
        {
            const Source& source = _sources[_nextSource];
            const uint64_t first = firstCode(source.level, source.prefix);
            if (first >= end)
                break;
            runs.push_back(glyphs.size());
            if (first < begin || !source.buckets->read(
                                     source.bucket,
                                     [&glyphs](const TileGlyphs& block)
                                     {
                                         glyphs.append(block);
                                         return true;
                                     },
                                     error))
            {
                if (error.empty())
                    error = "a bucket of the temporary files lies across two partitions";
                return false;
            }
        }
        for (std::size_t i = 0; i < tail.size(); ++i)
            if (_tailCodes[i] >= begin && _tailCodes[i] < end)
                glyphs.append(tail, i);
        if (!_tailCodes.empty())
            runs.clear();
        return true;
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
    TileRecordFormat _format;
    std::size_t _budget;
    unsigned int _countLevel;
    std::vector<std::size_t> _before; // glyphs before each node of the count level
    std::vector<Unit> _units;         // in octree order
    std::vector<std::size_t> _partitionStarts;
    std::vector<uint64_t> _partitionCodes;
    std::string _temporaryPrefix;
    std::vector<uint64_t> _tailCodes;
    std::vector<Source> _sources; // in octree order
    std::size_t _nextSource = 0;  // the first that the next partition reads
    std::vector<std::unique_ptr<TileBuckets>> _splits;
    std::vector<OpenNode> _open; // the nodes above the current unit, root first
    osg::ref_ptr<osg::Node> _root;
};

}

std::unique_ptr<TileBuckets> osgGlyphsTiles::detail::createStreamBuckets(const std::string& path,
                                                                         const TileRecordFormat& format,
                                                                         const OctreeCube& cube,
                                                                         const TileOptions& options,
                                                                         std::vector<std::size_t>& counts)
{
    const unsigned int countLevel = countLevelOf(options);
    auto buckets =
        std::make_unique<TileBuckets>(path, format, cube, 0, 0, std::min(BUCKET_LEVELS, countLevel));
    counts.assign(std::size_t(1) << 3 * countLevel, 0);
    buckets->setCounter(&counts, countLevel);
    return buckets;
}

osg::ref_ptr<osg::Node>
osgGlyphsTiles::detail::buildStreamedTree(TileBuckets& buckets, std::vector<std::size_t> counts,
                                          const TileGlyphs& tail, TileWriter& writer, std::size_t budget,
                                          const std::string& temporaryPrefix, std::string& error)
{
    StreamedTree tree(writer, buckets.getFormat(), budget, temporaryPrefix);
    tree.count(counts, tail);
    tree.partition();
    if (!tree.findSources(buckets, error))
        return nullptr;
    return tree.build(tail, error);
}
