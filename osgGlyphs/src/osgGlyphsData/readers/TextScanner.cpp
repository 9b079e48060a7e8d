#include "TextScanner.h"

#include <algorithm>
#include <cstring>
#include <istream>
#include <limits>

using namespace osgGlyphsData::readers;

namespace
{

std::string_view trimLineEnd(const std::string& line)
{
    std::string_view text(line);
    if (!text.empty() && text.back() == '\r')
        text.remove_suffix(1);
    return text;
}

}

TextScanner::TextScanner(std::istream& in, const std::string& name, uint64_t totalBytes,
                         const Progress& progress, uint64_t startOffset, uint64_t startLine)
    : _in(in), _name(name), _totalBytes(totalBytes), _progress(progress),
      // A small stream gets a small buffer; a large or unknown one reads a block at a time.
      _blockSize(totalBytes > 0 ? static_cast<std::size_t>(std::min<uint64_t>(totalBytes + 1, BlockSize))
                                : UnknownSizeBlockSize),
      _begin(0), _end(0), _startOffset(startOffset), _bufferOffset(startOffset), _bytesRead(0),
      _lineNumber(startLine), _lineOffset(startOffset), _lineTerminated(true), _eof(false),
      _streamStart(static_cast<int64_t>(in.tellg()))
{
}

uint64_t TextScanner::getRemainingBytes() const
{
    if (_totalBytes == 0)
        return std::numeric_limits<uint64_t>::max();
    const uint64_t read = getOffset() - _startOffset;
    return read < _totalBytes ? _totalBytes - read : 0;
}

uint64_t TextScanner::getMaxItems(uint64_t minBytesEach) const
{
    const uint64_t remaining = getRemainingBytes();
    if (remaining == std::numeric_limits<uint64_t>::max())
        return remaining;
    return remaining / std::max<uint64_t>(minBytesEach, 1);
}

std::size_t TextScanner::boundedReserve(uint64_t count, uint64_t minBytesEach) const
{
    // Of a stream of unknown size, reserve what one block could hold; the arrays grow from there.
    uint64_t limit = getMaxItems(minBytesEach);
    if (limit == std::numeric_limits<uint64_t>::max())
        limit = BlockSize / std::max<uint64_t>(minBytesEach, 1);
    return static_cast<std::size_t>(std::min(count, limit));
}

// Makes at least wanted bytes available from _begin, if the stream has them.
bool TextScanner::fill(std::size_t wanted)
{
    while (_end - _begin < wanted && !_eof)
    {
        if (_begin > 0)
        {
            std::memmove(_buffer.data(), _buffer.data() + _begin, _end - _begin);
            _bufferOffset += _begin;
            _end -= _begin;
            _begin = 0;
        }
        // Grow only for a line (or record) longer than the buffer.
        std::size_t capacity = std::max(_buffer.size(), _blockSize);
        while (capacity < wanted || capacity == _end)
            capacity *= 2;
        if (capacity != _buffer.size())
            _buffer.resize(capacity);

        _in.read(_buffer.data() + _end, static_cast<std::streamsize>(_buffer.size() - _end));
        const std::size_t count = static_cast<std::size_t>(_in.gcount());
        if (_in.bad())
            failAtByte(_bufferOffset + _end, "read error");
        _end += count;
        _bytesRead += count;
        if (count == 0 || _in.eof())
            _eof = true;
        reportProgress();
    }
    return _end - _begin >= wanted;
}

bool TextScanner::nextLine(std::string_view& line)
{
    std::size_t searched = 0;
    for (;;)
    {
        const char* start = _buffer.data() + _begin;
        const void* newline = std::memchr(start + searched, '\n', _end - _begin - searched);
        if (newline || (_eof && _end > _begin))
        {
            const char* stop = newline ? static_cast<const char*>(newline) : _buffer.data() + _end;
            std::size_t length = static_cast<std::size_t>(stop - start);
            ++_lineNumber;
            _lineOffset = getOffset();
            _begin += length + (newline ? 1 : 0);
            _lineTerminated = newline != nullptr;
            if (length > 0 && start[length - 1] == '\r')
                --length;
            line = std::string_view(start, length);
            return true;
        }
        if (_eof)
            return false;
        searched = _end - _begin;
        if (searched >= MaxLineLength)
            failAtLine(_lineNumber + 1, "line longer than " + std::to_string(MaxLineLength >> 20) +
                                            " MiB (is this binary data?)");
        fill(searched + 1);
    }
}

std::string_view TextScanner::requireLine(const std::string& what)
{
    std::string_view line;
    if (!nextLine(line))
        failEndOfFile(", expected " + what);
    return line;
}

const char* TextScanner::peekBytes(std::size_t n)
{
    if (_end - _begin < n && !fill(n))
        return nullptr;
    return _buffer.data() + _begin;
}

bool TextScanner::readBytes(void* destination, std::size_t n)
{
    char* out = static_cast<char*>(destination);
    while (n > 0)
    {
        if (_begin == _end && !fill(1))
            return false;
        const std::size_t count = std::min(n, _end - _begin);
        std::memcpy(out, _buffer.data() + _begin, count);
        _begin += count;
        out += count;
        n -= count;
    }
    return true;
}

bool TextScanner::skipBytes(uint64_t n)
{
    // Past the buffer, in a stream that can seek and says how far it goes: a seek.
    if (n > _end - _begin && _streamStart >= 0 && _totalBytes > 0 && n <= getRemainingBytes() &&
        seekStream(getOffset() + n))
        return true;
    while (n > 0)
    {
        if (_begin == _end && !fill(1))
            return false;
        const std::size_t count = static_cast<std::size_t>(std::min<uint64_t>(n, _end - _begin));
        _begin += count;
        n -= count;
    }
    return true;
}

