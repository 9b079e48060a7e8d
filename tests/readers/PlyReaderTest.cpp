// PLY in its three encodings, every property type, skipped elements and lists, and lying headers.

#include "ReaderTestUtil.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

using namespace osgGlyphsData;
using namespace readertest;

namespace
{

const char* const header = "ply\n"
                           "format %s 1.0\n"
                           "comment made by the test\n"
                           "element face 1\n"
                           "property list uchar int vertex_indices\n"
                           "element vertex 2\n"
                           "property char a\nproperty uchar b\nproperty short c\nproperty ushort d\n"
                           "property int e\nproperty uint f\nproperty float x\nproperty double y\n"
                           "property int8 g\nproperty uint8 h\nproperty int16 i\nproperty uint16 j\n"
                           "property int32 k\nproperty uint32 l\nproperty float32 z\nproperty float64 m\n"
                           "property list ushort float extra\n"
                           "element edge 2\n"
                           "property int from\nproperty int to\n"
                           "end_header\n";

std::string headerFor(const std::string& format)
{
    char text[2048];
    std::snprintf(text, sizeof(text), header, format.c_str());
    return text;
}

// The two vertices every encoding stores.
const std::vector<std::vector<double>> vertices = {
    {-128, 255, -32768, 65535, -2147483648.0, 4294967295.0, 1.5, -2.25, 127, 0, 32767, 0, 2147483647.0, 0,
     0.125, 1e10},
    {1, 2, 3, 4, 5, 6, 7.5, 8.5, -1, 200, -2, 3, -4, 5, -0.5, -1e-10},
};

std::string binaryPly(bool bigEndian)
{
    Bytes bytes(bigEndian);
    bytes.text(headerFor(bigEndian ? "binary_big_endian" : "binary_little_endian"));
    bytes.put<uint8_t>(3).put<int32_t>(0).put<int32_t>(1).put<int32_t>(1);
    for (std::size_t v = 0; v < 2; ++v)
    {
        const std::vector<double>& p = vertices[v];
        bytes.put<int8_t>(static_cast<int8_t>(p[0])).put<uint8_t>(static_cast<uint8_t>(p[1]));
        bytes.put<int16_t>(static_cast<int16_t>(p[2])).put<uint16_t>(static_cast<uint16_t>(p[3]));
        bytes.put<int32_t>(static_cast<int32_t>(p[4])).put<uint32_t>(static_cast<uint32_t>(p[5]));
        bytes.put<float>(static_cast<float>(p[6])).put<double>(p[7]);
        bytes.put<int8_t>(static_cast<int8_t>(p[8])).put<uint8_t>(static_cast<uint8_t>(p[9]));
        bytes.put<int16_t>(static_cast<int16_t>(p[10])).put<uint16_t>(static_cast<uint16_t>(p[11]));
        bytes.put<int32_t>(static_cast<int32_t>(p[12])).put<uint32_t>(static_cast<uint32_t>(p[13]));
        bytes.put<float>(static_cast<float>(p[14])).put<double>(p[15]);
        bytes.put<uint16_t>(static_cast<uint16_t>(v)); // list "extra": v floats
        for (std::size_t i = 0; i < v; ++i)
            bytes.put<float>(9.0f);
    }
    bytes.put<int32_t>(0).put<int32_t>(1).put<int32_t>(1).put<int32_t>(0);
    return bytes.str();
}

std::string asciiPly()
{
    return headerFor("ascii") +
           "3 0 1 1\n"
           "-128 255 -32768 65535 -2147483648 4294967295 1.5 -2.25 127 0 32767 0 2147483647 0 "
           "0.125 1e10 0\n"
           "1 2 3 4 5 6 7.5 8.5 -1 200 -2 3 -4 5 -0.5 -1e-10 1 9\n"
           "0 1\n1 0\n";
}

void expectVertices(const std::string& bytes, const std::string& name)
{
    std::string error;
    osg::ref_ptr<PointDataset> dataset = readString(bytes, "ply", error, name);
    ASSERT_TRUE(dataset.valid()) << error;
    const PointData& frame = *dataset->getFrame(0);
    const std::vector<std::string> names = {"a", "b", "c", "d", "e", "f", "x", "y",
                                            "g", "h", "i", "j", "k", "l", "z", "m"};
    ASSERT_EQ(frame.getColumnNames(), names) << name;
    ASSERT_EQ(frame.getNumPoints(), 2u);
    for (std::size_t c = 0; c < names.size(); ++c)
    {
        for (std::size_t v = 0; v < 2; ++v)
            EXPECT_EQ(static_cast<float>(frame.getValue(c, v)), static_cast<float>(vertices[v][c]))
                << name << " " << names[c];
    }
}

std::string simpleBinary(const std::string& vertexCount, std::size_t floats, bool bigEndian = false)
{
    Bytes bytes(bigEndian);
    bytes.text(std::string("ply\nformat ") + (bigEndian ? "binary_big_endian" : "binary_little_endian") +
               " 1.0\nelement vertex " + vertexCount + "\nproperty float x\nproperty float y\nend_header\n");
    for (std::size_t i = 0; i < floats; ++i)
        bytes.put<float>(static_cast<float>(i));
    return bytes.str();
}

// Many vertices of every type, more than the reader's buffer holds (1 MiB), in records of 34
// bytes that straddle its blocks; column "far" starts far from zero and comes back at row 30000,
// "farf" stays far. The numbers are the same in every encoding (ascii prints them exactly).
const char* const manyTypes[] = {"char", "uchar", "short", "ushort", "int", "uint", "float", "double"};
const uint64_t manyRows = 40000;

double manyValue(uint64_t row, std::size_t column)
{
    uint64_t h = (row * 10 + column + 1) * 0x9E3779B97F4A7C15ull;
    h = (h ^ (h >> 31)) * 0xBF58476D1CE4E5B9ull;
    h ^= h >> 29;
    const double fraction = static_cast<double>(h % 1000000) / 1024.0;
    switch (column)
    {
    case 0:
        return static_cast<int8_t>(h);
    case 1:
        return static_cast<uint8_t>(h);
    case 2:
        return static_cast<int16_t>(h);
    case 3:
        return static_cast<uint16_t>(h);
    case 4:
        return static_cast<int32_t>(h);
    case 5:
        return static_cast<uint32_t>(h);
    case 6:
        return row == 7 ? std::numeric_limits<float>::max() : static_cast<float>(fraction - 400.0);
    case 7:
        return std::ldexp(static_cast<double>(static_cast<int32_t>(h)), static_cast<int>(h >> 58) - 40);
    case 8:
        return (row < 30000 ? 12345678.0 : -2.0) + fraction / 1000.0;
    default:
        return static_cast<float>(1000000.0 + fraction);
    }
}

std::string manyVertices(const std::string& format)
{
    std::string text = "ply\nformat " + format + " 1.0\nelement vertex " + std::to_string(manyRows) + "\n";
    for (const char* type : manyTypes)
        text += std::string("property ") + type + " " + type + "\n";
    Bytes bytes(format == "binary_big_endian");
    bytes.text(text + "property double far\nproperty float farf\nend_header\n");
    for (uint64_t row = 0; row < manyRows; ++row)
    {
        if (format == "ascii")
        {
            char number[32];
            for (std::size_t c = 0; c < 10; ++c)
            {
                std::snprintf(number, sizeof(number), c < 9 ? "%.17g " : "%.17g\n", manyValue(row, c));
                bytes.text(number);
            }
            continue;
        }
        bytes.put(static_cast<int8_t>(manyValue(row, 0))).put(static_cast<uint8_t>(manyValue(row, 1)));
        bytes.put(static_cast<int16_t>(manyValue(row, 2))).put(static_cast<uint16_t>(manyValue(row, 3)));
        bytes.put(static_cast<int32_t>(manyValue(row, 4))).put(static_cast<uint32_t>(manyValue(row, 5)));
        bytes.put(static_cast<float>(manyValue(row, 6))).put(manyValue(row, 7));
        bytes.put(manyValue(row, 8)).put(static_cast<float>(manyValue(row, 9)));
    }
    return bytes.str();
}

// The same columns, origins and stored floats, bit for bit.
void expectSameFrame(const PointData& expected, const PointData& actual, const std::string& what)
{
    ASSERT_EQ(actual.getColumnNames(), expected.getColumnNames()) << what;
    for (std::size_t c = 0; c < expected.getNumColumns(); ++c)
    {
        const std::string& name = expected.getColumnNames()[c];
        EXPECT_EQ(actual.getColumnOrigin(c), expected.getColumnOrigin(c)) << what << " " << name;
        const std::vector<float>& want = *expected.getColumn(c);
        const std::vector<float>& got = *actual.getColumn(c);
        ASSERT_EQ(got.size(), want.size()) << what << " " << name;
        const auto differs =
            std::mismatch(want.begin(), want.end(), got.begin(),
                          [](float a, float b) { return std::memcmp(&a, &b, sizeof(float)) == 0; });
        EXPECT_TRUE(differs.first == want.end())
            << what << " " << name << " row " << (differs.first - want.begin()) << ": " << *differs.second
            << " instead of " << *differs.first;
    }
}

// 3000 vertices x (float), y (double), z (float), with bad values in some places.
struct BadValue
{
    uint64_t row;
    std::size_t column;
    double value;
};

std::string badVertices(bool bigEndian, const std::vector<BadValue>& bad, std::size_t& headerSize)
{
    Bytes bytes(bigEndian);
    bytes.text(std::string("ply\nformat binary_") + (bigEndian ? "big" : "little") +
               "_endian 1.0\nelement vertex 3000\nproperty float x\nproperty double y\nproperty float "
               "z\nend_header\n");
    headerSize = bytes.str().size();
    for (uint64_t row = 0; row < 3000; ++row)
    {
        double values[3] = {row * 0.5, 70000.0 + row, -1.0 * row};
        for (const BadValue& value : bad)
        {
            if (value.row == row)
                values[value.column] = value.value;
        }
        bytes.put(static_cast<float>(values[0])).put(values[1]).put(static_cast<float>(values[2]));
    }
    return bytes.str();
}

} // namespace

