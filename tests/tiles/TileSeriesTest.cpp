// Series of tile archives (TileSeries, TileSeriesPlayer): every frame paged in to its finest level
// renders exactly as a flat GlyphCloud of that frame; a frame change never leaves holes while the
// new frame pages in; the next frame is prefetched; a corrupt or missing frame is reported once and
// the others play; frames let go close their archives.

#include "RenderHarness.h"

#include <osgGlyphsData/RandomCloud>
#include <osgGlyphsTiles/TileBuilder>
#include <osgGlyphsTiles/TileSeries>
#include <osgGlyphsTiles/TileSeriesPlayer>

#include <osg/MatrixTransform>
#include <osgDB/Archive>
#include <osgDB/DatabasePager>
#include <osgDB/FileNameUtils>
#include <osgDB/ReadFile>
#include <osgDB/Registry>
#include <osgDB/WriteFile>
#include <osgUtil/IntersectionVisitor>
#include <osgUtil/LineSegmentIntersector>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

using namespace osgGlyphsTest;
using osgGlyphs::GlyphCloud;

namespace
{

const int SIZE = 320;

/** Frame k of a series: its own random glyphs (another seed). */
osg::ref_ptr<GlyphCloud> frameCloud(unsigned int frame, unsigned int count, float radius)
{
    osgGlyphsData::RandomCloudOptions options;
    options.count = count;
    options.radius = radius;
    options.seed = 11 + frame;
    return osgGlyphsData::createRandomCloud(options);
}

/** Frames 0 to frames - 1 of frameCloud(). */
std::vector<osg::ref_ptr<GlyphCloud>> frameClouds(unsigned int frames, unsigned int count, float radius)
{
    std::vector<osg::ref_ptr<GlyphCloud>> clouds;
    for (unsigned int frame = 0; frame < frames; ++frame)
        clouds.push_back(frameCloud(frame, count, radius));
    return clouds;
}

std::string framePath(const std::string& name, unsigned int frame)
{
    return outputPath(name + "_" + std::to_string(frame) + ".osga");
}

/** Writes frames' archives and their index (name.osgt), and reads the index back as osgDB does. */
osg::ref_ptr<osgGlyphsTiles::TileSeries> writeSeries(const std::string& name,
                                                     const std::vector<osg::ref_ptr<GlyphCloud>>& clouds,
                                                     bool compressedPositions)
{
    osgGlyphsTiles::TileOptions options;
    options.maxGlyphsPerTile = 1500;
    options.cellsPerAxis = 8;
    options.compressedPositions = compressedPositions;
    osg::ref_ptr<osgGlyphsTiles::TileSeries> series = new osgGlyphsTiles::TileSeries;
    for (unsigned int frame = 0; frame < clouds.size(); ++frame)
    {
        osg::ref_ptr<osgGlyphsTiles::TileBuilder> builder =
            new osgGlyphsTiles::TileBuilder(*clouds[frame], options);
        std::string error;
        EXPECT_TRUE(builder->addGlyphs(*clouds[frame], error)) << error;
        EXPECT_TRUE(builder->write(framePath(name, frame), error)) << error;
        // Relative to the index's folder.
        series->addFrame(std::filesystem::path(framePath(name, frame)).filename().string(),
                         1234567.0 + 100.0 * frame);
    }
    const std::string index = outputPath(name + ".osgt");
    EXPECT_TRUE(osgDB::writeNodeFile(*series, index));
    return dynamic_cast<osgGlyphsTiles::TileSeries*>(osgDB::readNodeFile(index));
}

void lookAtTheUnitCube(Renderer& renderer)
{
    renderer.setPerspective(30.0, 0.1, 10.0);
    renderer.setLookAt(osg::Vec3d(1.9, -1.2, 1.4), osg::Vec3d(0.5, 0.5, 0.5), osg::Vec3d(0.0, 0.0, 1.0));
}

bool pagerIsBusy(osgDB::DatabasePager& pager)
{
    return pager.getRequestsInProgress() || pager.getFileRequestListSize() > 0 ||
           pager.getDataToMergeListSize() > 0;
}

/** Renders frames until the series shows frame and the pager is idle; every picture in during. */
Frame playUntilShown(Renderer& renderer, osgGlyphsTiles::TileSeries& series, std::size_t frame,
                     std::vector<Frame>& during)
{
    osgViewer::Viewer* viewer = renderer.getViewer();
    osgDB::DatabasePager* pager = viewer->getDatabasePager();
    std::string error;
    // Until the frame is shown, the next one's root is read (on the series' thread, not the
    // pager's) and the pager has stayed idle for three renders (it is idle before the first cull
    // asks for anything).
    for (int frames = 0, idle = 0; frames < 4000 && idle < 3; ++frames)
    {
        viewer->frame();
        during.push_back(renderer.capture());
        const std::size_t next = series.getPrefetchFrame();
        const bool settled =
            series.getShownFrame() == frame && !pagerIsBusy(*pager) &&
            (next == SIZE_MAX || series.isFrameLoaded(next) || series.getFrameError(next, error));
        idle = settled ? idle + 1 : 0;
        if (pager->getDataToMergeListSize() == 0)
            OpenThreads::Thread::microSleep(2000);
    }
    viewer->frame();
    return renderer.capture();
}

}

