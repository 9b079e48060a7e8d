// The reader entry points: formats, extensions, files, progress and errors common to all formats.

#include "ReaderTestUtil.h"

#include <osgGlyphsData/FrameFile>

using namespace osgGlyphsData;
using namespace readertest;

TEST(PointReader, ListsItsFormats)
{
    EXPECT_EQ(getSupportedPointFormats(),
              (std::vector<std::string>{"csv", "xyz", "lammps", "ply", "vtk", "dcd", "xtc", "trr", "gsd",
                                        "las", "pdb", "gro", "lammpsdata"}));
    EXPECT_FALSE(isFrameFileFormat("lammps"));
    EXPECT_TRUE(isFrameFileFormat("DCD"));
    EXPECT_TRUE(isFrameFileFormat("laz"));
}

TEST(PointReader, TellsFormatsFromExtensions)
{
    EXPECT_EQ(formatFromExtension("a/b/points.CSV"), "csv");
    EXPECT_EQ(formatFromExtension("water.xyz"), "xyz");
    EXPECT_EQ(formatFromExtension("water.extxyz"), "xyz");
    EXPECT_EQ(formatFromExtension("melt.lammpstrj"), "lammps");
    EXPECT_EQ(formatFromExtension("melt.dump"), "lammps");
    EXPECT_EQ(formatFromExtension("run.lammps"), "lammps");
    EXPECT_EQ(formatFromExtension("/tmp/dump.melt"), "lammps");
    EXPECT_EQ(formatFromExtension("data.peptide"), "lammpsdata");
    EXPECT_EQ(formatFromExtension("data.csv"), "csv");
    EXPECT_EQ(formatFromExtension("dump.xyz"), "xyz");
    EXPECT_EQ(formatFromExtension("bunny.ply"), "ply");
    EXPECT_EQ(formatFromExtension("grid.vtk"), "vtk");
    EXPECT_EQ(formatFromExtension("notes.txt"), "");
    EXPECT_EQ(formatFromExtension("README"), "");
}

TEST(PointReader, DescribesEachFormatAndTheFileNamesThatSelectIt)
{
    const std::vector<PointFormat>& formats = getPointFormats();
    ASSERT_EQ(formats.size(), getSupportedPointFormats().size());
    for (const PointFormat& format : formats)
    {
        EXPECT_FALSE(format.description.empty()) << format.name;
        ASSERT_FALSE(format.extensions.empty()) << format.name;
        for (const std::string& extension : format.extensions)
            EXPECT_EQ(formatFromExtension("file." + extension), format.name) << extension;
        for (const std::string& prefix : format.prefixes)
            EXPECT_EQ(formatFromExtension(prefix + "file"), format.name) << prefix;
    }
    EXPECT_EQ(formats[2].prefixes, std::vector<std::string>{"dump."});
}

namespace
{

std::string detailFormatList()
{
    std::string list;
    for (const std::string& name : getSupportedPointFormats())
        list += (list.empty() ? "" : ", ") + name;
    return list;
}

}

TEST(PointReader, RejectsUnknownFormatNames)
{
    std::string error;
    EXPECT_FALSE(readString("x\n1\n", "netcdf", error, "in.nc").valid());
    EXPECT_EQ(error, "in.nc: unknown point format 'netcdf' (supported: " + detailFormatList() + ")");
    EXPECT_FALSE(readString("x\n1\n", "dcd", error, "in.dcd").valid());
    EXPECT_EQ(error, "in.dcd: dcd files are read by seeking in them: give a file, not a stream");
    EXPECT_TRUE(readString("x\n1\n", "CSV", error).valid()) << error;
    EXPECT_TRUE(readString("1\n\nH 0 0 0\n", "extxyz", error).valid()) << error;
}

TEST(PointReader, ReadsFilesByExtensionAndNamedFormat)
{
    const std::string path = writeFile("points.csv", "x,y,z\n1,2,3\n");
    std::string error;
    osg::ref_ptr<PointDataset> dataset = readPointFile(path, PointReadOptions(), error);
    ASSERT_TRUE(dataset.valid()) << error;
    EXPECT_EQ(dataset->getFormat(), "csv");
    EXPECT_EQ(dataset->getSource(), path);
    EXPECT_EQ(dataset->getFrame(0)->getSource(), path);

    const std::string other = writeFile("points.dat", "x y z\n1 2 3\n");
    EXPECT_FALSE(readPointFile(other, PointReadOptions(), error).valid());
    EXPECT_TRUE(hasError(error, other + ": ", "cannot tell the point format from the file name"));
    PointReadOptions options;
    options.format = "csv";
    EXPECT_TRUE(readPointFile(other, options, error).valid()) << error;
}

TEST(PointReader, ReportsMissingFilesAndFolders)
{
    std::string error;
    const std::string missing = testFile("missing.lammpstrj");
    EXPECT_FALSE(readPointFile(missing, PointReadOptions(), error).valid());
    EXPECT_EQ(error, missing + ": cannot open: No such file or directory");
    const std::string folder = testFile("folder.vtk");
    std::filesystem::create_directories(folder);
    EXPECT_FALSE(readPointFile(folder, PointReadOptions(), error).valid());
    EXPECT_EQ(error, folder + ": is a directory");
}

