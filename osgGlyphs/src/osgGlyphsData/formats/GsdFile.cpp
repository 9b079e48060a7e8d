// GSD (General Simulation Data, HOOMD-blue's trajectory format), file layer versions 1.0 and 2.x,
// little-endian as every writer stores it:
//   header (256 bytes): magic 0x65DF65DF65DF65DF; where the index lies and its allocated entries;
//     where the name list lies and its size in 64-byte segments; schema and file layer versions
//     (major << 16 | minor); the application and schema names;
//   index: 32-byte entries (frame, N, location, M, name id, type, flags), sorted by frame, ended
//     by the first entry at location 0; each names an N x M array of one type at location;
//   name list: v1.0, one name per 64-byte segment; v2.x, names separated by 0 bytes; the first
//     empty name ends it.
// The whole index is read at opening into each frame's chunks by name; a frame is decoded by
// reading its chunks (a share reads its rows of each by seeking).
//
// The hoomd schema (1.x): configuration/step and /box; particles/N, types, typeid, position,
// velocity, orientation, angmom, image, mass, charge, diameter, body and moment_inertia become
// columns (typeid with types as the categorical column "species"); bonds/N and bonds/group are the
// frame's bond list (PointData::getBonds()); type_shapes' Ellipsoids are the columns shapex, shapey,
// shapez (diameters, as LAMMPS writes them); the other groups, state/ and log/ are not read. A frame that
// omits a chunk takes frame 0's (for a per-particle chunk, only when frame 0 has as many particles), else the
// schema's default.

#include "../ListedBonds.h"
#include "../readers/Fields.h"
#include "BinaryFile.h"
#include "FormatFrameFile.h"
#include "Formats.h"
#include "GsdShapes.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <mutex>
#include <type_traits>
#include <unordered_map>

using namespace osgGlyphsData;
using namespace osgGlyphsData::formats;

namespace
{

const uint64_t MAGIC = 0x65DF65DF65DF65DFull;
const uint64_t HEADER_BYTES = 256;
const uint64_t ENTRY_BYTES = 32;
const uint64_t NAME_SEGMENT = 64;
/** Index entries read at once. */
const std::size_t ENTRIES_PER_READ = 4096;
/** Values read at once from a per-particle chunk. */
const std::size_t BLOCK_VALUES = 16384;
/** Type ids are exact as floats up to 2^24. */
const uint64_t MAX_TYPES = uint64_t(1) << 24;

/** GSD's chunk types (gsd.h's gsd_type). */
enum ChunkType : uint8_t
{
    UInt8 = 1,
    UInt16,
    UInt32,
    UInt64,
    Int8,
    Int16,
    Int32,
    Int64,
    Float32,
    Float64,
    Character
};

std::size_t typeSize(uint8_t type)
{
    static const std::size_t sizes[] = {0, 1, 2, 4, 8, 1, 2, 4, 8, 4, 8, 1};
    return type <= Character ? sizes[type] : 0;
}

const char* typeName(uint8_t type)
{
    static const char* const names[] = {"",      "uint8", "uint16", "uint32",  "uint64",  "int8",
                                        "int16", "int32", "int64",  "float32", "float64", "char"};
    return type <= Character ? names[type] : "unknown";
}

bool isInteger(uint8_t type)
{
    return type >= UInt8 && type <= Int64;
}

bool isNumber(uint8_t type)
{
    return type >= UInt8 && type <= Float64;
}

/** One index entry: an N x M array of one type. */
struct Chunk
{
    uint64_t frame = 0;
    uint64_t rows = 0;
    uint64_t location = 0;
    uint32_t columns = 0;
    uint16_t name = 0;
    uint8_t type = 0;
    /** Where its index entry lies, for messages. */
    uint64_t entryAt = 0;

    uint64_t bytes() const { return rows * columns * typeSize(type); }
};

/** A per-particle quantity of the hoomd schema and the columns it becomes. */
struct Quantity
{
    const char* chunk;
    unsigned int width;
    std::array<const char*, 4> columns;
    std::array<float, 4> fallback;
};

const Quantity POSITION = {"particles/position", 3, {"x", "y", "z"}, {0.0f, 0.0f, 0.0f}};
const Quantity QUANTITIES[] = {
    {"particles/velocity", 3, {"vx", "vy", "vz"}, {0.0f, 0.0f, 0.0f}},
    {"particles/orientation", 4, {"quatw", "quati", "quatj", "quatk"}, {1.0f, 0.0f, 0.0f, 0.0f}},
    {"particles/angmom", 4, {"angmomw", "angmomi", "angmomj", "angmomk"}, {0.0f, 0.0f, 0.0f, 0.0f}},
    {"particles/image", 3, {"ix", "iy", "iz"}, {0.0f, 0.0f, 0.0f}},
    {"particles/mass", 1, {"mass"}, {1.0f}},
    {"particles/charge", 1, {"charge"}, {0.0f}},
    {"particles/diameter", 1, {"diameter"}, {1.0f}},
    {"particles/body", 1, {"body"}, {-1.0f}},
    {"particles/moment_inertia", 3, {"moment_inertia_x", "moment_inertia_y", "moment_inertia_z"}, {0.0f}},
};

/** The other chunks of the schema that the reader uses or knowingly leaves out. */
const char* const OTHER_PARTICLE_CHUNKS[] = {"particles/N", "particles/types", "particles/typeid",
                                             "particles/type_shapes"};

/** A name from the file for a message: its control and other bytes escaped. */
std::string quoted(const std::string& name)
{
    return readers::quote(name);
}

class GsdFile : public FormatFrameFile
{
public:
    explicit GsdFile(const std::string& path) : FormatFrameFile(path, "gsd") {}

