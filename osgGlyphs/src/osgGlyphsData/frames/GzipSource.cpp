#include "GzipSource.h"

#include <algorithm>
#include <climits>
#include <new>

using namespace osgGlyphsData::frames;

namespace
{

const int GZIP_WINDOW_BITS = 15 + 16;
const int RAW_WINDOW_BITS = -15;
const char* const MAGIC = "GZCP";
// in, out, memberOut, memberCrc, bits, the window's size
const std::size_t POINT_BYTES = 8 + 8 + 8 + 4 + 1 + 4;

uint32_t littleEndian32(const unsigned char* bytes)
{
    return uint32_t(bytes[0]) | uint32_t(bytes[1]) << 8 | uint32_t(bytes[2]) << 16 | uint32_t(bytes[3]) << 24;
}

std::size_t windowLength(const GzipCheckpoints::Point& point)
{
    return static_cast<std::size_t>(
        std::min<uint64_t>(GzipCheckpoints::WindowSize, point.out - point.memberOut));
}

/** The window of point, uncompressed into window (of WindowSize bytes); false when it is corrupt. */
bool expandWindow(const GzipCheckpoints::Point& point, unsigned char* window)
{
    const std::string& packed = *point.window;
    uLongf length = GzipCheckpoints::WindowSize;
    return uncompress(window, &length, reinterpret_cast<const Bytef*>(packed.data()), uLong(packed.size())) ==
               Z_OK &&
           length == windowLength(point);
}

uint64_t bitPosition(const GzipCheckpoints::Point& point)
{
    return point.in * 8 - uint64_t(point.bits);
}

/** Whether point may follow previous (nullptr: first) in a valid list. */
bool canFollow(const GzipCheckpoints::Point* previous, const GzipCheckpoints::Point& point)
{
    if (point.bits < 0 || point.bits > 7 || point.in >= (uint64_t(1) << 60) || point.memberOut > point.out)
        return false;
    if (point.isMemberStart() && (point.bits != 0 || point.memberCrc != 0 || !point.window->empty()))
        return false;
    if (!previous)
        return point.in == 0 && point.out == 0 && point.isMemberStart();
    if (point.out <= previous->out || bitPosition(point) <= bitPosition(*previous))
        return false;
    // A member's start has no point of its own where a point of the member before is at its end.
    return point.isMemberStart() || point.memberOut == previous->memberOut ||
           point.memberOut >= previous->out;
}

bool readFields(BlobReader& reader, GzipCheckpoints::Point& point)
{
    uint64_t crc = 0, bits = 0, packedSize = 0;
    std::string window;
    if (!reader.number(point.in, 8) || !reader.number(point.out, 8) || !reader.number(point.memberOut, 8) ||
        !reader.number(crc, 4) || !reader.number(bits, 1) || !reader.number(packedSize, 4) ||
        packedSize > compressBound(GzipCheckpoints::WindowSize) || !reader.bytes(window, packedSize))
        return false;
    point.memberCrc = static_cast<uint32_t>(crc);
    point.bits = static_cast<int>(bits);
    point.window = std::make_shared<const std::string>(std::move(window));
    return true;
}

}

GzipCheckpoints::GzipCheckpoints(uint64_t span)
    : CheckpointTable(MAGIC, POINT_BYTES), _span(std::max<uint64_t>(span, 1))
{
}

void GzipCheckpoints::writePoint(std::string& body, const Point& point) const
{
    appendLittleEndian(body, point.in, 8);
    appendLittleEndian(body, point.out, 8);
    appendLittleEndian(body, point.memberOut, 8);
    appendLittleEndian(body, point.memberCrc, 4);
    appendLittleEndian(body, uint64_t(point.bits), 1);
    appendLittleEndian(body, point.window->size(), 4);
    body += *point.window;
}

bool GzipCheckpoints::readPoint(BlobReader& reader, const Point* previous, Point& point) const
{
    if (!readFields(reader, point) || !canFollow(previous, point))
        return false;
    if (point.isMemberStart())
        return true;
    std::unique_ptr<unsigned char[]> window(new unsigned char[WindowSize]);
    return expandWindow(point, window.get());
}

bool GzipCheckpoints::wantsPoint(uint64_t runStart, uint64_t out, bool memberStart) const
{
    std::lock_guard<std::mutex> lock(_mutex);
    return wanted(runStart, out, memberStart);
}

bool GzipCheckpoints::wanted(uint64_t runStart, uint64_t out, bool memberStart) const
{
    if (runStart > _coveredEnd)
        return false;
    if (_points.empty())
        return memberStart && out == 0;
    const uint64_t last = _points.back().out;
    return out > last && (memberStart || out - last >= _span);
}

void GzipCheckpoints::addPoint(uint64_t runStart, Point point)
{
    std::lock_guard<std::mutex> lock(_mutex);
    if (!wanted(runStart, point.out, point.isMemberStart()))
        return;
    _coveredEnd = std::max(_coveredEnd, point.out);
    _points.push_back(std::move(point));
}

GzipSource::GzipSource(std::unique_ptr<SourceFile> file, std::shared_ptr<GzipCheckpoints> checkpoints)
    : StreamSource(std::move(file), checkpoints), _stream(), _packer(), _window(GzipCheckpoints::WindowSize)
{
    if (inflateInit2(&_stream, RAW_WINDOW_BITS) != Z_OK)
        throw std::bad_alloc();
}

GzipSource::~GzipSource()
{
    inflateEnd(&_stream);
    if (_packerReady)
        deflateEnd(&_packer);
}

