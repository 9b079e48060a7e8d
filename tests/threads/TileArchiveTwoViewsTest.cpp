// A tile archive, read as any OSG application reads it, shared by the two views of an
// osgViewer::CompositeViewer with a cull thread per camera and a draw thread per context: both
// views page tiles in through one DatabasePager while their TileRoot applies the glyph budget in
// each cull and its read callback checks every tile. Once paged in, every frame of each view must
// equal that view rendered alone, single-threaded, to the bit.

#include "RenderHarness.h"

#include <osgGlyphsData/RandomCloud>
#include <osgGlyphsHeadless/FrameCapture>
#include <osgGlyphsHeadless/HeadlessContext>
#include <osgGlyphsTiles/TileBuilder>
#include <osgGlyphsTiles/TileRoot>
#include <osgGlyphsTiles/TileSeriesPlayer>

#include <osg/PagedLOD>
#include <osgDB/DatabasePager>
#include <osgDB/ReadFile>
#include <osgViewer/CompositeViewer>

#include <OpenThreads/Thread>

#include <atomic>
#include <chrono>
#include <functional>
#include <thread>

using namespace osgGlyphsTest;

namespace
{

struct TileView
{
    const char* name;
    int width;
    int height;
    osg::Vec3d eye;
};

const TileView VIEWS[] = {
    {"large", 400, 300, osg::Vec3d(1.9, -1.2, 1.4)},
    {"small", 200, 200, osg::Vec3d(-0.9, 2.1, 1.2)},
};
const osg::Vec3d CENTRE(0.5, 0.5, 0.5);
/** The frames checked once every tile is in. */
const unsigned int CHECKED_FRAMES = 40;
/** Below what the large view would draw: the budget chooses its levels. */
const std::size_t GLYPH_BUDGET = 16000;

void setUpCamera(osg::Camera& camera, const TileView& view)
{
    camera.setViewport(0, 0, view.width, view.height);
    camera.setProjectionMatrixAsPerspective(30.0, double(view.width) / view.height, 0.1, 10.0);
    camera.setViewMatrixAsLookAt(view.eye, CENTRE, osg::Vec3d(0.0, 0.0, 1.0));
    camera.setComputeNearFarMode(osg::CullSettings::DO_NOT_COMPUTE_NEAR_FAR);
    camera.setClearColor(osg::Vec4(0.0f, 0.0f, 0.0f, 1.0f));
}

/** 20,000 spheres in 1,500-glyph tiles, written into an archive; its path. */
std::string writeArchive(const std::string& name = "tile_archive_two_views", unsigned int seed = 1)
{
    osgGlyphsData::RandomCloudOptions random;
    random.count = 20000;
    random.radius = 0.008f;
    random.seed = seed;
    osg::ref_ptr<osgGlyphs::GlyphCloud> cloud = osgGlyphsData::createRandomCloud(random);
    osgGlyphsTiles::TileOptions options;
    options.maxGlyphsPerTile = 1500;
    options.cellsPerAxis = 8;
    options.glyphBudget = GLYPH_BUDGET;
    osg::ref_ptr<osgGlyphsTiles::TileBuilder> builder = new osgGlyphsTiles::TileBuilder(*cloud, options);
    std::string error;
    const std::string path = outputPath(name + ".osga");
    EXPECT_TRUE(builder->addGlyphs(*cloud, error)) << error;
    EXPECT_TRUE(builder->write(path, error)) << error;
    return path;
}

/** Compares the frames a draw thread reads back, from a frame number on, with one expected frame. */
class SettledCapture : public osgGlyphsHeadless::FrameCapture
{
public:
    explicit SettledCapture(const Frame& expected) : _expected(expected) {}

    void checkFrom(unsigned int frameNumber) { _from.store(frameNumber, std::memory_order_release); }

    void operator()(osg::RenderInfo& renderInfo) const override
    {
        FrameCapture::operator()(renderInfo);
        const osg::FrameStamp* stamp = renderInfo.getState()->getFrameStamp();
        if (!stamp || stamp->getFrameNumber() < _from.load(std::memory_order_acquire))
            return;
        const osg::Image& color = *getColorImage();
        const float* depth = reinterpret_cast<const float*>(getDepthImage()->data());
        int differing = color.s() * color.t() == _expected.width() * _expected.height() ? 0 : 1;
        for (int i = 0; !differing && i < color.s() * color.t(); ++i)
            differing = !std::equal(color.data() + 4 * i, color.data() + 4 * i + 4,
                                    _expected.color->data() + 4 * i) ||
                        depth[i] != reinterpret_cast<const float*>(_expected.depth->data())[i];
        _differing.fetch_add(differing, std::memory_order_relaxed);
        _checked.fetch_add(1, std::memory_order_release);
    }

