// The converter's archive writer (its private source is compiled in): the bytes osgDB's own osga
// plugin writes for the same files, index blocks included, and what that plugin reads back.

#include "TileArchive.h"
#include "RenderHarness.h"

#include <osgGlyphs/Version>

#include <osg/Group>
#include <osgDB/Archive>
#include <osgDB/ReadFile>

#include <fstream>
#include <iterator>
#include <string>
#include <thread>
#include <vector>

using osgGlyphsTiles::detail::TileArchive;

namespace
{

std::string readBytes(const std::string& path)
{
    std::ifstream file(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>());
}

/** A small node that tells which file it was written as. */
osg::ref_ptr<osg::Group> namedGroup(const std::string& name)
{
    osg::ref_ptr<osg::Group> group = new osg::Group;
    group->setName(name);
    return group;
}

std::string fileName(unsigned int i)
{
    return "n" + std::to_string(i) + "-" + std::to_string(i * 7919) + ".osgb";
}

// Enough files for their index to fill several of its 4096-byte blocks.
const unsigned int FILES = 500;

}

TEST(TileArchive, WritesTheBytesOfOsgDBsArchiveWriter)
{
    const std::string stock = osgGlyphsTest::outputPath("archive_stock.osga");
    const std::string ours = osgGlyphsTest::outputPath("archive_ours.osga");
    std::remove(stock.c_str());
    {
        // Ours asks for the version of osgGlyphs' serializers, as a writer may.
        osg::ref_ptr<osgDB::Options> versioned = new osgDB::Options;
        versioned->setPluginStringData("CustomDomains", OSGGLYPHS_SERIALIZER_DOMAIN_ENTRY);
        osg::ref_ptr<osgDB::Archive> archive = osgDB::openArchive(stock, osgDB::ReaderWriter::CREATE);
        ASSERT_TRUE(archive.valid());
        for (unsigned int i = 0; i < FILES; ++i)
            ASSERT_TRUE(archive->writeNode(*namedGroup(fileName(i)), fileName(i), versioned.get()).success());
        ASSERT_TRUE(archive->writeNode(*namedGroup("again"), fileName(3), versioned.get()).success());
        archive->close();
    }
    TileArchive archive;
    std::string error;
    ASSERT_TRUE(archive.create(ours, error)) << error;
    for (unsigned int i = 0; i < FILES; ++i)
        ASSERT_TRUE(archive.writeNode(*namedGroup(fileName(i)), fileName(i), error)) << error;
    ASSERT_TRUE(archive.writeNode(*namedGroup("again"), fileName(3), error)) << error;
    ASSERT_TRUE(archive.close(error)) << error;
    const std::string stockBytes = readBytes(stock);
    EXPECT_GT(stockBytes.size(), 3u * 4096u);
    EXPECT_TRUE(readBytes(ours) == stockBytes)
        << "sizes " << readBytes(ours).size() << " and " << stockBytes.size();
}

TEST(TileArchive, FilesWrittenFromSeveralThreadsReadBackThroughTheOsgaPlugin)
{
    const std::string path = osgGlyphsTest::outputPath("archive_threads.osga");
    TileArchive archive;
    std::string error;
    ASSERT_TRUE(archive.create(path, error)) << error;
    ASSERT_TRUE(archive.writeNode(*namedGroup("master"), "root.osgb", error)) << error;
    std::vector<std::thread> threads;
    std::vector<std::string> errors(4);
    for (unsigned int t = 0; t < 4; ++t)
        threads.emplace_back(
            [&archive, &errors, t]
            {
                for (unsigned int i = t; i < FILES; i += 4)
                    if (!archive.writeNode(*namedGroup(fileName(i)), fileName(i), errors[t]))
                        return;
            });
    for (std::thread& thread : threads)
        thread.join();
    for (const std::string& threadError : errors)
        EXPECT_EQ(threadError, "");
    ASSERT_TRUE(archive.close(error)) << error;

    osg::ref_ptr<osgDB::Archive> reading = osgDB::openArchive(path, osgDB::ReaderWriter::READ);
    ASSERT_TRUE(reading.valid());
    EXPECT_EQ(reading->getMasterFileName(), "root.osgb");
    osgDB::Archive::FileNameList names;
    reading->getFileNames(names);
    EXPECT_EQ(names.size(), FILES + 1);
    for (unsigned int i = 0; i < FILES; i += 37)
    {
        osg::ref_ptr<osg::Node> node = reading->readNode(fileName(i)).getNode();
        ASSERT_TRUE(node.valid()) << fileName(i);
        EXPECT_EQ(node->getName(), fileName(i));
    }
}

TEST(TileArchive, AnUnwritablePathIsOneError)
{
    TileArchive archive;
    std::string error;
    EXPECT_FALSE(archive.create(osgGlyphsTest::outputPath("no_such_folder/archive.osga"), error));
    EXPECT_NE(error.find("cannot create the archive"), std::string::npos) << error;
}
