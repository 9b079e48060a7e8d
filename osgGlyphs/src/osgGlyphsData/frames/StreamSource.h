/* osgGlyphs - private: what the compressed sources (gzip, zstd) share: the table of their restart
 * points, and the reading of a stream that goes on where it stands or restarts at a point. */

#ifndef OSGGLYPHS_FRAMES_STREAMSOURCE_H
#define OSGGLYPHS_FRAMES_STREAMSOURCE_H 1

#include "ByteSource.h"

#include <algorithm>
#include <mutex>
#include <vector>

namespace osgGlyphsData
{
namespace frames
{

/** The restart points of a compressed file, in the order of their offsets; PointT has the compressed
 * offset in and the uncompressed offset out where decompression restarts. Thread-safe.
 *
 * toBytes(), all little-endian: the magic (4 characters), version 1 (4 bytes), the CRC-32 of what
 * follows (4), the covered end (8), the number of points (8), then the points as writePoint() writes
 * them. */
template <class PointT>
class CheckpointTable : public Checkpoints
{
public:
    typedef PointT Point;

    std::size_t size() const override;
    uint64_t getCoveredEnd() const override;
    std::string toBytes() const override;
    bool fromBytes(const std::string& bytes) override;

    /** The last point at or before offset; false when there is none. */
    bool findPoint(uint64_t offset, Point& point) const;

    /** Records that a reader decompressed without a gap from runStart to end. */
    void cover(uint64_t runStart, uint64_t end);

protected:
    /** magic: the 4 characters that begin toBytes(); pointBytes: the fewest bytes a point takes in
     * it (bounds the points a blob may claim). */
    CheckpointTable(const char* magic, std::size_t pointBytes) : _magic(magic), _pointBytes(pointBytes) {}

    /** Appends point to the serialisation body. */
    virtual void writePoint(std::string& body, const Point& point) const = 0;

    /** Reads the next point; false when it is malformed or may not follow previous (nullptr: it is
     * the first). */
    virtual bool readPoint(BlobReader& reader, const Point* previous, Point& point) const = 0;

    mutable std::mutex _mutex;
    std::vector<Point> _points;
    uint64_t _coveredEnd = 0;

private:
    bool readPoints(BlobReader& reader, std::vector<Point>& points) const;

    const char* const _magic;
    const std::size_t _pointBytes;
};

/** Reads a compressed file (a sequence of units: gzip members, zstd frames) at any offset: goes on
 * where its stream stands, else restarts at the last point of Table (a CheckpointTable) before the
 * offset. The compression's steps are the virtual functions. */
template <class Table>
class StreamSource : public ByteSource
{
public:
    typedef typename Table::Point Point;

    const std::string& getName() const override { return _file->getName(); }
    std::size_t read(uint64_t offset, char* out, std::size_t size) override;
    uint64_t getFileSize() const override { return _file->getSize(); }
    std::shared_ptr<Checkpoints> getCheckpoints() const override { return _checkpoints; }

    /** For tests and measurements: how often decompression restarted, and the bytes it produced. */
    uint64_t getRestarts() const { return _restarts; }
    uint64_t getDecodedBytes() const { return _decoded; }

protected:
    static constexpr std::size_t InputSize = std::size_t(256) << 10;
    static constexpr std::size_t DiscardSize = std::size_t(64) << 10;

    enum class Mode
    {
        UnitStart, // before a unit's header, or the end
        Decoding,
        Trailer, // after a unit's data: what ends it (gzip, restarted mid-member: its CRC and size)
        Failed   // corrupt data: the next read restarts
    };

    /** checkpoints: nullptr for new ones. */
    StreamSource(std::unique_ptr<SourceFile> file, std::shared_ptr<Table> checkpoints);

    /** In Mode::UnitStart: starts the unit at the input (Mode::Decoding), or passes what is not
     * decoded; false at the end of the file. */
    virtual bool startUnit() = 0;

    /** In Mode::Decoding: decodes up to size bytes into out, through advance(); may return 0 (when
     * the unit ends, or only its metadata was read). */
    virtual std::size_t decodeSome(unsigned char* out, std::size_t size) = 0;

    /** In Mode::Trailer: reads and checks what ends the unit, then Mode::UnitStart (by default,
     * nothing ends it). */
    virtual void readTrailer() { _mode = Mode::UnitStart; }

    /** After a restart at point, with the input at point.in and Mode::UnitStart: readies the stream
     * where the point is not at a unit's start. */
    virtual void enter(const Point& /*point*/) {}

    /** Counts count more bytes decoded. */
    void advance(std::size_t count);

    /** Throws SourceError "<file>: byte <byte>: <what>", in Mode::Failed. */
    [[noreturn]] void failCorrupt(uint64_t byte, const std::string& what);

    std::unique_ptr<SourceFile> _file;
    std::shared_ptr<Table> _checkpoints;
    SourceInput _input;
    Mode _mode = Mode::UnitStart;
    uint64_t _out = 0;
    uint64_t _runStart = 0;

private:
    void moveTo(uint64_t offset);
    void restart(const Point* point);
    std::size_t produce(unsigned char* out, std::size_t size);