    unsigned int getChecked() const { return _checked.load(std::memory_order_acquire); }
    unsigned int getDiffering() const { return _differing.load(std::memory_order_relaxed); }

private:
    const Frame _expected;
    std::atomic<unsigned int> _from{~0u};
    mutable std::atomic<unsigned int> _checked{0}, _differing{0};
};

/** The PagedLODs whose children are loaded. */
class LoadedTiles : public osg::NodeVisitor
{
public:
    LoadedTiles() : osg::NodeVisitor(TRAVERSE_ALL_CHILDREN) {}
    void apply(osg::PagedLOD& lod) override
    {
        tiles += lod.getNumChildren() > 1;
        traverse(lod);
    }
    int tiles = 0;
};

bool pagerIsIdle(osgDB::DatabasePager& pager)
{
    return !pager.getRequestsInProgress() && pager.getFileRequestListSize() == 0 &&
           pager.getDataToMergeListSize() == 0;
}

/** Shows scene in the two views of a CompositeViewer (a cull thread per camera, a draw thread per
 * context), renders until ready() and neither view pages anything in, then checks that
 * CHECKED_FRAMES more frames of each view equal its reference. */
void expectEverySettledFrameIsTheReference(osg::Node* scene, const std::vector<Frame>& references,
                                           const std::function<bool()>& ready)
{
    osg::ref_ptr<osgViewer::CompositeViewer> viewer = new osgViewer::CompositeViewer;
    viewer->setThreadingModel(osgViewer::ViewerBase::CullThreadPerCameraDrawThreadPerContext);
    std::vector<osg::ref_ptr<SettledCapture>> captures;
    std::vector<osg::ref_ptr<osgViewer::View>> views;
    for (std::size_t v = 0; v < references.size(); ++v)
    {
        osg::ref_ptr<osgGlyphsHeadless::HeadlessContext> context =
            osgGlyphsHeadless::HeadlessContext::create(VIEWS[v].width, VIEWS[v].height);
        ASSERT_TRUE(context.valid());
        osg::ref_ptr<osgViewer::View> view = new osgViewer::View;
        osg::Camera* camera = view->getCamera();
        camera->setGraphicsContext(context.get());
        setUpCamera(*camera, VIEWS[v]);
        camera->setDrawBuffer(GL_FRONT);
        camera->setReadBuffer(GL_FRONT);
        captures.push_back(new SettledCapture(references[v]));
        camera->setFinalDrawCallback(captures.back().get());
        view->setSceneData(scene);
        viewer->addView(view.get());
        views.push_back(view);
    }
    // Page in until neither view asks for more, then check the frames after.
    unsigned int frame = 0;
    for (int idleFrames = 0; idleFrames < 3 && frame < 2000; ++frame)
    {
        viewer->frame();
        bool idle = true;
        for (const osg::ref_ptr<osgViewer::View>& view : views)
            idle = idle && pagerIsIdle(*view->getDatabasePager());
        idle = idle && ready();
        idleFrames = idle ? idleFrames + 1 : 0;
        if (!idle)
            OpenThreads::Thread::microSleep(2000);
    }
    ASSERT_LT(frame, 2000u) << "the pager never settled";
    for (const osg::ref_ptr<SettledCapture>& capture : captures)
        capture->checkFrom(frame + 1);
    for (unsigned int last = frame + 1 + CHECKED_FRAMES; frame < last; ++frame)
        viewer->frame();
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
    for (const osg::ref_ptr<SettledCapture>& capture : captures)
        while (capture->getChecked() < CHECKED_FRAMES && std::chrono::steady_clock::now() < deadline)
            std::this_thread::sleep_for(std::chrono::milliseconds(1));
    viewer->stopThreading();

    for (std::size_t v = 0; v < captures.size(); ++v)
    {
        EXPECT_GE(captures[v]->getChecked(), CHECKED_FRAMES) << VIEWS[v].name << ": frames not drawn";
        EXPECT_EQ(captures[v]->getDiffering(), 0u)
            << VIEWS[v].name << ": frames that differ from the view rendered alone, of "
            << captures[v]->getChecked();
    }
}

}

