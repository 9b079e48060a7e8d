/* osgGlyphs - private: a binary file read at any offset from any thread, every read checked. */

#ifndef OSGGLYPHS_FORMATS_BINARYFILE_H
#define OSGGLYPHS_FORMATS_BINARYFILE_H 1

#include "../readers/BinaryValues.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace osgGlyphsData
{
namespace formats
{

/** What a frame file reader throws: one line naming the file, the frame and the byte or dataset. */
struct FormatError
{
    std::string message;
};

/** Where in a file a reader is, for messages: "<file>: frame <n>: byte <offset>: <what>". */
struct FilePlace
{
    const std::string* path = nullptr;
    /** The frame (0-based, printed as such); SIZE_MAX for the file's header. */
    std::size_t frame = SIZE_MAX;

    /** "<file>: frame <n>: byte <offset>: <what>" */
    std::string describe(uint64_t offset, const std::string& what) const;
    /** Throws FormatError with describe(offset, what). */
    [[noreturn]] void fail(uint64_t offset, const std::string& what) const;
};

/** A read-only file read with pread: any offset, from several threads at once, each read checked
 * against the file's size (taken at opening), so that no count or offset from the file makes a
 * read or an allocation beyond it. */
class BinaryFile
{
public:
    BinaryFile() = default;
    ~BinaryFile();
    BinaryFile(const BinaryFile&) = delete;
    BinaryFile& operator=(const BinaryFile&) = delete;

    /** False with "<path>: cannot open: <reason>" (or "is a directory"). */
    bool open(const std::string& path, std::string& error);

    const std::string& getPath() const { return _path; }
    uint64_t getSize() const { return _size; }

    /** Whether [offset, offset + bytes) lies in the file, without overflowing. */
    bool holds(uint64_t offset, uint64_t bytes) const { return offset <= _size && bytes <= _size - offset; }

    /** Reads bytes at offset; throws at place when they are not all in the file ("the file ends at
     * byte <size>, <n> bytes short of <what>") or the system fails. */
    void read(uint64_t offset, void* data, std::size_t bytes, const FilePlace& place, const char* what) const;

    /** Reads count values of type T stored in the given byte order (big: most significant first). */
    template <typename T>
    void readValues(uint64_t offset, T* values, std::size_t count, bool bigEndian, const FilePlace& place,
                    const char* what) const
    {
        if (count > _size / sizeof(T) + 1)
            place.fail(offset,
                       std::string(what) + ": " + std::to_string(count) + " values cannot fit in the file");
        read(offset, values, count * sizeof(T), place, what);
        if (bigEndian != readers::isHostBigEndian())
        {
            for (std::size_t i = 0; i < count; ++i)
                values[i] = readers::loadScalar<T>(reinterpret_cast<const char*>(values + i), bigEndian);
        }
    }

    template <typename T>
    T readValue(uint64_t offset, bool bigEndian, const FilePlace& place, const char* what) const
    {
        T value;
        readValues(offset, &value, 1, bigEndian, place, what);
        return value;
    }

private:
    int _descriptor = -1;
    uint64_t _size = 0;
    std::string _path;
};

} // namespace formats
}

#endif
