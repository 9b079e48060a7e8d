// XTC's compression of positions (GROMACS's xdr3dfcoord, as the GROMACS and xdrfile documentation
// describe it), decoded here from that description. Positions are integers, position * precision;
// the bytes are one stream of bits, each byte's most significant bit first. Atom by atom:
//   - an atom's three integers minus the frame's minimum, packed into one number below the product
//     of the three ranges (x most significant: ((x * ny) + y) * nz + z), in as many bits as that
//     product needs, sent 8 bits at a time with the least significant group first; or, when a range
//     is wider than 2^24, each integer in its own bits;
//   - one bit: whether a run length follows; if it does, 5 bits r: r / 3 * 3 is the number of atoms
//     times 3 that follow as small differences, and r % 3 - 1 moves the index of their size up or
//     down one step after this atom; without it the last run length holds;
//   - the run's atoms: each a difference from the atom before, its three parts packed as above in
//     smallIndex bits with the range SIZES[smallIndex] on each axis, offset by half that range. The
//     first of the run is the atom before the one packed in full (the writer swaps the first two,
//     water's oxygen and first hydrogen, so that the larger step comes first).

#include "XtcCoordinates.h"

#include <algorithm>
#include <cmath>

using namespace osgGlyphsData;

namespace
{

/** The ranges of the small differences, by index: three of them take about index bits
 * (SIZES[i]^3 ~ 2^i). A constant of the format, quirks included (5060, 524287, 8388607). */
const int32_t SIZES[] = {
    0,       0,       0,       0,       0,        0,        0,       0,       0,       8,       10,
    12,      16,      20,      25,      32,       40,       50,      64,      80,      101,     128,
    161,     203,     256,     322,     406,      512,      645,     812,     1024,    1290,    1625,
    2048,    2580,    3250,    4096,    5060,     6501,     8192,    10321,   13003,   16384,   20642,
    26007,   32768,   41285,   52015,   65536,    82570,    104031,  131072,  165140,  208063,  262144,
    330280,  416127,  524287,  660561,  832255,   1048576,  1321122, 1664510, 2097152, 2642245, 3329021,
    4194304, 5284491, 6658042, 8388607, 10568983, 13316085, 16777216};
const int FIRST_INDEX = 9;
const int INDEX_COUNT = int(sizeof(SIZES) / sizeof(SIZES[0]));
/** Wider ranges than this are sent one integer at a time. */
const int64_t PACKED_RANGE = 0xffffff;

// Three ranges of up to 24 bits pack into up to 72 bits.
__extension__ typedef unsigned __int128 Wide;

int bitLength(Wide value)
{
    int bits = 0;
    for (; value != 0; value >>= 1)
        ++bits;
    return bits;
}

/** The bits of the compressed data, the first bit of each byte the most significant. */
class BitStream
{
public:
    BitStream(const unsigned char* data, std::size_t size) : _data(data), _size(size) {}

    /** The next bits (1 to 32) as a number, the first bit most significant; false past the end. */
    bool read(int bits, uint32_t& value)
    {
        if (_held < bits && !refill(bits))
            return false;
        _held -= bits;
        value = static_cast<uint32_t>((_buffer >> _held) & ((uint64_t(1) << bits) - 1));
        return true;
    }

    /** A number sent in groups of 8 bits, the least significant group first, and the bits left
     * over (1 to 8) last, as the most significant. */
    template <typename Number>
    bool readPacked(int bits, Number& value)
    {
        uint32_t part;
        if (bits <= 32)
        {
            // All at once: the whole groups, their order turned round, then the rest.
            if (!read(bits, part))
                return false;
            const int groups = (bits - 1) / 8;
            const int rest = bits - 8 * groups;
            const uint32_t whole = groups > 0 ? reverseBytes(part >> rest) >> (32 - 8 * groups) : 0;
            value = static_cast<Number>(whole | ((part & ((1u << rest) - 1)) << (8 * groups)));
            return true;
        }
        value = 0;
        int shift = 0;
        while (bits > 8)
        {
            // Up to 4 whole groups at once, their order turned round.
            const int groups = std::min((bits - 1) / 8, 4);
            if (!read(8 * groups, part))
                return false;
            value |= static_cast<Number>(reverseBytes(part) >> (32 - 8 * groups)) << shift;
            shift += 8 * groups;
            bits -= 8 * groups;
        }
        if (!read(bits, part))
            return false;
        value |= static_cast<Number>(part) << shift;
        return true;
    }

    /** The bytes that the bits read so far reach into. */
    std::size_t byte() const { return _next - std::size_t(_held) / 8; }
    std::size_t size() const { return _size; }
    /** The byte that holds the next bit. */
    std::size_t nextBitByte() const { return _next - std::size_t(_held + 7) / 8; }

private:
    static uint32_t reverseBytes(uint32_t value)
    {
        return (value >> 24) | ((value >> 8) & 0xff00) | ((value << 8) & 0xff0000) | (value << 24);
    }

