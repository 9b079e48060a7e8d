// Legacy VTK: POLYDATA and UNSTRUCTURED_GRID, ASCII and BINARY, attributes kept or read past.

#include "ReaderTestUtil.h"

using namespace osgGlyphsData;
using namespace readertest;

namespace
{

osg::ref_ptr<PointData> readVtk(const std::string& text, const std::string& name = "in.vtk")
{
    std::string error;
    osg::ref_ptr<PointDataset> dataset = readString(text, "vtk", error, name);
    EXPECT_TRUE(dataset.valid()) << error;
    return dataset.valid() ? osg::ref_ptr<PointData>(dataset->getFrame(0))
                           : osg::ref_ptr<PointData>(new PointData);
}

const std::string polydata = "# vtk DataFile Version 3.0\n"
                             "three points\n"
                             "ASCII\n"
                             "DATASET POLYDATA\n"
                             "POINTS 3 float\n"
                             "0 0 0 1 0 0\n"
                             "0 1.5\n"
                             "-2\n"
                             "VERTICES 3 6\n"
                             "1 0\n1 1\n1 2\n"
                             "LINES 1 3\n"
                             "2 0 1\n"
                             "POINT_DATA 3\n"
                             "SCALARS mass double 1\n"
                             "LOOKUP_TABLE default\n"
                             "1.5 2.5 3.5\n"
                             "VECTORS velocity float\n"
                             "1 2 3\n4 5 6\n7 8 9\n"
                             "NORMALS my%20normal float\n"
                             "0 0 1 0 0 1 0 0 1\n"
                             "SCALARS pair int 2\n"
                             "LOOKUP_TABLE default\n"
                             "1 2 3 4 5 6\n";

const std::string grid = "# vtk DataFile Version 4.2\n"
                         "grid\n"
                         "ASCII\n"
                         "\n"
                         "DATASET UNSTRUCTURED_GRID\n"
                         "FIELD FieldData 1\n"
                         "TIME 1 1 double\n"
                         "0.5\n"
                         "POINTS 4 double\n"
                         "0 0 0\n1 0 0\n0 1 0\n0 0 1\n"
                         "METADATA\n"
                         "INFORMATION 0\n"
                         "\n"
                         "CELLS 1 5\n"
                         "4 0 1 2 3\n"
                         "CELL_TYPES 1\n"
                         "10\n"
                         "CELL_DATA 1\n"
                         "SCALARS quality float\n"
                         "LOOKUP_TABLE default\n"
                         "0.9\n"
                         "VECTORS flow float\n"
                         "1 1 1\n"
                         "POINT_DATA 4\n"
                         "FIELD attributes 2\n"
                         "temperature 1 4 float\n"
                         "300 310 320 330\n"
                         "displacement 3 4 double\n"
                         "0 0 0 0.1 0 0 0 0.2 0 0 0 0.3\n"
                         "SCALARS id int\n"
                         "LOOKUP_TABLE default\n"
                         "7 8 9 10\n";

} // namespace

TEST(VtkReader, ReadsAsciiPolydataWithScalarsAndVectors)
{
    osg::ref_ptr<PointData> frame = readVtk(polydata);
    ASSERT_EQ(frame->getColumnNames(),
              (std::vector<std::string>{"x", "y", "z", "mass", "velocity_x", "velocity_y", "velocity_z",
                                        "my normal_x", "my normal_y", "my normal_z", "pair_0", "pair_1"}));
    EXPECT_EQ(column(*frame, "x"), (std::vector<float>{0, 1, 0}));
    EXPECT_EQ(column(*frame, "y"), (std::vector<float>{0, 0, 1.5f}));
    EXPECT_EQ(column(*frame, "z"), (std::vector<float>{0, 0, -2}));
    EXPECT_EQ(column(*frame, "mass"), (std::vector<float>{1.5f, 2.5f, 3.5f}));
    EXPECT_EQ(column(*frame, "velocity_y"), (std::vector<float>{2, 5, 8}));
    EXPECT_EQ(column(*frame, "pair_1"), (std::vector<float>{2, 4, 6}));
}

