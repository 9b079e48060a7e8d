/* osgGlyphs - private: scalar types of binary point data and their decoding in either byte order. */

#ifndef OSGGLYPHS_READERS_BINARYVALUES_H
#define OSGGLYPHS_READERS_BINARYVALUES_H 1

#include <cstddef>
#include <cstdint>
#include <cstring>

namespace osgGlyphsData
{
namespace readers
{

enum class ScalarType
{
    Int8,
    UInt8,
    Int16,
    UInt16,
    Int32,
    UInt32,
    Int64,
    UInt64,
    Float32,
    Float64
};

/** Size in bytes. */
inline std::size_t scalarSize(ScalarType type)
{
    switch (type)
    {
    case ScalarType::Int8:
    case ScalarType::UInt8:
        return 1;
    case ScalarType::Int16:
    case ScalarType::UInt16:
        return 2;
    case ScalarType::Int32:
    case ScalarType::UInt32:
    case ScalarType::Float32:
        return 4;
    default:
        return 8;
    }
}

inline bool isIntegerType(ScalarType type)
{
    return type != ScalarType::Float32 && type != ScalarType::Float64;
}

/** The raw bits of a value of size bytes, assembled from either byte order (any host). */
inline uint64_t loadBits(const unsigned char* p, std::size_t size, bool bigEndian)
{
    uint64_t bits = 0;
    if (bigEndian)
    {
        for (std::size_t i = 0; i < size; ++i)
            bits = (bits << 8) | p[i];
    }
    else
    {
        for (std::size_t i = size; i-- > 0;)
            bits = (bits << 8) | p[i];
    }
    return bits;
}

/** The value at p as a double. */
inline double decodeScalar(const char* p, ScalarType type, bool bigEndian)
{
    const uint64_t bits = loadBits(reinterpret_cast<const unsigned char*>(p), scalarSize(type), bigEndian);
    switch (type)
    {
    case ScalarType::Int8:
        return static_cast<int8_t>(static_cast<uint8_t>(bits));
    case ScalarType::UInt8:
        return static_cast<uint8_t>(bits);
    case ScalarType::Int16:
        return static_cast<int16_t>(static_cast<uint16_t>(bits));
    case ScalarType::UInt16:
        return static_cast<uint16_t>(bits);
    case ScalarType::Int32:
        return static_cast<int32_t>(static_cast<uint32_t>(bits));
    case ScalarType::UInt32:
        return static_cast<uint32_t>(bits);
    case ScalarType::Int64:
        return static_cast<double>(static_cast<int64_t>(bits));
    case ScalarType::UInt64:
        return static_cast<double>(bits);
    case ScalarType::Float32:
    {
        const uint32_t narrow = static_cast<uint32_t>(bits);
        float value;
        std::memcpy(&value, &narrow, sizeof(value));
        return value;
    }
    case ScalarType::Float64:
    {
        double value;
        std::memcpy(&value, &bits, sizeof(value));
        return value;
    }
    }
    return 0.0;
}

/** An integer value at p (list counts): false when it is negative or not integral. */
inline bool decodeCount(const char* p, ScalarType type, bool bigEndian, uint64_t& count)
{
    const double value = decodeScalar(p, type, bigEndian);
    if (!(value >= 0.0) || value >= 18446744073709551616.0 ||
        value != static_cast<double>(static_cast<uint64_t>(value)))
        return false;
    count = static_cast<uint64_t>(value);
    return true;
}

} // namespace readers
}

#endif