// Float positions: a frame's finest level holds its glyphs exactly as given. The index is written
// and read back through osgDB, and names the frames relative to its folder.
TEST(TileSeries, EveryFrameAtFullDetailIsItsFlatCloud)
{
    const std::vector<osg::ref_ptr<GlyphCloud>> clouds = frameClouds(3, 20000, 0.008f);
    osg::ref_ptr<osgGlyphsTiles::TileSeries> series = writeSeries("series_full", clouds, false);
    ASSERT_TRUE(series.valid()) << "the index read back";
    ASSERT_EQ(series->getNumFrames(), 3u);
    EXPECT_EQ(series->getFrames()[2].timestep, 1234767.0) << "every digit through the text index";
    osg::ref_ptr<osgGlyphsTiles::TileSeriesPlayer> player =
        new osgGlyphsTiles::TileSeriesPlayer(series.get());
    series->setUpdateCallback(player.get());
    std::vector<Frame> flats;
    for (unsigned int frame = 0; frame < 3; ++frame)
    {
        std::string error;
        ASSERT_TRUE(player->showNow(frame, error)) << error;
        EXPECT_EQ(series->getShownFrame(), frame);
        EXPECT_EQ(player->getTimestep(), 1234567.0 + 100.0 * frame);
        Renderer flatRenderer(SIZE, SIZE), pagedRenderer(SIZE, SIZE);
        lookAtTheUnitCube(flatRenderer);
        lookAtTheUnitCube(pagedRenderer);
        flats.push_back(flatRenderer.render(clouds[frame].get()));
        int frames = 0;
        const Frame paged = renderPaged(pagedRenderer, series.get(), frames);
        saveFrame(paged, "series_full_" + std::to_string(frame));
        EXPECT_GT(frames, 2) << "frame " << frame << ": the tiles were not paged in";
        EXPECT_EQ(series->getShownRoot(), series->getChild(0)) << "frame " << frame << " read twice";
        EXPECT_TRUE(osgDB::Registry::instance()->getRefFromArchiveCache(series->getFramePath(frame)).valid())
            << "frame " << frame << "'s archive is not cached under its path";
        EXPECT_EQ(countDifferingPixels(paged, flats.back()), 0)
            << "frame " << frame << ": pixels that differ";
    }
    EXPECT_GT(countDifferingPixels(flats[0], flats[1]), SIZE * SIZE / 10) << "the frames differ";
    // Frame 2 shown, frame 0 prefetched (playback loops): frame 1 is let go, its archive closed.
    EXPECT_EQ(series->getPrefetchFrame(), 0u);
    EXPECT_FALSE(osgDB::Registry::instance()->getRefFromArchiveCache(series->getFramePath(1)).valid());
}

