#include "TileBuckets.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

using namespace osgGlyphsTiles::detail;

namespace
{

/** Records of one bucket written or read at a time: with 512 buckets of 36-byte records, 36 MiB
 * of buffers. */
const std::size_t BLOCK_RECORDS = 2048;

/** Blocks waiting for the writing thread before adding waits for it. */
const std::size_t MAX_QUEUED_WRITES = 64;

}

TileBuckets::TileBuckets(const std::string& path, const TileRecordFormat& format, const OctreeCube& cube,
                         unsigned int level, uint64_t prefix, unsigned int bucketLevel)
    : _path(path), _format(format), _cube(cube), _bucketLevel(bucketLevel),
      _firstBucket(prefix << 3 * (bucketLevel - level)),
      _buckets(std::size_t(1) << 3 * (bucketLevel - level)),
      _file(::open(path.c_str(), O_RDWR | O_CREAT | O_TRUNC | O_CLOEXEC, 0600))
{
}

TileBuckets::~TileBuckets()
{
    if (_writer.joinable())
    {
        {
            std::lock_guard<std::mutex> lock(_mutex);
            _stopping = true;
        }
        _changed.notify_all();
        _writer.join();
    }
    if (_file >= 0)
    {
        ::close(_file);
        ::unlink(_path.c_str());
    }
}

void TileBuckets::setCounter(std::vector<std::size_t>* counts, unsigned int countLevel)
{
    _counts = counts;
    _countShift = 3 * (MORTON_LEVELS - countLevel);
}

bool TileBuckets::writeBlock(Bucket& bucket, std::string& error)
{
    const std::size_t size = BLOCK_RECORDS * _format.size();
    bucket.blocks.push_back(_fileSize);
    {
        std::unique_lock<std::mutex> lock(_mutex);
        _changed.wait(lock, [this] { return _writes.size() < MAX_QUEUED_WRITES || !_writeError.empty(); });
        if (!_writeError.empty())
        {
            error = _writeError;
            return false;
        }
        _writes.push_back({_fileSize, std::move(bucket.buffer)});
        if (!_spare.empty())
        {
            bucket.buffer = std::move(_spare.back());
            _spare.pop_back();
        }
    }
    _changed.notify_all();
    if (!_writer.joinable())
        _writer = std::thread(&TileBuckets::writeBlocks, this);
    if (!bucket.buffer)
        bucket.buffer.reset(new unsigned char[size]);
    _fileSize += size;
    bucket.pending = 0;
    return true;
}

void TileBuckets::writeBlocks()
{
    const std::size_t size = BLOCK_RECORDS * _format.size();
    std::unique_lock<std::mutex> lock(_mutex);
    while (true)
    {
        _changed.wait(lock, [this] { return !_writes.empty() || _stopping; });
        if (_writes.empty())
            return;
        Write write = std::move(_writes.front());
        _writes.pop_front();
        ++_writing;
        lock.unlock();
        std::string error;
        const unsigned char* bytes = write.bytes.get();
        for (std::size_t done = 0; done < size && error.empty();)
        {
            const ssize_t written =
                ::pwrite(_file, bytes + done, size - done, static_cast<off_t>(write.offset + done));
            if (written > 0)
                done += static_cast<std::size_t>(written);
            else
                error = _path + ": cannot write the temporary file (" +
                        std::strerror(written < 0 ? errno : ENOSPC) + ")";
        }
        lock.lock();
        --_writing;
        _spare.push_back(std::move(write.bytes));
        if (!error.empty() && _writeError.empty())
            _writeError = error;
        _changed.notify_all();
    }
}

bool TileBuckets::finishWrites(std::string& error)
{
    std::unique_lock<std::mutex> lock(_mutex);
    _changed.wait(lock, [this] { return _writes.empty() && _writing == 0; });
    if (!_writeError.empty())
        error = _writeError;
    return _writeError.empty();
}

bool TileBuckets::add(const TileGlyphs& glyphs, std::size_t begin, std::size_t end, std::string& error)
{
    const std::size_t size = _format.size();
    const unsigned int bucketShift = 3 * (MORTON_LEVELS - _bucketLevel);
    for (std::size_t i = begin; i < end; ++i)
    {
        const uint64_t code = _cube.code(osg::Vec3d(glyphs.positions[i]));
        if (_counts)
            ++(*_counts)[code >> _countShift];
        Bucket& bucket = _buckets[(code >> bucketShift) - _firstBucket];
        if (!bucket.buffer)
            bucket.buffer.reset(new unsigned char[BLOCK_RECORDS * size]);
        _format.pack(glyphs, i, bucket.buffer.get() + bucket.pending * size);
        ++bucket.count;
        if (++bucket.pending == BLOCK_RECORDS && !writeBlock(bucket, error))
            return false;
    }
    _count += end - begin;
    return true;
}

bool TileBuckets::read(std::size_t index, const std::function<bool(const TileGlyphs& block)>& visit,
                       std::string& error)
{
    if (!finishWrites(error))
        return false;
    const Bucket& bucket = _buckets[index];
    const std::size_t size = _format.size();
    std::vector<unsigned char> bytes(BLOCK_RECORDS * size);
    TileGlyphs block;
    for (const uint64_t offset : bucket.blocks)
    {
        const ssize_t got = ::pread(_file, bytes.data(), bytes.size(), static_cast<off_t>(offset));
        if (got != static_cast<ssize_t>(bytes.size()))
        {
            error = _path + ": cannot read the temporary file back at byte " + std::to_string(offset) +
                    (got < 0 ? std::string(" (") + std::strerror(errno) + ")" : std::string(": it ends"));
            return false;
        }
        _format.unpack(bytes.data(), BLOCK_RECORDS, block);
        if (!visit(block))
            return true;
    }
    if (bucket.pending)
    {
        _format.unpack(bucket.buffer.get(), bucket.pending, block);
        visit(block);
    }
    return true;
}
