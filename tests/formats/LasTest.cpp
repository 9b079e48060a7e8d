/* LAS: files of every version (1.2, 1.3, 1.4) and point format (0 to 10) against the values that
 * tests/data/formats/las/write_las.py put in them. Debian packages no LAS writer, so that script
 * writes them from the specification; its lists of values are repeated here. Also: extra bytes in
 * the records, extended VLRs after the points, shares, LAZ refused, and headers that lie. */

#include "FormatTestData.h"

#include <algorithm>
#include <cstring>
#include <iomanip>
#include <map>

using namespace formattest;
using namespace osgGlyphsData;

namespace
{

// write_las.py's points.
const std::vector<double> X = {0, 1, -1, 123456, -654321, 999999};
const std::vector<double> Y = {0, 2, -2, 234567, -765432, 888888};
const std::vector<double> Z = {0, 3, -3, 34567, -76543, 77777};
const double SCALE[3] = {0.001, 0.001, 0.01};
const double OFFSET[3] = {500000.0, 4000000.0, 100.0};
const std::vector<double> INTENSITY = {0, 1, 65535, 1234, 40000, 7};
const std::vector<double> SCAN_DIRECTION = {0, 1, 0, 1, 1, 0};
const std::vector<double> EDGE = {1, 0, 0, 1, 0, 1};
const std::vector<double> USER_DATA = {0, 1, 127, 128, 200, 255};
const std::vector<double> POINT_SOURCE = {0, 1, 65535, 1234, 2, 3};
const std::vector<double> GPS_TIME = {300000000.0,   300000000.5,    300000001.25,
                                      300000010.125, 300000100.0625, 300003600.5};
const std::vector<double> RED = {0, 1, 65535, 256, 1000, 30000};
const std::vector<double> GREEN = {65535, 2, 0, 512, 2000, 40000};
const std::vector<double> BLUE = {7, 3, 1, 1024, 3000, 50000};
const std::vector<double> NIR = {9, 4, 65535, 2048, 4000, 60000};
const std::vector<double> LEGACY_RETURN = {1, 2, 3, 4, 5, 7};
const std::vector<double> LEGACY_RETURNS = {1, 2, 3, 5, 7, 7};
const std::vector<double> LEGACY_CLASS = {0, 1, 2, 6, 9, 31};
const std::vector<double> LEGACY_FLAGS = {0, 1, 2, 4, 7, 3};
const std::vector<double> LEGACY_ANGLE = {-90, -1, 0, 1, 45, 90};
const std::vector<double> RETURN = {1, 2, 3, 8, 15, 15};
const std::vector<double> RETURNS = {1, 2, 4, 9, 15, 15};
const std::vector<double> CLASS = {0, 1, 2, 6, 64, 255};
const std::vector<double> FLAGS = {0, 1, 2, 4, 8, 15};
const std::vector<double> CHANNEL = {0, 1, 2, 3, 0, 3};
const std::vector<double> ANGLE = {-90, -0.006, 0, 0.006, 45, 90}; // int16 * 0.006 degrees

std::vector<double> coordinates(const std::vector<double>& integers, int axis)
{
    std::vector<double> values;
    for (double integer : integers)
        values.push_back(integer * SCALE[axis] + OFFSET[axis]);
    return values;
}

/** The columns and values that a file of point format holds. */
std::map<std::string, std::vector<double>> expectedColumns(int format)
{
    const bool extended = format >= 6;
    std::map<std::string, std::vector<double>> columns = {
        {"x", coordinates(X, 0)},
        {"y", coordinates(Y, 1)},
        {"z", coordinates(Z, 2)},
        {"intensity", INTENSITY},
        {"return_number", extended ? RETURN : LEGACY_RETURN},
        {"number_of_returns", extended ? RETURNS : LEGACY_RETURNS},
        {"scan_direction", SCAN_DIRECTION},
        {"edge_of_flight_line", EDGE},
        {"classification", extended ? CLASS : LEGACY_CLASS},
        {"classification_flags", extended ? FLAGS : LEGACY_FLAGS},
        {"scan_angle", extended ? ANGLE : LEGACY_ANGLE},
        {"user_data", USER_DATA},
        {"point_source_id", POINT_SOURCE}};
    if (extended)
        columns["scanner_channel"] = CHANNEL;
    if (format != 0 && format != 2)
        columns["gps_time"] = GPS_TIME;
    if (format == 2 || format == 3 || format == 5 || format == 7 || format == 8 || format == 10)
    {
        columns["red"] = RED;
        columns["green"] = GREEN;
        columns["blue"] = BLUE;
    }
    if (format == 8 || format == 10)
        columns["nir"] = NIR;
    return columns;
}

/** Expects data to hold exactly the format's columns with write_las.py's values, point i holding
 * the values of point i % 6. */
void expectWrittenValues(const PointData& data, int format)
{
    const std::map<std::string, std::vector<double>> expected = expectedColumns(format);
    std::vector<std::string> names(data.getColumnNames());
    std::sort(names.begin(), names.end());
    std::vector<std::string> expectedNames;
    for (const auto& column : expected)
        expectedNames.push_back(column.first);
    EXPECT_EQ(names, expectedNames);
    for (const auto& column : expected)
    {
        const int index = data.findColumn(column.first);
        if (index < 0)
            continue;
        // Coordinates within a tenth of the scale (at 4e6 for y); others exactly (scan angles
        // as floats of multiples of 0.006).
        const double tolerance = column.first == "x" || column.first == "y" ? SCALE[0] / 10
                                 : column.first == "z"                      ? SCALE[2] / 10
                                 : column.first == "scan_angle"             ? 1e-5
                                                                            : 0.0;
        std::size_t wrong = 0;
        for (std::size_t i = 0; i < data.getNumPoints(); ++i)
        {
            const double want = column.second[i % column.second.size()];
            const double got = data.getValue(std::size_t(index), i);
            if (!(std::fabs(got - want) <= tolerance) && wrong++ < 3)
                ADD_FAILURE() << column.first << " of point " << i << ": " << std::setprecision(17) << got
                              << ", expected " << want;
        }
    }
}

std::string lasPath(const std::string& name)
{
    return dataPath("las/" + name);
}

const struct
{
    const char* file;
    int format;
} FILES[] = {{"las12_f0.las", 0},       {"las12_f1.las", 1},     {"las12_f2.las", 2}, {"las12_f3.las", 3},
             {"las13_f4.las", 4},       {"las13_f5.las", 5},     {"las14_f1.las", 1}, {"las14_f6.las", 6},
             {"las14_f7.las", 7},       {"las14_f8.las", 8},     {"las14_f9.las", 9}, {"las14_f10.las", 10},
             {"las14_f7_extra.las", 7}, {"las14_f6_evlr.las", 6}};

/** Opens path, collecting its warnings. */
osg::ref_ptr<FrameSource> openWithWarnings(const std::string& path, std::vector<std::string>& warnings,
                                           FrameSourceOptions options = {})
{
    options.warning = [&warnings](const std::string& warning) { warnings.push_back(warning); };
    return openFrames(path, options);
}

template <typename T>
void put(std::string& bytes, std::size_t offset, T value)
{
    std::memcpy(&bytes[offset], &value, sizeof(T));
}

template <typename T>
T get(const std::string& bytes, std::size_t offset)
{
    T value;
    std::memcpy(&value, &bytes[offset], sizeof(T));
    return value;
}

/** A copy of a test file whose records repeat to count points (point i is record i % 6). */
std::string repeated(const std::string& name, uint64_t count)
{
    const std::string bytes = readBytes(lasPath(name));
    const uint32_t offset = get<uint32_t>(bytes, 96);
    const uint16_t length = get<uint16_t>(bytes, 105);
    const std::string records = bytes.substr(offset, 6 * std::size_t(length));
    std::string out = bytes.substr(0, offset);
    out.reserve(offset + count * length);
    for (uint64_t i = 0; i < count; ++i)
        out.append(records, (i % 6) * length, length);
    if (get<uint8_t>(bytes, 25) >= 4)
        put<uint64_t>(out, 247, count);
    if (get<uint32_t>(bytes, 107) != 0)
        put<uint32_t>(out, 107, uint32_t(count));
    return out;
}

}