    std::vector<unsigned char> _discard;
    uint64_t _restarts = 0;
    uint64_t _decoded = 0;
};

template <class PointT>
std::size_t CheckpointTable<PointT>::size() const
{
    std::lock_guard<std::mutex> lock(_mutex);
    return _points.size();
}

template <class PointT>
uint64_t CheckpointTable<PointT>::getCoveredEnd() const
{
    std::lock_guard<std::mutex> lock(_mutex);
    return _coveredEnd;
}

template <class PointT>
std::string CheckpointTable<PointT>::toBytes() const
{
    std::lock_guard<std::mutex> lock(_mutex);
    std::string body;
    appendLittleEndian(body, _coveredEnd, 8);
    appendLittleEndian(body, _points.size(), 8);
    for (const Point& point : _points)
        writePoint(body, point);
    return sealCheckpoints(_magic, body);
}

template <class PointT>
bool CheckpointTable<PointT>::fromBytes(const std::string& bytes)
{
    if (!checkSeal(bytes, _magic))
        return false;
    BlobReader reader(bytes);
    uint64_t coveredEnd = 0, count = 0;
    if (!reader.number(coveredEnd, 8) || !reader.number(count, 8) || count > reader.left() / _pointBytes)
        return false;
    std::vector<Point> points(static_cast<std::size_t>(count));
    if (!readPoints(reader, points) || reader.left() != 0 ||
        (!points.empty() && coveredEnd < points.back().out) || (points.empty() && coveredEnd))
        return false;
    std::lock_guard<std::mutex> lock(_mutex);
    _points = std::move(points);
    _coveredEnd = coveredEnd;
    return true;
}

template <class PointT>
bool CheckpointTable<PointT>::readPoints(BlobReader& reader, std::vector<Point>& points) const
{
    for (std::size_t i = 0; i < points.size(); ++i)
    {
        if (!readPoint(reader, i ? &points[i - 1] : nullptr, points[i]))
            return false;
    }
    return true;
}

template <class PointT>
bool CheckpointTable<PointT>::findPoint(uint64_t offset, Point& point) const
{
    std::lock_guard<std::mutex> lock(_mutex);
    auto after = std::upper_bound(_points.begin(), _points.end(), offset,
                                  [](uint64_t value, const Point& p) { return value < p.out; });
    if (after == _points.begin())
        return false;
    point = *(after - 1);
    return true;
}

template <class PointT>
void CheckpointTable<PointT>::cover(uint64_t runStart, uint64_t end)
{
    std::lock_guard<std::mutex> lock(_mutex);
    if (runStart <= _coveredEnd)
        _coveredEnd = std::max(_coveredEnd, end);
}

template <class Table>
StreamSource<Table>::StreamSource(std::unique_ptr<SourceFile> file, std::shared_ptr<Table> checkpoints)
    : _file(std::move(file)), _checkpoints(checkpoints ? checkpoints : std::make_shared<Table>()),
      _input(*_file, InputSize), _discard(DiscardSize)
{
}

template <class Table>
std::size_t StreamSource<Table>::read(uint64_t offset, char* out, std::size_t size)
{
    moveTo(offset);
    while (_out < offset)
    {
        const std::size_t skip = static_cast<std::size_t>(std::min<uint64_t>(offset - _out, _discard.size()));
        if (produce(_discard.data(), skip) == 0)
            break;
    }
    std::size_t done = 0;
    while (done < size && _out == offset + done) // _out < offset: the content ends before offset
    {
        const std::size_t got = produce(reinterpret_cast<unsigned char*>(out) + done, size - done);
        if (got == 0)
            break;
        done += got;
    }
    _checkpoints->cover(_runStart, _out);
    return done;
}

template <class Table>
void StreamSource<Table>::moveTo(uint64_t offset)
{
    Point point;
    const bool found = _checkpoints->findPoint(offset, point);
    if (_mode != Mode::Failed && offset >= _out && (!found || point.out <= _out))
        return;
    restart(found ? &point : nullptr);
}

template <class Table>
void StreamSource<Table>::restart(const Point* point)
{
    ++_restarts;
    _out = _runStart = point ? point->out : 0;
    _mode = Mode::UnitStart;
    _input.seek(point ? point->in : 0);
    if (point)
        enter(*point);
}

template <class Table>
std::size_t StreamSource<Table>::produce(unsigned char* out, std::size_t size)
{
    for (;;)
    {
        if (_mode == Mode::UnitStart && !startUnit())
            return 0;
        if (_mode == Mode::Trailer)
            readTrailer();
        if (_mode == Mode::Decoding)
        {
            const std::size_t got = decodeSome(out, size);
            if (got)
                return got;
        }
    }
}

template <class Table>
void StreamSource<Table>::advance(std::size_t count)
{
    _out += count;
    _decoded += count;
}

template <class Table>
void StreamSource<Table>::failCorrupt(uint64_t byte, const std::string& what)
{
    _mode = Mode::Failed;
    _file->fail(byte, what);
}

}
}

#endif