    void findFrames() override
    {
        const FilePlace place{&_path};
        readHeader(place);
        readNames(place);
        readIndex(place);
        findQuantities();
        readFrameHeaders();
    }

    std::size_t getNumFrames() const override { return _frames; }

    FrameInfo getFrameInfo(std::size_t frame) const override
    {
        FrameInfo info;
        if (frame >= _frames)
            return info;
        info.offset = _extents[frame].first;
        info.end = _extents[frame].second;
        info.timestep = _steps[frame];
        info.points = _points[frame];
        info.fileFrame = frame;
        return info;
    }

private:
    void readHeader(const FilePlace& place)
    {
        if (_file.getSize() < HEADER_BYTES)
            place.fail(0, "not a GSD file: " + std::to_string(_file.getSize()) +
                              " bytes, shorter than the 256-byte header");
        uint64_t words[5];
        _file.readValues(0, words, 5, false, place, "the header");
        if (words[0] != MAGIC)
            place.fail(0, "not a GSD file: it does not start with the GSD magic number");
        uint32_t versions[2];
        _file.readValues(40, versions, 2, false, place, "the header's versions");
        char schema[65] = {};
        _file.read(48 + 64, schema, 64, place, "the schema name");
        _version = versions[1] >> 16;
        if (versions[1] != (1u << 16) && _version != 2)
            place.fail(44, "GSD file layer version " + std::to_string(_version) + "." +
                               std::to_string(versions[1] & 0xffff) + ": versions 1.0 and 2.x are read");
        if (std::string(schema) != "hoomd")
            place.fail(112, "the schema is " + quoted(schema) + ", not hoomd: only hoomd files are read");
        if (versions[0] >> 16 != 1)
            _warnings.push_back(
                place.describe(40, "hoomd schema version " + std::to_string(versions[0] >> 16) + "." +
                                       std::to_string(versions[0] & 0xffff) + ", read as 1.x"));
        _indexAt = words[1];
        _indexEntries = words[2];
        _namesAt = words[3];
        _nameSegments = words[4];
        checkBlock(_indexAt, _indexEntries, ENTRY_BYTES, 8, "the index", place);
        checkBlock(_namesAt, _nameSegments, NAME_SEGMENT, 24, "the name list", place);
    }

    /** Checks that a block of count items of size bytes at offset lies after the header and in the file. */
    void checkBlock(uint64_t offset, uint64_t count, uint64_t size, uint64_t field, const char* what,
                    const FilePlace& place) const
    {
        const bool fits =
            count <= _file.getSize() / size && offset >= HEADER_BYTES && _file.holds(offset, count * size);
        if (!fits)
            place.fail(field, std::string(what) + " of " + std::to_string(count) + " x " +
                                  std::to_string(size) + " bytes at byte " + std::to_string(offset) +
                                  " does not lie between the header and the end of the file at byte " +
                                  std::to_string(_file.getSize()));
    }

    void readNames(const FilePlace& place)
    {
        std::string block(static_cast<std::size_t>(_nameSegments * NAME_SEGMENT), '\0');
        _file.read(_namesAt, &block[0], block.size(), place, "the name list");
        const std::size_t step = _version == 1 ? NAME_SEGMENT : 0;
        std::size_t at = 0;
        while (at < block.size() && block[at] != '\0')
        {
            const std::size_t end = block.find('\0', at);
            const std::size_t limit = step ? at + step : block.size();
            if (end == std::string::npos || end >= limit)
                place.fail(_namesAt + at, "the name list's name " + std::to_string(_names.size()) +
                                              " does not end with a 0 byte");
            if (_names.size() > std::numeric_limits<uint16_t>::max())
                place.fail(_namesAt + at, "more than 65536 names in the name list");
            _ids.emplace(block.substr(at, end - at), _names.size());
            _names.push_back(block.substr(at, end - at));
            at = step ? limit : end + 1;
        }
    }

    void readIndex(const FilePlace& place)
    {
        std::vector<unsigned char> bytes;
        bool ended = false;
        for (uint64_t first = 0; first < _indexEntries && !ended; first += ENTRIES_PER_READ)
        {
            const uint64_t count = std::min<uint64_t>(ENTRIES_PER_READ, _indexEntries - first);
            bytes.resize(static_cast<std::size_t>(count * ENTRY_BYTES));
            _file.read(_indexAt + first * ENTRY_BYTES, bytes.data(), bytes.size(), place, "the index");
            for (uint64_t i = 0; i < count && !ended; ++i)
                ended = !addEntry(bytes.data() + i * ENTRY_BYTES, _indexAt + (first + i) * ENTRY_BYTES);
        }
        sortChunks();
        leaveOutCutFrames();
    }