// From frame 0 paged in, the player goes to frame 2 (not prefetched: frame 1 is). Until frame 2's
// root tile is in, frame 0 stays drawn; then frame 2's coarse level, refined as its tiles arrive. A
// hole: a block of 16x16 pixels that the settled frame 2 covers (almost) wholly, and that a picture
// on the way leaves wholly uncovered.
TEST(TileSeries, AFrameChangeNeverLeavesHoles)
{
    const float dense = 0.4f * std::cbrt(1.0f / 20000.0f);
    const std::vector<osg::ref_ptr<GlyphCloud>> clouds = frameClouds(3, 20000, dense);
    osg::ref_ptr<osgGlyphsTiles::TileSeries> series = writeSeries("series_holes", clouds, true);
    ASSERT_TRUE(series.valid());
    osg::ref_ptr<osgGlyphsTiles::TileSeriesPlayer> player =
        new osgGlyphsTiles::TileSeriesPlayer(series.get());
    series->setUpdateCallback(player.get());
    Renderer renderer(SIZE, SIZE);
    lookAtTheUnitCube(renderer);
    renderer.getViewer()->setSceneData(series.get());
    std::vector<Frame> before, during;
    playUntilShown(renderer, *series, 0, before);
    player->seek(2.0);
    const Frame settled = playUntilShown(renderer, *series, 2, during);
    saveFrame(settled, "series_holes_settled");
    ASSERT_FALSE(during.empty());
    saveFrame(during.front(), "series_holes_first");
    EXPECT_GE(during.size(), 3u) << "frame 2's tiles were paged in after the change";
    EXPECT_GE(player->getStatistics().late, 1u) << "the change waited for frame 2's root";
    const int BLOCK = 16;
    int holes = 0, blocks = 0;
    const auto coveredIn = [BLOCK](const Frame& frame, int bx, int by)
    {
        int covered = 0;
        for (int y = by; y < by + BLOCK; ++y)
            for (int x = bx; x < bx + BLOCK; ++x)
                covered += frame.isCovered(x, y);
        return covered;
    };
    for (int by = 0; by + BLOCK <= SIZE; by += BLOCK)
        for (int bx = 0; bx + BLOCK <= SIZE; bx += BLOCK)
        {
            if (coveredIn(settled, bx, by) < BLOCK * BLOCK * 9 / 10)
                continue;
            ++blocks;
            for (const Frame& frame : during)
                holes += coveredIn(frame, bx, by) == 0;
        }
    ASSERT_GT(blocks, 60);
    EXPECT_EQ(holes, 0) << "of " << blocks << " covered blocks, over " << during.size() << " pictures";
}

// Once frame 0 is in, frame 1 (the next of playback) is read ahead with its tiles in view: the step
// to it pages nothing in, and its first picture is already the full one.
TEST(TileSeries, TheNextFrameIsPrefetchedWithItsTilesInView)
{
    const std::vector<osg::ref_ptr<GlyphCloud>> clouds = frameClouds(2, 20000, 0.008f);
    osg::ref_ptr<osgGlyphsTiles::TileSeries> series = writeSeries("series_prefetch", clouds, false);
    ASSERT_TRUE(series.valid());
    osg::ref_ptr<osgGlyphsTiles::TileSeriesPlayer> player =
        new osgGlyphsTiles::TileSeriesPlayer(series.get());
    // Frame 1 is the last: no frame after it is prefetched (looping would read frame 0 ahead again
    // and page its tiles in while frame 1 is checked).
    player->setLoop(false);
    series->setUpdateCallback(player.get());
    Renderer renderer(SIZE, SIZE), flatRenderer(SIZE, SIZE);
    lookAtTheUnitCube(renderer);
    lookAtTheUnitCube(flatRenderer);
    renderer.getViewer()->setSceneData(series.get());
    std::vector<Frame> before;
    playUntilShown(renderer, *series, 0, before);
    EXPECT_EQ(series->getPrefetchFrame(), 1u);
    const uint64_t late = player->getStatistics().late; // frame 0's first read
    player->seek(1.0);
    renderer.getViewer()->frame();
    ASSERT_EQ(series->getShownFrame(), 1u) << "frame 1's root was read ahead";
    EXPECT_FALSE(pagerIsBusy(*renderer.getViewer()->getDatabasePager())) << "tiles left to page in";
    const Frame first = renderer.capture();
    saveFrame(first, "series_prefetch_first");
    EXPECT_EQ(countDifferingPixels(first, flatRenderer.render(clouds[1].get())), 0)
        << "the first picture of frame 1 is not its full detail";
    EXPECT_EQ(player->getStatistics().late, late);
}

