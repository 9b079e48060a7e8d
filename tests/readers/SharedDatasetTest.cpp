/* What a share of a dataset cannot know alone (osgGlyphsData::unifyShares): label numbering and
 * column origins, agreed over K shares played by K threads (ThreadShares.h). Every share must
 * end with exactly the values and labels of one reading of the whole file. */

#include "ReaderTestUtil.h"
#include "ThreadShares.h"

#include <osgGlyphsData/SharedDataset>

using namespace osgGlyphsData;
using namespace readertest;

namespace
{

/** A column's stored values (offsets from its origin), origin, and labels. */
struct StoredColumn
{
    std::vector<float> values;
    std::vector<double> origins;                  // one per share
    std::vector<std::vector<std::string>> labels; // one per share
};

/** Count shares of text as count processes read them, each agreed with the others through
 * unifyShares (unless agree is false): null where reading or agreeing failed, with its error. */
struct SharedReading
{
    std::vector<osg::ref_ptr<PointDataset>> shares;
    std::vector<std::string> errors;
};

SharedReading readAndAgree(const std::string& text, const std::string& format, unsigned int count,
                           bool agree = true, const std::string& name = "data")
{
    SharedReading reading{std::vector<osg::ref_ptr<PointDataset>>(count), std::vector<std::string>(count)};
    runShares(count,
              [&](const ShareReduction& reduction, unsigned int index)
              {
                  PointReadOptions options;
                  options.share = reduction.getShare();
                  std::vector<std::string> warnings;
                  std::string& error = reading.errors[index];
                  osg::ref_ptr<PointDataset> share =
                      readWithOptions(text, format, options, warnings, error, name);
                  if (share.valid() && (!agree || unifyShares(*share, reduction, error)))
                      reading.shares[index] = share;
              });
    return reading;
}

/** Reads count shares of text, agrees on them through unifyShares (unless agree is false), and
 * joins column name of frame 0 in share order. */
StoredColumn readShares(const std::string& text, const std::string& format, const std::string& name,
                        unsigned int count, bool agree = true)
{
    const SharedReading reading = readAndAgree(text, format, count, agree);
    const std::vector<osg::ref_ptr<PointDataset>>& shares = reading.shares;
    const std::vector<std::string>& errors = reading.errors;
    StoredColumn joined;
    for (unsigned int index = 0; index < count; ++index)
    {
        EXPECT_TRUE(shares[index].valid()) << errors[index];
        if (!shares[index].valid())
            continue;
        const PointData& frame = *shares[index]->getFrame(0);
        const std::vector<float>* values = frame.getColumn(name);
        EXPECT_TRUE(values) << name;
        if (values)
            joined.values.insert(joined.values.end(), values->begin(), values->end());
        joined.origins.push_back(frame.getColumnOrigin(name));
        joined.labels.push_back(frame.getColumnLabels(name));
    }
    return joined;
}

/** Every share of 1 to 4 holds column name as the whole reading does: stored values, origin, labels. */
void expectSharesAgreeWithWhole(const std::string& text, const std::string& format, const std::string& name)
{
    std::string error;
    osg::ref_ptr<PointDataset> whole = readString(text, format, error);
    ASSERT_TRUE(whole.valid()) << error;
    const PointData& frame = *whole->getFrame(0);
    for (unsigned int count = 1; count <= 4; ++count)
    {
        const StoredColumn shares = readShares(text, format, name, count);
        EXPECT_EQ(shares.values, *frame.getColumn(name)) << name << " in " << count << " shares";
        for (unsigned int index = 0; index < shares.origins.size(); ++index)
        {
            EXPECT_EQ(shares.origins[index], frame.getColumnOrigin(name))
                << name << ": share " << index << " of " << count;
            EXPECT_EQ(shares.labels[index], frame.getColumnLabels(name))
                << name << ": share " << index << " of " << count;
        }
    }
}

/** Extended XYZ whose later atoms meet the labels in another order than the first ones. */
const std::string LABELLED_XYZ = "6\nProperties=species:S:1:pos:R:3:phase:S:1\n"
                                 "Cu 0 0 0 solid\nCu 1 0 0 solid\nCu 2 0 0 solid\n"
                                 "Ni 3 0 0 liquid\nAl 4 0 0 gas\nNi 5 0 0 solid\n";

} // namespace

TEST(SharedDataset, LabelsAreNumberedAsInTheWholeFile)
{
    expectSharesAgreeWithWhole(LABELLED_XYZ, "xyz", "species");
    expectSharesAgreeWithWhole(LABELLED_XYZ, "xyz", "phase");
    expectSharesAgreeWithWhole(LABELLED_XYZ, "xyz", "element");
    const std::string dump =
        "ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n5\nITEM: BOX BOUNDS pp pp pp\n0 9\n0 9\n0 9\n"
        "ITEM: ATOMS id element x y z\n1 O 0 0 0\n2 O 1 0 0\n3 H 2 0 0\n4 C 3 0 0\n5 H 4 0 0\n";
    expectSharesAgreeWithWhole(dump, "lammps", "species");
}

