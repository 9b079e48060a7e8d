// Paged glyph tiles (osgGlyphsTiles): a converted dataset paged in to its finest level renders
// exactly as one flat GlyphCloud of the same glyphs; a coarse level, from the distance where it
// is shown, keeps the coverage and the mean colour of the full render; paging never leaves holes.

#include "RenderHarness.h"

#include <osgGlyphsData/RandomCloud>
#include <osgGlyphsTiles/TileBudget>
#include <osgGlyphsTiles/TileBuilder>
#include <osgGlyphsTiles/TileChecksum>
#include <osgGlyphsTiles/TileRoot>

#include <osg/PagedLOD>
#include <osgDB/DatabasePager>
#include <osgDB/ReadFile>
#include <osgDB/Registry>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <set>
#include <string>
#include <tuple>
#include <vector>

using namespace osgGlyphsTest;
using osgGlyphs::GlyphCloud;

namespace
{

const int SIZE = 320;
const osg::Vec3d CENTRE(0.5, 0.5, 0.5);

osg::ref_ptr<GlyphCloud> randomCloud(unsigned int count, float radius, osgGlyphs::GlyphShape shape)
{
    osgGlyphsData::RandomCloudOptions options;
    options.count = count;
    options.radius = radius;
    options.shape = shape;
    return osgGlyphsData::createRandomCloud(options);
}

osgGlyphsTiles::TileOptions smallTiles()
{
    osgGlyphsTiles::TileOptions options;
    options.maxGlyphsPerTile = 1500;
    options.cellsPerAxis = 8;
    return options;
}

int countCovered(const Frame& frame)
{
    int covered = 0;
    for (int y = 0; y < SIZE; ++y)
        for (int x = 0; x < SIZE; ++x)
            covered += frame.isCovered(x, y);
    return covered;
}

osg::Vec3d meanCoveredColor(const Frame& frame)
{
    osg::Vec3d sum;
    int covered = 0;
    for (int y = 0; y < SIZE; ++y)
        for (int x = 0; x < SIZE; ++x)
            if (frame.isCovered(x, y))
            {
                const osg::Vec4ub c = frame.colorAt(x, y);
                sum += osg::Vec3d(c.r(), c.g(), c.b());
                ++covered;
            }
    return covered ? sum / covered : sum;
}

std::string archivePath(const std::string& name)
{
    return outputPath(name + ".osga");
}

/** Writes the tiles of the cloud into an archive and reads its root back. */
osg::ref_ptr<osg::Node> convert(const GlyphCloud& cloud, const std::string& name,
                                const osgGlyphsTiles::TileOptions& options = smallTiles())
{
    osg::ref_ptr<osgGlyphsTiles::TileBuilder> builder = new osgGlyphsTiles::TileBuilder(cloud, options);
    std::string error;
    EXPECT_TRUE(builder->addGlyphs(cloud, error)) << error;
    EXPECT_TRUE(builder->write(archivePath(name), error)) << error;
    return osgDB::readNodeFile(archivePath(name));
}

class PagedTiles : public ::testing::TestWithParam<osgGlyphs::GlyphShape>
{
};

namespace
{

/** The flat cloud and its tiles paged in to the finest level, from the same view. */
void renderFlatAndFinest(const GlyphCloud& cloud, const std::string& name,
                         const osgGlyphsTiles::TileOptions& options, Frame& flat, Frame& paged)
{
    osg::ref_ptr<osg::Node> root = convert(cloud, name, options);
    ASSERT_TRUE(root.valid());
    const osgGlyphsTiles::TileRoot* tileRoot = dynamic_cast<osgGlyphsTiles::TileRoot*>(root.get());
    ASSERT_NE(tileRoot, nullptr) << "the archive's root";
    ASSERT_EQ(tileRoot->getNumChildren(), 1u);
    ASSERT_NE(dynamic_cast<const osg::PagedLOD*>(tileRoot->getChild(0)), nullptr)
        << "20,000 glyphs make more than one tile";
    Renderer flatRenderer(SIZE, SIZE), pagedRenderer(SIZE, SIZE);
    for (Renderer* renderer : {&flatRenderer, &pagedRenderer})
    {
        renderer->setPerspective(30.0, 0.1, 10.0);
        renderer->setLookAt(osg::Vec3d(1.9, -1.2, 1.4), CENTRE, osg::Vec3d(0.0, 0.0, 1.0));
    }
    flat = flatRenderer.render(const_cast<GlyphCloud*>(&cloud));
    int frames = 0;
    paged = renderPaged(pagedRenderer, root.get(), frames);
    saveFrame(flat, name + "_flat");
    saveFrame(paged, name + "_paged");
    EXPECT_GT(frames, 2) << "the tiles were not paged in";
    ASSERT_GT(countCovered(flat), SIZE * SIZE / 4);
}

}

// With float positions, the finest level holds every glyph exactly as given.
TEST_P(PagedTiles, FinestLevelRendersExactlyAsTheFlatCloud)
{
    const std::string name = std::string("tiles_finest_") + osgGlyphs::getShapeName(GetParam());
    osg::ref_ptr<GlyphCloud> cloud = randomCloud(20000, 0.008f, GetParam());
    osgGlyphsTiles::TileOptions options = smallTiles();
    options.compressedPositions = false;
    Frame flat, paged;
    renderFlatAndFinest(*cloud, name, options, flat, paged);
    EXPECT_EQ(countDifferingPixels(paged, flat), 0) << "pixels that differ in colour or depth";
}

// With 16-bit positions (the default), each glyph moves by at most half a grid step (1/131,064 of
// its tile): a hundredth of a pixel here. Depths may differ in their last bits, and a few pixels
// flip: at silhouettes, and where two glyphs that cut each other swap which is in front.
TEST_P(PagedTiles, FinestLevelOfCompressedTilesIsTheFlatCloudWithinTheirGrid)
{
    const std::string name = std::string("tiles_finest16_") + osgGlyphs::getShapeName(GetParam());
    osg::ref_ptr<GlyphCloud> cloud = randomCloud(20000, 0.008f, GetParam());
    Frame flat, paged;
    renderFlatAndFinest(*cloud, name, smallTiles(), flat, paged);
    int covered = 0, coverageFlips = 0, colorDiffering = 0, depthDiffering = 0;
    for (int y = 0; y < SIZE; ++y)
        for (int x = 0; x < SIZE; ++x)
        {
            covered += flat.isCovered(x, y);
            if (flat.isCovered(x, y) != paged.isCovered(x, y))
                ++coverageFlips;
            else if (flat.isCovered(x, y))
            {
                colorDiffering += !colorNear(flat, x, y, paged.colorAt(x, y), 2);
                depthDiffering += std::abs(double(flat.depthAt(x, y)) - paged.depthAt(x, y)) > 1e-6;
            }
        }
    std::cout << name << ": " << covered << " covered pixels, " << coverageFlips << " flipped, "
              << colorDiffering << " of another colour, " << depthDiffering
              << " of another depth (beyond 1e-6)" << std::endl;
    EXPECT_LE(coverageFlips, covered / 2000);
    EXPECT_LE(colorDiffering, covered / 1000);
    EXPECT_LE(depthDiffering, covered / 1000);
}

// 16-bit positions, and scalars stored as the 16-bit steps the GPU draws: at most 12 bytes a glyph
// in the archive, every level and the archive's index included.
TEST(TileArchives, TakeAtMostTwelveBytesAGlyph)
{
    osg::ref_ptr<GlyphCloud> cloud = randomCloud(200000, 0.002f, osgGlyphs::GlyphShape::Sphere);
    ASSERT_EQ(cloud->getColorMode(), osgGlyphs::GlyphColorMode::Scalar);
    osg::ref_ptr<osgGlyphsTiles::TileBuilder> builder = new osgGlyphsTiles::TileBuilder(*cloud);
    std::string error;
    ASSERT_TRUE(builder->addGlyphs(*cloud, error)) << error;
    ASSERT_TRUE(builder->write(archivePath("tiles_bytes"), error)) << error;
    const double bytesPerGlyph = double(std::filesystem::file_size(archivePath("tiles_bytes"))) / 200000.0;
    std::cout << "tile archive: " << bytesPerGlyph << " bytes per glyph" << std::endl;
    EXPECT_LE(bytesPerGlyph, 12.0);
    EXPECT_GE(bytesPerGlyph, 8.0) << "each glyph holds 6 bytes of position and 2 of scalar";
}

TEST_P(PagedTiles, PagingNeverLeavesHoles)
{
    const std::string name = std::string("tiles_paging_") + osgGlyphs::getShapeName(GetParam());
    // Dense: spheres of 0.4 times the mean spacing, which cover the view.
    osg::ref_ptr<GlyphCloud> cloud = randomCloud(20000, 0.4f * std::cbrt(1.0f / 20000.0f), GetParam());
    osg::ref_ptr<osg::Node> root = convert(*cloud, name);
    ASSERT_TRUE(root.valid());
    Renderer renderer(SIZE, SIZE);
    renderer.setPerspective(30.0, 0.1, 10.0);
    renderer.setLookAt(osg::Vec3d(1.9, -1.2, 1.4), CENTRE, osg::Vec3d(0.0, 0.0, 1.0));
    std::vector<Frame> during;
    int frames = 0;
    const Frame settled = renderPaged(renderer, root.get(), frames, &during);
    ASSERT_GE(during.size(), 3u) << "nothing was paged in";
    saveFrame(during.front(), name + "_first");
    saveFrame(settled, name + "_settled");
    // A hole: a block of 16x16 pixels (smaller than any tile here) that the settled frame
    // covers (almost) wholly, and that a frame during paging leaves wholly uncovered.
    const int BLOCK = 16;
    int holes = 0, blocks = 0;
    for (int by = 0; by + BLOCK <= SIZE; by += BLOCK)
        for (int bx = 0; bx + BLOCK <= SIZE; bx += BLOCK)
        {
            int settledCovered = 0;
            for (int y = by; y < by + BLOCK; ++y)
                for (int x = bx; x < bx + BLOCK; ++x)
                    settledCovered += settled.isCovered(x, y);
            if (settledCovered < BLOCK * BLOCK * 9 / 10)
                continue;
            ++blocks;
            for (const Frame& frame : during)
            {
                int covered = 0;
                for (int y = by; y < by + BLOCK; ++y)
                    for (int x = bx; x < bx + BLOCK; ++x)
                        covered += frame.isCovered(x, y);
                holes += covered == 0;
            }
        }
    ASSERT_GT(blocks, 60);
    EXPECT_EQ(holes, 0) << "of " << blocks << " covered blocks, over " << during.size() << " frames";
}

/** The glyphs of every tile loaded under node. */
class LoadedGlyphs : public osg::NodeVisitor
{
public:
    LoadedGlyphs() : osg::NodeVisitor(TRAVERSE_ALL_CHILDREN) {}
    void apply(osg::Drawable& drawable) override
    {
        if (const GlyphCloud* cloud = dynamic_cast<const GlyphCloud*>(&drawable))
            glyphs += cloud->getNumGlyphs();
    }
    std::size_t glyphs = 0;
};

/** The PagedLODs of a graph, and how many of them read through a given read callback. */
class PagedLODs : public osg::NodeVisitor
{
public:
    explicit PagedLODs(const osgDB::ReadFileCallback* callback)
        : osg::NodeVisitor(TRAVERSE_ALL_CHILDREN), _callback(callback)
    {
    }
    void apply(osg::PagedLOD& lod) override
    {
        ++count;
        const osgDB::Options* options = dynamic_cast<const osgDB::Options*>(lod.getDatabaseOptions());
        checked += options && options->getReadFileCallback() == _callback;
        loaded += lod.getNumChildren() > 1;
        traverse(lod);
    }
    int count = 0, checked = 0, loaded = 0;

private:
    const osgDB::ReadFileCallback* _callback;
};

const osgGlyphsTiles::TileRoot* tileRootOf(const osg::Node* node)
{
    return dynamic_cast<const osgGlyphsTiles::TileRoot*>(node);
}

/** Renders the archive's root, read as stock osgviewer reads it: nothing but osgDB::readNodeFile. */
Frame renderAsStockViewer(osg::Node* root)
{
    Renderer renderer(SIZE, SIZE);
    renderer.setPerspective(30.0, 0.1, 10.0);
    renderer.setLookAt(osg::Vec3d(1.9, -1.2, 1.4), CENTRE, osg::Vec3d(0.0, 0.0, 1.0));
    int frames = 0;
    return renderPaged(renderer, root, frames);
}

// The budget is stored in the archive's root, so any viewer keeps it.
TEST(TileBudget, KeepsTheGlyphsDrawnWithinItAndPagesLess)
{
    osg::ref_ptr<GlyphCloud> cloud = randomCloud(20000, 0.008f, osgGlyphs::GlyphShape::Sphere);
    auto render = [&](std::size_t budget)
    {
        osgGlyphsTiles::TileOptions options = smallTiles();
        options.glyphBudget = budget;
        osg::ref_ptr<osg::Node> root = convert(*cloud, "tiles_budget_" + std::to_string(budget), options);
        EXPECT_TRUE(tileRootOf(root.get()) && tileRootOf(root.get())->getGlyphBudget() == budget);
        const Frame frame = renderAsStockViewer(root.get());
        saveFrame(frame, "tiles_budget_" + std::to_string(budget));
        LoadedGlyphs loaded;
        root->accept(loaded);
        return std::make_tuple(frame, loaded.glyphs, root);
    };
    const auto unlimited = render(0);
    const auto limited = render(6000);
    const osgGlyphsTiles::TileBudget* budget = tileRootOf(std::get<2>(limited).get())->getBudget();
    EXPECT_LE(budget->getLastGlyphs(), 6000u);
    EXPECT_GT(budget->getLastGlyphs(), 2000u) << "the budget refines what it can";
    EXPECT_GT(budget->getLastScale(), 1.0);
    EXPECT_LT(std::get<1>(limited), std::get<1>(unlimited) / 2) << "glyphs loaded";
    // Fewer, larger glyphs cover about as much.
    const double coverage = double(countCovered(std::get<0>(limited))) / countCovered(std::get<0>(unlimited));
    EXPECT_NEAR(coverage, 1.0, 0.15);

    // Options replace the stored budget, as `osgviewer data.osga -O glyphBudget=3000` does.
    osg::ref_ptr<osgDB::Options> options = new osgDB::Options("glyphBudget=3000");
    osg::ref_ptr<osg::Node> asked = osgDB::readNodeFile(archivePath("tiles_budget_6000"), options.get());
    ASSERT_TRUE(tileRootOf(asked.get()));
    EXPECT_EQ(tileRootOf(asked.get())->getGlyphBudget(), 3000u);
    options->setOptionString("glyphBudget=-3");
    asked = osgDB::readNodeFile(archivePath("tiles_budget_6000"), options.get());
    ASSERT_TRUE(tileRootOf(asked.get()));
    EXPECT_EQ(tileRootOf(asked.get())->getGlyphBudget(), 6000u) << "a wrong option keeps the archive's";
}

// Read as stock osgviewer reads it, an archive checks its own tiles: the root's TileRoot gives
// its checking read callback to every PagedLOD, tile by tile as they are paged in.
TEST(CorruptTiles, AreRefusedWithOneErrorAndTheRestDraws)
{
    osg::ref_ptr<GlyphCloud> cloud =
        randomCloud(20000, 0.4f * std::cbrt(1.0f / 20000.0f), osgGlyphs::GlyphShape::Sphere);
    osg::ref_ptr<osg::Node> intact = convert(*cloud, "tiles_intact");
    ASSERT_TRUE(tileRootOf(intact.get()));
    // The same archive with bytes in its middle overwritten: inside a tile's glyphs.
    const std::string corruptPath = archivePath("tiles_corrupt");
    {
        std::ifstream in(archivePath("tiles_intact"), std::ios::binary);
        std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        ASSERT_GT(bytes.size(), 100000u);
        std::fill(bytes.begin() + bytes.size() / 2, bytes.begin() + bytes.size() / 2 + 256, '\xab');
        std::ofstream(corruptPath, std::ios::binary) << bytes;
    }
    osg::ref_ptr<osg::Node> corrupt = osgDB::readNodeFile(corruptPath);
    ASSERT_TRUE(tileRootOf(corrupt.get())) << "the root is intact";
    std::string error;
    EXPECT_TRUE(osgGlyphsTiles::checkTileChecksum(*corrupt, error)) << error;

    const Frame intactFrame = renderAsStockViewer(intact.get());
    const osgGlyphsTiles::TileCheckingReadCallback* intactChecking =
        tileRootOf(intact.get())->getTileChecking();
    EXPECT_TRUE(intactChecking->getRefusedTiles().empty()) << "an intact archive is refused";
    PagedLODs lods(intactChecking);
    intact->accept(lods);
    EXPECT_GT(lods.loaded, 8) << "tiles paged in, several levels deep";
    EXPECT_EQ(lods.checked, lods.count) << "PagedLODs that read without the checks";

    const Frame corruptFrame = renderAsStockViewer(corrupt.get());
    saveFrame(corruptFrame, "tiles_corrupt");
    const std::set<std::string> refused = tileRootOf(corrupt.get())->getTileChecking()->getRefusedTiles();
    ASSERT_EQ(refused.size(), 1u) << "tiles refused";
    EXPECT_NE(refused.begin()->find("tiles_corrupt.osga/"), std::string::npos) << *refused.begin();
    // The refused tile's parent stands in for it: the picture covers what the intact one does.
    const double coverage = double(countCovered(corruptFrame)) / countCovered(intactFrame);
    EXPECT_NEAR(coverage, 1.0, 0.05);
}

INSTANTIATE_TEST_SUITE_P(Shapes, PagedTiles,
                         ::testing::Values(osgGlyphs::GlyphShape::Sphere, osgGlyphs::GlyphShape::Cone,
                                           osgGlyphs::GlyphShape::Ellipsoid,
                                           osgGlyphs::GlyphShape::Superquadric),
                         [](const ::testing::TestParamInfo<osgGlyphs::GlyphShape>& shape)
                         { return std::string(osgGlyphs::getShapeName(shape.param)); });

const unsigned int COARSE_TEST_GLYPHS = 100000;

/** The root tile's representatives against every glyph, seen from where the root gives way to
 * its children (its bounding sphere spans refineAt pixels): coverage and mean colour agree. */
void expectCoarseLevelLooksLikeTheFineOne(float radius, const std::string& name, double coverageTolerance,
                                          double colorTolerance,
                                          osgGlyphs::GlyphShape shape = osgGlyphs::GlyphShape::Sphere)
{
    osg::ref_ptr<GlyphCloud> cloud = randomCloud(COARSE_TEST_GLYPHS, radius, shape);
    osgGlyphsTiles::TileOptions options;
    options.maxGlyphsPerTile = 4096;
    osg::ref_ptr<osgGlyphsTiles::TileBuilder> builder = new osgGlyphsTiles::TileBuilder(*cloud, options);
    std::string error;
    ASSERT_TRUE(builder->addGlyphs(*cloud, error)) << error;
    osg::ref_ptr<osg::Group> tree = builder->createTree()->asGroup();
    ASSERT_TRUE(tree.valid() && tree->getNumChildren() == 1);
    osg::ref_ptr<osg::PagedLOD> root = dynamic_cast<osg::PagedLOD*>(tree->getChild(0));
    ASSERT_TRUE(root.valid());
    osg::ref_ptr<GlyphCloud> coarse = dynamic_cast<GlyphCloud*>(root->getChild(0));
    ASSERT_TRUE(coarse.valid());
    ASSERT_LT(coarse->getNumGlyphs(), cloud->getNumGlyphs() / 2);

    // The distance at which the bounding sphere spans refineAt pixels across SIZE pixels at 30 degrees.
    const double refineAt = root->getRangeList()[0].second;
    const double focal = 0.5 * SIZE / std::tan(osg::DegreesToRadians(15.0));
    const double distance = 2.0 * root->getRadius() * focal / refineAt;
    Renderer renderer(SIZE, SIZE);
    renderer.setPerspective(30.0, 0.01, 100.0);
    renderer.setLookAt(CENTRE + osg::Vec3d(0.8, -0.5, 0.4) * (distance / 1.0247), CENTRE,
                       osg::Vec3d(0, 0, 1));
    const Frame fine = renderer.render(cloud.get());
    const Frame coarseFrame = renderer.render(coarse.get());
    saveFrame(fine, name + "_fine");
    saveFrame(coarseFrame, name + "_coarse");
    const int fineCovered = countCovered(fine), coarseCovered = countCovered(coarseFrame);
    ASSERT_GT(fineCovered, 400);
    const double coverage = double(coarseCovered) / fineCovered - 1.0;
    const osg::Vec3d colorDifference = meanCoveredColor(coarseFrame) - meanCoveredColor(fine);
    ::testing::Test::RecordProperty("coverage_change", std::to_string(coverage));
    std::cerr << name << ": " << coarse->getNumGlyphs() << " of " << cloud->getNumGlyphs()
              << " glyphs, coverage " << coarseCovered << " vs " << fineCovered << " (" << coverage * 100
              << "%), mean colour difference " << colorDifference.x() << " " << colorDifference.y() << " "
              << colorDifference.z() << std::endl;
    EXPECT_LE(std::abs(coverage), coverageTolerance);
    for (int channel = 0; channel < 3; ++channel)
        EXPECT_LE(std::abs(colorDifference[channel]), colorTolerance) << "channel " << channel;
}

TEST(CoarseTiles, DenseDataKeepsCoverageAndMeanColour)
{
    expectCoarseLevelLooksLikeTheFineOne(0.4f * std::cbrt(1.0f / COARSE_TEST_GLYPHS), "tiles_coarse_dense",
                                         0.05, 6.0);
}

TEST(CoarseTiles, SparseDataKeepsCoverageAndMeanColour)
{
    expectCoarseLevelLooksLikeTheFineOne(osgGlyphsData::getDefaultRandomRadius(COARSE_TEST_GLYPHS),
                                         "tiles_coarse_sparse", 0.05, 6.0);
}

// Random ellipsoids (semi-axes of 1 and 0.25 to 1 of their radius, turned at random) and
// superquadrics (exponents 0.1 to 1 as well): each representative keeps its glyph's shape and turn,
// grown to the coverage of its cell.
TEST(CoarseTiles, DenseEllipsoidsKeepCoverageAndMeanColour)
{
    expectCoarseLevelLooksLikeTheFineOne(0.4f * std::cbrt(1.0f / COARSE_TEST_GLYPHS),
                                         "tiles_coarse_ellipsoids", 0.05, 6.0,
                                         osgGlyphs::GlyphShape::Ellipsoid);
}

TEST(CoarseTiles, SparseSuperquadricsKeepCoverageAndMeanColour)
{
    expectCoarseLevelLooksLikeTheFineOne(osgGlyphsData::getDefaultRandomRadius(COARSE_TEST_GLYPHS),
                                         "tiles_coarse_superquadrics", 0.05, 6.0,
                                         osgGlyphs::GlyphShape::Superquadric);
}

} // namespace

