// Tiles cut on several threads: every file of the archive is the one a single thread writes, for a
// dataset in memory and for one sorted through temporary files (only the order of the files in
// the archive may differ). .ci/bootstrap test --sanitize=thread runs it under ThreadSanitizer.

#include "RenderHarness.h"

#include <osgGlyphsData/RandomCloud>
#include <osgGlyphsTiles/TileBuilder>

#include <osgDB/Archive>
#include <osgDB/Registry>

#include <filesystem>
#include <map>
#include <sstream>
#include <string>

using namespace osgGlyphsTest;
using osgGlyphs::GlyphCloud;

namespace
{

const unsigned int GLYPHS = 40000;
const unsigned int BATCH = 8000;

osg::ref_ptr<GlyphCloud> randomBatch(osgGlyphs::GlyphShape shape, unsigned int seed)
{
    osgGlyphsData::RandomCloudOptions options;
    options.count = BATCH;
    options.shape = shape;
    options.seed = seed;
    options.radius = 0.01f;
    return osgGlyphsData::createRandomCloud(options);
}

/** Each file of the archive at path, by name, as osgb bytes written again from what it reads as. */
std::map<std::string, std::string> filesOf(const std::string& path)
{
    std::map<std::string, std::string> files;
    // The plugin's, not the Registry's: that one keeps the archive as the builder left it.
    osgDB::ReaderWriter* osga = osgDB::Registry::instance()->getReaderWriterForExtension("osga");
    osg::ref_ptr<osgDB::Archive> archive =
        osga ? osga->openArchive(path, osgDB::ReaderWriter::READ).takeArchive() : nullptr;
    EXPECT_TRUE(archive.valid()) << path;
    if (!archive)
        return files;
    osgDB::ReaderWriter* osgb = osgDB::Registry::instance()->getReaderWriterForExtension("osgb");
    osgDB::Archive::FileNameList names;
    archive->getFileNames(names);
    for (const std::string& name : names)
    {
        osg::ref_ptr<osg::Node> node = archive->readNode(name).getNode();
        EXPECT_TRUE(node.valid()) << path << ": " << name;
        std::ostringstream bytes;
        if (node && osgb)
            osgb->writeNode(*node, bytes);
        files[name] = bytes.str();
    }
    return files;
}

/** The archive of the dataset cut by threads threads, holding at most maxInMemory glyphs. */
std::string writeArchive(osgGlyphs::GlyphShape shape, unsigned int threads, std::size_t maxInMemory,
                         const std::string& name)
{
    osgGlyphsTiles::TileOptions options;
    options.maxGlyphsPerTile = 500;
    options.cellsPerAxis = 8;
    options.maxGlyphsInMemory = maxInMemory;
    options.threads = threads;
    options.temporaryDirectory = outputPath("");
    osg::ref_ptr<osgGlyphsTiles::TileBuilder> builder =
        new osgGlyphsTiles::TileBuilder(*randomBatch(shape, 1), options);
    // Past the memory, the glyphs are sorted into octree buckets on a thread while more come.
    EXPECT_TRUE(builder->setBounds(osg::BoundingBoxd(0.0, 0.0, 0.0, 1.0, 1.0, 1.0)));
    std::string error;
    for (unsigned int first = 0; first < GLYPHS; first += BATCH)
        EXPECT_TRUE(builder->addGlyphs(*randomBatch(shape, 1 + first), error)) << error;
    const std::string path = outputPath(name + ".osga");
    EXPECT_TRUE(builder->write(path, error)) << error;
    return path;
}

class TileThreads : public ::testing::TestWithParam<osgGlyphs::GlyphShape>
{
};

TEST_P(TileThreads, WriteTheFilesOfOneThread)
{
    const osgGlyphs::GlyphShape shape = GetParam();
    const std::string prefix =
        std::string("tile_threads_") + (shape == osgGlyphs::GlyphShape::Sphere ? "spheres" : "cones");
    const auto single = filesOf(writeArchive(shape, 1, GLYPHS, prefix + "_1"));
    // Many more subtrees than tiles of 500 glyphs: threads start and wait at every level.
    ASSERT_GT(single.size(), 20u);
    for (const auto& [threads, inMemory] :
         {std::make_pair(4u, std::size_t(GLYPHS)), std::make_pair(3u, std::size_t(9000))})
    {
        const auto several =
            filesOf(writeArchive(shape, threads, inMemory, prefix + "_" + std::to_string(threads)));
        EXPECT_EQ(several.size(), single.size()) << threads << " threads";
        std::size_t differ = 0;
        for (const auto& [name, bytes] : single)
        {
            const auto found = several.find(name);
            differ += found == several.end() || found->second != bytes;
        }
        EXPECT_EQ(differ, 0u) << "files missing or different with " << threads << " threads, " << inMemory
                              << " glyphs in memory, of " << single.size();
    }
}

INSTANTIATE_TEST_SUITE_P(Shapes, TileThreads,
                         ::testing::Values(osgGlyphs::GlyphShape::Sphere, osgGlyphs::GlyphShape::Cone),
                         [](const ::testing::TestParamInfo<osgGlyphs::GlyphShape>& instance) {
                             return std::string(instance.param == osgGlyphs::GlyphShape::Sphere ? "spheres"
                                                                                                : "cones");
                         });

}
