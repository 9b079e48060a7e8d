// Colour map files: a huge file or a device fails at once, without being read whole; binary
// content is quoted in one short line.

#include "AllocationMeter.h"

#include <osgGlyphs/ColorMap>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace
{

using hostiletest::AllocationMeter;

std::string testFile(const std::string& name, const std::string& bytes)
{
    std::filesystem::create_directories(OSGGLYPHS_HOSTILE_TEST_DIR);
    const std::string path = std::string(OSGGLYPHS_HOSTILE_TEST_DIR) + "/" + name;
    std::ofstream(path, std::ios::binary) << bytes;
    return path;
}

} // namespace

// A colour map is read no further than the largest one: a huge file or a device fails at once.
TEST(ColorMapLimits, RefusesFilesLargerThanAColourMap)
{
    std::string lines;
    while (lines.size() <= 4 * osgGlyphs::ColorMap::MaxFileBytes)
        lines += "#102030\n";
    const std::string large = testFile("large.txt", lines);
    std::string error;
    {
        AllocationMeter meter(4 * osgGlyphs::ColorMap::MaxFileBytes);
        EXPECT_FALSE(osgGlyphs::ColorMap::readFile(large, error).valid());
        EXPECT_FALSE(meter.wasCapReached());
    }
    EXPECT_EQ(error, large + ": more than 1024 KiB, not a colour map (one #rrggbb a line)");

    if (std::filesystem::exists("/dev/zero"))
    {
        AllocationMeter meter(4 * osgGlyphs::ColorMap::MaxFileBytes);
        EXPECT_FALSE(osgGlyphs::ColorMap::readFile("/dev/zero", error).valid());
        EXPECT_FALSE(meter.wasCapReached());
        EXPECT_EQ(error, "/dev/zero: more than 1024 KiB, not a colour map (one #rrggbb a line)");
    }
}

// Bytes that do not show are shown escaped, and a message stays short.
TEST(ColorMapLimits, QuotesBinaryContentInOneShortLine)
{
    const std::string zeros = testFile("zeros.txt", std::string(100000, '\0'));
    std::string error;
    EXPECT_FALSE(osgGlyphs::ColorMap::readFile(zeros, error).valid());
    EXPECT_EQ(
        error,
        zeros + ":1: expected a colour \"#rrggbb\", found "
                "\"\\x00\\x00\\x00\\x00\\x00\\x00\\x00\\x00\\x00\\x00\\x00\\x00\\x00\\x00\\x00\\x00\\x00\\x00"
                "\\x00\\x00\\x00\\x00\\x00\\x00\\x00\\x00\\x00\\x00\\x00\\x00\\x00\\x00\\x00\\x00\\x00\\x00"
                "\\x00\\x00\\x00\\x00...\"");
}
