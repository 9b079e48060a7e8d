// The data model: columns, frame metadata, positions, the element table.

#include <osgGlyphsData/Elements>
#include <osgGlyphsData/PointData>

#include <gtest/gtest.h>

#include <cstring>

using namespace osgGlyphsData;

TEST(PointData, AddsColumnsInOrderAndFindsThem)
{
    osg::ref_ptr<PointData> data = new PointData(3);
    EXPECT_TRUE(data->addColumn("x", {1.0f, 2.0f, 3.0f}));
    EXPECT_TRUE(data->addColumn("mass", {0.5f, 0.25f, 0.125f}));
    EXPECT_EQ(data->getNumPoints(), 3u);
    ASSERT_EQ(data->getColumnNames(), (std::vector<std::string>{"x", "mass"}));
    EXPECT_TRUE(data->hasColumn("mass"));
    EXPECT_FALSE(data->hasColumn("y"));
    EXPECT_EQ(data->getColumn("y"), nullptr);
    ASSERT_NE(data->getColumn("mass"), nullptr);
    EXPECT_EQ((*data->getColumn("mass"))[2], 0.125f);
    EXPECT_EQ(data->findColumn("mass"), 1);
    EXPECT_EQ(data->getColumn(std::size_t(5)), nullptr);
}

TEST(PointData, RejectsLengthMismatchDuplicatesAndEmptyNames)
{
    osg::ref_ptr<PointData> data = new PointData(2);
    std::string error;
    EXPECT_FALSE(data->addColumn("x", {1.0f}, error));
    EXPECT_EQ(error, "column 'x' has 1 values, the frame has 2 points");
    EXPECT_TRUE(data->addColumn("x", {1.0f, 2.0f}, error));
    EXPECT_FALSE(data->addColumn("x", {3.0f, 4.0f}, error));
    EXPECT_EQ(error, "duplicate column 'x'");
    EXPECT_FALSE(data->addColumn("", {3.0f, 4.0f}, error));
    EXPECT_EQ(data->getNumColumns(), 1u);
    EXPECT_FALSE(data->setNumPoints(5));
}

TEST(PointData, KeepsLabelsBoxTimestepAndSource)
{
    osg::ref_ptr<PointData> data = new PointData(2);
    data->addColumn("species", {0.0f, 1.0f});
    EXPECT_TRUE(data->setColumnLabels("species", {"O", "H"}));
    EXPECT_FALSE(data->setColumnLabels("none", {}));
    EXPECT_EQ(data->getColumnLabels("species"), (std::vector<std::string>{"O", "H"}));
    EXPECT_TRUE(data->getColumnLabels("other").empty());

    EXPECT_FALSE(data->hasBox());
    data->setBox(osg::BoundingBoxd(0, 0, 0, 1, 2, 3), osg::Vec3d(0.5, 0, 0));
    EXPECT_TRUE(data->hasBox());
    EXPECT_TRUE(data->isTriclinic());
    data->clearBox();
    EXPECT_FALSE(data->hasBox());
    data->setTimestep(int64_t(1) << 40);
    EXPECT_EQ(data->getTimestep(), int64_t(1) << 40);
    data->setSource("run.dump");
    EXPECT_EQ(data->getSource(), "run.dump");

    osg::ref_ptr<PointDataset> dataset = new PointDataset;
    dataset->addFrame(data.get());
    dataset->setFormat("lammps");
    EXPECT_EQ(dataset->getNumFrames(), 1u);
    EXPECT_EQ(dataset->getFrame(0), data.get());
    EXPECT_EQ(dataset->getFrame(1), nullptr);
}

TEST(Positions, PrefersXYZThenUnwrappedThenScaled)
{
    osg::ref_ptr<PointData> data = new PointData(1);
    data->addColumn("xu", {7.0f});
    data->addColumn("yu", {8.0f});
    data->addColumn("zu", {9.0f});
    std::vector<osg::Vec3f> positions;
    std::string error;
    ASSERT_TRUE(getPositions(*data, {}, positions, error)) << error;
    EXPECT_EQ(positions[0], osg::Vec3f(7, 8, 9));
    data->addColumn("x", {1.0f});
    data->addColumn("y", {2.0f});
    data->addColumn("z", {3.0f});
    ASSERT_TRUE(getPositions(*data, {}, positions, error)) << error;
    EXPECT_EQ(positions[0], osg::Vec3f(1, 2, 3));
    ASSERT_TRUE(getPositions(*data, {"z", "xu", "y"}, positions, error)) << error;
    EXPECT_EQ(positions[0], osg::Vec3f(3, 7, 2));
}

