// Datasets larger than memory: a TileBuilder that holds fewer glyphs than the dataset has sorts
// them through temporary files and writes the archive byte for byte as one that held them all.

#include "RenderHarness.h"

#include <osgGlyphsData/RandomCloud>
#include <osgGlyphsTiles/TileBuilder>

#include <osg/NodeVisitor>
#include <osg/PagedLOD>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <ostream>
#include <string>
#include <vector>

using namespace osgGlyphsTest;
using osgGlyphs::GlyphCloud;

namespace
{

const unsigned int GLYPHS = 60000;
const unsigned int BATCH = 7000;

/** clustered: positions p -> p^4, gathering a fifth of the glyphs into one 512th of the cube. */
osg::ref_ptr<GlyphCloud> randomBatch(osgGlyphs::GlyphShape shape, bool rgba, unsigned int seed,
                                     bool clustered = false)
{
    osgGlyphsData::RandomCloudOptions options;
    options.count = BATCH;
    options.shape = shape;
    options.seed = seed;
    options.radius = 0.01f;
    osg::ref_ptr<GlyphCloud> cloud = osgGlyphsData::createRandomCloud(options);
    if (rgba)
    {
        osg::ref_ptr<osg::Vec4ubArray> colors = new osg::Vec4ubArray;
        for (unsigned int i = 0; i < cloud->getNumGlyphs(); ++i)
            colors->push_back(osg::Vec4ub(i * 7, i * 13, i * 29, 255));
        cloud->setColors(colors.get());
    }
    if (clustered)
    {
        osg::ref_ptr<osg::Vec3Array> positions = new osg::Vec3Array(*cloud->getPositions());
        for (osg::Vec3f& p : *positions)
            p.set(std::pow(p.x(), 4.0f), std::pow(p.y(), 4.0f), std::pow(p.z(), 4.0f));
        cloud->setPositions(positions.get());
    }
    return cloud;
}

std::string readBytes(const std::string& path)
{
    std::ifstream file(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>());
}

std::size_t filesIn(const std::filesystem::path& folder)
{
    return static_cast<std::size_t>(
        std::distance(std::filesystem::directory_iterator(folder), std::filesystem::directory_iterator()));
}

struct Dataset
{
    osgGlyphs::GlyphShape shape;
    bool rgba;
    const char* name;
    bool clustered = false;
};

void PrintTo(const Dataset& dataset, std::ostream* out)
{
    *out << dataset.name;
}

class TilesLargerThanMemory : public ::testing::TestWithParam<Dataset>
{
};

/** The box of the dataset's positions. */
osg::BoundingBoxd boxOf(const Dataset& dataset)
{
    osg::BoundingBoxd box;
    for (unsigned int first = 0; first < GLYPHS; first += BATCH)
    {
        const osg::ref_ptr<GlyphCloud> cloud =
            randomBatch(dataset.shape, dataset.rgba, 1 + first, dataset.clustered);
        for (const osg::Vec3f& p : *cloud->getPositions())
            box.expandBy(osg::Vec3d(p));
    }
    return box;
}

/** Writes the dataset's tiles holding at most maxInMemory glyphs; temporary files go to folder.
 * With bounds valid, they are given to the builder first. */
std::string writeArchive(const Dataset& dataset, std::size_t maxInMemory, const std::filesystem::path& folder,
                         const std::string& name, std::size_t* filesDuringBuild = nullptr,
                         const osg::BoundingBoxd& bounds = osg::BoundingBoxd())
{
    osgGlyphsTiles::TileOptions options;
    options.maxGlyphsPerTile = 1000;
    // Clustered: buckets (512 nodes) of more than the glyphs in memory are sorted into nodes 2
    // levels further down, where some still hold more.
    options.cellsPerAxis = dataset.clustered ? 32 : 8;
    options.maxGlyphsInMemory = maxInMemory;
    options.temporaryDirectory = folder.string();
    options.threads = 1; // the files' order in the archive too (tests/threads/TileThreadsTest.cpp)
    osg::ref_ptr<osgGlyphsTiles::TileBuilder> builder =
        new osgGlyphsTiles::TileBuilder(*randomBatch(dataset.shape, dataset.rgba, 1), options);
    if (bounds.valid())
    {
        EXPECT_TRUE(builder->setBounds(bounds));
    }
    std::string error;
    for (unsigned int first = 0; first < GLYPHS; first += BATCH)
        EXPECT_TRUE(builder->addGlyphs(
            *randomBatch(dataset.shape, dataset.rgba, 1 + first, dataset.clustered), error))
            << error;
    EXPECT_EQ(builder->getNumGlyphs(), std::size_t(GLYPHS + BATCH - 1) / BATCH * BATCH);
    const std::string path = outputPath(name + ".osga");
    EXPECT_TRUE(builder->write(path, error)) << error;
    if (filesDuringBuild)
        *filesDuringBuild = filesIn(folder);
    return readBytes(path);
}

TEST_P(TilesLargerThanMemory, WriteTheArchiveOfAllGlyphsInMemory)
{
    const Dataset dataset = GetParam();
    const std::filesystem::path folder = outputPath(std::string("tiles_temporary_") + dataset.name);
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder);
    const std::string whole =
        writeArchive(dataset, GLYPHS * 2, folder, std::string("tiles_whole_") + dataset.name);
    std::size_t spilled = 0;
    const std::string streamed =
        writeArchive(dataset, 4000, folder, std::string("tiles_streamed_") + dataset.name, &spilled);
    ASSERT_GT(whole.size(), 100000u);
    EXPECT_TRUE(whole == streamed) << "the archive built 4000 glyphs at a time differs (" << streamed.size()
                                   << " bytes against " << whole.size() << ")";
    // While the builder lived, its one spill file; the partitions' files were gone after writing.
    EXPECT_EQ(spilled, 1u);
    // With the box declared, the glyphs are sorted into octree nodes as they come: the same archive.
    const std::string bounded = writeArchive(
        dataset, 4000, folder, std::string("tiles_bounded_") + dataset.name, &spilled, boxOf(dataset));
    EXPECT_TRUE(whole == bounded) << "the archive of a builder given its bounds differs (" << bounded.size()
                                  << " bytes against " << whole.size() << ")";
    EXPECT_EQ(spilled, 1u);
    EXPECT_EQ(filesIn(folder), 0u) << "temporary files left in " << folder;
}