TEST(Las, EveryVersionAndFormatHoldsTheWrittenValues)
{
    for (const auto& file : FILES)
    {
        SCOPED_TRACE(file.file);
        std::vector<std::string> warnings;
        osg::ref_ptr<FrameSource> las = openWithWarnings(lasPath(file.file), warnings);
        ASSERT_TRUE(las);
        EXPECT_EQ(las->getFormat(), "las");
        EXPECT_EQ(las->getNumFrames(), 1u);
        EXPECT_TRUE(warnings.empty()) << warnings.front();
        osg::ref_ptr<PointData> points = frameOf(*las, 0);
        ASSERT_TRUE(points);
        EXPECT_EQ(points->getNumPoints(), 6u);
        EXPECT_EQ(points->getFilePointCount(), 6u);
        expectWrittenValues(*points, file.format);
    }
}

TEST(Las, CoordinatesFarFromZeroKeepTheirDecimalsThroughTheOrigin)
{
    osg::ref_ptr<PointData> points = frameOf(*openFrames(lasPath("las14_f6.las")), 0);
    ASSERT_TRUE(points);
    // y is about 4e6: a float alone would round it to 0.25; the double origin keeps 0.001.
    EXPECT_GT(std::fabs(points->getColumnOrigin("y")), 3.9e6);
    EXPECT_GT(std::fabs(points->getColumnOrigin("gps_time")), 1e8);
    const int y = points->findColumn("y");
    for (std::size_t i = 0; i < 6; ++i)
    {
        EXPECT_LT(std::fabs((*points->getColumn("y"))[i]), 2000.0f);
        // The file's integer back from the double origin and the float offset, to a hundredth.
        const double stored = (points->getValue(std::size_t(y), i) - OFFSET[1]) / SCALE[1];
        EXPECT_NEAR(stored, Y[i], 1e-2) << "point " << i;
        EXPECT_NEAR(points->getValue(std::size_t(y), i), Y[i] * SCALE[1] + OFFSET[1], 1e-3);
    }
}

