#include "ZstdSource.h"

#include <zstd.h>

#include <algorithm>
#include <new>

using namespace osgGlyphsData::frames;

namespace
{

const std::size_t INPUT_SIZE = std::size_t(256) << 10;
const std::size_t DISCARD_SIZE = std::size_t(64) << 10;
const char* const MAGIC = "ZSCP";
const uint32_t FRAME_MAGIC = 0xFD2FB528u;
const uint32_t SKIPPABLE_MAGIC = 0x184D2A50u; // to 0x184D2A5F
const std::size_t SKIPPABLE_HEADER = 8;

uint32_t littleEndian32(const unsigned char* bytes)
{
    return uint32_t(bytes[0]) | uint32_t(bytes[1]) << 8 | uint32_t(bytes[2]) << 16 | uint32_t(bytes[3]) << 24;
}

bool canFollow(const ZstdCheckpoints::Point* previous, const ZstdCheckpoints::Point& point)
{
    if (!previous)
        return point.in == 0 && point.out == 0;
    return point.in > previous->in && point.out > previous->out;
}

}

std::size_t ZstdCheckpoints::size() const
{
    std::lock_guard<std::mutex> lock(_mutex);
    return _points.size();
}

uint64_t ZstdCheckpoints::getCoveredEnd() const
{
    std::lock_guard<std::mutex> lock(_mutex);
    return _coveredEnd;
}

std::string ZstdCheckpoints::toBytes() const
{
    std::lock_guard<std::mutex> lock(_mutex);
    std::string body;
    appendLittleEndian(body, _coveredEnd, 8);
    appendLittleEndian(body, _points.size(), 8);
    for (const Point& point : _points)
    {
        appendLittleEndian(body, point.in, 8);
        appendLittleEndian(body, point.out, 8);
    }
    return sealCheckpoints(MAGIC, body);
}

bool ZstdCheckpoints::fromBytes(const std::string& bytes)
{
    if (!checkSeal(bytes, MAGIC))
        return false;
    BlobReader reader(bytes);
    uint64_t coveredEnd = 0, count = 0;
    if (!reader.number(coveredEnd, 8) || !reader.number(count, 8) || count != reader.left() / 16 ||
        reader.left() % 16 != 0)
        return false;
    std::vector<Point> points(static_cast<std::size_t>(count));
    for (std::size_t i = 0; i < points.size(); ++i)
    {
        if (!reader.number(points[i].in, 8) || !reader.number(points[i].out, 8) ||
            !canFollow(i ? &points[i - 1] : nullptr, points[i]))
            return false;
    }
    if ((!points.empty() && coveredEnd < points.back().out) || (points.empty() && coveredEnd))
        return false;
    std::lock_guard<std::mutex> lock(_mutex);
    _points = std::move(points);
    _coveredEnd = coveredEnd;
    return true;
}

bool ZstdCheckpoints::findPoint(uint64_t offset, Point& point) const
{
    std::lock_guard<std::mutex> lock(_mutex);
    auto after = std::upper_bound(_points.begin(), _points.end(), offset,
                                  [](uint64_t value, const Point& p) { return value < p.out; });
    if (after == _points.begin())
        return false;
    point = *(after - 1);
    return true;
}

void ZstdCheckpoints::addPoint(uint64_t runStart, const Point& point)
{
    std::lock_guard<std::mutex> lock(_mutex);
    if (runStart > _coveredEnd)
        return;
    const Point* last = _points.empty() ? nullptr : &_points.back();
    if (canFollow(last, point))
        _points.push_back(point);
    _coveredEnd = std::max(_coveredEnd, point.out);
}

void ZstdCheckpoints::cover(uint64_t runStart, uint64_t end)
{
    std::lock_guard<std::mutex> lock(_mutex);
    if (runStart <= _coveredEnd)
        _coveredEnd = std::max(_coveredEnd, end);
}