TEST(PlyReader, ReadsManyBinaryVerticesAsTheirAsciiText)
{
    const std::string ascii = manyVertices("ascii");
    for (const char* format : {"binary_little_endian", "binary_big_endian"})
    {
        const std::string binary = manyVertices(format);
        for (const PointShare share :
             {PointShare{0, 1}, PointShare{0, 3}, PointShare{1, 3}, PointShare{2, 3}})
        {
            PointReadOptions options;
            options.share = share;
            std::vector<std::string> warnings;
            std::string error;
            osg::ref_ptr<PointDataset> expected = readWithOptions(ascii, "ply", options, warnings, error);
            ASSERT_TRUE(expected.valid()) << error;
            osg::ref_ptr<PointDataset> actual = readWithOptions(binary, "ply", options, warnings, error);
            ASSERT_TRUE(actual.valid()) << error;
            expectSameFrame(*expected->getFrame(0), *actual->getFrame(0),
                            std::string(format) + " share " + std::to_string(share.index) + " of " +
                                std::to_string(share.count));
        }
        // From a pipe: the buffer holds 64 KiB at first, filled piece by piece.
        PipeBuffer pipe(binary);
        std::istream stream(&pipe);
        std::string error;
        osg::ref_ptr<PointDataset> piped = readPointStream(stream, "ply", "pipe", PointReadOptions(), error);
        ASSERT_TRUE(piped.valid()) << error;
        osg::ref_ptr<PointDataset> whole = readString(ascii, "ply", error);
        ASSERT_TRUE(whole.valid()) << error;
        expectSameFrame(*whole->getFrame(0), *piped->getFrame(0), std::string(format) + " from a pipe");
    }
}

