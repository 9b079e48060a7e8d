// CSV: header detection, separators, comments, and every malformed row.

#include "ReaderTestUtil.h"

using namespace osgGlyphsData;
using namespace readertest;

namespace
{

osg::ref_ptr<PointData> readCsv(const std::string& text)
{
    std::string error;
    osg::ref_ptr<PointDataset> dataset = readString(text, "csv", error, "in.csv");
    EXPECT_TRUE(dataset.valid()) << error;
    if (!dataset.valid())
        return new PointData;
    EXPECT_EQ(dataset->getNumFrames(), 1u);
    return dataset->getFrame(0);
}

} // namespace

TEST(CsvReader, ReadsCommaSeparatedValuesExactly)
{
    osg::ref_ptr<PointData> data =
        readCsv("# comment\nx,y,z,temperature\n1.5,-2,3e2,300.25\n0.1,+4,.5,1e-3\n");
    ASSERT_EQ(data->getColumnNames(), (std::vector<std::string>{"x", "y", "z", "temperature"}));
    ASSERT_EQ(data->getNumPoints(), 2u);
    EXPECT_EQ(column(*data, "x"), (std::vector<float>{1.5f, 0.1f}));
    EXPECT_EQ(column(*data, "y"), (std::vector<float>{-2.0f, 4.0f}));
    EXPECT_EQ(column(*data, "z"), (std::vector<float>{300.0f, 0.5f}));
    EXPECT_EQ(column(*data, "temperature"), (std::vector<float>{300.25f, 0.001f}));
    EXPECT_EQ(data->getTimestep(), 0);
}

TEST(CsvReader, DetectsTabsAndBlanksFromTheHeader)
{
    osg::ref_ptr<PointData> tabs = readCsv("x\ty\tz\n1\t2\t3\n");
    EXPECT_EQ(column(*tabs, "z"), (std::vector<float>{3.0f}));
    osg::ref_ptr<PointData> blanks = readCsv("  x   y z\n\n 1  2   3 \n# skipped\n4 5 6\n");
    EXPECT_EQ(column(*blanks, "x"), (std::vector<float>{1.0f, 4.0f}));
    EXPECT_EQ(column(*blanks, "z"), (std::vector<float>{3.0f, 6.0f}));
    osg::ref_ptr<PointData> semicolons = readCsv("a;b\n1;2\n");
    EXPECT_EQ(column(*semicolons, "b"), (std::vector<float>{2.0f}));
}

TEST(CsvReader, HandlesQuotesByteOrderMarkAndWindowsLineEnds)
{
    osg::ref_ptr<PointData> data = readCsv("\xEF\xBB\xBF\"x\", \"y\" ,z\r\n\"1\",2 , 3\r\n");
    ASSERT_EQ(data->getColumnNames(), (std::vector<std::string>{"x", "y", "z"}));
    EXPECT_EQ(column(*data, "x"), (std::vector<float>{1.0f}));
    EXPECT_EQ(column(*data, "y"), (std::vector<float>{2.0f}));
}

TEST(CsvReader, AcceptsAHeaderWithoutRows)
{
    osg::ref_ptr<PointData> data = readCsv("x,y,z\n");
    EXPECT_EQ(data->getNumPoints(), 0u);
    EXPECT_EQ(data->getNumColumns(), 3u);
}

TEST(CsvReader, RejectsWrongNumberOfColumns)
{
    EXPECT_EQ(readError("x,y,z\n1,2,3\n1,2\n", "csv", "bad.csv"),
              "bad.csv:3: wrong number of columns: 2 fields, expected 3 (x y z)");
    EXPECT_EQ(readError("x y z\n1 2 3 4\n", "csv", "bad.csv"),
              "bad.csv:2: wrong number of columns: 4 fields, expected 3 (x y z)");
    EXPECT_EQ(readError("x,y\n1,2,\n", "csv", "bad.csv"),
              "bad.csv:2: wrong number of columns: 3 fields, expected 2 (x y)");
}

TEST(CsvReader, RejectsNonNumericEmptyAndNonFiniteFields)
{
    EXPECT_EQ(readError("x,y\n1,abc\n", "csv", "bad.csv"), "bad.csv:2: column 'y': 'abc' is not a number");
    EXPECT_EQ(readError("x,y\n1,2\n3,\n", "csv", "bad.csv"), "bad.csv:3: column 'y': empty field");
    EXPECT_EQ(readError("x,y\nnan,1\n", "csv", "bad.csv"),
              "bad.csv:2: column 'x': 'nan' is not a finite number");
    EXPECT_EQ(readError("x y\n1 -inf\n", "csv", "bad.csv"),
              "bad.csv:2: column 'y': '-inf' is not a finite number");
    EXPECT_EQ(readError("x y\n1 1e999\n", "csv", "bad.csv"),
              "bad.csv:2: column 'y': '1e999' is out of the range of a float");
    EXPECT_EQ(readError("x y\n1 2.5.1\n", "csv", "bad.csv"),
              "bad.csv:2: column 'y': '2.5.1' is not a number");
    EXPECT_EQ(readError("x y\n1 0x10\n", "csv", "bad.csv"), "bad.csv:2: column 'y': '0x10' is not a number");
}

TEST(CsvReader, RejectsMissingOrNumericHeadersAndDuplicateNames)
{
    EXPECT_EQ(readError("# only\n\n# comments\n", "csv", "bad.csv"),
              "bad.csv:3: no header line: the file has only comments and blank lines");
    EXPECT_EQ(readError("1,2,3\n4,5,6\n", "csv", "bad.csv"),
              "bad.csv:1: the first line must name the columns, found '1,2,3'");
    EXPECT_EQ(readError("x,y,x\n1,2,3\n", "csv", "bad.csv"), "bad.csv:1: duplicate column 'x'");
    EXPECT_EQ(readError("x,,z\n1,2,3\n", "csv", "bad.csv"), "bad.csv:1: empty column name");
}

TEST(CsvReader, QuotesControlBytesInMessages)
{
    EXPECT_EQ(readError(std::string("x\n1\x01\xff\n", 7), "csv", "bad.csv"),
              "bad.csv:2: column 'x': '1\\x01\\xff' is not a number");
}
