#include "ByteSource.h"
#include "GzipSource.h"
#include "ZstdSource.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#include <zlib.h>

using namespace osgGlyphsData::frames;

namespace
{

uint32_t crcOf(const std::string& bytes, std::size_t from)
{
    uLong crc = crc32(0, Z_NULL, 0);
    for (std::size_t at = from; at < bytes.size();)
    {
        const std::size_t piece = std::min<std::size_t>(bytes.size() - at, std::size_t(1) << 30);
        crc = crc32(crc, reinterpret_cast<const Bytef*>(bytes.data() + at), static_cast<uInt>(piece));
        at += piece;
    }
    return static_cast<uint32_t>(crc);
}

bool endsWith(const std::string& text, const std::string& suffix)
{
    return text.size() > suffix.size() &&
           text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

/** An uncompressed file: its bytes as they are. */
class PlainSource : public ByteSource
{
public:
    explicit PlainSource(std::unique_ptr<SourceFile> file) : _file(std::move(file)) {}

    const std::string& getName() const override { return _file->getName(); }
    Compression getCompression() const override { return Compression::None; }
    uint64_t getFileSize() const override { return _file->getSize(); }
    std::shared_ptr<Checkpoints> getCheckpoints() const override { return nullptr; }

    std::size_t read(uint64_t offset, char* out, std::size_t size) override
    {
        return _file->readAt(offset, reinterpret_cast<unsigned char*>(out), size);
    }

private:
    std::unique_ptr<SourceFile> _file;
};

}

namespace osgGlyphsData
{
namespace frames
{

Compression compressionFromName(const std::string& path, std::string& stripped)
{
    stripped = path;
    if (endsWith(path, ".gz"))
    {
        stripped = path.substr(0, path.size() - 3);
        return Compression::Gzip;
    }
    if (endsWith(path, ".zst"))
    {
        stripped = path.substr(0, path.size() - 4);
        return Compression::Zstd;
    }
    return Compression::None;
}

Compression compressionFromMagic(const unsigned char* bytes, std::size_t size)
{
    if (size >= 2 && bytes[0] == 0x1f && bytes[1] == 0x8b)
        return Compression::Gzip;
    if (size >= 4 && bytes[0] == 0x28 && bytes[1] == 0xb5 && bytes[2] == 0x2f && bytes[3] == 0xfd)
        return Compression::Zstd;
    return Compression::None;
}

std::unique_ptr<ByteSource> openByteSource(const std::string& path, Compression compression,
                                           std::shared_ptr<Checkpoints> checkpoints, std::string& error)
{
    std::unique_ptr<SourceFile> file(new SourceFile);
    if (!file->open(path, error))
        return nullptr;
    switch (compression)
    {
    case Compression::None:
        return std::unique_ptr<ByteSource>(new PlainSource(std::move(file)));
    case Compression::Gzip:
    {
        std::shared_ptr<GzipCheckpoints> points = std::dynamic_pointer_cast<GzipCheckpoints>(checkpoints);
        if (checkpoints && !points)
            break;
        return std::unique_ptr<ByteSource>(new GzipSource(std::move(file), points));
    }
    case Compression::Zstd:
    {
        std::shared_ptr<ZstdCheckpoints> points = std::dynamic_pointer_cast<ZstdCheckpoints>(checkpoints);
        if (checkpoints && !points)
            break;
        return std::unique_ptr<ByteSource>(new ZstdSource(std::move(file), points));
    }
    }
    error = path + ": the checkpoints given are of another compression";
    return nullptr;
}

SourceFile::~SourceFile()
{
    if (_descriptor >= 0)
        ::close(_descriptor);
}

bool SourceFile::open(const std::string& path, std::string& error)
{
    _name = path;
    _descriptor = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    struct stat status;
    if (_descriptor < 0 || ::fstat(_descriptor, &status) != 0)
    {
        error = path + ": " + std::strerror(errno);
        return false;
    }
    if (S_ISDIR(status.st_mode))
    {
        error = path + ": is a directory";
        return false;
    }
    _size = static_cast<uint64_t>(status.st_size);
    return true;
}

std::size_t SourceFile::readAt(uint64_t offset, unsigned char* out, std::size_t size) const
{
    std::size_t done = 0;
    while (done < size)
    {
        const uint64_t at = offset + done;
        if (at > static_cast<uint64_t>(INT64_MAX))
            break;
        const ssize_t got = ::pread(_descriptor, out + done, size - done, static_cast<off_t>(at));
        if (got < 0 && errno == EINTR)
            continue;
        if (got < 0)
            fail(at, std::strerror(errno));
        if (got == 0)
            break;
        done += static_cast<std::size_t>(got);
    }
    return done;
}

void SourceFile::fail(uint64_t byte, const std::string& what, bool endOfInput) const
{
    SourceError error;
    error.message = _name + ": byte " + std::to_string(byte) + ": " + what;
    error.endOfInput = endOfInput;
    throw error;
}

SourceInput::SourceInput(const SourceFile& file, std::size_t capacity)
    : _file(file), _buffer(new unsigned char[capacity]), _capacity(capacity)
{
}

void SourceInput::seek(uint64_t offset)
{
    _begin = _end = 0;
    _fileOffset = offset;
}

std::size_t SourceInput::fill(std::size_t need)
{
    if (available() >= need)
        return available();
    std::memmove(_buffer.get(), data(), available());
    _end -= _begin;
    _begin = 0;
    while (_end < need)
    {
        const std::size_t got = _file.readAt(_fileOffset, _buffer.get() + _end, _capacity - _end);
        if (got == 0)
            break;
        _end += got;
        _fileOffset += got;
    }
    return available();
}

void appendLittleEndian(std::string& bytes, uint64_t value, unsigned size)
{
    for (unsigned i = 0; i < size; ++i)
        bytes.push_back(static_cast<char>((value >> (8 * i)) & 0xff));
}

std::string sealCheckpoints(const char* magic, const std::string& body)
{
    std::string bytes(magic, 4);
    appendLittleEndian(bytes, 1, 4);
    appendLittleEndian(bytes, crcOf(body, 0), 4);
    return bytes + body;
}

bool checkSeal(const std::string& bytes, const char* magic)
{
    if (bytes.size() < BlobReader::SealSize || bytes.compare(0, 4, magic, 4) != 0)
        return false;
    uint64_t version = 0, crc = 0;
    std::string seal = bytes.substr(4, 8);
    for (unsigned i = 0; i < 4; ++i)
    {
        version |= uint64_t(static_cast<unsigned char>(seal[i])) << (8 * i);
        crc |= uint64_t(static_cast<unsigned char>(seal[4 + i])) << (8 * i);
    }
    return version == 1 && crc == crcOf(bytes, BlobReader::SealSize);
}

bool BlobReader::number(uint64_t& value, unsigned size)
{
    if (left() < size)
        return false;
    value = 0;
    for (unsigned i = 0; i < size; ++i)
        value |= uint64_t(static_cast<unsigned char>(_bytes[_at + i])) << (8 * i);
    _at += size;
    return true;
}

bool BlobReader::bytes(std::string& value, std::size_t count)
{
    if (left() < count)
        return false;
    value.assign(_bytes, _at, count);
    _at += count;
    return true;
}

}
}
