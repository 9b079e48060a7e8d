/* osgGlyphs - private: one table of names for an enumeration, read both ways. Not installed. */

#ifndef OSGGLYPHS_ENUMNAMES_H
#define OSGGLYPHS_ENUMNAMES_H 1

#include <string>
#include <utility>

namespace osgGlyphs
{
namespace detail
{

/** The name of value in a table of {value, name} pairs, or fallback. */
template <class Enum, std::size_t N>
const char* nameOf(const std::pair<Enum, const char*> (&table)[N], Enum value,
                   const char* fallback = "unknown")
{
    for (const auto& entry : table)
        if (entry.first == value)
            return entry.second;
    return fallback;
}

/** The value named name in a table of {value, name} pairs; false if no entry has that name. */
template <class Enum, std::size_t N>
bool parseName(const std::pair<Enum, const char*> (&table)[N], const std::string& name, Enum& value)
{
    for (const auto& entry : table)
    {
        if (name == entry.second)
        {
            value = entry.first;
            return true;
        }
    }
    return false;
}

}
}

#endif
