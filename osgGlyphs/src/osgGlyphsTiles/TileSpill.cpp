#include "TileSpill.h"

#include <cerrno>
#include <cstring>

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

TileSpill::TileSpill(const std::string& path, bool scalars, bool colors, bool vectors)
    : _path(path), _scalars(scalars), _colors(colors), _vectors(vectors),
      _file(std::fopen(path.c_str(), "w+b"))
{
    _buffer.reserve(BLOCK_RECORDS * recordSize());
}

TileSpill::~TileSpill()
{
    if (_file)
    {
        std::fclose(_file);
        std::remove(_path.c_str());
    }
}

std::unique_ptr<TileSpill> TileSpill::createLike(const std::string& path) const
{
    return std::make_unique<TileSpill>(path, _scalars, _colors, _vectors);
}

std::size_t TileSpill::recordSize() const
{
    return sizeof(osg::Vec3f) + sizeof(float) + (_scalars ? sizeof(float) : 0) +
           (_colors ? sizeof(osg::Vec4ub) : 0) + (_vectors ? sizeof(osg::Vec3f) : 0);
}

void TileSpill::pack(const TileGlyphs& glyphs, std::size_t i, unsigned char* record) const
{
    record = put(record, glyphs.positions[i]);
    record = put(record, glyphs.radii[i]);
    if (_scalars)
        record = put(record, glyphs.scalars[i]);
    if (_colors)
        record = put(record, glyphs.colors[i]);
    if (_vectors)
        put(record, glyphs.vectors[i]);
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

template <typename IndexOf>
bool TileSpill::appendRecords(const TileGlyphs& glyphs, std::size_t count, const IndexOf& indexOf,
                              std::string& error)
{
    const std::size_t size = recordSize();
    for (std::size_t done = 0; done < count;)
    {
        if (_buffer.size() + size > _buffer.capacity() && !writeBuffer(error))
            return false;
        const std::size_t records = std::min((_buffer.capacity() - _buffer.size()) / size, count - done);
        const std::size_t at = _buffer.size();
        _buffer.resize(at + records * size);
        unsigned char* record = _buffer.data() + at;
        for (std::size_t i = 0; i < records; ++i, record += size)
            pack(glyphs, indexOf(done + i), record);
        done += records;
        _count += records;
    }
    return true;
}

bool TileSpill::append(const TileGlyphs& glyphs, std::size_t begin, std::size_t end, std::string& error)
{
    return appendRecords(
        glyphs, end - begin, [begin](std::size_t i) { return begin + i; }, error);
}

bool TileSpill::append(const TileGlyphs& glyphs, const std::vector<unsigned int>& indices, std::string& error)
{
    return appendRecords(
        glyphs, indices.size(), [&indices](std::size_t i) { return indices[i]; }, error);
}

bool TileSpill::read(const std::function<bool(const TileGlyphs& block)>& visit, std::string& error)
{
    if (!writeBuffer(error) || std::fflush(_file) != 0 || std::fseek(_file, 0, SEEK_SET) != 0)
    {
        error = _path + ": cannot read the temporary file back (" + std::strerror(errno) + ")";
        return false;
    }
    const std::size_t size = recordSize();
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
        block.positions.resize(records);
        block.radii.resize(records);
        block.scalars.resize(_scalars ? records : 0);
        block.colors.resize(_colors ? records : 0);
        block.vectors.resize(_vectors ? records : 0);
        const unsigned char* from = bytes.data();
        for (std::size_t i = 0; i < records; ++i)
        {
            from = take(from, block.positions[i]);
            from = take(from, block.radii[i]);
            if (_scalars)
                from = take(from, block.scalars[i]);
            if (_colors)
                from = take(from, block.colors[i]);
            if (_vectors)
                from = take(from, block.vectors[i]);
        }
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
