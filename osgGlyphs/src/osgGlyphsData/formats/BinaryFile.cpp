#include "BinaryFile.h"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

using namespace osgGlyphsData::formats;

std::string FilePlace::describe(uint64_t offset, const std::string& what) const
{
    std::string text = path ? *path : std::string("file");
    if (frame != SIZE_MAX)
        text += ": frame " + std::to_string(frame);
    return text + ": byte " + std::to_string(offset) + ": " + what;
}

void FilePlace::fail(uint64_t offset, const std::string& what) const
{
    throw FormatError{describe(offset, what)};
}

BinaryFile::~BinaryFile()
{
    if (_descriptor >= 0)
        ::close(_descriptor);
}

bool BinaryFile::open(const std::string& path, std::string& error)
{
    _path = path;
    _descriptor = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (_descriptor < 0)
    {
        error = path + ": cannot open: " + std::strerror(errno);
        return false;
    }
    struct stat status;
    if (::fstat(_descriptor, &status) != 0)
    {
        error = path + ": cannot read: " + std::strerror(errno);
        return false;
    }
    if (!S_ISREG(status.st_mode))
    {
        error = path + (S_ISDIR(status.st_mode) ? ": is a directory" : ": not a regular file");
        return false;
    }
    _size = static_cast<uint64_t>(status.st_size);
    return true;
}

void BinaryFile::read(uint64_t offset, void* data, std::size_t bytes, const FilePlace& place,
                      const char* what) const
{
    if (!holds(offset, bytes))
        place.fail(offset, std::string("the file ends at byte ") + std::to_string(_size) + ", " +
                               std::to_string(offset > _size ? bytes : bytes - (_size - offset)) +
                               " bytes short of " + what);
    char* out = static_cast<char*>(data);
    while (bytes > 0)
    {
        const ssize_t got = ::pread(_descriptor, out, bytes, static_cast<off_t>(offset));
        if (got < 0 && errno == EINTR)
            continue;
        if (got <= 0)
            place.fail(offset,
                       std::string("cannot read ") + what + ": " +
                           (got < 0 ? std::strerror(errno) : "the file was cut short since it was opened"));
        out += got;
        offset += static_cast<uint64_t>(got);
        bytes -= static_cast<std::size_t>(got);
    }
}