    /** Adds the entry of the index at entryAt; false for the entry that ends the index. */
    bool addEntry(const unsigned char* bytes, uint64_t entryAt)
    {
        Chunk chunk;
        int64_t location;
        std::memcpy(&chunk.frame, bytes, 8);
        std::memcpy(&chunk.rows, bytes + 8, 8);
        std::memcpy(&location, bytes + 16, 8);
        std::memcpy(&chunk.columns, bytes + 24, 4);
        std::memcpy(&chunk.name, bytes + 28, 2);
        chunk.type = bytes[30];
        const uint8_t flags = bytes[31];
        chunk.entryAt = entryAt;
        if (location == 0)
            return false;
        chunk.location = static_cast<uint64_t>(location);
        const FilePlace place{&_path,
                              static_cast<std::size_t>(std::min<uint64_t>(chunk.frame, SIZE_MAX - 1))};
        const std::string name = chunk.name < _names.size() ? quoted(_names[chunk.name]) : "the chunk";
        if (chunk.name >= _names.size())
            place.fail(entryAt, "index entry names name " + std::to_string(chunk.name) +
                                    ", the name list holds " + std::to_string(_names.size()));
        if (typeSize(chunk.type) == 0)
            place.fail(entryAt, name + " has type " + std::to_string(chunk.type) + ", not a GSD type");
        if (chunk.columns == 0 || flags != 0)
            place.fail(entryAt, name + (flags ? " has flags set, which GSD reserves" : " has M = 0 columns"));
        if (chunk.frame >= _indexEntries)
            place.fail(entryAt, name + " is in frame " + std::to_string(chunk.frame) + ", past the " +
                                    std::to_string(_indexEntries) + " entries of the index");
        if (!_chunks.empty() && chunk.frame < _chunks.back().frame)
            place.fail(entryAt, name + " of frame " + std::to_string(chunk.frame) + " follows frame " +
                                    std::to_string(_chunks.back().frame) + " in the index");
        const uint64_t bytesPerRow = chunk.columns * uint64_t(typeSize(chunk.type));
        if (location < 0 || static_cast<uint64_t>(location) < HEADER_BYTES ||
            chunk.rows > std::numeric_limits<uint64_t>::max() / bytesPerRow)
            place.fail(entryAt, name + " lies at byte " + std::to_string(location) + " with " +
                                    std::to_string(chunk.rows) + " x " + std::to_string(chunk.columns) + " " +
                                    typeName(chunk.type) + " values: not a place in the file");
        _chunks.push_back(chunk);
        return true;
    }

    void sortChunks()
    {
        // v2.x sorts each frame's entries by name; v1.0 keeps them in the order they were written.
        std::stable_sort(_chunks.begin(), _chunks.end(),
                         [](const Chunk& a, const Chunk& b)
                         { return a.frame != b.frame ? a.frame < b.frame : a.name < b.name; });
        for (std::size_t i = 1; i < _chunks.size(); ++i)
        {
            if (_chunks[i].frame == _chunks[i - 1].frame && _chunks[i].name == _chunks[i - 1].name)
                FilePlace{&_path, static_cast<std::size_t>(_chunks[i].frame)}.fail(
                    _chunks[i].entryAt, quoted(_names[_chunks[i].name]) + " appears twice in the frame");
        }
        _frames = _chunks.empty() ? 0 : static_cast<std::size_t>(_chunks.back().frame + 1);
    }

    /** A file cut short (a killed writer, a copy in progress) loses its last frames' data: those
     * frames are left out with a warning. Any other chunk past the end of the file is an error. */
    void leaveOutCutFrames()
    {
        const auto pastEnd = [this](const Chunk& chunk)
        { return !_file.holds(chunk.location, chunk.bytes()); };
        const auto cut = std::find_if(_chunks.begin(), _chunks.end(), pastEnd);
        if (cut == _chunks.end())
            return;
        const std::size_t frame = static_cast<std::size_t>(cut->frame);
        const FilePlace place{&_path, frame};
        const std::string what = quoted(_names[cut->name]) + " (" + std::to_string(cut->bytes()) +
                                 " bytes at byte " + std::to_string(cut->location) +
                                 ") runs past the end of the file at byte " + std::to_string(_file.getSize());
        const auto later =
            std::find_if(cut, _chunks.end(), [frame](const Chunk& c) { return c.frame > frame; });
        if (!std::all_of(later, _chunks.end(), pastEnd))
            place.fail(cut->entryAt, what);
        if (frame == 0)
            place.fail(cut->entryAt, what + ": the file is cut short before its first frame ends");
        const std::string lost = frame + 1 == _frames ? "frame " + std::to_string(frame) + " is"
                                                      : "frames " + std::to_string(frame) + " to " +
                                                            std::to_string(_frames - 1) + " are";
        _warnings.push_back(
            place.describe(cut->entryAt, what + ": the file is cut short; " + lost + " left out"));
        _chunks.erase(std::find_if(_chunks.begin(), _chunks.end(),
                                   [frame](const Chunk& c) { return c.frame >= frame; }),
                      _chunks.end());
        _frames = frame;
    }

