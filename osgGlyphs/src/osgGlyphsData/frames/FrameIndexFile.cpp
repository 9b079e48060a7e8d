#include "FrameIndexFile.h"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

using namespace osgGlyphsData;
using namespace osgGlyphsData::frames;

namespace
{

const char MAGIC[8] = {'O', 'G', 'F', 'R', 'I', 'D', 'X', '2'};
const std::size_t TAIL_BYTES = 4096;
/** An index larger than this is not one of ours (100M frames). */
const uint64_t MAX_INDEX_BYTES = uint64_t(8) << 30;
const std::size_t FRAME_RECORD_BYTES = 8 * 7 + 1;

uint64_t fnv1a(const char* data, std::size_t size, uint64_t hash = 14695981039346656037ull)
{
    for (std::size_t i = 0; i < size; ++i)
        hash = (hash ^ static_cast<unsigned char>(data[i])) * 1099511628211ull;
    return hash;
}

bool hashRange(int fd, uint64_t from, uint64_t to, uint64_t& hash)
{
    std::string bytes(static_cast<std::size_t>(to - from), '\0');
    std::size_t done = 0;
    while (done < bytes.size())
    {
        const ssize_t got = ::pread(fd, &bytes[done], bytes.size() - done, static_cast<off_t>(from + done));
        if (got <= 0)
            return false;
        done += static_cast<std::size_t>(got);
    }
    hash = fnv1a(bytes.data(), bytes.size());
    return true;
}

/** Little-endian fields appended to a string. */
class Writer
{
public:
    void u64(uint64_t value)
    {
        for (int i = 0; i < 8; ++i)
            _bytes.push_back(static_cast<char>((value >> (8 * i)) & 0xff));
    }
    void i64(int64_t value) { u64(static_cast<uint64_t>(value)); }
    void f64(double value)
    {
        uint64_t bits = 0;
        std::memcpy(&bits, &value, 8);
        u64(bits);
    }
    void byte(uint8_t value) { _bytes.push_back(static_cast<char>(value)); }
    void text(const std::string& value)
    {
        u64(value.size());
        _bytes += value;
    }
    std::string& bytes() { return _bytes; }

private:
    std::string _bytes;
};

/** The same fields read back; every read is checked against what is left. */
class Reader
{
public:
    explicit Reader(const std::string& bytes) : _bytes(bytes) {}
    bool u64(uint64_t& value)
    {
        if (left() < 8)
            return false;
        value = 0;
        for (int i = 0; i < 8; ++i)
            value |= uint64_t(static_cast<unsigned char>(_bytes[_at + i])) << (8 * i);
        _at += 8;
        return true;
    }
    bool i64(int64_t& value)
    {
        uint64_t bits = 0;
        if (!u64(bits))
            return false;
        value = static_cast<int64_t>(bits);
        return true;
    }
    bool f64(double& value)
    {
        uint64_t bits = 0;
        if (!u64(bits))
            return false;
        std::memcpy(&value, &bits, 8);
        return true;
    }
    bool byte(uint8_t& value)
    {
        if (left() < 1)
            return false;
        value = static_cast<uint8_t>(_bytes[_at++]);
        return true;
    }
    bool text(std::string& value)
    {
        uint64_t size = 0;
        if (!u64(size) || size > left())
            return false;
        value.assign(_bytes, _at, static_cast<std::size_t>(size));
        _at += static_cast<std::size_t>(size);
        return true;
    }
    std::size_t left() const { return _bytes.size() - _at; }

private:
    const std::string& _bytes;
    std::size_t _at = 0;
};

void writeFrame(Writer& out, const FrameInfo& frame)
{
    out.u64(frame.offset);
    out.u64(frame.line);
    out.u64(frame.end);
    out.i64(frame.timestep);
    out.u64(frame.points);
    out.u64(frame.fileFrame);
    out.f64(frame.time);
    out.byte(frame.hasTime ? 1 : 0);
}

bool readFrame(Reader& in, FrameInfo& frame)
{
    uint8_t hasTime = 0;
    const bool read = in.u64(frame.offset) && in.u64(frame.line) && in.u64(frame.end) &&
                      in.i64(frame.timestep) && in.u64(frame.points) && in.u64(frame.fileFrame) &&
                      in.f64(frame.time) && in.byte(hasTime);
    frame.hasTime = hasTime != 0;
    return read && hasTime <= 1;
}

/** Frames in file order, each within the scan, the lines and frames counting up. */
bool framesAreOrdered(const StoredFrameIndex& index)
{
    ScanPosition last;
    for (const FrameInfo& frame : index.frames)
    {
        if (frame.offset < last.offset || frame.end <= frame.offset || frame.end > index.end.offset ||
            frame.line < last.line || frame.fileFrame < last.fileFrame ||
            frame.fileFrame >= index.end.fileFrame)
            return false;
        last = {frame.end, frame.line + 1, frame.fileFrame + 1};
    }
    return true;
}

bool readWholeFile(const std::string& path, std::string& bytes, std::string& error)
{
    std::ifstream in(path, std::ios::binary);
    if (!in)
    {
        error = "no index file";
        return false;
    }
    in.seekg(0, std::ios::end);
    const std::streamoff size = in.tellg();
    if (size < 0 || uint64_t(size) > MAX_INDEX_BYTES)
    {
        error = "the index file is too large to be one";
        return false;
    }
    in.seekg(0);
    bytes.resize(static_cast<std::size_t>(size));
    if (!in.read(bytes.data(), size))
    {
        error = "cannot read the index file";
        return false;
    }
    return true;
}

}