bool TextScanner::atEnd()
{
    return _begin == _end && !fill(1);
}

void TextScanner::skipToLineStart(uint64_t offset)
{
    const uint64_t from = getOffset();
    if (offset <= from)
        return;
    std::string_view line;
    if (offset - 1 < _bufferOffset + _end || _streamStart < 0 || !seekStream(offset - 1))
    {
        while (getOffset() < offset && nextLine(line))
        {
        }
        return;
    }
    // The rest of the line that holds offset - 1 (nothing when that byte ends a line).
    const uint64_t linesBefore = _lineNumber;
    nextLine(line);
    _lineNumber = linesBefore;
    _jumps.push_back(Jump{from, getOffset(), linesBefore});
}

bool TextScanner::seekStream(uint64_t offset)
{
    _in.clear();
    if (!_in.seekg(static_cast<std::streamoff>(_streamStart + (offset - _startOffset))))
    {
        _in.clear();
        return false;
    }
    _begin = _end = 0;
    _bufferOffset = offset;
    _eof = false;
    return true;
}

uint64_t TextScanner::getFileLine(uint64_t line) const
{
    // Counted only now: a failure ends the reading, so the stream may move.
    uint64_t jumped = 0;
    std::vector<char> block;
    for (const Jump& jump : _jumps)
    {
        if (line <= jump.linesBefore)
            break;
        block.resize(BlockSize);
        _in.clear();
        _in.seekg(static_cast<std::streamoff>(_streamStart + (jump.from - _startOffset)));
        uint64_t left = jump.to - jump.from;
        while (left > 0 && _in)
        {
            _in.read(block.data(), static_cast<std::streamsize>(std::min<uint64_t>(left, block.size())));
            const std::size_t count = static_cast<std::size_t>(_in.gcount());
            if (count == 0)
                break;
            jumped += static_cast<uint64_t>(std::count(block.data(), block.data() + count, '\n'));
            left -= count;
        }
    }
    return line + jumped;
}

std::string TextScanner::readAt(uint64_t offset, std::size_t size)
{
    const uint64_t end = getEndOffset();
    if (!canSeek() || offset >= end)
        return std::string();
    std::string bytes(static_cast<std::size_t>(std::min<uint64_t>(size, end - offset)), '\0');
    _in.clear();
    const std::streampos resume = _in.tellg();
    _in.seekg(static_cast<std::streamoff>(_streamStart + (offset - _startOffset)));
    _in.read(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    bytes.resize(static_cast<std::size_t>(_in.gcount()));
    _bytesRead += bytes.size();
    _in.clear();
    _in.seekg(resume);
    return bytes;
}

uint64_t TextScanner::findLine(uint64_t offset, const LineTest& test)
{
    const uint64_t end = getEndOffset();
    if (!canSeek() || offset >= end)
        return end;
    _in.clear();
    const std::streampos resume = _in.tellg();
    // From the byte before offset, which tells whether a line starts at offset.
    const uint64_t first = offset > _startOffset ? offset - 1 : offset;
    _in.seekg(static_cast<std::streamoff>(_streamStart + (first - _startOffset)));
    std::vector<char> block(BlockSize);
    std::string line; // the part of a line that began in an earlier block
    uint64_t blockOffset = first, lineOffset = offset, found = end;
    bool inLine = first == offset; // within a line that starts at or after offset
    while (found == end && _in)
    {
        _in.read(block.data(), static_cast<std::streamsize>(block.size()));
        const std::size_t count = static_cast<std::size_t>(_in.gcount());
        _bytesRead += count;
        std::size_t begin = 0;
        if (blockOffset < offset && count > 0)
        {
            inLine = block[0] == '\n';
            begin = 1;
        }
        while (begin < count && found == end)
        {
            const char* newline =
                static_cast<const char*>(std::memchr(block.data() + begin, '\n', count - begin));
            const std::size_t stop = newline ? static_cast<std::size_t>(newline - block.data()) : count;
            if (inLine)
                line.append(block.data() + begin, stop - begin);
            if (!newline)
                break;
            if (inLine && test(trimLineEnd(line)))
                found = lineOffset;
            line.clear();
            inLine = true;
            begin = stop + 1;
            lineOffset = blockOffset + begin;
        }
        blockOffset += count;
        if (count == 0)
            break;
    }
    // The last line, without an end.
    if (found == end && inLine && !line.empty() && test(trimLineEnd(line)))
        found = lineOffset;
    _in.clear();
    _in.seekg(resume);
    return found;
}

void TextScanner::failAtLine(uint64_t line, const std::string& what) const
{
    line = getFileLine(line);
    throw ReadError{_name + ":" + std::to_string(line == 0 ? 1 : line) + ": " + what};
}

void TextScanner::fail(const std::string& what) const
{
    failAtLine(_lineNumber, what);
}

void TextScanner::failEndOfFile(const std::string& what) const
{
    const uint64_t line = getFileLine(_lineNumber);
    throw ReadError{_name + ":" + std::to_string(line == 0 ? 1 : line) + ": unexpected end of file" + what,
                    true};
}

void TextScanner::failAtByte(uint64_t offset, const std::string& what) const
{
    throw ReadError{_name + ": byte " + std::to_string(offset) + ": " + what};
}

void TextScanner::reportProgress() const
{
    if (_progress)
        _progress(_bytesRead, _totalBytes);
}
