/* osgGlyphs - private: the block-wise stream scanner every point reader shares. */

#ifndef OSGGLYPHS_READERS_TEXTSCANNER_H
#define OSGGLYPHS_READERS_TEXTSCANNER_H 1

#include <cstddef>
#include <cstdint>
#include <functional>
#include <iosfwd>
#include <string>
#include <string_view>
#include <vector>

namespace osgGlyphsData
{
namespace readers
{

/** What a reader throws on malformed input; readPointStream() turns it into its error string.
 * message is complete: "<file>:<line>: <what>" or "<file>: byte <offset>: <what>". */
struct ReadError
{
    std::string message;
    /** The stream ended where more was expected (a file cut short, or still being written). */
    bool endOfInput = false;
};

/** Reads a stream in blocks of BlockSize bytes and hands it out as lines (with their 1-based
 * numbers and byte offsets) or as raw bytes, for the binary body after a text header. Never holds
 * more than a block plus the longest line. Every failure throws ReadError with the position. */
class TextScanner
{
public:
    static constexpr std::size_t BlockSize = std::size_t(1) << 20;
    /** The first block of a stream of unknown size (a pipe); it grows for longer lines only. */
    static constexpr std::size_t UnknownSizeBlockSize = std::size_t(64) << 10;
    /** Longer lines are an error (binary data fed to a text reader, usually). */
    static constexpr std::size_t MaxLineLength = std::size_t(16) << 20;

    typedef std::function<void(uint64_t bytesRead, uint64_t totalBytes)> Progress;

    /** totalBytes is the size of what is left in the stream, 0 when unknown. Offsets and line
     * numbers count on from startOffset and startLine: where the stream starts in its file. */
    TextScanner(std::istream& in, const std::string& name, uint64_t totalBytes, const Progress& progress,
                uint64_t startOffset = 0, uint64_t startLine = 0);

    const std::string& getName() const { return _name; }

    /** The next line without its end ("\n" or "\r\n"), valid until the next call of any reading
     * method; false at the end of the stream. */
    bool nextLine(std::string_view& line);

    /** The next line, failing "unexpected end of file, expected <what>" at the end. */
    std::string_view requireLine(const std::string& what);

    /** 1-based number of the line nextLine() returned last; 0 (or startLine) before the first.
     * After skipToLineStart() sought past lines, without them (failures name the file's lines). */
    uint64_t getLineNumber() const { return _lineNumber; }

    /** False when the line nextLine() returned last ended with the stream, without "\n". */
    bool isLineTerminated() const { return _lineTerminated; }

    /** Byte offset of the first byte of that line. */
    uint64_t getLineOffset() const { return _lineOffset; }

    /** Byte offset of the next byte to be read. */
    uint64_t getOffset() const { return _bufferOffset + _begin; }

    /** The size of the stream, 0 when unknown. */
    uint64_t getTotalBytes() const { return _totalBytes; }

    /** Bytes left to read; UINT64_MAX when the size is unknown. */
    uint64_t getRemainingBytes() const;

    /** How many items of at least minBytesEach the rest of the stream can hold (UINT64_MAX when the
     * size is unknown). */
    uint64_t getMaxItems(uint64_t minBytesEach) const;

    /** A reservation for count items of at least minBytesEach: count when the rest of the stream
     * can hold them, less otherwise; when the size is unknown, what one BlockSize could hold. */
    std::size_t boundedReserve(uint64_t count, uint64_t minBytesEach) const;

    /** Pointer to the next n contiguous bytes, nullptr when the stream ends before them (then
     * getAvailableBytes() tells how many are left). Valid until the next reading call. */
    const char* peekBytes(std::size_t n);
    std::size_t getAvailableBytes() const { return _end - _begin; }

    /** Consumes n bytes that peekBytes() made available. */
    void consume(std::size_t n) { _begin += n; }

    /** Copies n bytes; false, with what could be read consumed, when the stream ends first. */
    bool readBytes(void* destination, std::size_t n);

    /** Skips n bytes (seeking past the buffer when the stream can); false when the stream ends
     * first. */
    bool skipBytes(uint64_t n);

    /** True when no byte is left. */
    bool atEnd();

    /** Continues at the first line that starts at or after offset (a byte offset of the file,
     * past getOffset()), or at the end. A seekable stream seeks there, and the lines it jumps
     * over are counted only when a failure names a line after them (by reading them then);
     * another stream reads the lines on the way. Line numbers stay the file's either way. */
    void skipToLineStart(uint64_t offset);

    /** True when the stream can seek and tells its size: skipToLineStart() and findLine() seek. */
    bool canSeek() const { return _streamStart >= 0 && _totalBytes > 0; }

    /** Up to size bytes from offset (a byte offset of the file), read there and back without
     * moving the scanner: for a stream that canSeek(). The bytes count as read. */
    std::string readAt(uint64_t offset, std::size_t size);

    /** Tells a line (without its end) that findLine() looks for. */
    typedef std::function<bool(std::string_view line)> LineTest;

    /** The offset of the first line that starts at or after offset (a byte offset of the file)
     * and passes test; getEndOffset() when no line does. Reads the stream there and back, without
     * moving the scanner: for a stream that canSeek(). The bytes it reads count as read. */
    uint64_t findLine(uint64_t offset, const LineTest& test);

    /** The offset of the file's end: where the stream started plus its size; 0 when unknown. */
    uint64_t getEndOffset() const { return _totalBytes > 0 ? _startOffset + _totalBytes : 0; }

    /** Throws "<name>:<line>: <what>". */
    [[noreturn]] void failAtLine(uint64_t line, const std::string& what) const;
    /** Throws at the line nextLine() returned last (line 1 before any). */
    [[noreturn]] void fail(const std::string& what) const;
    /** Throws "<name>:<line>: unexpected end of file<what>" as a ReadError of endOfInput. */
    [[noreturn]] void failEndOfFile(const std::string& what) const;
    /** Throws "<name>: byte <offset>: <what>". */
    [[noreturn]] void failAtByte(uint64_t offset, const std::string& what) const;

    /** Tells the progress callback how far the reading is, with the final count at the end. */
    void reportProgress() const;

private:
    bool fill(std::size_t wanted);
    /** Moves the stream to a file offset past the buffer; false when it cannot seek. */
    bool seekStream(uint64_t offset);
    /** The file's number of a line numbered without the lines skipToLineStart() jumped over. */
    uint64_t getFileLine(uint64_t line) const;

    std::istream& _in;
    std::string _name;
    uint64_t _totalBytes;
    Progress _progress;
    std::size_t _blockSize;
    std::vector<char> _buffer;
    std::size_t _begin;
    std::size_t _end;
    uint64_t _startOffset;
    uint64_t _bufferOffset;
    uint64_t _bytesRead;
    uint64_t _lineNumber;
    uint64_t _lineOffset;
    bool _lineTerminated;
    bool _eof;
    /** The stream's position at _startOffset; -1 when it cannot tell (a pipe: no seeking). */
    int64_t _streamStart;
    /** The bytes [from, to) that skipToLineStart() jumped over, after linesBefore lines. */
    struct Jump
    {
        uint64_t from = 0;
        uint64_t to = 0;
        uint64_t linesBefore = 0;
    };
    std::vector<Jump> _jumps;
};

} // namespace readers
}

#endif
