#include "TileArchive.h"

#include <osgGlyphs/Version>

#include <osgDB/FileNameUtils>
#include <osgDB/Options>
#include <osgDB/Registry>

#include <cerrno>
#include <cstring>
#include <sstream>

using namespace osgGlyphsTiles::detail;

namespace
{

/** The bytes of every index block's entries, as the osga plugin makes them. */
const uint32_t INDEX_BLOCK_BYTES = 4096;
/** What precedes a block's entries: its size, the next block's position, the entries' length. */
const std::size_t BLOCK_HEADER_BYTES = sizeof(uint32_t) + sizeof(uint64_t) + sizeof(uint32_t);

template <typename T>
void put(std::vector<char>& bytes, const T& value)
{
    const char* from = reinterpret_cast<const char*>(&value);
    bytes.insert(bytes.end(), from, from + sizeof(T));
}

}

TileArchive::~TileArchive()
{
    if (_file)
        std::fclose(_file);
}

bool TileArchive::writeAt(uint64_t position, const void* data, std::size_t size)
{
    return std::fseek(_file, static_cast<long>(position), SEEK_SET) == 0 &&
           std::fwrite(data, 1, size, _file) == size;
}

bool TileArchive::writeBlock(const IndexBlock& block)
{
    std::vector<char> bytes;
    bytes.reserve(BLOCK_HEADER_BYTES + INDEX_BLOCK_BYTES);
    put(bytes, INDEX_BLOCK_BYTES);
    put(bytes, block.next);
    put(bytes, static_cast<uint32_t>(block.entries.size()));
    bytes.insert(bytes.end(), block.entries.begin(), block.entries.end());
    bytes.resize(BLOCK_HEADER_BYTES + INDEX_BLOCK_BYTES, 0);
    return writeAt(block.position, bytes.data(), bytes.size());
}

bool TileArchive::create(const std::string& path, std::string& error)
{
    _file = std::fopen(path.c_str(), "w+b");
    if (!_file)
    {
        error = std::string("cannot create the archive (") + std::strerror(errno) + ")";
        return false;
    }
    // "osga", a word that tells the byte order, the format's version (0), the first index block.
    std::vector<char> header = {'o', 's', 'g', 'a'};
    put(header, uint32_t(1));
    put(header, 0.0f);
    _blocks.resize(1);
    _blocks.front().position = header.size();
    _end = header.size() + BLOCK_HEADER_BYTES + INDEX_BLOCK_BYTES;
    if (!writeAt(0, header.data(), header.size()) || !writeBlock(_blocks.front()))
    {
        error = std::string("cannot write the archive (") + std::strerror(errno) + ")";
        return false;
    }
    return true;
}

bool TileArchive::writeNode(const osg::Node& node, const std::string& name, std::string& error)
{
    osgDB::ReaderWriter* writer =
        osgDB::Registry::instance()->getReaderWriterForExtension(osgDB::getLowerCaseFileExtension(name));
    if (!writer)
    {
        error = "no osgDB plugin writes " + name;
        return false;
    }
    static const osg::ref_ptr<osgDB::Options> versioned = []
    {
        osg::ref_ptr<osgDB::Options> options = new osgDB::Options;
        options->setPluginStringData("CustomDomains", OSGGLYPHS_SERIALIZER_DOMAIN_ENTRY);
        return options;
    }();
    std::ostringstream bytes(std::ios::out | std::ios::binary);
    const osgDB::ReaderWriter::WriteResult written = writer->writeNode(node, bytes, versioned.get());
    if (!written.success())
    {
        error =
            "cannot write " + name + (written.message().empty() ? std::string() : ": " + written.message());
        return false;
    }
    return append(name, bytes.str(), error);
}

bool TileArchive::append(const std::string& name, const std::string& bytes, std::string& error)
{
    std::lock_guard<std::mutex> lock(_mutex);
    const uint64_t position = _end;
    if (!_file || !writeAt(position, bytes.data(), bytes.size()))
    {
        error = "cannot write " + name + " into the archive (" + std::strerror(errno) + ")";
        return false;
    }
    _end += bytes.size();
    // An entry: the file's position and size, its name's length and the name. A block holds
    // entries while they leave it a byte to spare; the next one goes where the file ends.
    std::vector<char> entry;
    put(entry, position);
    put(entry, static_cast<uint64_t>(bytes.size()));
    put(entry, static_cast<uint32_t>(name.size()));
    entry.insert(entry.end(), name.begin(), name.end());
    if (_blocks.back().entries.size() + entry.size() >= INDEX_BLOCK_BYTES)
    {
        _blocks.back().next = _end;
        _blocks.emplace_back();
        _blocks.back().position = _end;
        _end += BLOCK_HEADER_BYTES + INDEX_BLOCK_BYTES;
        if (!writeBlock(_blocks.back()))
        {
            error = std::string("cannot write the archive's index (") + std::strerror(errno) + ")";
            return false;
        }
    }
    _blocks.back().entries.insert(_blocks.back().entries.end(), entry.begin(), entry.end());
    return true;
}

bool TileArchive::close(std::string& error)
{
    std::lock_guard<std::mutex> lock(_mutex);
    if (!_file)
        return true;
    bool written = true;
    for (const IndexBlock& block : _blocks)
        written = written && writeBlock(block);
    written = std::fclose(_file) == 0 && written;
    _file = nullptr;
    if (!written)
        error = std::string("cannot write the archive's index (") + std::strerror(errno) + ")";
    return written;
}