TEST(PlyReader, RejectsTheFirstBadBinaryValueAmongManyAtItsOffset)
{
    for (const bool bigEndian : {false, true})
    {
        // Row 1500's z comes first, though other columns fail at rows 1600 and 1700.
        const double nan = std::numeric_limits<double>::quiet_NaN();
        const double inf = std::numeric_limits<double>::infinity();
        std::size_t headerSize = 0;
        std::string bytes =
            badVertices(bigEndian, {{1700, 0, inf}, {1600, 1, nan}, {1500, 2, nan}}, headerSize);
        EXPECT_EQ(readError(bytes, "ply", "bad.ply"), "bad.ply: byte " +
                                                          std::to_string(headerSize + 1500 * 16 + 12) +
                                                          ": column 'z': value nan is not a finite number");
        bytes = badVertices(bigEndian, {{2900, 0, inf}, {1601, 1, 1e39}}, headerSize);
        EXPECT_EQ(readError(bytes, "ply", "bad.ply"),
                  "bad.ply: byte " + std::to_string(headerSize + 1601 * 16 + 4) +
                      ": column 'y': value 1e+39 is out of the range of a float");
        // Cut short in a pipe (no size to check first): the last whole record counts.
        bytes = badVertices(bigEndian, {}, headerSize);
        PipeBuffer pipe(bytes.substr(0, headerSize + 2345 * 16 + 9));
        std::istream stream(&pipe);
        std::string error;
        EXPECT_FALSE(readPointStream(stream, "ply", "cut.ply", PointReadOptions(), error).valid());
        EXPECT_EQ(error, "cut.ply: byte " + std::to_string(headerSize + 2345 * 16) +
                             ": unexpected end of file: element 'vertex' has 2345 of 3000 items");
    }
}