TEST(SharedDataset, WithoutAgreeingSharesNumberTheirOwnLabels)
{
    // What unifyShares repairs: share 1 of 2 meets Ni first, and numbers it 0.
    const StoredColumn shares = readShares(LABELLED_XYZ, "xyz", "species", 2, false);
    EXPECT_EQ(shares.labels[1], (std::vector<std::string>{"Ni", "Al"}));
    EXPECT_EQ(shares.values, (std::vector<float>{0, 0, 0, 0, 1, 0}));
}

TEST(SharedDataset, FarCoordinatesHaveTheOriginOfTheWholeFile)
{
    // The first x is 1e6 + 0.1: every share stores offsets from 1000000, as the whole reading does.
    std::string xyz = "9\nfar\n", csv = "x y z\n";
    for (int i = 0; i < 9; ++i)
    {
        const std::string row =
            std::to_string(1000000.1 + 123.457 * i) + " " + std::to_string(-2e6 - 7.31 * i) + " 0.5\n";
        xyz += "C " + row;
        csv += row;
    }
    for (const char* name : {"x", "y"})
    {
        expectSharesAgreeWithWhole(xyz, "xyz", name);
        expectSharesAgreeWithWhole(csv, "csv", name);
    }
}

TEST(SharedDataset, FarCoordinatesOfBinaryPlyHaveTheOriginOfTheWholeFile)
{
    Bytes ply(false);
    ply.text("ply\nformat binary_little_endian 1.0\nelement vertex 7\nproperty double x\n"
             "property float y\nend_header\n");
    for (int i = 0; i < 7; ++i)
        ply.put(double(5e6 + 0.25 + 31.7 * i)).put(float(i));
    expectSharesAgreeWithWhole(ply.str(), "ply", "x");
}

TEST(SharedDataset, AColumnBackToPlainValuesInOneShareIsInEvery)
{
    // Row 5 is farther from the origin 1e6 than from zero: its share's x goes back to plain values.
    const std::string xyz = "6\nback\nC 1000000 0 0\nC 1000001 0 0\nC 1000002 0 0\nC 1000003 0 0\n"
                            "C 1000004 0 0\nC -1000000 0 0\n";
    std::string error;
    osg::ref_ptr<PointDataset> whole = readString(xyz, "xyz", error);
    ASSERT_TRUE(whole.valid()) << error;
    for (unsigned int count = 2; count <= 4; ++count)
    {
        const StoredColumn shares = readShares(xyz, "xyz", "x", count);
        for (double origin : shares.origins)
            EXPECT_EQ(origin, 0.0) << count << " shares";
        EXPECT_EQ(shares.values, *whole->getFrame(0)->getColumn("x")) << count << " shares";
    }
}

TEST(SharedDataset, SharesThatDoNotAddUpToTheFilesCountFailInEveryShare)
{
    // ITEM: NUMBER OF ATOMS says 5; the frame has 4 rows, and the file ends there.
    const std::string dump = "ITEM: TIMESTEP\n40\nITEM: NUMBER OF ATOMS\n5\nITEM: BOX BOUNDS pp pp pp\n"
                             "0 1\n0 1\n0 1\nITEM: ATOMS id x y z\n1 0 0 0\n2 1 0 0\n3 2 0 0\n4 3 0 0\n";
    const SharedReading reading = readAndAgree(dump, "lammps", 3, true, "short.dump");
    const std::vector<std::string>& errors = reading.errors;
    for (const std::string& error : errors)
        EXPECT_EQ(
            error,
            "short.dump: frame 1 (timestep 40): the file counts 5 points, its 3 shares read 4 together");
}

TEST(SharedDataset, ALastFrameCutShortIsLeftOutByEveryShare)
{
    // The second frame ends in the middle of its 6th of 8 rows: only the last share meets the cut.
    std::string dump;
    for (int frame = 0; frame < 2; ++frame)
    {
        dump +=
            "ITEM: TIMESTEP\n" + std::to_string(frame) +
            "\nITEM: NUMBER OF ATOMS\n8\nITEM: BOX BOUNDS pp pp pp\n0 1\n0 1\n0 1\nITEM: ATOMS id x y z\n";
        for (int i = 1; i <= (frame == 0 ? 8 : 5); ++i)
            dump += std::to_string(i) + " 0." + std::to_string(i) + " 0.5 0.5\n";
    }
    dump += "6 0.6";
    const SharedReading reading = readAndAgree(dump, "lammps", 3);
    for (unsigned int index = 0; index < 3; ++index)
    {
        ASSERT_TRUE(reading.shares[index].valid()) << reading.errors[index];
        EXPECT_EQ(reading.shares[index]->getNumFrames(), 1u) << "share " << index;
    }
}