// Frame 1's archive cut short, frame 2's missing: each is one message naming its file, once, even
// over two loops; frames 0 and 3 play. Frames let go are closed (out of osgDB's archive cache).
TEST(TileSeries, ACorruptOrMissingFrameIsReportedOnceAndTheOthersPlay)
{
    const std::vector<osg::ref_ptr<GlyphCloud>> clouds = frameClouds(4, 3000, 0.01f);
    osg::ref_ptr<osgGlyphsTiles::TileSeries> series = writeSeries("series_corrupt", clouds, true);
    ASSERT_TRUE(series.valid());
    std::filesystem::resize_file(framePath("series_corrupt", 1), 200);
    std::filesystem::remove(framePath("series_corrupt", 2));
    osg::ref_ptr<osgGlyphsTiles::TileSeriesPlayer> player =
        new osgGlyphsTiles::TileSeriesPlayer(series.get());
    std::vector<std::string> errors;
    player->setErrorHandler([&errors](const std::string& error) { errors.push_back(error); });
    series->setUpdateCallback(player.get());
    player->setFramesPerSecond(1000.0);
    player->setPlaying(true);
    Renderer renderer(SIZE, SIZE);
    lookAtTheUnitCube(renderer);
    renderer.getViewer()->setSceneData(series.get());
    std::vector<std::size_t> shown;
    for (int frames = 0; frames < 3000 && player->getStatistics().shown < 6; ++frames)
    {
        renderer.getViewer()->frame();
        if (series->getShownFrame() != SIZE_MAX && (shown.empty() || shown.back() != series->getShownFrame()))
            shown.push_back(series->getShownFrame());
        OpenThreads::Thread::microSleep(1000);
    }
    EXPECT_GE(player->getStatistics().shown, 6u) << "playback went on past the failed frames";
    for (std::size_t frame : shown)
        EXPECT_TRUE(frame == 0 || frame == 3) << "frame " << frame << " shown";
    ASSERT_EQ(errors.size(), 2u);
    EXPECT_NE(errors[0].find("series_corrupt_1.osga: not an OSG archive of glyph tiles"), std::string::npos)
        << errors[0];
    EXPECT_NE(errors[1].find("series_corrupt_2.osga: no such file"), std::string::npos) << errors[1];
    for (const std::string& error : errors)
        EXPECT_EQ(error.find('\n'), std::string::npos) << "one line: " << error;
    std::string error;
    EXPECT_TRUE(series->getFrameError(1, error));
    EXPECT_FALSE(series->getFrameError(3, error));
    const std::size_t other = series->getShownFrame() == 0 ? 3 : 0;
    EXPECT_FALSE(osgDB::Registry::instance()->getRefFromArchiveCache(series->getFramePath(other)).valid() &&
                 series->getPrefetchFrame() != other)
        << "frame " << other << "'s archive is still open";
}