TEST(PlyReader, ReadsAsciiWithEveryTypeSkippingFacesEdgesAndLists)
{
    expectVertices(asciiPly(), "ascii.ply");
}

TEST(PlyReader, ReadsBinaryLittleEndian)
{
    expectVertices(binaryPly(false), "little.ply");
}

TEST(PlyReader, ReadsBinaryBigEndian)
{
    expectVertices(binaryPly(true), "big.ply");
}

TEST(PlyReader, ReadsAFileFromDisk)
{
    const std::string path = writeFile("cloud.ply", binaryPly(false));
    std::string error;
    osg::ref_ptr<PointDataset> dataset = readPointFile(path, PointReadOptions(), error);
    ASSERT_TRUE(dataset.valid()) << error;
    EXPECT_EQ(dataset->getFormat(), "ply");
    EXPECT_EQ(dataset->getFrame(0)->getNumPoints(), 2u);
}

TEST(PlyReader, RejectsHeadersThatDeclareMoreDataThanPresent)
{
    EXPECT_EQ(readError(simpleBinary("3", 5), "ply", "short.ply"),
              "short.ply:3: element 'vertex' declares 3 items of at least 8 bytes, but only 20 bytes follow "
              "the header");
    EXPECT_EQ(readError(simpleBinary("4000000000", 4), "ply", "huge.ply"),
              "huge.ply:3: element 'vertex' declares 4000000000 items of at least 8 bytes, but only 16 bytes "
              "follow the header");
    EXPECT_EQ(readError("ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nend_header\n1.5\n2.5\n",
                        "ply", "a.ply"),
              "a.ply:7: unexpected end of file: element 'vertex' has 2 of 3 items");
}

TEST(PlyReader, RejectsHeadersThatDeclareLessDataThanPresent)
{
    const std::string bytes = simpleBinary("2", 5);
    EXPECT_EQ(readError(bytes, "ply", "long.ply"),
              "long.ply: byte " + std::to_string(bytes.size() - 4) +
                  ": 4 bytes after the last element: the header declares less data than the file has");
    EXPECT_EQ(readError("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nend_header\n1\n2\n",
                        "ply", "a.ply"),
              "a.ply:7: data after the last element: the header declares fewer items than the file has");
}

TEST(PlyReader, RejectsTruncatedListsWithTheirOffset)
{
    Bytes bytes(false);
    bytes.text("ply\nformat binary_little_endian 1.0\nelement vertex 1\nproperty float x\n"
               "element face 1\nproperty list uchar int vertex_indices\nend_header\n");
    const std::size_t headerSize = bytes.str().size();
    bytes.put<float>(1.0f).put<uint8_t>(200).put<int32_t>(1);
    EXPECT_EQ(
        readError(bytes.str(), "ply", "list.ply"),
        "list.ply: byte " + std::to_string(headerSize + 4) +
            ": list 'vertex_indices' of element 'face' has 200 items, more than the rest of the file holds");

    Bytes negative(false);
    negative.text("ply\nformat binary_little_endian 1.0\nelement vertex 1\nproperty float x\n"
                  "element face 1\nproperty list char int vertex_indices\nend_header\n");
    const std::size_t negativeHeaderSize = negative.str().size();
    negative.put<float>(1.0f).put<int8_t>(-3).put<int32_t>(1);
    EXPECT_EQ(readError(negative.str(), "ply", "list.ply"),
              "list.ply: byte " + std::to_string(negativeHeaderSize + 4) +
                  ": list 'vertex_indices' of element 'face' has a negative count");
}