    /** Adds bytes to the bits held until they are at least bits (at most 32); false at the end. */
    bool refill(int bits)
    {
        if (_size - _next >= 4)
        {
            const unsigned char* at = _data + _next;
            _buffer = (_buffer << 32) | (uint64_t(at[0]) << 24) | (uint64_t(at[1]) << 16) |
                      (uint64_t(at[2]) << 8) | uint64_t(at[3]);
            _next += 4;
            _held += 32;
            return true;
        }
        while (_held < bits)
        {
            if (_next == _size)
                return false;
            _buffer = (_buffer << 8) | _data[_next++];
            _held += 8;
        }
        return true;
    }

    const unsigned char* _data;
    std::size_t _size;
    std::size_t _next = 0;
    uint64_t _buffer = 0;
    int _held = 0;
};

/** Why decoding stopped, and the byte, from the start of the bytes, where it did. */
struct Failure
{
    std::string what;
    std::size_t byte;
};

class Decoder
{
public:
    Decoder(const formats::XtcCompressed& header, const unsigned char* bytes, std::size_t size)
        : _stream(bytes, size), _inverse(1.0f / header.precision)
    {
        bool wide = false;
        for (int axis = 0; axis < 3; ++axis)
        {
            _minimum[axis] = header.minimum[axis];
            _range[axis] = int64_t(header.maximum[axis]) - header.minimum[axis] + 1;
            _rangeBits[axis] = bitLength(Wide(_range[axis]));
            wide = wide || _range[axis] > PACKED_RANGE;
        }
        _packedBits = wide ? 0 : bitLength(Wide(_range[0]) * Wide(_range[1]) * Wide(_range[2]));
        _smallIndex = header.smallIndex;
    }

    void decode(std::size_t atoms, float* const out[3])
    {
        int64_t run = 0;
        std::size_t atom = 0;
        while (atom < atoms)
        {
            _atomByte = _stream.nextBitByte();
            int64_t full[3];
            readFull(atom, full);
            uint32_t flag, code = 0;
            need(_stream.read(1, flag), atom);
            int step = 0;
            if (flag)
            {
                need(_stream.read(5, code), atom);
                step = int(code % 3) - 1;
                run = code - code % 3;
            }
            if (run == 0)
                store(out, atom++, full);
            else
                atom = readRun(atoms, atom, run / 3, full, out);
            _smallIndex += step;
        }
    }

    std::size_t byte() const { return _stream.byte(); }

private:
    void need(bool read, std::size_t atom) const
    {
        if (!read)
            throw Failure{"the compressed coordinates end before atom " + std::to_string(atom + 1),
                          _stream.size()};
    }

    void store(float* const out[3], std::size_t atom, const int64_t position[3]) const
    {
        for (int axis = 0; axis < 3; ++axis)
            out[axis][atom] = static_cast<float>(position[axis]) * _inverse;
    }

    /** Three integers packed into bits below the product of ranges: the last axis least significant. */
    template <typename Number>
    void unpackAs(int bits, const int64_t range[3], std::size_t atom, int64_t values[3])
    {
        Number packed;
        need(_stream.readPacked(bits, packed), atom);
        for (int axis = 2; axis > 0; --axis)
        {
            values[axis] = static_cast<int64_t>(packed % static_cast<Number>(range[axis]));
            packed /= static_cast<Number>(range[axis]);
        }
        if (packed >= static_cast<Number>(range[0]))
            throw Failure{"atom " + std::to_string(atom + 1) + " lies beyond the frame's range", _atomByte};
        values[0] = static_cast<int64_t>(packed);
    }

    void unpack(int bits, const int64_t range[3], std::size_t atom, int64_t values[3])
    {
        if (bits <= 64)
            unpackAs<uint64_t>(bits, range, atom, values);
        else
            unpackAs<Wide>(bits, range, atom, values);
    }

    /** Three integers packed in at most 32 bits, below size^3: as unpack(), dividing by size with
     * a multiplication by inverse = ceil(2^64 / size) (Lemire, Kaser and Kurz, "Faster remainder
     * by direct computation", 2019: exact for 32-bit numbers and divisors). */
    void unpackSmall(std::size_t atom, uint32_t size, uint64_t inverse, int64_t values[3])
    {
        uint32_t packed;
        need(_stream.readPacked(_smallIndex, packed), atom);
        for (int axis = 2; axis > 0; --axis)
        {
            values[axis] = static_cast<int64_t>((Wide(inverse * packed) * size) >> 64);
            packed = static_cast<uint32_t>((Wide(inverse) * packed) >> 64);
        }
        if (packed >= size)
            throw Failure{"atom " + std::to_string(atom + 1) + " lies beyond the frame's range", _atomByte};
        values[0] = packed;
    }