TEST(VtkReader, ReadsUnstructuredGridsSkippingCellsAndCellData)
{
    osg::ref_ptr<PointData> frame = readVtk(grid);
    ASSERT_EQ(frame->getColumnNames(),
              (std::vector<std::string>{"x", "y", "z", "temperature", "displacement_x", "displacement_y",
                                        "displacement_z", "id"}));
    EXPECT_EQ(column(*frame, "z"), (std::vector<float>{0, 0, 0, 1}));
    EXPECT_EQ(column(*frame, "temperature"), (std::vector<float>{300, 310, 320, 330}));
    EXPECT_EQ(column(*frame, "displacement_y"), (std::vector<float>{0, 0, 0.2f, 0}));
    EXPECT_EQ(column(*frame, "id"), (std::vector<float>{7, 8, 9, 10}));
}

TEST(VtkReader, ReadsVersion5CellArrays)
{
    const std::string text = "# vtk DataFile Version 5.1\nv5\nASCII\nDATASET POLYDATA\n"
                             "POINTS 2 float\n0 0 0 1 1 1\n"
                             "VERTICES 3 2\nOFFSETS vtktypeint64\n0 1 2\nCONNECTIVITY vtktypeint64\n0 1\n"
                             "POINT_DATA 2\nSCALARS s float 1\nLOOKUP_TABLE default\n4 5\n";
    osg::ref_ptr<PointData> frame = readVtk(text);
    EXPECT_EQ(column(*frame, "s"), (std::vector<float>{4, 5}));
}

TEST(VtkReader, ReadsBinaryBigEndian)
{
    Bytes bytes(true);
    bytes.text("# vtk DataFile Version 3.0\nbinary\nBINARY\nDATASET UNSTRUCTURED_GRID\nPOINTS 2 double\n");
    bytes.put<double>(1.5).put<double>(-2.0).put<double>(3.0).put<double>(4.0).put<double>(5.0).put<double>(
        6.25);
    bytes.text("\nCELLS 2 4\n");
    bytes.put<int32_t>(1).put<int32_t>(0).put<int32_t>(1).put<int32_t>(1);
    bytes.text("\nCELL_TYPES 2\n");
    bytes.put<int32_t>(1).put<int32_t>(1);
    bytes.text("\nCELL_DATA 2\nSCALARS c short 1\nLOOKUP_TABLE default\n");
    bytes.put<int16_t>(1).put<int16_t>(2);
    bytes.text("\nPOINT_DATA 2\nSCALARS charge float\nLOOKUP_TABLE default\n");
    bytes.put<float>(-1.0f).put<float>(1.0f);
    bytes.text("\nVECTORS v int\n");
    bytes.put<int32_t>(1).put<int32_t>(-2).put<int32_t>(3).put<int32_t>(4).put<int32_t>(5).put<int32_t>(-6);
    bytes.text("\nCOLOR_SCALARS rgb 3\n");
    bytes.put<uint8_t>(255).put<uint8_t>(0).put<uint8_t>(51).put<uint8_t>(0).put<uint8_t>(255).put<uint8_t>(
        0);
    bytes.text("\n");
    osg::ref_ptr<PointData> frame = readVtk(bytes.str());
    ASSERT_EQ(frame->getColumnNames(), (std::vector<std::string>{"x", "y", "z", "charge", "v_x", "v_y", "v_z",
                                                                 "rgb_x", "rgb_y", "rgb_z"}));
    EXPECT_EQ(column(*frame, "x"), (std::vector<float>{1.5f, 4.0f}));
    EXPECT_EQ(column(*frame, "z"), (std::vector<float>{3.0f, 6.25f}));
    EXPECT_EQ(column(*frame, "charge"), (std::vector<float>{-1.0f, 1.0f}));
    EXPECT_EQ(column(*frame, "v_z"), (std::vector<float>{3, -6}));
    EXPECT_EQ(column(*frame, "rgb_z"), (std::vector<float>{0.2f, 0.0f}));
}

TEST(VtkReader, RejectsTruncatedBinaryDataWithItsOffset)
{
    Bytes bytes(true);
    bytes.text("# vtk DataFile Version 3.0\nbinary\nBINARY\nDATASET POLYDATA\nPOINTS 1 float\n");
    bytes.put<float>(1.0f).put<float>(2.0f).put<float>(3.0f);
    bytes.text("\nPOINT_DATA 1\nSCALARS s double\nLOOKUP_TABLE default\n");
    const std::size_t offset = bytes.str().size();
    bytes.put<float>(1.0f);
    EXPECT_EQ(readError(bytes.str(), "vtk", "b.vtk"),
              "b.vtk:9: SCALARS s: 1 tuples of 1 values are more than the 4 bytes left in the file hold");
    bytes.put<float>(1.0f).put<float>(7.0f);
    const std::string text =
        bytes.str().substr(0, offset) + std::string("\x7f\xf8", 2) + std::string(6, '\0');
    EXPECT_EQ(readError(text, "vtk", "b.vtk"),
              "b.vtk: byte " + std::to_string(offset) + ": column 's': value nan is not a finite number");
}

