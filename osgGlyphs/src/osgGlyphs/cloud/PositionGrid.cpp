#include "PositionGrid.h"

#include <algorithm>
#include <cmath>
#include <limits>

using osgGlyphs::detail::PositionGrid;

namespace
{

double roundHalfUp(double value)
{
    return std::floor(value + 0.5);
}

}

PositionGrid PositionGrid::fit(const osg::Vec3Array& positions, unsigned int count)
{
    double low[3], high[3];
    std::fill(low, low + 3, std::numeric_limits<double>::max());
    std::fill(high, high + 3, std::numeric_limits<double>::lowest());
    for (unsigned int i = 0; i < count && i < positions.size(); ++i)
    {
        const osg::Vec3& p = positions[i];
        if (!(std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z())))
            continue;
        for (int axis = 0; axis < 3; ++axis)
        {
            low[axis] = std::min(low[axis], double(p[axis]));
            high[axis] = std::max(high[axis], double(p[axis]));
        }
    }
    PositionGrid grid;
    if (low[0] > high[0])
        return grid; // no finite position
    double extent = 0.0, magnitude = 0.0;
    for (int axis = 0; axis < 3; ++axis)
    {
        extent = std::max(extent, high[axis] - low[axis]);
        magnitude = std::max({magnitude, std::abs(low[axis]), std::abs(high[axis])});
    }
    // Coincident positions: a step of about a float's resolution at their magnitude.
    if (extent == 0.0)
        extent =
            std::max(magnitude * std::ldexp(1.0, -23), double(std::numeric_limits<float>::min())) * MAX_STEPS;
    int exponent = 0;
    std::frexp(extent / MAX_STEPS, &exponent);
    double step = std::ldexp(1.0, exponent);
    while (step > std::numeric_limits<float>::min() && extent <= MAX_STEPS * step / 2.0)
        step /= 2.0;
    while (extent > MAX_STEPS * step)
        step *= 2.0;
    grid.step = static_cast<float>(step);
    for (int axis = 0; axis < 3; ++axis)
        grid.offset[axis] = static_cast<float>(roundHalfUp((low[axis] + high[axis]) / 2.0 / step) * step);
    return grid;
}

osg::Vec3s PositionGrid::quantise(const osg::Vec3& position) const
{
    osg::Vec3s q;
    for (int axis = 0; axis < 3; ++axis)
    {
        const double steps = roundHalfUp((double(position[axis]) - double(offset[axis])) / double(step));
        q[axis] = std::isfinite(steps) ? static_cast<short>(std::clamp(steps, -32767.0, 32767.0)) : short(0);
    }
    return q;
}