    int idOf(const char* name) const
    {
        const auto found = _ids.find(name);
        return found == _ids.end() ? -1 : static_cast<int>(found->second);
    }

    /** The schema's chunks in the name list, and which quantities the file has (in any frame). */
    void findQuantities()
    {
        _frameStart.assign(_frames + 1, _chunks.size());
        for (std::size_t i = _chunks.size(); i-- > 0;)
            _frameStart[static_cast<std::size_t>(_chunks[i].frame)] = i;
        for (std::size_t frame = _frames; frame-- > 0;)
            _frameStart[frame] = std::min(_frameStart[frame], _frameStart[frame + 1]);
        _stepId = idOf("configuration/step");
        _boxId = idOf("configuration/box");
        _countId = idOf("particles/N");
        _typesId = idOf("particles/types");
        _typeIdId = idOf("particles/typeid");
        _typeShapesId = idOf("particles/type_shapes");
        _positionId = idOf(POSITION.chunk);
        _bondCountId = idOf("bonds/N");
        _bondGroupId = idOf("bonds/group");
        std::vector<bool> used(_names.size(), false);
        for (const Chunk& chunk : _chunks)
            used[chunk.name] = true;
        for (const Quantity& quantity : QUANTITIES)
        {
            const int id = idOf(quantity.chunk);
            if (id >= 0 && used[static_cast<std::size_t>(id)])
                _quantities.push_back({&quantity, id});
        }
        warnOfUnknownChunks(used);
    }

    void warnOfUnknownChunks(const std::vector<bool>& used)
    {
        for (std::size_t id = 0; id < _names.size(); ++id)
        {
            const std::string& name = _names[id];
            if (!used[id] || name.compare(0, 10, "particles/") != 0 || name == POSITION.chunk)
                continue;
            const auto same = [&name](const char* known) { return name == known; };
            if (std::any_of(std::begin(OTHER_PARTICLE_CHUNKS), std::end(OTHER_PARTICLE_CHUNKS), same) ||
                std::any_of(std::begin(QUANTITIES), std::end(QUANTITIES),
                            [&same](const Quantity& q) { return same(q.chunk); }))
                continue;
            _warnings.push_back(FilePlace{&_path}.describe(
                _namesAt, "chunk " + quoted(name) + " is not in the hoomd schema: it is left out"));
        }
    }

    /** Each frame's step, particle count and extent in the file, for getFrameInfo(). */
    void readFrameHeaders()
    {
        _steps.resize(_frames);
        _points.resize(_frames);
        _extents.resize(_frames);
        uint64_t end = HEADER_BYTES;
        for (std::size_t frame = 0; frame < _frames; ++frame)
        {
            const FilePlace place{&_path, frame};
            const Chunk* step = persistent(frame, _stepId);
            const uint64_t value = step ? readInteger(*step, place) : 0;
            if (value > uint64_t(std::numeric_limits<int64_t>::max()))
                place.fail(step->location, "the step " + std::to_string(value) + " is too large");
            _steps[frame] = static_cast<int64_t>(value);
            const Chunk* count = persistent(frame, _countId);
            _points[frame] = count ? readInteger(*count, place) : 0;
            uint64_t first = std::numeric_limits<uint64_t>::max();
            for (std::size_t i = _frameStart[frame]; i < _frameStart[frame + 1]; ++i)
            {
                first = std::min(first, _chunks[i].location);
                end = std::max(end, _chunks[i].location + _chunks[i].bytes());
            }
            _extents[frame] = {first == std::numeric_limits<uint64_t>::max() ? end : first, end};
        }
    }

    /** The frame's chunk of that name, or nullptr. */
    const Chunk* find(std::size_t frame, int id) const
    {
        if (id < 0)
            return nullptr;
        const auto begin = _chunks.begin() + std::ptrdiff_t(_frameStart[frame]);
        const auto end = _chunks.begin() + std::ptrdiff_t(_frameStart[frame + 1]);
        const auto found =
            std::lower_bound(begin, end, id, [](const Chunk& chunk, int name) { return chunk.name < name; });
        return found != end && found->name == id ? &*found : nullptr;
    }

    /** The frame's chunk, or frame 0's, or nullptr. */
    const Chunk* persistent(std::size_t frame, int id) const
    {
        const Chunk* chunk = find(frame, id);
        return chunk ? chunk : find(0, id);
    }

    /** The frame's per-particle chunk, or frame 0's when frame 0 has as many particles, or nullptr. */
    const Chunk* perParticle(std::size_t frame, int id) const
    {
        const Chunk* chunk = find(frame, id);
        return chunk || _points[0] != _points[frame] ? chunk : find(0, id);
    }

    /** The one integer of a chunk (particles/N, configuration/step). */
    uint64_t readInteger(const Chunk& chunk, const FilePlace& place) const
    {
        if (!isInteger(chunk.type) || chunk.rows != 1 || chunk.columns != 1)
            place.fail(chunk.entryAt, quoted(_names[chunk.name]) + " holds " + std::to_string(chunk.rows) +
                                          " x " + std::to_string(chunk.columns) + " " + typeName(chunk.type) +
                                          " values, not one integer");
        int64_t value = 0;
        load(chunk, 0, 1, &value, place);
        if (value < 0 && chunk.type >= Int8)
            place.fail(chunk.location, quoted(_names[chunk.name]) + " is " + std::to_string(value));
        return static_cast<uint64_t>(value);
    }

