// VTK arrays of billions of components: the count is refused before a column name is made for
// each component, within a cap on the memory the test program may hold.

#include "AllocationMeter.h"

#include <osgGlyphsData/PointReader>

#include <gtest/gtest.h>

#include <sstream>
#include <string>

namespace
{

using hostiletest::AllocationMeter;
using hostiletest::MiB;

/** The error of reading text in a format, which must fail, with at most capBytes held at once. */
std::string readErrorWithin(const std::string& text, const std::string& format, std::size_t capBytes)
{
    std::istringstream stream(text);
    std::string error;
    AllocationMeter meter(capBytes);
    EXPECT_FALSE(osgGlyphsData::readPointStream(stream, format, "h." + format,
                                                osgGlyphsData::PointReadOptions(), error)
                     .valid());
    EXPECT_FALSE(meter.wasCapReached()) << error;
    return error;
}

} // namespace

// The component count of an array is checked before a name is made for each component.
TEST(VtkLimits, RefusesComponentCountsBeforeNamingThem)
{
    const std::string head = "# vtk DataFile Version 3.0\nt\nASCII\nDATASET POLYDATA\nPOINTS 1 float\n0 0 0\n"
                             "POINT_DATA 1\n";
    const std::size_t cap = 64 * MiB;
    EXPECT_EQ(readErrorWithin(head + "FIELD f 1\na 100000000 1 float\n1\n", "vtk", cap),
              "h.vtk:9: FIELD array a: 100000000 components per tuple (at most 1024)");
    EXPECT_EQ(readErrorWithin(head + "SCALARS s float 4611686018427387904\n1\n", "vtk", cap),
              "h.vtk:8: SCALARS s: 4611686018427387904 components per tuple (at most 1024)");
    EXPECT_EQ(readErrorWithin(head + "TEXTURE_COORDINATES t 100000000 float\n1\n", "vtk", cap),
              "h.vtk:8: TEXTURE_COORDINATES t: 100000000 components per tuple (at most 1024)");
    EXPECT_EQ(readErrorWithin(head + "COLOR_SCALARS c 100000000\n1\n", "vtk", cap),
              "h.vtk:8: COLOR_SCALARS c: 100000000 components per tuple (at most 1024)");
}