ZstdSource::ZstdSource(std::unique_ptr<SourceFile> file, std::shared_ptr<ZstdCheckpoints> checkpoints)
    : _file(std::move(file)), _checkpoints(checkpoints ? checkpoints : std::make_shared<ZstdCheckpoints>()),
      _input(*_file, INPUT_SIZE), _context(ZSTD_createDCtx()), _discard(DISCARD_SIZE)
{
    if (!_context)
        throw std::bad_alloc();
}

ZstdSource::~ZstdSource()
{
    ZSTD_freeDCtx(_context);
}

std::size_t ZstdSource::read(uint64_t offset, char* out, std::size_t size)
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

void ZstdSource::moveTo(uint64_t offset)
{
    ZstdCheckpoints::Point point;
    const bool found = _checkpoints->findPoint(offset, point);
    if (_mode != Mode::Failed && offset >= _out && (!found || point.out <= _out))
        return;
    ++_restarts;
    _out = _runStart = found ? point.out : 0;
    _input.seek(found ? point.in : 0);
    _mode = Mode::FrameStart;
}

std::size_t ZstdSource::produce(unsigned char* out, std::size_t size)
{
    for (;;)
    {
        if (_mode == Mode::FrameStart && !startFrame())
            return 0;
        if (_mode == Mode::Decoding)
        {
            const std::size_t got = decodeSome(out, size);
            if (got)
                return got;
        }
    }
}

bool ZstdSource::startFrame()
{
    const std::size_t available = _input.fill(4);
    const uint64_t at = _input.position();
    if (available == 0)
        return false;
    if (available < 4)
        _file->fail(at + available, "the zstd stream ends inside a frame header", true);
    const uint32_t magic = littleEndian32(_input.data());
    const bool skippable = (magic & 0xFFFFFFF0u) == SKIPPABLE_MAGIC;
    if (magic != FRAME_MAGIC && !skippable)
        failCorrupt(at, at == 0 ? "not zstd data (no zstd magic number)"
                                : "garbage after the end of a zstd frame (not a new frame)");
    ZstdCheckpoints::Point point;
    point.in = at;
    point.out = _out;
    _checkpoints->addPoint(_runStart, point);
    if (skippable)
    {
        skipFrame();
        return true;
    }
    ZSTD_DCtx_reset(_context, ZSTD_reset_session_only);
    _wanted = 1;
    _mode = Mode::Decoding;
    return true;
}

void ZstdSource::skipFrame()
{
    const uint64_t at = _input.position();
    if (_input.fill(SKIPPABLE_HEADER) < SKIPPABLE_HEADER)
        _file->fail(at + _input.available(), "the zstd stream ends inside a skippable frame", true);
    const uint64_t end = at + SKIPPABLE_HEADER + littleEndian32(_input.data() + 4);
    unsigned char last = 0;
    if (end > at + SKIPPABLE_HEADER && _file->readAt(end - 1, &last, 1) == 0)
        _file->fail(at, "the zstd stream ends inside a skippable frame", true);
    _input.seek(end);
}

std::size_t ZstdSource::decodeSome(unsigned char* out, std::size_t size)
{
    if (_input.available() == 0)
        _input.fill();
    // At most what the decoder asks for (the rest of a block and the next block's header), so that
    // an error names the block at fault.
    ZSTD_inBuffer input = {_input.data(), std::min(_input.available(), _wanted), 0};
    ZSTD_outBuffer output = {out, size, 0};
    const std::size_t result = ZSTD_decompressStream(_context, &output, &input);
    _input.consume(input.pos);
    _out += output.pos;
    _decoded += output.pos;
    if (ZSTD_isError(result))
        failCorrupt(_input.position(), std::string("corrupt zstd data (") + ZSTD_getErrorName(result) + ")");
    _wanted = std::max<std::size_t>(result, 1);
    if (result == 0)
        _mode = Mode::FrameStart;
    else if (input.pos == 0 && output.pos == 0)
    {
        if (input.size == 0)
            _file->fail(_input.position(), "the zstd stream ends inside a frame", true);
        failCorrupt(_input.position(), "corrupt zstd data (the decoder made no progress)");
    }
    return output.pos;
}

void ZstdSource::failCorrupt(uint64_t byte, const std::string& what)
{
    _mode = Mode::Failed;
    _file->fail(byte, what);
}