    /** Reads count values of the chunk from value first on, converted to Out. */
    template <typename Out>
    void load(const Chunk& chunk, uint64_t first, std::size_t count, Out* out, const FilePlace& place) const
    {
        switch (chunk.type)
        {
        case UInt8:
        case Character:
            return loadAs<uint8_t>(chunk, first, count, out, place);
        case UInt16:
            return loadAs<uint16_t>(chunk, first, count, out, place);
        case UInt32:
            return loadAs<uint32_t>(chunk, first, count, out, place);
        case UInt64:
            return loadAs<uint64_t>(chunk, first, count, out, place);
        case Int8:
            return loadAs<int8_t>(chunk, first, count, out, place);
        case Int16:
            return loadAs<int16_t>(chunk, first, count, out, place);
        case Int32:
            return loadAs<int32_t>(chunk, first, count, out, place);
        case Int64:
            return loadAs<int64_t>(chunk, first, count, out, place);
        case Float32:
            return loadAs<float>(chunk, first, count, out, place);
        default:
            return loadAs<double>(chunk, first, count, out, place);
        }
    }

    template <typename Stored, typename Out>
    void loadAs(const Chunk& chunk, uint64_t first, std::size_t count, Out* out, const FilePlace& place) const
    {
        const uint64_t at = chunk.location + first * sizeof(Stored);
        const std::string& what = _names[chunk.name];
        if constexpr (std::is_same<Stored, Out>::value)
            _file.readValues(at, out, count, false, place, what.c_str());
        else
        {
            std::vector<Stored> stored(count);
            _file.readValues(at, stored.data(), count, false, place, what.c_str());
            // uint64 steps past int64's range wrap here and are refused by the caller.
            std::transform(stored.begin(), stored.end(), out, [](Stored v) { return static_cast<Out>(v); });
        }
    }

    /** Checks that a per-particle chunk holds count rows of width numbers. */
    void checkShape(const Chunk& chunk, uint64_t count, unsigned int width, const FilePlace& place) const
    {
        const std::string name =
            quoted(_names[chunk.name]) + (chunk.frame != place.frame ? " of frame 0" : "");
        if (!isNumber(chunk.type))
            place.fail(chunk.entryAt, name + " holds " + typeName(chunk.type) + " values, not numbers");
        if (chunk.rows != count || chunk.columns != width)
            place.fail(chunk.entryAt,
                       name + " holds " + std::to_string(chunk.rows) + " x " + std::to_string(chunk.columns) +
                           " values, not " + std::to_string(count) + " x " + std::to_string(width) +
                           " for the frame's " + std::to_string(count) + " particles (particles/N)");
    }

    /** Passes the share's rows of a per-particle chunk to use, converted to Out, a block of rows at
     * a time: use(values, first row of the share, rows). Blocks keep the reads' buffer small. */
    template <typename Out, typename Use>
    void forEachBlock(const Chunk& chunk, const PointRange& range, const FilePlace& place, Use use) const
    {
        const std::size_t rows = static_cast<std::size_t>(range.end - range.begin);
        const std::size_t width = chunk.columns;
        const std::size_t blockRows = std::max<std::size_t>(1, BLOCK_VALUES / width);
        std::vector<Out> block;
        for (std::size_t row = 0; row < rows; row += blockRows)
        {
            const std::size_t count = std::min(blockRows, rows - row);
            block.resize(count * width);
            load(chunk, (range.begin + row) * width, block.size(), block.data(), place);
            use(block.data(), row, count);
        }
    }

    /** Spreads rows of Width values over the columns, from row first on. */
    template <std::size_t Width>
    static void deinterleave(const float* values, std::size_t first, std::size_t rows,
                             std::vector<std::vector<float>>& columns)
    {
        float* out[Width];
        for (std::size_t column = 0; column < Width; ++column)
            out[column] = columns[column].data() + first;
        for (std::size_t row = 0; row < rows; ++row)
        {
            for (std::size_t column = 0; column < Width; ++column)
                out[column][row] = values[row * Width + column];
        }
    }

    /** The share's rows of a per-particle chunk, one vector per column. */
    std::vector<std::vector<float>> readRows(const Chunk& chunk, const PointRange& range,
                                             const FilePlace& place) const
    {
        const std::size_t width = chunk.columns;
        std::vector<std::vector<float>> columns(width);
        for (std::vector<float>& column : columns)
            column.resize(static_cast<std::size_t>(range.end - range.begin));
        forEachBlock<float>(chunk, range, place,
                            [&columns, width](const float* values, std::size_t first, std::size_t rows)
                            {
                                if (width == 3)
                                    return deinterleave<3>(values, first, rows, columns);
                                if (width == 4)
                                    return deinterleave<4>(values, first, rows, columns);
                                for (std::size_t column = 0; column < width; ++column)
                                {
                                    for (std::size_t row = 0; row < rows; ++row)
                                        columns[column][first + row] = values[row * width + column];
                                }
                            });
        return columns;
    }

