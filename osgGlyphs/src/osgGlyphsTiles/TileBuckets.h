/* osgGlyphs - private: glyphs sorted into octree nodes as they come, in a temporary file, while a
 * dataset larger than memory is cut into tiles. Not installed. */

#ifndef OSGGLYPHS_TILEBUCKETS_H
#define OSGGLYPHS_TILEBUCKETS_H 1

#include "TileSpill.h"

#include <condition_variable>
#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace osgGlyphsTiles
{
namespace detail
{

/** Glyph records sorted by the octree node they fall in, the buckets: the nodes some levels below
 * a node of the cube. They go into one temporary file (deleted with the buckets) a block of one
 * bucket at a time, so that a bucket reads back as its glyphs in the order they were added, and
 * sorting a dataset into them costs one write of its records. The blocks are written on a thread
 * of the buckets' own while the next ones fill.
 *
 * The buckets can also count the glyphs per node of a deeper level as they come (setCounter). */
class TileBuckets
{
public:
    /** Buckets at bucketLevel under the node at level with prefix of cube; the file at path
     * (isOpen() tells whether it could be made). */
    TileBuckets(const std::string& path, const TileRecordFormat& format, const OctreeCube& cube,
                unsigned int level, uint64_t prefix, unsigned int bucketLevel);
    ~TileBuckets();
    TileBuckets(const TileBuckets&) = delete;
    TileBuckets& operator=(const TileBuckets&) = delete;

    bool isOpen() const { return _file >= 0; }
    const std::string& getPath() const { return _path; }
    const TileRecordFormat& getFormat() const { return _format; }
    unsigned int getBucketLevel() const { return _bucketLevel; }
    std::size_t getNumBuckets() const { return _buckets.size(); }
    /** The prefix of a bucket's node at getBucketLevel(). */
    uint64_t getBucketPrefix(std::size_t bucket) const { return _firstBucket + bucket; }
    std::size_t getBucketSize(std::size_t bucket) const { return _buckets[bucket].count; }
    std::size_t size() const { return _count; }

    /** Counts every glyph added from now on into counts (8^countLevel of them), by its node at
     * countLevel. */
    void setCounter(std::vector<std::size_t>* counts, unsigned int countLevel);

    /** Adds the glyphs [begin, end) of glyphs, which must lie in the buckets' node (codes outside
     * the cube are clamped to it). False with error naming the file when writing fails. */
    bool add(const TileGlyphs& glyphs, std::size_t begin, std::size_t end, std::string& error);

    /** Calls visit with the glyphs of a bucket in the order they were added, a block at a time
     * (the block's origin and range are not set); stops at the first false from visit. */
    bool read(std::size_t bucket, const std::function<bool(const TileGlyphs& block)>& visit,
              std::string& error);

private:
    typedef std::unique_ptr<unsigned char[]> Block;

    /** The records of one bucket: blocks in the file, then those not yet written. */
    struct Bucket
    {
        std::vector<uint64_t> blocks; // offsets of full blocks
        Block buffer;
        std::size_t pending = 0; // records in buffer
        std::size_t count = 0;
    };

    /** A block on its way to the file. */
    struct Write
    {
        uint64_t offset;
        Block bytes;
    };

    /** Hands the bucket's full block to the writing thread and gives it an empty one. */
    bool writeBlock(Bucket& bucket, std::string& error);
    /** Waits until every block handed over is in the file; false with error if one could not be. */
    bool finishWrites(std::string& error);
    void writeBlocks();

    std::string _path;
    TileRecordFormat _format;
    OctreeCube _cube;
    unsigned int _bucketLevel;
    uint64_t _firstBucket;
    std::vector<Bucket> _buckets;
    std::size_t _count = 0;
    int _file = -1;
    uint64_t _fileSize = 0;
    std::vector<std::size_t>* _counts = nullptr;
    unsigned int _countShift = 0;

    std::thread _writer;
    std::mutex _mutex; // the members below
    std::condition_variable _changed;
    std::deque<Write> _writes;
    std::size_t _writing = 0;  // writes taken from the queue, not yet done
    std::vector<Block> _spare; // written blocks, to fill again
    bool _stopping = false;
    std::string _writeError;
};

}
}

#endif
