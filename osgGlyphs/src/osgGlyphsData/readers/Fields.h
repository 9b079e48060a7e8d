/* osgGlyphs - private: locale-independent field splitting and number parsing for the readers. */

#ifndef OSGGLYPHS_READERS_FIELDS_H
#define OSGGLYPHS_READERS_FIELDS_H 1

#include <fast_float/fast_float.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace osgGlyphsData
{
namespace readers
{

inline bool isBlank(char c)
{
    return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

inline const char* skipBlanks(const char* p, const char* end)
{
    while (p < end && isBlank(*p))
        ++p;
    return p;
}

inline const char* skipField(const char* p, const char* end)
{
    while (p < end && !isBlank(*p))
        ++p;
    return p;
}

/** Parses a whole field as a float or a double (fast_float, C locale; a leading '+' is
 * accepted). False when the field is not exactly one number. The value may be infinite or NaN:
 * check it. */
template <class Number>
inline bool parseNumber(std::string_view field, Number& value)
{
    const char* p = field.data();
    const char* end = p + field.size();
    if (p < end && *p == '+')
        ++p;
    const fast_float::from_chars_result result = fast_float::from_chars(p, end, value);
    return result.ec == std::errc() && result.ptr == end && p < end;
}

inline bool parseFloat(std::string_view field, float& value)
{
    return parseNumber(field, value);
}

inline bool parseDouble(std::string_view field, double& value)
{
    return parseNumber(field, value);
}

/** Parses a whole field as a decimal integer; false when it is not one or out of range. */
bool parseInt64(std::string_view field, int64_t& value);
bool parseUInt64(std::string_view field, uint64_t& value);

/** The field with blanks trimmed on both sides. */
std::string_view trim(std::string_view text);

/** Splits at runs of blanks. */
void splitBlanks(std::string_view line, std::vector<std::string_view>& fields);

/** How many blank-separated fields a line has. */
std::size_t countFields(std::string_view line);

/** The field in single quotes for a message: control and non-ASCII bytes as \xNN, cut after
 * 40 characters. */
std::string quote(std::string_view field);

/** Why a field is no finite number, for a message: "column 'x': 'abc' is not a number". */
std::string describeBadNumber(std::string_view field, const std::string& column);

/** ASCII lower case. */
std::string toLower(std::string_view text);

/** ASCII case-insensitive equality. */
bool equalsIgnoreCase(std::string_view a, std::string_view b);

/** True when text starts with prefix. */
inline bool startsWith(std::string_view text, std::string_view prefix)
{
    return text.size() >= prefix.size() && text.compare(0, prefix.size(), prefix) == 0;
}

} // namespace readers
}

#endif