// A builder refuses an ellipsoid it could not draw in one message naming the glyph.
TEST(TileArchives, RefuseEllipsoidsWithoutASizeOrATurn)
{
    osg::ref_ptr<GlyphCloud> cloud = randomCloud(100, 0.01f, osgGlyphs::GlyphShape::Ellipsoid);
    osg::ref_ptr<osgGlyphsTiles::TileBuilder> builder = new osgGlyphsTiles::TileBuilder(*cloud);
    std::string error;
    osg::ref_ptr<osg::Vec3Array> semiAxes = new osg::Vec3Array(*cloud->getSemiAxes());
    (*semiAxes)[7].y() = 0.0f;
    cloud->setSemiAxes(semiAxes.get());
    EXPECT_FALSE(builder->addGlyphs(*cloud, error));
    EXPECT_EQ(error, "glyph 7 has semi-axes or exponents that are not finite and > 0");
    (*semiAxes)[7].y() = 0.01f;
    osg::ref_ptr<osg::Vec4Array> orientations = new osg::Vec4Array;
    orientations->assign(100, osg::Vec4(0.0f, 0.0f, 0.0f, 1.0f));
    (*orientations)[42] = osg::Vec4(NAN, 0.0f, 0.0f, 1.0f);
    cloud->setOrientations(orientations.get());
    EXPECT_FALSE(builder->addGlyphs(*cloud, error));
    EXPECT_EQ(error, "glyph 42 has a turn (quaternion) that is zero or not finite");
    cloud->setOrientations(new osg::Vec4Array(99));
    EXPECT_FALSE(builder->addGlyphs(*cloud, error));
    EXPECT_EQ(error, "the glyphs' arrays are shorter than their positions");
    EXPECT_EQ(builder->getNumGlyphs(), 0u);
}
