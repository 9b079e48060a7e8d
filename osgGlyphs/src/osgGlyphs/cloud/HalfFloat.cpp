#include "HalfFloat.h"

#include <cstring>

uint16_t osgGlyphs::detail::toHalf(float value)
{
    if (!(value > 0.0f))
        return 0;
    uint32_t bits = 0;
    std::memcpy(&bits, &value, sizeof(bits));
    const int exponent = static_cast<int>((bits >> 23) & 0xffu) - 127 + 15;
    uint32_t mantissa = bits & 0x7fffffu;
    if (exponent >= 31)
        return 0x7bff;
    if (exponent <= 0)
    {
        if (exponent < -10)
            return 1;
        mantissa |= 0x800000u;
        const int shift = 14 - exponent;
        uint32_t half = mantissa >> shift;
        if ((mantissa >> (shift - 1)) & 1u)
            ++half;
        return static_cast<uint16_t>(half ? half : 1);
    }
    uint32_t half = (static_cast<uint32_t>(exponent) << 10) | (mantissa >> 13);
    if (mantissa & 0x1000u)
        ++half; // a carry into the exponent is still the right rounding
    return static_cast<uint16_t>(half > 0x7bffu ? 0x7bffu : half);
}

float osgGlyphs::detail::fromHalf(uint16_t half)
{
    const uint32_t exponent = (half >> 10) & 31u;
    const uint32_t mantissa = half & 1023u;
    if (exponent == 0)
        return static_cast<float>(mantissa) * (1.0f / 16777216.0f);
    const uint32_t bits =
        (static_cast<uint32_t>(half & 0x8000u) << 16) | ((exponent + 112u) << 23) | (mantissa << 13);
    float value = 0.0f;
    std::memcpy(&value, &bits, sizeof(value));
    return value;
}
