/* osgGlyphs - private: random access to the bytes of a file, plain or compressed (gzip, zstd). */

#ifndef OSGGLYPHS_FRAMES_BYTESOURCE_H
#define OSGGLYPHS_FRAMES_BYTESOURCE_H 1

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>

namespace osgGlyphsData
{
namespace frames
{

/** How a file's bytes are stored. */
enum class Compression
{
    None,
    Gzip, // one or more gzip members (zlib), as gzip(1) and LAMMPS' dump */gz write them
    Zstd  // one or more zstd frames, as zstd(1) and LAMMPS' dump */zstd write them
};

/** The compression a file name says (".gz", ".zst"), and the name without that suffix in
 * stripped (the name itself when there is none). */
Compression compressionFromName(const std::string& path, std::string& stripped);

/** The compression the first bytes of a file say (gzip 1f 8b, zstd 28 b5 2f fd); None otherwise. */
Compression compressionFromMagic(const unsigned char* bytes, std::size_t size);

/** Places in a compressed stream where decompression can restart without what came before:
 * shared by the readers of one file (the index scan and the frame decoder) and persisted with
 * the frame index, so that reopening a file jumps at once. Thread-safe. What a point holds
 * depends on the compression (for gzip, the 32 KiB window before it, as zlib's zran example
 * describes; for zstd, only the start of a zstd frame). */
class Checkpoints
{
public:
    virtual ~Checkpoints() = default;
    /** The number of points. */
    virtual std::size_t size() const = 0;
    /** The uncompressed offset up to which the points are complete (the furthest byte any reader
     * decompressed from the start, or from a point, without a gap). */
    virtual uint64_t getCoveredEnd() const = 0;
    /** Serialised, for the index file; fromBytes() of another Checkpoints of the same
     * compression reads it back. */
    virtual std::string toBytes() const = 0;
    /** Replaces the points by those of toBytes(); false, leaving the points as they were, when
     * bytes are malformed (a corrupt index file). */
    virtual bool fromBytes(const std::string& bytes) = 0;
};

/** Reads the uncompressed bytes of a file at any offset. Not thread-safe: each thread opens its
 * own source; sources of one file share its Checkpoints. Reading on from where the last read
 * ended never restarts decompression. */
class ByteSource
{
public:
    virtual ~ByteSource() = default;

    /** The file, for messages. */
    virtual const std::string& getName() const = 0;

    virtual Compression getCompression() const = 0;

    /** Reads up to size bytes at offset (of the uncompressed content) into out; returns how many
     * were read: fewer only at the end of the content. Throws frames::SourceError on a read
     * failure or corrupt compressed data. After a SourceError with endOfInput, a later read goes
     * on once the file has grown. A corrupt gzip member may inflate without an error up to its
     * trailer (deflate has no check before the member's CRC-32): only reads through the trailer
     * are sure to fail on it (zstd's frames are checked block by block, and at their end when
     * they hold a checksum). */
    virtual std::size_t read(uint64_t offset, char* out, std::size_t size) = 0;

    /** The size of the file on disk (compressed). */
    virtual uint64_t getFileSize() const = 0;

    /** The checkpoints this source uses and adds to (nullptr for a plain file). */
    virtual std::shared_ptr<Checkpoints> getCheckpoints() const = 0;
};

/** A failure to read: message is complete, "<file>: byte <n>: <what>" where n is the offset of
 * the compressed byte at fault (or the uncompressed offset, for a plain file). endOfInput: the
 * file ends inside the compressed stream (truncated, or still being written). */
struct SourceError
{
    std::string message;
    bool endOfInput = false;
};

/** Opens path for random access, with the given compression. checkpoints: those of another
 * source of the same file, shared (nullptr: new ones; ignored for Compression::None). Returns
 * nullptr with a one-line error naming the file when it cannot be opened, or when checkpoints are
 * those of another compression. */
std::unique_ptr<ByteSource> openByteSource(const std::string& path, Compression compression,
                                           std::shared_ptr<Checkpoints> checkpoints, std::string& error);

/** For the sources' implementations: a file read at offsets (pread), without an end-of-file state,
 * so that a file that grows is read on. */
class SourceFile
{
public:
    SourceFile() = default;
    SourceFile(const SourceFile&) = delete;
    SourceFile& operator=(const SourceFile&) = delete;
    ~SourceFile();

    /** false with error "<path>: <why>" when it cannot be opened. */
    bool open(const std::string& path, std::string& error);

    const std::string& getName() const { return _name; }

    /** The size when it was opened. */
    uint64_t getSize() const { return _size; }

    /** Reads up to size bytes at offset; fewer only where the file ends now. */
    std::size_t readAt(uint64_t offset, unsigned char* out, std::size_t size) const;

    /** Throws SourceError "<file>: byte <byte>: <what>". */
    [[noreturn]] void fail(uint64_t byte, const std::string& what, bool endOfInput = false) const;

private:
    std::string _name;
    int _descriptor = -1;
    uint64_t _size = 0;
};

/** For the checkpoints' serialisation: value in size bytes, little-endian, appended to bytes. */
void appendLittleEndian(std::string& bytes, uint64_t value, unsigned size);

/** For the checkpoints' serialisation: body after a seal of 12 bytes, magic (4 characters), version
 * 1 (4 bytes) and the CRC-32 of body (4 bytes). */
std::string sealCheckpoints(const char* magic, const std::string& body);

/** Whether bytes begin with a seal for magic that matches the rest. */
bool checkSeal(const std::string& bytes, const char* magic);

/** Reads little-endian numbers and byte strings from a serialisation, never past its end. */
class BlobReader
{
public:
    static constexpr std::size_t SealSize = 12;

    /** From after the seal. */
    explicit BlobReader(const std::string& bytes) : _bytes(bytes), _at(SealSize) {}

    bool number(uint64_t& value, unsigned size);
    bool bytes(std::string& value, std::size_t count);
    std::size_t left() const { return _bytes.size() - _at; }

private:
    const std::string& _bytes;
    std::size_t _at;
};

/** For the compressed sources: the compressed bytes of a SourceFile from a position on, buffered. */
class SourceInput
{
public:
    SourceInput(const SourceFile& file, std::size_t capacity);

    /** Drops the buffer; the next bytes are those at offset. */
    void seek(uint64_t offset);

    /** Reads on until at least need bytes are buffered, or the file ends; returns how many are. */
    std::size_t fill(std::size_t need = 1);

    const unsigned char* data() const { return _buffer.get() + _begin; }
    std::size_t available() const { return _end - _begin; }
    void consume(std::size_t count) { _begin += count; }

    /** The file offset of data(). */
    uint64_t position() const { return _fileOffset - available(); }

private:
    const SourceFile& _file;
    std::unique_ptr<unsigned char[]> _buffer;
    std::size_t _capacity;
    std::size_t _begin = 0;
    std::size_t _end = 0;
    uint64_t _fileOffset = 0; // of _buffer[_end]
};

}
}

#endif
