// osgglyphbench: how numbers read in messages, the summary and the CSV.

#ifndef OSGGLYPHBENCH_BENCHTEXT_H
#define OSGGLYPHBENCH_BENCHTEXT_H 1

#include <iomanip>
#include <sstream>
#include <string>

/** A value with a fixed number of decimals. */
inline std::string format(double value, int decimals)
{
    std::ostringstream text;
    text << std::fixed << std::setprecision(decimals) << value;
    return text.str();
}

/** Milliseconds with three significant digits or more. */
inline std::string formatMs(double ms)
{
    return format(ms, ms >= 100.0 ? 0 : ms >= 10.0 ? 1 : ms >= 1.0 ? 2 : 3);
}

#endif
