#include "ZstdSource.h"

#include <zstd.h>

#include <algorithm>
#include <new>

using namespace osgGlyphsData::frames;

namespace
{

const char* const MAGIC = "ZSCP";
const std::size_t POINT_BYTES = 8 + 8; // in, out
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

ZstdCheckpoints::ZstdCheckpoints() : CheckpointTable(MAGIC, POINT_BYTES) {}

void ZstdCheckpoints::writePoint(std::string& body, const Point& point) const
{
    appendLittleEndian(body, point.in, 8);
    appendLittleEndian(body, point.out, 8);
}

bool ZstdCheckpoints::readPoint(BlobReader& reader, const Point* previous, Point& point) const
{
    return reader.number(point.in, 8) && reader.number(point.out, 8) && canFollow(previous, point);
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

ZstdSource::ZstdSource(std::unique_ptr<SourceFile> file, std::shared_ptr<ZstdCheckpoints> checkpoints)
    : StreamSource(std::move(file), checkpoints), _context(ZSTD_createDCtx())
{
    if (!_context)
        throw std::bad_alloc();
}

ZstdSource::~ZstdSource()
{
    ZSTD_freeDCtx(_context);
}

bool ZstdSource::startUnit()
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
    advance(output.pos);
    if (ZSTD_isError(result))
        failCorrupt(_input.position(), std::string("corrupt zstd data (") + ZSTD_getErrorName(result) + ")");
    _wanted = std::max<std::size_t>(result, 1);
    if (result == 0)
        _mode = Mode::UnitStart;
    else if (input.pos == 0 && output.pos == 0)
    {
        if (input.size == 0)
            _file->fail(_input.position(), "the zstd stream ends inside a frame", true);
        failCorrupt(_input.position(), "corrupt zstd data (the decoder made no progress)");
    }
    return output.pos;
}