void GzipSource::enter(const Point& point)
{
    if (point.isMemberStart())
        return;
    _mode = Mode::Failed;
    inflateReset2(&_stream, RAW_WINDOW_BITS);
    _raw = true;
    if (point.bits)
    {
        _input.seek(point.in - 1);
        if (_input.fill(1) < 1)
            _file->fail(point.in - 1, "the gzip stream ends inside a member", true);
        inflatePrime(&_stream, point.bits, _input.data()[0] >> (8 - point.bits));
        _input.consume(1);
    }
    if (!expandWindow(point, _window.data()))
        _file->fail(point.in, "corrupt checkpoint (its window does not uncompress)");
    inflateSetDictionary(&_stream, _window.data(), uInt(windowLength(point)));
    _memberOut = point.memberOut;
    _memberCrc = point.memberCrc;
    _mode = Mode::Decoding;
}

bool GzipSource::startUnit()
{
    const std::size_t available = _input.fill(2);
    const uint64_t at = _input.position();
    const unsigned char* bytes = _input.data();
    if (available == 0)
        return false;
    if (bytes[0] == 0 && at > 0)
    {
        // Trailing zeros after a member, which gzip(1) ignores too.
        std::size_t zeros = 0;
        while (zeros < available && bytes[zeros] == 0)
            ++zeros;
        _input.consume(zeros);
        return true;
    }
    if (bytes[0] != 0x1f || (available >= 2 && bytes[1] != 0x8b))
        failCorrupt(at, at == 0 ? "not gzip data (no gzip magic number)"
                                : "garbage after the end of a gzip member (not a new member)");
    if (available < 2)
        _file->fail(at + 1, "the gzip stream ends inside a member header", true);
    GzipCheckpoints::Point point;
    point.in = at;
    point.out = point.memberOut = _out;
    point.window = std::make_shared<const std::string>();
    _checkpoints->addPoint(_runStart, point);
    inflateReset2(&_stream, GZIP_WINDOW_BITS);
    _raw = false;
    _memberOut = _out;
    _mode = Mode::Decoding;
    return true;
}

std::size_t GzipSource::decodeSome(unsigned char* out, std::size_t size)
{
    if (_input.available() == 0)
        _input.fill();
    const uInt available = uInt(std::min<std::size_t>(_input.available(), UINT_MAX));
    _stream.next_in = const_cast<Bytef*>(_input.data());
    _stream.avail_in = available;
    _stream.next_out = out;
    _stream.avail_out = uInt(std::min<std::size_t>(size, UINT_MAX));
    const int result = inflate(&_stream, Z_BLOCK);
    _input.consume(available - _stream.avail_in);
    const std::size_t got = static_cast<std::size_t>(_stream.next_out - out);
    advance(got);
    if (_raw)
        _memberCrc = uint32_t(crc32(_memberCrc, out, uInt(got)));
    switch (result)
    {
    case Z_OK:
        notePoint();
        break;
    case Z_STREAM_END:
        _mode = _raw ? Mode::Trailer : Mode::UnitStart;
        break;
    case Z_BUF_ERROR: // no progress: the input is used up
        _file->fail(_input.position(), "the gzip stream ends inside a member", true);
    case Z_MEM_ERROR:
        _mode = Mode::Failed;
        throw std::bad_alloc();
    default: // Z_DATA_ERROR, Z_NEED_DICT (a preset dictionary, which gzip does not have)
        failCorrupt(_input.position(),
                    std::string("corrupt gzip data (") + (_stream.msg ? _stream.msg : zError(result)) + ")");
    }
    return got;
}

void GzipSource::notePoint()
{
    const bool boundary = (_stream.data_type & 128) && !(_stream.data_type & 64);
    if (!boundary || _out == _memberOut || !_checkpoints->wantsPoint(_runStart, _out, false))
        return;
    GzipCheckpoints::Point point;
    point.in = _input.position();
    point.bits = _stream.data_type & 7;
    point.out = _out;
    point.memberOut = _memberOut;
    point.memberCrc = _raw ? _memberCrc : uint32_t(_stream.adler);
    uInt length = uInt(_window.size());
    if (inflateGetDictionary(&_stream, _window.data(), &length) != Z_OK || length != windowLength(point))
        return;
    point.window = packWindow(length);
    _checkpoints->addPoint(_runStart, std::move(point));
}

std::shared_ptr<const std::string> GzipSource::packWindow(std::size_t length)
{
    // One deflate stream for all: compress() would allocate and clear its state each time.
    if (!_packerReady && deflateInit(&_packer, Z_BEST_SPEED) != Z_OK)
        throw std::bad_alloc();
    _packerReady = true;
    deflateReset(&_packer);
    std::string packed(deflateBound(&_packer, uLong(length)), '\0');
    _packer.next_in = _window.data();
    _packer.avail_in = uInt(length);
    _packer.next_out = reinterpret_cast<Bytef*>(&packed[0]);
    _packer.avail_out = uInt(packed.size());
    if (deflate(&_packer, Z_FINISH) != Z_STREAM_END)
        throw std::bad_alloc();
    packed.resize(_packer.total_out);
    return std::make_shared<const std::string>(std::move(packed));
}

void GzipSource::readTrailer()
{
    if (_input.fill(8) < 8)
        _file->fail(_input.position() + _input.available(), "the gzip stream ends inside a member", true);
    // The bytes named are those where zlib reports these errors, when it reads the trailer itself.
    const uint64_t at = _input.position();
    if (littleEndian32(_input.data()) != _memberCrc)
        failCorrupt(at + 4, "corrupt gzip data (incorrect data check)");
    if (littleEndian32(_input.data() + 4) != uint32_t(_out - _memberOut))
        failCorrupt(at + 8, "corrupt gzip data (incorrect length check)");
    _input.consume(8);
    _mode = Mode::UnitStart;
}