// An index that lies (an absurd frame count, a count larger than the frames listed, a timestep that
// is not a number, a frame without a file) reads as no series: nothing allocated for the count,
// nothing crashes, and the viewer says the file is not a series.
TEST(TileSeries, AnIndexThatLiesIsNoSeries)
{
    const std::string header = "#Ascii Scene\n#Version 161\n#Generator OpenSceneGraph 3.6.5\n\n"
                               "osgGlyphsTiles::TileSeries {\n  UniqueID 1\n";
    const std::vector<std::pair<std::string, std::string>> lies = {
        {"absurd_count", "  Frames 4000000000 {\n    \"a.osga\" 0\n  }\n"},
        {"short_list", "  Frames 3 {\n    \"a.osga\" 0\n  }\n"},
        {"nan_timestep", "  Frames 1 {\n    \"a.osga\" nan\n  }\n"},
        {"no_file", "  Frames 1 {\n    \"\" 0\n  }\n"},
    };
    std::string error;
    ASSERT_TRUE(osgGlyphsTiles::findTileSerializers(error)) << error;
    const std::string truthPath = outputPath("series_truth.osgt");
    std::ofstream(truthPath) << header << "  Frames 1 {\n    \"a.osga\" 20\n  }\n  GlyphBudget 0\n}\n";
    osg::ref_ptr<osgGlyphsTiles::TileSeries> truth =
        dynamic_cast<osgGlyphsTiles::TileSeries*>(osgDB::readNodeFile(truthPath));
    ASSERT_TRUE(truth.valid()) << "the same index, truthful";
    EXPECT_EQ(truth->getNumFrames(), 1u);
    EXPECT_EQ(truth->getFramePath(0), osgDB::getFilePath(truthPath) + "/a.osga");
    for (const auto& lie : lies)
    {
        const std::string path = outputPath("series_lie_" + lie.first + ".osgt");
        std::ofstream(path) << header << lie.second << "  GlyphBudget 0\n}\n";
        osg::ref_ptr<osg::Node> node = osgDB::readNodeFile(path);
        const osgGlyphsTiles::TileSeries* series =
            dynamic_cast<const osgGlyphsTiles::TileSeries*>(node.get());
        EXPECT_TRUE(!series || series->getNumFrames() == 0)
            << lie.first << ": read as a series of " << series->getNumFrames() << " frames";
    }
}

// Under a transform, a series pages in, draws and picks as its frame's cloud does: a ray down
// through a glyph of the shown frame (moved by the transform) hits that glyph's top, at the
// glyph's radius from its centre.
TEST(TileSeries, PicksTheShownFrameUnderATransform)
{
    const std::vector<osg::ref_ptr<GlyphCloud>> clouds = frameClouds(2, 5000, 0.01f);
    osg::ref_ptr<osgGlyphsTiles::TileSeries> series = writeSeries("series_pick", clouds, false);
    ASSERT_TRUE(series.valid());
    std::string error;
    ASSERT_EQ(series->showFrameNow(1, error), osgGlyphsTiles::TileSeries::FRAME_SHOWN) << error;
    const osg::Vec3d shift(2.0, -1.0, 0.5);
    osg::ref_ptr<osg::MatrixTransform> moved = new osg::MatrixTransform(osg::Matrixd::translate(shift));
    moved->addChild(series.get());
    Renderer renderer(SIZE, SIZE);
    renderer.setPerspective(30.0, 0.1, 20.0);
    renderer.setLookAt(osg::Vec3d(1.9, -1.2, 1.4) + shift, osg::Vec3d(0.5, 0.5, 0.5) + shift,
                       osg::Vec3d(0, 0, 1));
    int frames = 0;
    const Frame picture = renderPaged(renderer, moved.get(), frames);
    saveFrame(picture, "series_pick");
    int hits = 0;
    for (unsigned int i = 0; i < 5000; i += 250)
    {
        const osg::Vec3d centre =
            osg::Vec3d((*clouds[1]->getPositions())[i]) + clouds[1]->getOrigin() + shift;
        osg::ref_ptr<osgUtil::LineSegmentIntersector> ray = new osgUtil::LineSegmentIntersector(
            centre + osg::Vec3d(0.0, 0.0, 0.011), centre - osg::Vec3d(0.0, 0.0, 0.011));
        osgUtil::IntersectionVisitor visitor(ray.get());
        moved->accept(visitor);
        ASSERT_TRUE(ray->containsIntersections()) << "glyph " << i;
        const osg::Vec3d hit = ray->getFirstIntersection().getWorldIntersectPoint();
        // From just above the glyph's top: the first surface is its top, unless a glyph overlaps it.
        hits += std::abs((hit - centre).length() - 0.01) < 1e-5 && hit.z() > centre.z();
    }
    EXPECT_GE(hits, 18) << "of 20 rays, hitting their glyph's top";
}