    void addQuantity(PointData& data, std::size_t frame, const Quantity& quantity, int id,
                     const PointRange& range, const FilePlace& place) const
    {
        const Chunk* chunk = perParticle(frame, id);
        std::vector<std::vector<float>> columns;
        if (chunk)
        {
            checkShape(*chunk, _points[frame], quantity.width, place);
            columns = readRows(*chunk, range, place);
        }
        else
        {
            for (unsigned int i = 0; i < quantity.width; ++i)
                columns.emplace_back(data.getNumPoints(), quantity.fallback[i]);
        }
        for (unsigned int i = 0; i < quantity.width; ++i)
            data.addColumn(quantity.columns[i], std::move(columns[i]));
    }

    void addPositions(PointData& data, std::size_t frame, const PointRange& range,
                      const FilePlace& place) const
    {
        const Chunk* chunk = perParticle(frame, _positionId);
        if (!chunk && _points[frame] > 0)
            place.fail(_extents[frame].first, "no particles/position for the frame's " +
                                                  std::to_string(_points[frame]) +
                                                  " particles (particles/N)");
        if (!chunk)
            return addQuantity(data, frame, POSITION, _positionId, range, place);
        checkShape(*chunk, _points[frame], 3, place);
        std::vector<std::vector<float>> columns = readRows(*chunk, range, place);
        for (std::size_t axis = 0; axis < 3; ++axis)
        {
            const std::vector<float>& values = columns[axis];
            const auto bad =
                std::find_if(values.begin(), values.end(), [](float v) { return !std::isfinite(v); });
            if (bad == values.end())
                continue;
            const uint64_t particle = range.begin + uint64_t(bad - values.begin());
            place.fail(chunk->location + (particle * 3 + axis) * typeSize(chunk->type),
                       std::string(POSITION.columns[axis]) + " of particle " + std::to_string(particle) +
                           " is not a finite number");
        }
        for (std::size_t axis = 0; axis < 3; ++axis)
            data.addColumn(POSITION.columns[axis], std::move(columns[axis]));
    }

    /** The type names: the frame's particles/types, or frame 0's, or the schema's ['A']. */
    std::vector<std::string> readTypes(std::size_t frame, const FilePlace& place) const
    {
        const Chunk* chunk = persistent(frame, _typesId);
        if (!chunk)
            return {"A"};
        if (typeSize(chunk->type) != 1)
            place.fail(chunk->entryAt, "particles/types holds " + std::string(typeName(chunk->type)) +
                                           " values, not characters");
        std::string bytes(static_cast<std::size_t>(chunk->bytes()), '\0');
        _file.read(chunk->location, &bytes[0], bytes.size(), place, "particles/types");
        if (chunk->rows > MAX_TYPES)
            place.fail(chunk->entryAt, "particles/types names " + std::to_string(chunk->rows) +
                                           " types, more than type ids as floats tell apart");
        std::vector<std::string> types;
        for (uint64_t row = 0; row < chunk->rows; ++row)
        {
            const std::string text =
                bytes.substr(static_cast<std::size_t>(row * chunk->columns), chunk->columns);
            types.push_back(text.substr(0, text.find('\0')));
        }
        return types;
    }

    [[noreturn]] void failTypeId(const Chunk& chunk, uint64_t particle, int64_t id, std::size_t types,
                                 const FilePlace& place) const
    {
        place.fail(chunk.location + particle * typeSize(chunk.type),
                   "particle " + std::to_string(particle) + " has type id " + std::to_string(id) +
                       ", particles/types names " + std::to_string(types));
    }

    void addSpecies(PointData& data, std::size_t frame, const PointRange& range, const FilePlace& place) const
    {
        std::vector<std::string> types = readTypes(frame, place);
        const Chunk* chunk = perParticle(frame, _typeIdId);
        std::vector<float> species(data.getNumPoints(), 0.0f);
        if (chunk)
        {
            checkShape(*chunk, _points[frame], 1, place);
            if (!isInteger(chunk->type))
                place.fail(chunk->entryAt, std::string("particles/typeid holds ") + typeName(chunk->type) +
                                               " values, not integers");
            const auto check = [&](const int64_t* ids, std::size_t first, std::size_t rows)
            {
                for (std::size_t i = 0; i < rows; ++i)
                {
                    if (ids[i] < 0 || uint64_t(ids[i]) >= types.size())
                        failTypeId(*chunk, range.begin + first + i, ids[i], types.size(), place);
                    species[first + i] = static_cast<float>(ids[i]);
                }
            };
            forEachBlock<int64_t>(*chunk, range, place, check);
        }
        else if (types.empty() && !species.empty())
            place.fail(_extents[frame].first, "particles/types is empty: no type for particles of type id 0");
        data.addColumn("species", std::move(species));
        data.setColumnLabels("species", std::move(types));
    }