TEST(Positions, ConvertsScaledCoordinatesThroughOrthogonalAndTriclinicBoxes)
{
    osg::ref_ptr<PointData> data = new PointData(2);
    data->addColumn("xs", {0.5f, 1.0f});
    data->addColumn("ys", {0.25f, 1.0f});
    data->addColumn("zs", {0.0f, 1.0f});
    std::vector<osg::Vec3f> positions;
    std::string error;
    EXPECT_FALSE(getPositions(*data, {}, positions, error));
    EXPECT_EQ(error, "scaled coordinates need a simulation box, and the frame has none");

    data->setBox(osg::BoundingBoxd(-1, 0, 2, 3, 8, 4));
    ASSERT_TRUE(getPositions(*data, {}, positions, error)) << error;
    EXPECT_EQ(positions[0], osg::Vec3f(1.0f, 2.0f, 2.0f));
    EXPECT_EQ(positions[1], osg::Vec3f(3.0f, 8.0f, 4.0f));

    // Triclinic: a = (4,0,0), b = (xy, 8, 0), c = (xz, yz, 2).
    data->setBox(osg::BoundingBoxd(-1, 0, 2, 3, 8, 4), osg::Vec3d(1.0, 2.0, 3.0));
    ASSERT_TRUE(getPositions(*data, {}, positions, error)) << error;
    EXPECT_EQ(positions[0], osg::Vec3f(-1.0f + 2.0f + 0.25f, 2.0f, 2.0f));
    EXPECT_EQ(positions[1], osg::Vec3f(-1.0f + 4.0f + 1.0f + 2.0f, 8.0f + 3.0f, 4.0f));
}

TEST(Positions, NamesAMissingColumnAndListsTheOthers)
{
    osg::ref_ptr<PointData> data = new PointData(1);
    data->addColumn("id", {1.0f});
    data->addColumn("x", {1.0f});
    std::vector<osg::Vec3f> positions;
    std::string error;
    EXPECT_FALSE(getPositions(*data, {"x", "y", "z"}, positions, error));
    EXPECT_EQ(error, "no column 'y'; available columns: id x");
    EXPECT_FALSE(getPositions(*data, {}, positions, error));
    EXPECT_EQ(error,
              "no position columns (x y z, xu yu zu, xs ys zs or xsu ysu zsu); available columns: id x");
    EXPECT_FALSE(getPositions(*data, {"x"}, positions, error));
    EXPECT_EQ(error, "positions need exactly three columns, 1 given");
}

TEST(Elements, CoversHydrogenToPlutoniumWithoutGaps)
{
    ASSERT_GE(getMaxAtomicNumber(), 36u);
    for (unsigned int number = 1; number <= getMaxAtomicNumber(); ++number)
    {
        const Element& element = getElement(number);
        EXPECT_EQ(element.number, number);
        EXPECT_GT(element.covalentRadius, 0.2f) << element.symbol;
        EXPECT_GT(element.vdwRadius, 1.0f) << element.symbol;
        const Element* found = findElement(element.symbol);
        ASSERT_NE(found, nullptr) << element.symbol;
        EXPECT_EQ(found->number, number);
    }
    EXPECT_STREQ(getElement(26).symbol, "Fe");
    EXPECT_STREQ(getElement(79).name, "Gold");
}

TEST(Elements, FindsSymbolsCaseInsensitivelyAndFallsBack)
{
    EXPECT_EQ(findElement("Cl")->number, 17u);
    EXPECT_EQ(findElement("CL")->number, 17u);
    EXPECT_EQ(findElement(" c ")->number, 6u);
    EXPECT_EQ(findElement("Xx"), nullptr);
    EXPECT_EQ(findElement(""), nullptr);
    EXPECT_EQ(findElement("Carbon"), nullptr);
    const Element& unknown = getElementBySymbol("Xx");
    EXPECT_EQ(unknown.number, 0u);
    EXPECT_STREQ(unknown.symbol, "X");
    EXPECT_EQ(unknown.rgb, 0xFF1493u);
    EXPECT_EQ(&getElement(0), &getUnknownElement());
    EXPECT_EQ(&getElement(500), &getUnknownElement());
}

TEST(Elements, GivesCpkColoursAndRadii)
{
    EXPECT_EQ(getElement(8).getColor(), osg::Vec4(1.0f, 13.0f / 255.0f, 13.0f / 255.0f, 1.0f));
    EXPECT_EQ(getElement(1).getColor(), osg::Vec4(1.0f, 1.0f, 1.0f, 1.0f));
    EXPECT_FLOAT_EQ(getElement(6).vdwRadius, 1.70f);
    EXPECT_FLOAT_EQ(getElement(6).covalentRadius, 0.76f);
}