TEST(PointReader, RejectsEmptyFilesInEveryFormat)
{
    for (const std::string& format : getSupportedPointFormats())
    {
        const std::string path = writeFile("empty." + format, "");
        std::string error;
        EXPECT_FALSE(readPointFile(path, PointReadOptions(), error).valid()) << format;
        EXPECT_EQ(error, path + (isFrameFileFormat(format) ? "" : ":1") + ": the file is empty");
    }
}

TEST(PointReader, RejectsBinaryGarbageInEveryFormat)
{
    std::string garbage;
    for (int i = 0; i < 3000; ++i)
        garbage += static_cast<char>((i * 7919 + 13) % 256);
    for (const std::string& format : getSupportedPointFormats())
    {
        const std::string error = readError(garbage, format, "garbage." + format);
        EXPECT_TRUE(hasError(error, "garbage." + format + ":", "")) << format;
    }
}

TEST(PointReader, ReportsProgressUpToTheWholeFile)
{
    std::string text = "x y z\n";
    for (int i = 0; i < 200000; ++i)
        text += std::to_string(i) + " 1 2\n";
    const std::string path = writeFile("progress.csv", text);
    std::vector<std::pair<uint64_t, uint64_t>> calls;
    PointReadOptions options;
    options.progress = [&calls](uint64_t read, uint64_t total) { calls.emplace_back(read, total); };
    std::string error;
    osg::ref_ptr<PointDataset> dataset = readPointFile(path, options, error);
    ASSERT_TRUE(dataset.valid()) << error;
    EXPECT_EQ(dataset->getFrame(0)->getNumPoints(), 200000u);
    ASSERT_GE(calls.size(), 2u);
    for (std::size_t i = 1; i < calls.size(); ++i)
        EXPECT_GE(calls[i].first, calls[i - 1].first);
    EXPECT_EQ(calls.back().first, text.size());
    EXPECT_EQ(calls.back().second, text.size());
}

TEST(PointReader, ReadsStreamsOfUnknownSize)
{
    PipeBuffer pipe("ITEM: TIMESTEP\n7\nITEM: NUMBER OF ATOMS\n2\nITEM: BOX BOUNDS pp pp pp\n0 1\n0 1\n0 1\n"
                    "ITEM: ATOMS id x y z\n1 0.5 0.25 0.125\n2 1 2 3\n");
    std::istream stream(&pipe);
    std::string error;
    osg::ref_ptr<PointDataset> dataset = readPointStream(stream, "lammps", "pipe", PointReadOptions(), error);
    ASSERT_TRUE(dataset.valid()) << error;
    EXPECT_EQ(dataset->getFrame(0)->getTimestep(), 7);
    EXPECT_EQ(column(*dataset->getFrame(0), "z"), (std::vector<float>{0.125f, 3.0f}));
}

TEST(PointReader, FailsAbsurdCountsOfStreamsOfUnknownSizeAtTheirEnd)
{
    PipeBuffer pipe(
        "ITEM: TIMESTEP\n7\nITEM: NUMBER OF ATOMS\n999999999999\nITEM: BOX BOUNDS pp pp pp\n0 1\n0 1\n"
        "0 1\nITEM: ATOMS id x y z\n1 0.5 0.25 0.125\n");
    std::istream stream(&pipe);
    std::string error;
    EXPECT_FALSE(readPointStream(stream, "lammps", "pipe", PointReadOptions(), error).valid());
    EXPECT_EQ(error, "pipe:10: unexpected end of file: ITEM: ATOMS has 1 of 999999999999 rows");

    PipeBuffer ply(
        "ply\nformat binary_little_endian 1.0\nelement vertex 4000000000\nproperty float x\nend_header\n"
        "\1\2\3\4");
    std::istream plyStream(&ply);
    EXPECT_FALSE(readPointStream(plyStream, "ply", "pipe.ply", PointReadOptions(), error).valid());
    EXPECT_EQ(error, "pipe.ply: byte 94: unexpected end of file: element 'vertex' has 1 of 4000000000 items");
}

// Counts that no stream can hold, from a pipe: the message names no made-up stream size.
TEST(PointReader, NamesNoSizeOfAStreamOfUnknownSize)
{
    PipeBuffer pipe(
        "ply\nformat binary_little_endian 1.0\nelement vertex 2000000000000000000\nproperty double x\n"
        "element face 2000000000000000000\nproperty double a\nend_header\n");
    std::istream stream(&pipe);
    std::string error;
    EXPECT_FALSE(readPointStream(stream, "ply", "pipe.ply", PointReadOptions(), error).valid());
    EXPECT_EQ(error,
              "pipe.ply:5: element 'face' declares 2000000000000000000 items of at least 8 bytes, but with "
              "the elements before it that is more than a stream can hold (2^64 bytes)");
}