bool osgGlyphsData::frames::stampFile(const std::string& path, FileStamp& stamp, std::string& error)
{
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    struct stat status;
    if (fd < 0 || ::fstat(fd, &status) != 0)
    {
        error = path + ": cannot open: " + std::strerror(errno);
        if (fd >= 0)
            ::close(fd);
        return false;
    }
    stamp.size = static_cast<uint64_t>(status.st_size);
    stamp.modifiedNanoseconds = int64_t(status.st_mtim.tv_sec) * 1000000000 + status.st_mtim.tv_nsec;
    const uint64_t from = stamp.size > TAIL_BYTES ? stamp.size - TAIL_BYTES : 0;
    const bool hashed = hashRange(fd, from, stamp.size, stamp.tailHash);
    ::close(fd);
    if (!hashed)
        error = path + ": cannot read its last bytes";
    return hashed;
}

bool osgGlyphsData::frames::fileGrewFrom(const std::string& path, const FileStamp& stamp)
{
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0)
        return false;
    struct stat status;
    uint64_t hash = 0;
    const uint64_t from = stamp.size > TAIL_BYTES ? stamp.size - TAIL_BYTES : 0;
    const bool grew = ::fstat(fd, &status) == 0 && uint64_t(status.st_size) >= stamp.size &&
                      hashRange(fd, from, stamp.size, hash) && hash == stamp.tailHash;
    ::close(fd);
    return grew;
}

bool osgGlyphsData::frames::writeFrameIndex(const std::string& path, const StoredFrameIndex& index,
                                            std::string& error)
{
    Writer out;
    out.bytes().append(MAGIC, sizeof(MAGIC));
    out.u64(index.stamp.size);
    out.i64(index.stamp.modifiedNanoseconds);
    out.u64(index.stamp.tailHash);
    out.text(index.format);
    out.u64(index.compression);
    out.u64(index.end.offset);
    out.u64(index.end.line);
    out.u64(index.end.fileFrame);
    out.byte(index.complete ? 1 : 0);
    out.u64(index.frames.size());
    for (const FrameInfo& frame : index.frames)
        writeFrame(out, frame);
    out.u64(index.warnings.size());
    for (const std::string& warning : index.warnings)
        out.text(warning);
    out.text(index.checkpoints);
    out.u64(fnv1a(out.bytes().data(), out.bytes().size()));

    const std::string temporary = path + ".tmp" + std::to_string(::getpid());
    {
        std::ofstream file(temporary, std::ios::binary | std::ios::trunc);
        if (!file || !file.write(out.bytes().data(), static_cast<std::streamsize>(out.bytes().size())) ||
            !file.flush())
        {
            error = temporary + ": cannot write: " + std::strerror(errno);
            std::remove(temporary.c_str());
            return false;
        }
    }
    if (std::rename(temporary.c_str(), path.c_str()) != 0)
    {
        error = path + ": cannot write: " + std::strerror(errno);
        std::remove(temporary.c_str());
        return false;
    }
    return true;
}