    /** Where particles/type_shapes (the frame's or frame 0's) makes a type an Ellipsoid, the columns
     * shapex, shapey, shapez: the diameters along the body axes (2a, 2b, 2c; LAMMPS's convention,
     * which quatw..quatk turn as GSD's orientation does), and for the particles of other types their
     * diameter. */
    void addEllipsoidShapes(PointData& data, std::size_t frame, const FilePlace& place) const
    {
        const Chunk* chunk = persistent(frame, _typeShapesId);
        if (!chunk)
            return;
        if (typeSize(chunk->type) != 1)
            place.fail(chunk->entryAt, "particles/type_shapes holds " + std::string(typeName(chunk->type)) +
                                           " values, not characters");
        const std::vector<std::string>& types = data.getColumnLabels("species");
        std::string bytes(static_cast<std::size_t>(chunk->bytes()), '\0');
        _file.read(chunk->location, &bytes[0], bytes.size(), place, "particles/type_shapes");
        std::vector<osg::Vec3> diameters(types.size());
        bool ellipsoids = false;
        for (uint64_t row = 0; row < chunk->rows && row < types.size(); ++row)
        {
            const uint64_t at = row * chunk->columns;
            const std::string text = bytes.substr(static_cast<std::size_t>(at), chunk->columns);
            GsdShapeKind kind;
            osg::Vec3 semiAxes;
            std::string error;
            if (!parseGsdShape(text.substr(0, text.find('\0')), kind, semiAxes, error))
                place.fail(chunk->location + at,
                           "particles/type_shapes of type '" + types[row] + "': " + error);
            ellipsoids = ellipsoids || kind == GsdShapeKind::Ellipsoid;
            diameters[row] = kind == GsdShapeKind::Ellipsoid ? semiAxes * 2.0f : osg::Vec3();
        }
        if (!ellipsoids)
            return;
        const std::vector<float>& species = *data.getColumn("species");
        const std::vector<float>* diameter = data.getColumn("diameter");
        std::vector<float> columns[3];
        for (std::size_t i = 0; i < species.size(); ++i)
        {
            const osg::Vec3& d = diameters[static_cast<std::size_t>(species[i])];
            const float sphere = diameter ? (*diameter)[i] : 1.0f;
            for (int axis = 0; axis < 3; ++axis)
                columns[axis].push_back(d[axis] > 0.0f ? d[axis] : sphere);
        }
        data.addColumn("shapex", std::move(columns[0]));
        data.addColumn("shapey", std::move(columns[1]));
        data.addColumn("shapez", std::move(columns[2]));
    }

    /** HOOMD's box [Lx, Ly, Lz, xy, xz, yz]: the cell a1 = (Lx, 0, 0), a2 = (xy Ly, Ly, 0),
     * a3 = (xz Lz, yz Lz, Lz) (tilt factors are dimensionless), centred at the origin (BoxDim's
     * lo = -L/2, to which makeCoordinates adds the tilts of lo itself): its corner lies at
     * -(a1 + a2 + a3) / 2. */
    void setBox(PointData& data, std::size_t frame, const FilePlace& place) const
    {
        const Chunk* chunk = persistent(frame, _boxId);
        double box[6] = {1.0, 1.0, 1.0, 0.0, 0.0, 0.0};
        if (chunk)
        {
            if (!isNumber(chunk->type) || chunk->bytes() / typeSize(chunk->type) != 6)
                place.fail(chunk->entryAt, "configuration/box holds " + std::to_string(chunk->rows) + " x " +
                                               std::to_string(chunk->columns) + " " + typeName(chunk->type) +
                                               " values, not 6 numbers");
            load(*chunk, 0, 6, box, place);
        }
        const bool finite = std::all_of(box, box + 6, [](double v) { return std::isfinite(v); });
        if (!finite || !(box[0] > 0.0) || !(box[1] > 0.0) || !(box[2] >= 0.0))
            place.fail(chunk->location, "configuration/box is not a box: Lx " + std::to_string(box[0]) +
                                            ", Ly " + std::to_string(box[1]) + ", Lz " +
                                            std::to_string(box[2]));
        const osg::Vec3d lengths(box[0], box[1], box[2]);
        const osg::Vec3d tilt(box[3] * box[1], box[4] * box[2], box[5] * box[2]);
        const osg::Vec3d corner = -(lengths + osg::Vec3d(tilt.x() + tilt.y(), tilt.z(), 0.0)) * 0.5;
        data.setBox(osg::BoundingBoxd(corner, corner + lengths), tilt);
    }

