// osgglyphviewer: how numbers and lists read in messages and in the legend.

#ifndef OSGGLYPHVIEWER_VIEWERTEXT_H
#define OSGGLYPHVIEWER_VIEWERTEXT_H 1

#include <cstdio>
#include <string>
#include <vector>

/** "a, b, c" (or with another separator). */
inline std::string joinNames(const std::vector<std::string>& names, const char* separator = ", ")
{
    std::string list;
    for (const std::string& name : names)
        list += (list.empty() ? "" : separator) + name;
    return list;
}

/** A value with 4 significant digits ("0.2297", "4.554", "1.5e+04"). */
inline std::string formatValue(float value)
{
    char text[32];
    std::snprintf(text, sizeof(text), "%.4g", value);
    return text;
}

/** A value of a file with its digits, up to 10 ("0.2297", "0.3", "4512345.678"). */
inline std::string formatFullValue(double value)
{
    char text[32];
    std::snprintf(text, sizeof(text), "%.10g", value);
    return text;
}

#endif