TEST(Las, TheFrameReadTwiceIsTheSameAndThereIsNoOther)
{
    osg::ref_ptr<FrameSource> las = openFrames(lasPath("las12_f3.las"));
    ASSERT_TRUE(las);
    osg::ref_ptr<PointData> first = frameOf(*las, 0);
    osg::ref_ptr<PointData> again = frameOf(*las, 0);
    ASSERT_TRUE(first && again);
    for (const std::string& name : first->getColumnNames())
        expectColumnMatches(*first, *again, name, 0.0);
    std::string error;
    EXPECT_FALSE(las->readFrame(1, error));
    EXPECT_NE(error.find("no frame 1"), std::string::npos) << error;
}

TEST(Las, ManyChunksOfRecordsAndSharesTogetherAreTheWhole)
{
    // 100003 records of 38 bytes: more than one 2 MiB read, and shares that are not whole reads.
    const uint64_t count = 100003;
    const std::string path = writeScratchFile("many.las", repeated("las14_f8.las", count));
    osg::ref_ptr<PointData> whole = frameOf(*openFrames(path), 0);
    ASSERT_TRUE(whole);
    ASSERT_EQ(whole->getNumPoints(), count);
    expectWrittenValues(*whole, 8);
    for (unsigned int shares : {3u, 7u})
    {
        std::vector<osg::ref_ptr<PointData>> parts;
        for (unsigned int index = 0; index < shares; ++index)
        {
            FrameSourceOptions options;
            options.share = {index, shares};
            parts.push_back(frameOf(*openFrames(path, options), 0));
            ASSERT_TRUE(parts.back());
            EXPECT_EQ(parts.back()->getFilePointCount(), count);
        }
        for (const std::string& name : whole->getColumnNames())
        {
            std::vector<double> joined;
            for (const auto& part : parts)
            {
                EXPECT_EQ(part->getColumnOrigin(name), whole->getColumnOrigin(name)) << name;
                const int column = part->findColumn(name);
                ASSERT_GE(column, 0) << name;
                for (std::size_t i = 0; i < part->getNumPoints(); ++i)
                    joined.push_back(part->getValue(std::size_t(column), i));
            }
            std::vector<double> all;
            const int column = whole->findColumn(name);
            for (std::size_t i = 0; i < whole->getNumPoints(); ++i)
                all.push_back(whole->getValue(std::size_t(column), i));
            EXPECT_EQ(joined, all) << name << " in " << shares << " shares";
        }
    }
}

TEST(Las, BytesAfterThePointsAreReadPastWithAWarning)
{
    const std::string path = writeScratchFile("trailing.las", readBytes(lasPath("las12_f1.las")) + "junk");
    std::vector<std::string> warnings;
    osg::ref_ptr<FrameSource> las = openWithWarnings(path, warnings);
    ASSERT_TRUE(las);
    expectWrittenValues(*frameOf(*las, 0), 1);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find(path + ": byte 471: 4 bytes after the 6 point records"), std::string::npos)
        << warnings[0];
}

