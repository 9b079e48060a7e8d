#include "Fields.h"

#include <charconv>
#include <cmath>

namespace osgGlyphsData
{
namespace readers
{

bool parseInt64(std::string_view field, int64_t& value)
{
    const char* p = field.data();
    const char* end = p + field.size();
    if (p < end && *p == '+')
        ++p;
    const std::from_chars_result result = std::from_chars(p, end, value);
    return result.ec == std::errc() && result.ptr == end && p < end;
}

bool parseUInt64(std::string_view field, uint64_t& value)
{
    const char* p = field.data();
    const char* end = p + field.size();
    if (p < end && *p == '+')
        ++p;
    if (p < end && *p == '-')
        return false;
    const std::from_chars_result result = std::from_chars(p, end, value);
    return result.ec == std::errc() && result.ptr == end && p < end;
}

std::string_view trim(std::string_view text)
{
    std::size_t begin = 0;
    std::size_t end = text.size();
    while (begin < end && isBlank(text[begin]))
        ++begin;
    while (end > begin && isBlank(text[end - 1]))
        --end;
    return text.substr(begin, end - begin);
}

void splitBlanks(std::string_view line, std::vector<std::string_view>& fields)
{
    fields.clear();
    const char* p = line.data();
    const char* end = p + line.size();
    for (;;)
    {
        p = skipBlanks(p, end);
        if (p == end)
            return;
        const char* stop = skipField(p, end);
        fields.emplace_back(p, static_cast<std::size_t>(stop - p));
        p = stop;
    }
}

std::size_t countFields(std::string_view line)
{
    std::size_t count = 0;
    const char* p = line.data();
    const char* end = p + line.size();
    for (;;)
    {
        p = skipBlanks(p, end);
        if (p == end)
            return count;
        p = skipField(p, end);
        ++count;
    }
}

std::string quote(std::string_view field)
{
    static const char hex[] = "0123456789abcdef";
    const std::size_t limit = 40;
    std::string text = "'";
    for (std::size_t i = 0; i < field.size() && i < limit; ++i)
    {
        const unsigned char c = static_cast<unsigned char>(field[i]);
        if (c >= 0x20 && c < 0x7F && c != '\\')
        {
            text += static_cast<char>(c);
        }
        else
        {
            text += "\\x";
            text += hex[c >> 4];
            text += hex[c & 0xF];
        }
    }
    if (field.size() > limit)
        text += "...";
    return text + "'";
}

std::string describeBadNumber(std::string_view field, const std::string& column)
{
    const std::string prefix = "column '" + column + "': ";
    if (field.empty())
        return prefix + "empty field";
    float value = 0.0f;
    if (!parseFloat(field, value))
        return prefix + quote(field) + " is not a number";
    if (std::isnan(value) || toLower(field).find("inf") != std::string::npos)
        return prefix + quote(field) + " is not a finite number";
    return prefix + quote(field) + " is out of the range of a float";
}

std::string toLower(std::string_view text)
{
    std::string lower(text);
    for (char& c : lower)
    {
        if (c >= 'A' && c <= 'Z')
            c = static_cast<char>(c - 'A' + 'a');
    }
    return lower;
}

bool equalsIgnoreCase(std::string_view a, std::string_view b)
{
    return a.size() == b.size() && toLower(a) == toLower(b);
}

} // namespace readers
}