    void readFull(std::size_t atom, int64_t position[3])
    {
        if (_packedBits == 0)
        {
            for (int axis = 0; axis < 3; ++axis)
            {
                uint32_t value;
                need(_stream.read(_rangeBits[axis], value), atom);
                if (value >= _range[axis])
                    throw Failure{"atom " + std::to_string(atom + 1) + " lies beyond the frame's range",
                                  _atomByte};
                position[axis] = value;
            }
        }
        else
            unpack(_packedBits, _range, atom, position);
        for (int axis = 0; axis < 3; ++axis)
            position[axis] += _minimum[axis];
    }

    /** The atom packed in full and the count atoms after it as small differences; returns the
     * index after them. */
    std::size_t readRun(std::size_t atoms, std::size_t atom, int64_t count, const int64_t full[3],
                        float* const out[3])
    {
        if (static_cast<uint64_t>(count) >= atoms - atom)
            throw Failure{"atom " + std::to_string(atom + 1) + ": a run of " + std::to_string(count) +
                              " atoms goes past the frame's " + std::to_string(atoms),
                          _atomByte};
        if (_smallIndex < FIRST_INDEX || _smallIndex >= INDEX_COUNT)
            throw Failure{"atom " + std::to_string(atom + 1) + ": the size index of small differences is " +
                              std::to_string(_smallIndex) + ", outside " + std::to_string(FIRST_INDEX) +
                              " to " + std::to_string(INDEX_COUNT - 1),
                          _atomByte};
        const int64_t size = SIZES[_smallIndex];
        const int64_t ranges[3] = {size, size, size};
        const uint64_t inverse = UINT64_MAX / uint64_t(size) + 1;
        int64_t previous[3] = {full[0], full[1], full[2]};
        for (int64_t i = 0; i < count; ++i)
        {
            int64_t position[3];
            if (_smallIndex <= 32)
                unpackSmall(atom, uint32_t(size), inverse, position);
            else
                unpack(_smallIndex, ranges, atom, position);
            for (int axis = 0; axis < 3; ++axis)
                position[axis] += previous[axis] - size / 2;
            store(out, atom++, position);
            if (i == 0)
                store(out, atom++, full);
            for (int axis = 0; axis < 3; ++axis)
                previous[axis] = position[axis];
        }
        return atom;
    }

    BitStream _stream;
    float _inverse;
    int64_t _minimum[3];
    int64_t _range[3];
    int _rangeBits[3];
    int _packedBits;
    int _smallIndex;
    /** Where the bits of the atom being read start. */
    std::size_t _atomByte = 0;
};

}

std::string formats::checkXtcCompressed(const XtcCompressed& header)
{
    if (!std::isfinite(header.precision) || !(header.precision > 0.0f))
        return "the precision is " + std::to_string(header.precision);
    for (int axis = 0; axis < 3; ++axis)
    {
        if (header.maximum[axis] < header.minimum[axis] ||
            int64_t(header.maximum[axis]) - header.minimum[axis] >= int64_t(0xffffffff))
            return "the range of axis " + std::to_string(axis) + " is " +
                   std::to_string(header.minimum[axis]) + " to " + std::to_string(header.maximum[axis]);
    }
    if (header.smallIndex < FIRST_INDEX || header.smallIndex >= INDEX_COUNT)
        return "the size index of small differences is " + std::to_string(header.smallIndex) + ", outside " +
               std::to_string(FIRST_INDEX) + " to " + std::to_string(INDEX_COUNT - 1);
    return std::string();
}

uint64_t formats::maxXtcCompressedBytes(uint64_t atoms)
{
    // At most 3 x 32 bits, the flag and 5 bits of run length for an atom.
    return atoms * 13 + 16;
}

std::string formats::decodeXtcCoordinates(const XtcCompressed& header, const unsigned char* bytes,
                                          std::size_t size, std::size_t atoms, float* const out[3],
                                          std::size_t& byte)
{
    Decoder decoder(header, bytes, size);
    try
    {
        decoder.decode(atoms, out);
        // Writers count the bytes they fill, so that lying atom counts show here.
        if (decoder.byte() != size)
            throw Failure{"the compressed coordinates of " + std::to_string(atoms) + " atoms end " +
                              std::to_string(size - decoder.byte()) + " bytes before their byte count",
                          decoder.byte()};
    }
    catch (const Failure& failure)
    {
        byte = failure.byte;
        return failure.what;
    }
    return std::string();
}
