#include "TileSpill.h"

#include <cerrno>
#include <cstring>
#include <type_traits>

using namespace osgGlyphsTiles::detail;

namespace
{

/** Records read or buffered for writing at a time. */
const std::size_t BLOCK_RECORDS = 1u << 16;

template <typename T>
unsigned char* put(unsigned char* to, const T& value)
{
    std::memcpy(to, &value, sizeof(T));
    return to + sizeof(T);
}

template <typename T>
const unsigned char* take(const unsigned char* from, T& value)
{
    std::memcpy(&value, from, sizeof(T));
    return from + sizeof(T);
}

}

TileRecordFormat::TileRecordFormat(const TileGlyphs& like)
{
    unsigned int index = 0;
    TileGlyphs::forEachArray(
        [this, &index](const auto& values)
        {
            // Every record has a position and a radius.
            if (index < 2 || !values.empty())
            {
                _used |= 1u << index;
                _size += sizeof(typename std::decay_t<decltype(values)>::value_type);
            }
            ++index;
        },
        like);
}

void TileRecordFormat::pack(const TileGlyphs& glyphs, std::size_t i, unsigned char* record) const
{
    forEachArray(glyphs, [&](const auto& values) { record = put(record, values[i]); });
}

void TileRecordFormat::reserve(TileGlyphs& glyphs, std::size_t count) const
{
    forEachArray(glyphs, [count](auto& values) { values.reserve(count); });
}

void TileRecordFormat::unpack(const unsigned char* bytes, std::size_t count, TileGlyphs& glyphs) const
{
    glyphs.clear();
    forEachArray(glyphs, [count](auto& values) { values.resize(count); });
    for (std::size_t i = 0; i < count; ++i)
        forEachArray(glyphs, [&](auto& values) { bytes = take(bytes, values[i]); });
}

TileSpill::TileSpill(const std::string& path, const TileRecordFormat& format)
    : _path(path), _format(format), _file(std::fopen(path.c_str(), "w+b"))
{
    _buffer.reserve(BLOCK_RECORDS * _format.size());
}

TileSpill::~TileSpill()
{
    if (_file)
    {
        std::fclose(_file);
        std::remove(_path.c_str());
    }
}

bool TileSpill::writeBuffer(std::string& error)
{
    if (!_buffer.empty() && std::fwrite(_buffer.data(), 1, _buffer.size(), _file) != _buffer.size())
    {
        error = _path + ": cannot write the temporary file (" + std::strerror(errno) + ")";
        return false;
    }
    _buffer.clear();
    return true;
}

bool TileSpill::append(const TileGlyphs& glyphs, std::size_t begin, std::size_t end, std::string& error)
{
    const std::size_t size = _format.size();
    for (std::size_t i = begin; i < end;)
    {
        if (_buffer.size() + size > _buffer.capacity() && !writeBuffer(error))
            return false;
        const std::size_t records = std::min((_buffer.capacity() - _buffer.size()) / size, end - i);
        const std::size_t at = _buffer.size();
        _buffer.resize(at + records * size);
        unsigned char* record = _buffer.data() + at;
        for (std::size_t last = i + records; i < last; ++i, record += size)
            _format.pack(glyphs, i, record);
        _count += records;
    }
    return true;
}

bool TileSpill::read(const std::function<bool(const TileGlyphs& block)>& visit, std::string& error)
{
    if (!writeBuffer(error) || std::fflush(_file) != 0 || std::fseek(_file, 0, SEEK_SET) != 0)
    {
        error = _path + ": cannot read the temporary file back (" + std::strerror(errno) + ")";
        return false;
    }
    const std::size_t size = _format.size();
    std::vector<unsigned char> bytes(BLOCK_RECORDS * size);
    TileGlyphs block;
    for (std::size_t done = 0; done < _count;)
    {
        const std::size_t records = std::min(BLOCK_RECORDS, _count - done);
        if (std::fread(bytes.data(), size, records, _file) != records)
        {
            error = _path + ": the temporary file ends at record " + std::to_string(done) + " of " +
                    std::to_string(_count);
            return false;
        }
        _format.unpack(bytes.data(), records, block);
        done += records;
        if (!visit(block))
            break;
    }
    // Appending after reading goes on at the end.
    if (std::fseek(_file, 0, SEEK_END) != 0)
    {
        error = _path + ": cannot seek in the temporary file";
        return false;
    }
    return true;
}