bool osgGlyphsData::frames::readFrameIndex(const std::string& path, StoredFrameIndex& index,
                                           std::string& error)
{
    std::string bytes;
    if (!readWholeFile(path, bytes, error))
        return false;
    if (bytes.size() < sizeof(MAGIC) + 8 || std::memcmp(bytes.data(), MAGIC, sizeof(MAGIC)) != 0)
    {
        error = "not an index of this version";
        return false;
    }
    uint64_t stored = 0;
    std::string body = bytes.substr(0, bytes.size() - 8);
    const std::string last = bytes.substr(bytes.size() - 8);
    Reader(last).u64(stored);
    if (stored != fnv1a(body.data(), body.size()))
    {
        error = "its checksum does not match: corrupt";
        return false;
    }
    body.erase(0, sizeof(MAGIC));
    Reader in(body);
    uint64_t frameCount = 0, warningCount = 0, compression = 0;
    uint8_t complete = 0;
    bool ok = in.u64(index.stamp.size) && in.i64(index.stamp.modifiedNanoseconds) &&
              in.u64(index.stamp.tailHash) && in.text(index.format) && in.u64(compression) &&
              in.u64(index.end.offset) && in.u64(index.end.line) && in.u64(index.end.fileFrame) &&
              in.byte(complete) && complete <= 1 && in.u64(frameCount) &&
              frameCount <= in.left() / FRAME_RECORD_BYTES;
    index.compression = static_cast<uint32_t>(compression);
    index.complete = complete == 1;
    index.frames.clear();
    for (uint64_t i = 0; ok && i < frameCount; ++i)
    {
        index.frames.emplace_back();
        ok = readFrame(in, index.frames.back());
    }
    ok = ok && in.u64(warningCount) && warningCount <= in.left() / 8;
    index.warnings.clear();
    for (uint64_t i = 0; ok && i < warningCount; ++i)
    {
        index.warnings.emplace_back();
        ok = in.text(index.warnings.back());
    }
    ok = ok && in.text(index.checkpoints) && in.left() == 0 && compression <= 2 && framesAreOrdered(index);
    if (!ok)
        error = "its contents are inconsistent: corrupt";
    return ok;
}

std::string osgGlyphsData::frames::chooseIndexPath(const std::string& file, FrameIndexLocation location,
                                                   const std::string& cacheFolder)
{
    namespace fs = std::filesystem;
    if (location == FrameIndexLocation::None)
        return std::string();
    std::error_code code;
    const fs::path absolute = fs::absolute(file, code);
    if (location == FrameIndexLocation::BesideOrCache)
    {
        const fs::path folder = absolute.parent_path();
        if (::access(folder.c_str(), W_OK) == 0)
            return absolute.string() + ".glyphindex";
    }
    fs::path cache = cacheFolder;
    if (cache.empty())
    {
        if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg)
            cache = fs::path(xdg) / "osgGlyphs";
        else if (const char* home = std::getenv("HOME"); home && *home)
            cache = fs::path(home) / ".cache" / "osgGlyphs";
        else
            cache = fs::temp_directory_path(code) / "osgGlyphs";
    }
    fs::create_directories(cache, code);
    char hash[17];
    std::snprintf(hash, sizeof(hash), "%016llx",
                  static_cast<unsigned long long>(fnv1a(absolute.string().data(), absolute.string().size())));
    return (cache / (std::string(hash) + "-" + absolute.filename().string() + ".glyphindex")).string();
}
