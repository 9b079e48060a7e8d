#include "ByteRangeStream.h"

#include <algorithm>
#include <cstring>

using namespace osgGlyphsData::frames;

namespace
{
const std::size_t BUFFER_SIZE = std::size_t(1) << 20;
const std::size_t MIN_READ = std::size_t(4) << 10;
}

std::size_t osgGlyphsData::frames::readBeforeFailure(ByteSource& source, uint64_t offset, char* out,
                                                     std::size_t size, std::unique_ptr<SourceError>& failure)
{
    failure.reset();
    for (std::size_t want = size; want > 0; want = want > MIN_READ ? std::max(want / 4, MIN_READ) : 0)
    {
        try
        {
            return source.read(offset, out, want);
        }
        catch (const SourceError& error)
        {
            failure.reset(new SourceError(error));
        }
    }
    return 0;
}

ByteRangeBuffer::ByteRangeBuffer(ByteSource& source, uint64_t begin, uint64_t end)
    : _source(source), _begin(begin), _end(std::max(begin, end)), _buffer(BUFFER_SIZE)
{
    setg(_buffer.data(), _buffer.data(), _buffer.data());
}

uint64_t ByteRangeBuffer::position() const
{
    return _bufferStart + static_cast<uint64_t>(gptr() - eback());
}

ByteRangeBuffer::int_type ByteRangeBuffer::underflow()
{
    if (gptr() < egptr())
        return traits_type::to_int_type(*gptr());
    const uint64_t next = position();
    const uint64_t left = _end - _begin - std::min(next, _end - _begin);
    std::size_t got = 0;
    if (!_failed && left > 0)
    {
        std::unique_ptr<SourceError> failure;
        got = readBeforeFailure(_source, _begin + next, _buffer.data(),
                                static_cast<std::size_t>(std::min<uint64_t>(left, _buffer.size())), failure);
        if (failure && got == 0)
        {
            _failed = true;
            _failedAt = next;
            _error = *failure;
        }
    }
    _bufferStart = next;
    setg(_buffer.data(), _buffer.data(), _buffer.data() + got);
    return got ? traits_type::to_int_type(_buffer[0]) : traits_type::eof();
}

std::streamsize ByteRangeBuffer::xsgetn(char* out, std::streamsize count)
{
    std::streamsize done = 0;
    while (done < count)
    {
        if (gptr() == egptr() && underflow() == traits_type::eof())
            break;
        const std::streamsize n = std::min<std::streamsize>(count - done, egptr() - gptr());
        std::memcpy(out + done, gptr(), static_cast<std::size_t>(n));
        gbump(static_cast<int>(n));
        done += n;
    }
    return done;
}

ByteRangeBuffer::pos_type ByteRangeBuffer::seekoff(off_type offset, std::ios_base::seekdir direction,
                                                   std::ios_base::openmode mode)
{
    if (direction == std::ios_base::cur)
        return seekpos(pos_type(static_cast<off_type>(position()) + offset), mode);
    if (direction == std::ios_base::beg)
        return seekpos(pos_type(offset), mode);
    if (_end == UINT64_MAX)
        return pos_type(off_type(-1)); // the end is not known: a stream of unknown size
    return seekpos(pos_type(static_cast<off_type>(_end - _begin) + offset), mode);
}

ByteRangeBuffer::pos_type ByteRangeBuffer::seekpos(pos_type position, std::ios_base::openmode mode)
{
    const off_type target = off_type(position);
    if (!(mode & std::ios_base::in) || target < 0 || (_end != UINT64_MAX && uint64_t(target) > _end - _begin))
        return pos_type(off_type(-1));
    const uint64_t to = static_cast<uint64_t>(target);
    if (to >= _bufferStart && to <= _bufferStart + static_cast<uint64_t>(egptr() - eback()))
    {
        setg(eback(), eback() + (to - _bufferStart), egptr());
        return position;
    }
    _bufferStart = to;
    setg(_buffer.data(), _buffer.data(), _buffer.data());
    return position;
}