TEST(VtkReader, RejectsBadHeadersAndDatasets)
{
    EXPECT_EQ(readError("# vtk DataFile\n", "vtk", "h.vtk"),
              "h.vtk:1: not a legacy VTK file: the first line must be '# vtk DataFile Version <n>'");
    EXPECT_EQ(readError("# vtk DataFile Version 3.0\ntitle\nXML\n", "vtk", "h.vtk"),
              "h.vtk:3: expected ASCII or BINARY, found 'xml'");
    EXPECT_EQ(
        readError("# vtk DataFile Version 3.0\ntitle\nASCII\nDATASET STRUCTURED_POINTS\n", "vtk", "h.vtk"),
        "h.vtk:4: DATASET 'STRUCTURED_POINTS' is not supported (POLYDATA or UNSTRUCTURED_GRID)");
    EXPECT_EQ(readError("# vtk DataFile Version 3.0\ntitle\nASCII\nPOINTS 1 float\n", "vtk", "h.vtk"),
              "h.vtk:4: expected DATASET POLYDATA or DATASET UNSTRUCTURED_GRID, found 'POINTS'");
    EXPECT_EQ(readError("# vtk DataFile Version 3.0\ntitle\nASCII\nDATASET POLYDATA\n", "vtk", "h.vtk"),
              "h.vtk:4: unexpected end of file: no POINTS section");
}

TEST(VtkReader, RejectsBadSections)
{
    const std::string head = "# vtk DataFile Version 3.0\nt\nASCII\nDATASET POLYDATA\n";
    EXPECT_EQ(readError(head + "POINTS 2 float\n0.0 0.0 0.0\n1.0 1.0\n", "vtk", "s.vtk"),
              "s.vtk:7: unexpected end of file in POINTS: 5 of 6 values");
    EXPECT_EQ(readError(head + "POINTS 1 float\n0 0 zero\n", "vtk", "s.vtk"),
              "s.vtk:6: column 'z': 'zero' is not a number");
    EXPECT_EQ(readError(head + "POINTS 1 quad\n0 0 0\n", "vtk", "s.vtk"),
              "s.vtk:5: POINTS: unknown data type 'quad'");
    EXPECT_EQ(
        readError(head + "POINTS 999999999999 float\n0 0 0\n", "vtk", "s.vtk"),
        "s.vtk:5: POINTS: 999999999999 tuples of 3 values are more than the 6 bytes left in the file hold");
    EXPECT_EQ(readError(head + "POINTS 1 float\n0 0 0 5\n", "vtk", "s.vtk"),
              "s.vtk:6: unexpected '5' after the values of POINTS");
    EXPECT_EQ(readError(head + "POINTS 1 float\n0 0 0\nPOINT_DATA 2\n", "vtk", "s.vtk"),
              "s.vtk:7: POINT_DATA 2 does not match POINTS 1");
    EXPECT_EQ(readError(head + "POINTS 1 float\n0 0 0\nSCALARS s float\n1\n", "vtk", "s.vtk"),
              "s.vtk:7: SCALARS outside POINT_DATA and CELL_DATA");
    EXPECT_EQ(readError(head + "POINTS 1 float\n0 0 0\nVERTICES 1 2\n1 CELL_TYPES\n", "vtk", "s.vtk"),
              "s.vtk:8: VERTICES: 'CELL_TYPES' is not a number");
    EXPECT_EQ(
        readError(head + "POINTS 1 float\n0 0 0\nPOINT_DATA 1\nVECTORS v float\n1 2 nan\n", "vtk", "s.vtk"),
        "s.vtk:9: column 'v_z': 'nan' is not a finite number");
    EXPECT_EQ(readError(head + "POINTS 1 float\n0 0 0\nPOLYHEDRA 1\n", "vtk", "s.vtk"),
              "s.vtk:7: unknown keyword 'POLYHEDRA'");
    EXPECT_EQ(readError(head + "POINTS 1 float\n0 0 0\nPOINT_DATA 1\nFIELD f 1\nt 1 3 float\n1 2 3\n", "vtk",
                        "s.vtk"),
              "s.vtk:9: FIELD array 't' has 3 tuples, POINT_DATA has 1");
}

