/* osgGlyphs - private: a range of a ByteSource as a seekable std::istream, for the point readers. */

#ifndef OSGGLYPHS_FRAMES_BYTERANGESTREAM_H
#define OSGGLYPHS_FRAMES_BYTERANGESTREAM_H 1

#include "ByteSource.h"

#include <istream>
#include <memory>
#include <streambuf>
#include <string>
#include <vector>

namespace osgGlyphsData
{
namespace frames
{

/** Reads up to size bytes at offset; where that fails, tries again smaller, down to 4 KiB, so
 * that the bytes before corrupt data are read. Returns the bytes read; failure, when not null
 * after the call, holds the error that stopped it (at the returned count's end). */
std::size_t readBeforeFailure(ByteSource& source, uint64_t offset, char* out, std::size_t size,
                              std::unique_ptr<SourceError>& failure);

/** The bytes [begin, end) of a source as a stream buffer whose positions count from begin. With
 * end UINT64_MAX (a range whose end is not known yet) it reads to the end of the source and
 * cannot seek to its end, so that readers treat it as a stream of unknown size. A SourceError
 * is kept (getError()) and ends the stream. */
class ByteRangeBuffer : public std::streambuf
{
public:
    ByteRangeBuffer(ByteSource& source, uint64_t begin, uint64_t end);

    /** The error that ended the stream early, if any. */
    const SourceError* getError() const { return _failed ? &_error : nullptr; }
    /** The offset of the source where the error came: the bytes before it were read. */
    uint64_t getErrorOffset() const { return _begin + _failedAt; }

protected:
    int_type underflow() override;
    pos_type seekoff(off_type offset, std::ios_base::seekdir direction,
                     std::ios_base::openmode mode) override;
    pos_type seekpos(pos_type position, std::ios_base::openmode mode) override;
    std::streamsize xsgetn(char* out, std::streamsize count) override;

private:
    uint64_t position() const;

    ByteSource& _source;
    uint64_t _begin;
    uint64_t _end;
    uint64_t _bufferStart = 0; // the range position of the buffer's first byte
    std::vector<char> _buffer;
    bool _failed = false;
    uint64_t _failedAt = 0;
    SourceError _error;
};

/** A std::istream over a ByteRangeBuffer. */
class ByteRangeStream : public std::istream
{
public:
    ByteRangeStream(ByteSource& source, uint64_t first, uint64_t past)
        : std::istream(nullptr), _buffer(source, first, past)
    {
        rdbuf(&_buffer);
    }

    const SourceError* getError() const { return _buffer.getError(); }
    uint64_t getErrorOffset() const { return _buffer.getErrorOffset(); }

private:
    ByteRangeBuffer _buffer;
};

}
}

#endif
