/* osgGlyphs - private: scalar types of binary point data and their decoding in either byte order. */

#ifndef OSGGLYPHS_READERS_BINARYVALUES_H
#define OSGGLYPHS_READERS_BINARYVALUES_H 1

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <type_traits>

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

/** True on a host that stores the most significant byte first. */
inline bool isHostBigEndian()
{
    const uint16_t one = 1;
    unsigned char first;
    std::memcpy(&first, &one, 1);
    return first == 0;
}

/** The bytes of bits in the other order. */
inline uint8_t byteSwap(uint8_t bits)
{
    return bits;
}
inline uint16_t byteSwap(uint16_t bits)
{
    return static_cast<uint16_t>(bits << 8 | bits >> 8);
}
inline uint32_t byteSwap(uint32_t bits)
{
    return bits << 24 | (bits & 0xff00u) << 8 | (bits >> 8 & 0xff00u) | bits >> 24;
}
inline uint64_t byteSwap(uint64_t bits)
{
    return static_cast<uint64_t>(byteSwap(static_cast<uint32_t>(bits))) << 32 |
           byteSwap(static_cast<uint32_t>(bits >> 32));
}

/** The value of type T at p, stored in either byte order (any host): one load, and a byte swap
 * when the order is not the host's. */
template <typename T>
inline T loadScalar(const char* p, bool bigEndian)
{
    typedef std::conditional_t<
        sizeof(T) == 1, uint8_t,
        std::conditional_t<sizeof(T) == 2, uint16_t, std::conditional_t<sizeof(T) == 4, uint32_t, uint64_t>>>
        Bits;
    static_assert(sizeof(Bits) == sizeof(T), "a scalar of 1, 2, 4 or 8 bytes");
    Bits bits;
    std::memcpy(&bits, p, sizeof(bits));
    if (bigEndian != isHostBigEndian())
        bits = byteSwap(bits);
    T value;
    std::memcpy(&value, &bits, sizeof(value));
    return value;
}

/** Calls f with a value of the C++ type of type (0): f(int8_t()), f(float()) and so on. */
template <typename Function>
inline auto visitScalarType(ScalarType type, Function&& f)
{
    switch (type)
    {
    case ScalarType::Int8:
        return f(int8_t());
    case ScalarType::UInt8:
        return f(uint8_t());
    case ScalarType::Int16:
        return f(int16_t());
    case ScalarType::UInt16:
        return f(uint16_t());
    case ScalarType::Int32:
        return f(int32_t());
    case ScalarType::UInt32:
        return f(uint32_t());
    case ScalarType::Int64:
        return f(int64_t());
    case ScalarType::UInt64:
        return f(uint64_t());
    case ScalarType::Float32:
        return f(float());
    default:
        return f(double());
    }
}

/** The value at p as a double. */
inline double decodeScalar(const char* p, ScalarType type, bool bigEndian)
{
    return visitScalarType(type, [&](auto zero)
                           { return static_cast<double>(loadScalar<decltype(zero)>(p, bigEndian)); });
}

/** The values at first, first + stride, ... (count of them) as doubles, into out. */
inline void decodeScalars(const char* first, std::size_t stride, std::size_t count, ScalarType type,
                          bool bigEndian, double* out)
{
    visitScalarType(type,
                    [&](auto zero)
                    {
                        typedef decltype(zero) T;
                        // The byte order as a constant in each loop: no test per value.
                        if (bigEndian)
                        {
                            for (std::size_t i = 0; i < count; ++i)
                                out[i] = static_cast<double>(loadScalar<T>(first + i * stride, true));
                        }
                        else
                        {
                            for (std::size_t i = 0; i < count; ++i)
                                out[i] = static_cast<double>(loadScalar<T>(first + i * stride, false));
                        }
                    });
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