TEST(TileArchiveTwoViews, EveryPagedInFrameOfEachViewIsItsSingleThreadedRender)
{
    const std::string path = writeArchive();
    std::vector<Frame> references;
    for (const TileView& view : VIEWS)
    {
        osg::ref_ptr<osg::Node> root = osgDB::readNodeFile(path);
        ASSERT_TRUE(dynamic_cast<osgGlyphsTiles::TileRoot*>(root.get())) << path;
        Renderer renderer(view.width, view.height);
        setUpCamera(*renderer.getViewer()->getCamera(), view);
        int frames = 0;
        references.push_back(renderPaged(renderer, root.get(), frames));
        saveFrame(references.back(), std::string("tile_archive_two_views_") + view.name);
        LoadedTiles loaded;
        root->accept(loaded);
        EXPECT_GT(loaded.tiles, 4) << view.name << ": tiles paged in";
        const double scale = dynamic_cast<osgGlyphsTiles::TileRoot*>(root.get())->getBudget()->getLastScale();
        EXPECT_GT(scale, 1.0) << view.name << ": the budget chooses the levels";
        std::cout << view.name << ": " << loaded.tiles << " tiles paged in, LOD scaled by " << scale
                  << std::endl;
    }
    const osg::ref_ptr<osgGlyphsTiles::TileRoot> root =
        dynamic_cast<osgGlyphsTiles::TileRoot*>(osgDB::readNodeFile(path));
    ASSERT_TRUE(root.valid());
    // Bounds are computed lazily: before cull threads share a scene, as a viewer's home position
    // does. Below the root's PagedLOD the clouds compute their own as they are read.
    root->getBound();

    expectEverySettledFrameIsTheReference(root.get(), references, [] { return true; });
    EXPECT_TRUE(root->getTileChecking()->getRefusedTiles().empty());
    EXPECT_LE(root->getBudget()->getLastGlyphs(), GLYPH_BUDGET);
}

// A series of tile archives playing in the same two views: the player goes to frame 2 in the update
// traversal while both cull threads page frame 2's tiles in and prefetch frame 0's (the next of
// playback, looping). Once settled, every frame of each view is frame 2 rendered alone.
TEST(TileSeriesTwoViews, EverySettledFrameOfEachViewIsItsSingleThreadedRender)
{
    osg::ref_ptr<osgGlyphsTiles::TileSeries> series = new osgGlyphsTiles::TileSeries;
    for (unsigned int frame = 0; frame < 3; ++frame)
        series->addFrame(writeArchive("tile_series_two_views_" + std::to_string(frame), 11 + frame),
                         10.0 * frame);
    std::vector<Frame> references;
    for (const TileView& view : VIEWS)
    {
        osg::ref_ptr<osgGlyphsTiles::TileSeries> alone = new osgGlyphsTiles::TileSeries(*series);
        std::string error;
        ASSERT_EQ(alone->showFrameNow(2, error), osgGlyphsTiles::TileSeries::FRAME_SHOWN) << error;
        Renderer renderer(view.width, view.height);
        setUpCamera(*renderer.getViewer()->getCamera(), view);
        int frames = 0;
        references.push_back(renderPaged(renderer, alone.get(), frames));
        saveFrame(references.back(), std::string("tile_series_two_views_") + view.name);
    }
    osg::ref_ptr<osgGlyphsTiles::TileSeriesPlayer> player =
        new osgGlyphsTiles::TileSeriesPlayer(series.get());
    series->setUpdateCallback(player.get());
    std::string error;
    ASSERT_TRUE(player->showNow(0.0, error)) << error;
    series->getBound();
    player->seek(2.0);
    expectEverySettledFrameIsTheReference(series.get(), references,
                                          [&series] { return series->getShownFrame() == 2; });
    EXPECT_EQ(series->getShownFrame(), 2u);
    EXPECT_EQ(series->getPrefetchFrame(), 0u);
    EXPECT_TRUE(series->getShownRoot()->getTileChecking()->getRefusedTiles().empty());
}