// VTK keeps the points apart from the arrays: an array may be called x. Its column gets a suffix.
TEST(VtkReader, KeepsArraysNamedLikeThePositions)
{
    const std::string head =
        "# vtk DataFile Version 3.0\nt\nASCII\nDATASET POLYDATA\nPOINTS 1 float\n1 2 3\n";
    osg::ref_ptr<PointData> frame =
        readVtk(head + "POINT_DATA 1\nSCALARS x float\nLOOKUP_TABLE default\n7\nSCALARS x float\n8\n"
                       "FIELD f 1\ny 1 1 float\n9\nVECTORS x float\n4 5 6\n");
    ASSERT_EQ(frame->getColumnNames(),
              (std::vector<std::string>{"x", "y", "z", "x_2", "x_3", "y_2", "x_x", "x_y", "x_z"}));
    EXPECT_EQ(column(*frame, "x"), std::vector<float>{1.0f});
    EXPECT_EQ(column(*frame, "x_2"), std::vector<float>{7.0f});
    EXPECT_EQ(column(*frame, "x_3"), std::vector<float>{8.0f});
    EXPECT_EQ(column(*frame, "y_2"), std::vector<float>{9.0f});
}

// VTK reads keywords in any case, after any blanks.
TEST(VtkReader, ReadsLowerCaseAndIndentedLookupTables)
{
    const std::string head =
        "# vtk DataFile Version 3.0\nt\nASCII\nDATASET POLYDATA\nPOINTS 2 float\n0 0 0 1 1 1\n"
        "POINT_DATA 2\n";
    osg::ref_ptr<PointData> frame = readVtk(head + "SCALARS a float 1\n  lookup_table default\n1 2\n"
                                                   "SCALARS b int\n\tLookup_Table my_table\n3\n4\n");
    EXPECT_EQ(column(*frame, "a"), (std::vector<float>{1.0f, 2.0f}));
    EXPECT_EQ(column(*frame, "b"), (std::vector<float>{3.0f, 4.0f}));
    EXPECT_EQ(readError(head + "SCALARS a float 1\nLOOKUP_TABLE default 1 2\n", "vtk", "l.vtk"),
              "l.vtk:9: malformed LOOKUP_TABLE line: expected 'LOOKUP_TABLE <name>'");
}

// Legacy VTK binary data is big-endian. Floats written little-endian read as absurd values
// (1.0f as 4.6e-41): the reader says what the data look like rather than read garbage.
TEST(VtkReader, RejectsLittleEndianFloatsNamingTheByteOrder)
{
    const std::string head = "# vtk DataFile Version 3.0\nle\nBINARY\nDATASET POLYDATA\nPOINTS 2 float\n";
    Bytes little(false);
    little.text(head)
        .put<float>(1.0f)
        .put<float>(0.0f)
        .put<float>(0.0f)
        .put<float>(2.5f)
        .put<float>(-3.0f)
        .put<float>(4.0f);
    EXPECT_EQ(
        readError(little.str(), "vtk", "le.vtk"),
        "le.vtk: byte " + std::to_string(head.size()) +
            ": POINTS: the values look little-endian: read big-endian, as legacy VTK binary data is, "
            "they are not finite, subnormal or more than 1e40 apart; read little-endian they lie within 1 "
            "and 4. Write the file big-endian");

    Bytes doubles(false);
    doubles.text("# vtk DataFile Version 3.0\nle\nBINARY\nDATASET POLYDATA\nPOINTS 1 double\n")
        .put<double>(1.25)
        .put<double>(-7.0)
        .put<double>(1000.0);
    EXPECT_TRUE(hasError(readError(doubles.str(), "vtk", "le.vtk"), "le.vtk: byte", "look little-endian"));

    // Big-endian data with values VTK files do hold, tiny ones included, read as they are.
    Bytes big(true);
    big.text(head)
        .put<float>(1e-30f)
        .put<float>(0.0f)
        .put<float>(1.0f)
        .put<float>(2.5f)
        .put<float>(-3.0f)
        .put<float>(1e6f);
    osg::ref_ptr<PointData> frame = readVtk(big.str());
    EXPECT_EQ(column(*frame, "x"), (std::vector<float>{1e-30f, 2.5f}));
}