TEST(Las, LazIsRefusedWithTheReason)
{
    const std::string las = readBytes(lasPath("las14_f7.las"));
    std::string bit7 = las;
    bit7[104] = char(7 | 128);
    // The VLR that LASzip writes: user "laszip encoded", record 22204, in place of the test's VLR.
    std::string vlr = las;
    std::memcpy(&vlr[375 + 2], "laszip encoded\0\0", 16);
    put<uint16_t>(vlr, 375 + 18, 22204);
    const struct
    {
        std::string path, expected;
    } cases[] = {
        {writeScratchFile("compressed.laz", las), ": byte 0: LAZ"},
        {writeScratchFile("bit7.las", bit7), ": byte 104: point format 135 has bit 7 set: LAZ"},
        {writeScratchFile("vlr.las", vlr), ": byte 375: a LASzip VLR: LAZ"},
    };
    for (const auto& laz : cases)
    {
        SCOPED_TRACE(laz.path);
        const std::string error = firstError(laz.path);
        EXPECT_NE(error.find(laz.path + laz.expected), std::string::npos) << error;
        EXPECT_NE(error.find("Debian has no LASzip"), std::string::npos) << error;
    }
}

TEST(Las, FilesThatLieFailNamingTheFileAndByte)
{
    const std::string v12 = readBytes(lasPath("las12_f0.las"));
    const std::string v14 = readBytes(lasPath("las14_f8.las"));
    const uint32_t points12 = get<uint32_t>(v12, 96);
    auto with = [](std::string bytes, auto change)
    {
        change(bytes);
        return bytes;
    };
    const struct
    {
        std::string name, bytes, expected;
    } cases[] = {
        {"empty", "", "the file is empty"},
        {"not las", std::string(400, 'x'), "byte 0: not a LAS file"},
        {"header cut", v12.substr(0, 200),
         "byte 0: the file ends at byte 200, 27 bytes short of the public header"},
        {"records cut", v12.substr(0, v12.size() - 10),
         "byte 107: the header counts 6 point records of 20 bytes from byte " + std::to_string(points12) +
             ", the end of the file at byte " + std::to_string(v12.size() - 10) + " leaves room for 5"},
        {"legacy count lies", with(v12, [](std::string& b) { put<uint32_t>(b, 107, 4000000000u); }),
         "byte 107: the header counts 4000000000 point records"},
        {"64-bit count lies", with(v14, [](std::string& b) { put<uint64_t>(b, 247, uint64_t(1) << 62); }),
         "byte 247: the header counts 4611686018427387904 point records of 38 bytes"},
        {"counts disagree", with(v14, [](std::string& b) { put<uint32_t>(b, 107, 5); }),
         "byte 247: the number of point records, 6, differs from the legacy one at byte 107, 5"},
        {"record shorter than format", with(v14, [](std::string& b) { put<uint16_t>(b, 105, 30); }),
         "byte 105: the point record length is 30 bytes, shorter than point format 8's 38"},
        {"points past the end", with(v12, [](std::string& b) { put<uint32_t>(b, 96, 100000); }),
         "byte 96: the offset to the point data, 100000, lies past the end of the file at byte 423"},
        {"points inside the header", with(v14, [](std::string& b) { put<uint32_t>(b, 96, 300); }),
         "byte 96: the offset to the point data, 300, lies inside the 375-byte header"},
        {"header too small", with(v14, [](std::string& b) { put<uint16_t>(b, 94, 227); }),
         "byte 94: the header size is 227 bytes, LAS 1.4 needs 375"},
        {"header past the end", with(v12, [](std::string& b) { put<uint16_t>(b, 94, 60000); }),
         "byte 94: the header size is 60000 bytes, past the end of the file at byte 423"},
        {"version", with(v12, [](std::string& b) { b[24] = 2; }), "byte 24: LAS version 2.2 is not read"},
        {"format", with(v12, [](std::string& b) { b[104] = 11; }), "byte 104: point format 11 is not read"},
        {"zero scale", with(v12, [](std::string& b) { put<double>(b, 139, 0.0); }),
         "byte 139: the y scale factor is 0"},
        {"nan scale", with(v12, [](std::string& b) { put<double>(b, 147, std::nan("")); }),
         "byte 147: the z scale factor is nan"},
        {"infinite offset", with(v12, [](std::string& b) { put<double>(b, 155, HUGE_VAL); }),
         "byte 155: the x offset is inf"},
        {"absurd scale", with(v12, [](std::string& b) { put<double>(b, 131, 1e300); }),
         "byte 131: the x scale factor 1"},
        {"nan gps time",
         with(v14, [](std::string& b) { put<double>(b, get<uint32_t>(b, 96) + 3 * 38 + 22, std::nan("")); }),
         "frame 0: byte " + std::to_string(get<uint32_t>(v14, 96) + 3 * 38 + 22) +
             ": the GPS time of point 4 is not a finite number"},
    };
    for (const auto& bad : cases)
    {
        SCOPED_TRACE(bad.name);
        const std::string path = writeScratchFile("bad.las", bad.bytes);
        const std::string error = firstError(path);
        EXPECT_NE(error.find(path + ": " + bad.expected), std::string::npos) << error;
    }
}