INSTANTIATE_TEST_SUITE_P(Datasets, TilesLargerThanMemory,
                         ::testing::Values(Dataset{osgGlyphs::GlyphShape::Sphere, false, "spheres"},
                                           Dataset{osgGlyphs::GlyphShape::Arrow, false, "arrows"},
                                           Dataset{osgGlyphs::GlyphShape::Sphere, true, "rgba"},
                                           Dataset{osgGlyphs::GlyphShape::Superquadric, false,
                                                   "superquadrics"},
                                           Dataset{osgGlyphs::GlyphShape::Cone, false, "clustered", true}),
                         [](const ::testing::TestParamInfo<Dataset>& instance)
                         { return std::string(instance.param.name); });

TEST(TilesLargerThanMemory, GlyphsOutsideTheDeclaredBoundsAreRefused)
{
    osg::ref_ptr<GlyphCloud> cloud = randomBatch(osgGlyphs::GlyphShape::Sphere, false, 1);
    osg::ref_ptr<osgGlyphsTiles::TileBuilder> builder = new osgGlyphsTiles::TileBuilder(*cloud);
    EXPECT_FALSE(builder->setBounds(osg::BoundingBoxd()));
    ASSERT_TRUE(builder->setBounds(osg::BoundingBoxd(0.0, 0.0, 0.0, 1.0, 1.0, 0.5)));
    std::string error;
    EXPECT_FALSE(builder->addGlyphs(*cloud, error));
    EXPECT_NE(error.find("lies outside the bounds given to the tile builder"), std::string::npos) << error;
    EXPECT_EQ(builder->getNumGlyphs(), 0u);
    ASSERT_TRUE(builder->setBounds(osg::BoundingBoxd(0.0, 0.0, 0.0, 1.0, 1.0, 1.0)));
    EXPECT_TRUE(builder->addGlyphs(*cloud, error)) << error;
    EXPECT_FALSE(builder->setBounds(osg::BoundingBoxd(0.0, 0.0, 0.0, 2.0, 2.0, 2.0)))
        << "bounds declared after glyphs were added";
}

TEST(TilesLargerThanMemory, AnUnwritableTemporaryFolderIsOneClearError)
{
    osgGlyphsTiles::TileOptions options;
    options.maxGlyphsInMemory = 1000;
    options.temporaryDirectory = "/nonexistent/osgglyphs-temporary";
    osg::ref_ptr<GlyphCloud> cloud = randomBatch(osgGlyphs::GlyphShape::Sphere, false, 1);
    osg::ref_ptr<osgGlyphsTiles::TileBuilder> builder = new osgGlyphsTiles::TileBuilder(*cloud, options);
    std::string error;
    EXPECT_FALSE(builder->addGlyphs(*cloud, error));
    EXPECT_NE(error.find("/nonexistent/osgglyphs-temporary/"), std::string::npos) << error;
    EXPECT_NE(error.find("cannot create a temporary file"), std::string::npos) << error;
}

}

namespace
{

/** Every GlyphCloud under a node. */
class CloudCollector : public osg::NodeVisitor
{
public:
    CloudCollector() : osg::NodeVisitor(TRAVERSE_ALL_CHILDREN) {}
    void apply(osg::Drawable& drawable) override
    {
        if (GlyphCloud* cloud = dynamic_cast<GlyphCloud*>(&drawable))
            clouds.push_back(cloud);
    }
    std::vector<GlyphCloud*> clouds;
};

}

// A converter's clouds only carry glyphs to the builder: made without culling, they skip the sort
// into chunks, and the tiles still cull as the TileBuilder documents.
TEST(TileStyle, TilesCullByOcclusionWhateverTheirStyleCloud)
{
    osgGlyphsData::RandomCloudOptions random;
    random.count = 20000;
    random.culling = osgGlyphs::GlyphCulling::Off;
    osg::ref_ptr<GlyphCloud> carrier = osgGlyphsData::createRandomCloud(random);
    EXPECT_EQ(carrier->getCullingChunks(), nullptr);
    osgGlyphsTiles::TileOptions options;
    options.maxGlyphsPerTile = 3000;
    osg::ref_ptr<osgGlyphsTiles::TileBuilder> builder = new osgGlyphsTiles::TileBuilder(*carrier, options);
    std::string error;
    ASSERT_TRUE(builder->addGlyphs(*carrier, error)) << error;
    const osg::ref_ptr<osg::Node> tree = builder->createTree();
    CloudCollector collector;
    tree->accept(collector);
    ASSERT_GT(collector.clouds.size(), 8u);
    unsigned int glyphsInLeaves = 0;
    for (GlyphCloud* tile : collector.clouds)
    {
        EXPECT_EQ(tile->getCulling(), osgGlyphs::GlyphCulling::Occlusion);
        EXPECT_NE(tile->getCullingChunks(), nullptr);
        if (!tile->getNumParents() || !dynamic_cast<osg::PagedLOD*>(tile->getParent(0)))
            glyphsInLeaves += tile->getNumGlyphs();
    }
    EXPECT_EQ(glyphsInLeaves, random.count);
}