    /** The frame's bonds/group (or frame 0's) as particle index pairs, checked against the frame's
     * particles and bonds/N. */
    std::vector<std::pair<uint32_t, uint32_t>> readBondGroup(const Chunk& group, std::size_t frame,
                                                             const FilePlace& place) const
    {
        const Chunk* count = persistent(frame, _bondCountId);
        const uint64_t bonds = count ? readInteger(*count, place) : 0;
        const std::string name = std::string("bonds/group") + (group.frame != frame ? " of frame 0" : "");
        if (!isInteger(group.type) || group.columns != 2 || group.rows != bonds)
            place.fail(group.entryAt, name + " holds " + std::to_string(group.rows) + " x " +
                                          std::to_string(group.columns) + " " + typeName(group.type) +
                                          " values, not " + std::to_string(bonds) +
                                          " x 2 particle indices for the frame's bonds (bonds/N)");
        // The chunk lies within the file: its values are at most the file's bytes.
        std::vector<int64_t> indices(static_cast<std::size_t>(2 * bonds));
        load(group, 0, indices.size(), indices.data(), place);
        std::vector<std::pair<uint32_t, uint32_t>> rows(static_cast<std::size_t>(bonds));
        for (std::size_t k = 0; k < rows.size(); ++k)
        {
            const int64_t a = indices[2 * k], b = indices[2 * k + 1];
            const uint64_t at = group.location + 2 * k * typeSize(group.type);
            for (int64_t particle : {a, b})
                if (particle < 0 || uint64_t(particle) >= _points[frame])
                    place.fail(at, name + ": bond " + std::to_string(k) + " joins particle " +
                                       std::to_string(particle) + ", not one of the frame's " +
                                       std::to_string(_points[frame]) + " (particles/N)");
            if (a == b)
                place.fail(at, name + ": bond " + std::to_string(k) + " joins particle " + std::to_string(a) +
                                   " to itself");
            rows[k] = {static_cast<uint32_t>(a), static_cast<uint32_t>(b)};
        }
        return rows;
    }

    /** The frame's bonds: one list for every whole frame that shares a bonds/group chunk. */
    void addBonds(PointData& data, std::size_t frame, const PointRange& range, const FilePlace& place) const
    {
        const Chunk* group = persistent(frame, _bondGroupId);
        if (!group)
        {
            const Chunk* count = persistent(frame, _bondCountId);
            if (count && readInteger(*count, place) > 0)
                place.fail(count->entryAt, "bonds/N is " + std::to_string(readInteger(*count, place)) +
                                               " but the frame has no bonds/group");
            return;
        }
        const bool whole = range.begin == 0 && range.end == _points[frame];
        {
            std::lock_guard<std::mutex> lock(_bondsMutex);
            if (whole && _bondsOf == group && _bondsPoints == _points[frame])
                return data.setBonds(_bonds);
        }
        std::vector<uint32_t> frameIndexOfRow(static_cast<std::size_t>(_points[frame]), NOT_IN_FRAME);
        for (uint64_t row = range.begin; row < range.end; ++row)
            frameIndexOfRow[static_cast<std::size_t>(row)] = static_cast<uint32_t>(row - range.begin);
        std::shared_ptr<const PointData::BondList> bonds =
            makeListedBonds(readBondGroup(*group, frame, place), frameIndexOfRow);
        if (whole)
        {
            std::lock_guard<std::mutex> lock(_bondsMutex);
            _bondsOf = group;
            _bondsPoints = _points[frame];
            _bonds = bonds;
        }
        data.setBonds(bonds);
    }

    osg::ref_ptr<PointData> decodeFrame(std::size_t frame, const PointShare& share) const override
    {
        const FilePlace place{&_path, frame};
        if (frame >= _frames)
            place.fail(_file.getSize(), "no such frame (the file holds " + std::to_string(_frames) + ")");
        const PointRange range = getShareRange(share, _points[frame]);
        osg::ref_ptr<PointData> data = new PointData(static_cast<std::size_t>(range.end - range.begin));
        addPositions(*data, frame, range, place);
        addSpecies(*data, frame, range, place);
        for (const auto& quantity : _quantities)
            addQuantity(*data, frame, *quantity.first, quantity.second, range, place);
        addEllipsoidShapes(*data, frame, place);
        setBox(*data, frame, place);
        addBonds(*data, frame, range, place);
        data->setTimestep(_steps[frame]);
        data->setFilePointCount(_points[frame]);
        return data;
    }

    uint32_t _version = 0;
    uint64_t _indexAt = 0;
    uint64_t _indexEntries = 0;
    uint64_t _namesAt = 0;
    uint64_t _nameSegments = 0;
    std::vector<std::string> _names;
    std::unordered_map<std::string, std::size_t> _ids;
    /** The index sorted by frame, then name; frame f's chunks are [_frameStart[f], _frameStart[f + 1]). */
    std::vector<Chunk> _chunks;
    std::vector<std::size_t> _frameStart;
    std::size_t _frames = 0;
    int _stepId = -1;
    int _boxId = -1;
    int _countId = -1;
    int _typesId = -1;
    int _typeIdId = -1;
    int _typeShapesId = -1;
    int _positionId = -1;
    int _bondCountId = -1;
    int _bondGroupId = -1;
    /** The per-particle quantities besides position and type that the file has, with their name ids. */
    std::vector<std::pair<const Quantity*, int>> _quantities;
    std::vector<int64_t> _steps;
    std::vector<uint64_t> _points;
    std::vector<std::pair<uint64_t, uint64_t>> _extents;
    /** The last whole frame's bonds, and the bonds/group chunk and particle count they are of. */
    mutable std::mutex _bondsMutex;
    mutable const Chunk* _bondsOf = nullptr;
    mutable uint64_t _bondsPoints = 0;
    mutable std::shared_ptr<const PointData::BondList> _bonds;
};

}

osg::ref_ptr<FrameFile> formats::openGsd(const std::string& path, const FrameFileOptions&, std::string& error)
{
    return openFormatFile<GsdFile>(path, error);
}