TEST(PlyReader, RejectsNonFiniteBinaryValuesNamingTheColumn)
{
    Bytes bytes(false);
    bytes.text("ply\nformat binary_little_endian 1.0\nelement vertex 2\nproperty float x\nproperty double "
               "y\nend_header\n");
    const std::size_t headerSize = bytes.str().size();
    bytes.put<float>(1.0f).put<double>(2.0).put<float>(3.0f).put<double>(
        std::numeric_limits<double>::quiet_NaN());
    EXPECT_EQ(readError(bytes.str(), "ply", "nan.ply"), "nan.ply: byte " + std::to_string(headerSize + 16) +
                                                            ": column 'y': value nan is not a finite number");
}

TEST(PlyReader, RejectsMalformedHeaders)
{
    EXPECT_EQ(readError("plyx\n", "ply", "h.ply"), "h.ply:1: not a PLY file: the first line must be 'ply'");
    EXPECT_EQ(readError("ply\nformat ascii 1.0\nelement vertex 1\nproperty quad x\nend_header\n1\n", "ply",
                        "h.ply"),
              "h.ply:4: unknown property type 'quad' (char, uchar, short, ushort, int, uint, float, double "
              "or int8 ... "
              "float64)");
    EXPECT_EQ(readError("ply\nformat binary_middle_endian 1.0\n", "ply", "h.ply"),
              "h.ply:2: unknown PLY format 'binary_middle_endian' (ascii, binary_little_endian or "
              "binary_big_endian)");
    EXPECT_EQ(readError("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n", "ply", "h.ply"),
              "h.ply:4: unexpected end of file in the header: no 'end_header'");
    EXPECT_EQ(readError("ply\nformat ascii 1.0\nelement face 0\nend_header\n", "ply", "h.ply"),
              "h.ply:4: the header has no 'element vertex'");
    EXPECT_EQ(readError("ply\nelement vertex 1\nproperty float x\nend_header\n1\n", "ply", "h.ply"),
              "h.ply:4: the header has no 'format' line");
    EXPECT_EQ(readError("ply\nformat ascii 1.0\nproperty float x\n", "ply", "h.ply"),
              "h.ply:3: 'property' before any 'element'");
    EXPECT_EQ(readError("ply\nformat ascii 1.0\nelement vertex -1\n", "ply", "h.ply"),
              "h.ply:3: malformed element line: expected 'element <name> <count>'");
    EXPECT_EQ(readError("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty int x\n", "ply",
                        "h.ply"),
              "h.ply:5: duplicate property 'x' in element 'vertex'");
    EXPECT_EQ(
        readError("ply\nformat ascii 1.0\nelement vertex 1\nproperty list float int x\n", "ply", "h.ply"),
        "h.ply:4: the count type of list 'x' must be an integer type");
    EXPECT_EQ(readError("ply\nformat ascii 1.0\nbogus\n", "ply", "h.ply"),
              "h.ply:3: unknown header keyword 'bogus'");
}

TEST(PlyReader, RejectsBadAsciiRows)
{
    const std::string head =
        "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nend_header\n";
    EXPECT_EQ(readError(head + "1.5\n", "ply", "r.ply"),
              "r.ply:7: wrong number of columns: 1 fields, expected 2 (x y)");
    EXPECT_EQ(readError(head + "1 inf\n", "ply", "r.ply"),
              "r.ply:7: column 'y': 'inf' is not a finite number");
    const std::string faces = "ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\n"
                              "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
    EXPECT_EQ(readError(faces + "3 1 2\n", "ply", "r.ply"),
              "r.ply:8: list 'vertex_indices' declares 3 items, the line has 2 values left");
    EXPECT_EQ(readError(faces + "2 1 2 3\n", "ply", "r.ply"),
              "r.ply:8: element 'face': 4 values, more than its properties take (3)");
    EXPECT_EQ(readError(faces + "2 1 b\n", "ply", "r.ply"),
              "r.ply:8: property 'vertex_indices': 'b' is not a number");
}
