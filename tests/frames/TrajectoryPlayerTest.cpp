// FrameCache and TrajectoryPlayer: frames decoded ahead on a worker within a byte budget, played
// into a GlyphCloud at a rate, late frames counted, interpolated pictures exact for linear motion.

#include "TrajectoryTestData.h"

#include <osgGlyphsData/FrameCache>
#include <osgGlyphsData/TrajectoryPlayer>

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <thread>

using namespace trajectorytest;
using namespace osgGlyphsData;

namespace
{

osg::ref_ptr<FrameSource> openQuietly(const std::string& path)
{
    FrameSourceOptions options;
    options.warning = [](const std::string&) {};
    options.indexLocation = FrameIndexLocation::None;
    std::string error;
    osg::ref_ptr<FrameSource> source = FrameSource::open(path, options, error);
    EXPECT_TRUE(source.valid()) << error;
    return source;
}

/** A player of path's frames into a cloud of spheres coloured by vx. */
struct Playback
{
    osg::ref_ptr<FrameSource> source;
    osg::ref_ptr<osgGlyphs::GlyphCloud> cloud;
    osg::ref_ptr<TrajectoryPlayer> player;

    Playback(const std::string& path, uint64_t budget)
    {
        source = openQuietly(path);
        source->waitForIndex();
        GlyphMappingOptions options;
        options.colorBy = "vx";
        options.radius = 0.1f;
        GlyphMapper mapper(options);
        std::string error;
        EXPECT_TRUE(mapper.prepare(*sampleFrames(*source, 3), 0, error)) << error;
        cloud = mapper.createCloud(*source->getFirstFrame(), error);
        EXPECT_TRUE(cloud.valid()) << error;
        player = new TrajectoryPlayer(new FrameCache(source.get(), budget), mapper, cloud.get());
        player->setErrorHandler([](const std::string&) {});
    }
};

/** Each glyph at its atom's analytic position at (fractional) frame f, glyphs in row order of
 * the frame whose ids are given. */
void expectAnalytic(const osgGlyphs::GlyphCloud& cloud, const PointData& rows, double f)
{
    const std::vector<float>& ids = *rows.getColumn("id");
    ASSERT_EQ(cloud.getPositions()->size(), ids.size());
    for (std::size_t i = 0; i < ids.size(); ++i)
    {
        const int id = static_cast<int>(ids[i]);
        const osg::Vec3d p = cloud.getOrigin() + osg::Vec3d((*cloud.getPositions())[i]);
        const int lo = static_cast<int>(std::floor(f));
        const double t = f - lo;
        const double x = (1 - t) * analyticX(id, lo) + t * analyticX(id, lo + 1);
        const double y = (1 - t) * analyticY(id, lo) + t * analyticY(id, lo + 1);
        // Within the single precision of the glyphs' positions.
        const auto tolerance = [](double value) { return std::max(2e-6, 1.2e-7 * std::abs(value)); };
        EXPECT_NEAR(p.x(), x, tolerance(x)) << "id " << id << " at frame " << f;
        EXPECT_NEAR(p.y(), y, tolerance(y)) << "id " << id << " at frame " << f;
        EXPECT_NEAR(p.z(), analyticZ(id, 0), tolerance(p.z()));
    }
}

/** Runs update() until the player shows count pictures more than before; the wall clock only
 * guards against a hang. */
std::vector<double> playPictures(TrajectoryPlayer& player, std::size_t count, double& time)
{
    std::vector<double> shown{player.getPosition()};
    const auto start = std::chrono::steady_clock::now();
    while (shown.size() <= count && std::chrono::steady_clock::now() - start < std::chrono::seconds(300))
    {
        time += 0.05;
        player.update(time);
        if (player.getPosition() != shown.back())
            shown.push_back(player.getPosition());
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    return shown;
}

uint64_t peakResidentKiB()
{
    std::ifstream status("/proc/self/status");
    std::string line;
    while (std::getline(status, line))
    {
        if (line.rfind("VmHWM:", 0) == 0)
            return std::stoull(line.substr(6));
    }
    return 0;
}

}

TEST(TrajectoryPlayer, ShowsStoredAndInterpolatedFramesExactly)
{
    const std::string path = scratchFolder("player") + "/motion.lammpstrj";
    writeFile(path, lammpsDump(8, 60));
    Playback playback(path, FrameCache::DEFAULT_BUDGET_BYTES);
    std::string error;
    ASSERT_TRUE(playback.player->showNow(3.0, error)) << error;
    osg::ref_ptr<PointData> frame3 = playback.source->readFrame(3, error);
    expectAnalytic(*playback.cloud, *frame3, 3.0);
    EXPECT_EQ(playback.player->getTimestep(), 300.0);

    playback.player->setSubframes(3);
    for (double f : {3.25, 3.5, 5.75})
    {
        ASSERT_TRUE(playback.player->showNow(f, error)) << error;
        // Interpolated pictures keep the rows of the frame before them.
        osg::ref_ptr<PointData> before = playback.source->readFrame(static_cast<std::size_t>(f), error);
        expectAnalytic(*playback.cloud, *before, f);
        EXPECT_DOUBLE_EQ(playback.player->getTimestep(), 100.0 * f);
    }
    // The style is kept: the colour range of the mapping, not of the frame.
    EXPECT_FALSE(playback.cloud->getScalarRangeIsAutomatic());
    EXPECT_EQ(playback.player->getStatistics().failed, 0u);
}

TEST(TrajectoryPlayer, PlaysEveryPictureInOrderAtTheRate)
{
    const std::string path = scratchFolder("play") + "/motion.lammpstrj";
    writeFile(path, lammpsDump(10, 40));
    Playback playback(path, FrameCache::DEFAULT_BUDGET_BYTES);
    TrajectoryPlayer& player = *playback.player;
    player.setFramesPerSecond(10.0); // a picture every 0.1 s; update() runs every 0.05 s
    player.setSubframes(1);
    player.setLoop(false);
    player.setPlaying(true);
    double time = 0.0;
    const std::vector<double> shown = playPictures(player, 18, time);
    ASSERT_EQ(shown.size(), 19u); // 0, 0.5, ..., 9
    for (std::size_t i = 0; i < shown.size(); ++i)
        EXPECT_DOUBLE_EQ(shown[i], 0.5 * i);
    EXPECT_FALSE(player.isPlaying()); // stopped at the end without loop
    std::string error;
    expectAnalytic(*playback.cloud, *playback.source->readFrame(9, error), 9.0);
    // Never faster than the rate: 18 pictures at 10 per second took at least 1.8 s of time.
    EXPECT_GE(time, 1.8 - 1e-9);

    // Every other frame, backwards, looping.
    player.setSubframes(0);
    player.setStep(-2);
    player.setLoop(true);
    ASSERT_TRUE(player.showNow(4.0, error)) << error;
    player.setPlaying(true);
    const std::vector<double> back = playPictures(player, 4, time);
    const std::vector<double> expected{4.0, 2.0, 0.0, 8.0, 6.0};
    EXPECT_EQ(back, expected);
}

TEST(TrajectoryPlayer, APictureNotDecodedIsLateAndTheLastStays)
{
    // Frames large enough that decoding one takes far longer than the update after the seek.
    const std::string path = scratchFolder("late") + "/motion.lammpstrj";
    writeFile(path, lammpsDump(12, 20000));
    Playback playback(path, 1); // the budget of a byte: two frames held
    TrajectoryPlayer& player = *playback.player;
    player.update(0.0);
    player.seek(9.0); // not held: requested from the worker by the next update
    player.update(0.1);
    EXPECT_EQ(player.getStatistics().late, 1u);
    EXPECT_EQ(player.getPosition(), 0.0);
    std::string error;
    expectAnalytic(*playback.cloud, *playback.source->readFrame(0, error), 0.0);
    double time = 0.1;
    playPictures(player, 1, time);
    EXPECT_EQ(player.getPosition(), 9.0);
    EXPECT_EQ(player.getStatistics().late, 1u); // counted once per picture
}

TEST(TrajectoryPlayer, APictureShownLateStaysAWholeInterval)
{
    // A picture wanted but not shown yet, as a late one is: the update that shows it must not go
    // on to show the next one over it, though that one is due and decoded too. It did, and under
    // load PlaysEveryPictureInOrderAtTheRate never saw the late picture and waited for it forever.
    const std::string path = scratchFolder("overdue") + "/motion.lammpstrj";
    writeFile(path, lammpsDump(10, 40));
    Playback playback(path, FrameCache::DEFAULT_BUDGET_BYTES);
    TrajectoryPlayer& player = *playback.player;
    player.setLoop(false);
    player.setPlaying(true);
    player.update(0.0);
    std::string error;
    for (std::size_t frame : {3, 4})
        ASSERT_TRUE(player.getCache()->getFrame(frame, error).valid()) << error;
    player.seek(3.0);
    player.update(1.0); // ten pictures due: the one wanted is shown, and only it
    ASSERT_EQ(player.getPosition(), 3.0);
    expectAnalytic(*playback.cloud, *playback.source->readFrame(3, error), 3.0);
    player.update(2.0);
    EXPECT_EQ(player.getPosition(), 4.0);
    EXPECT_EQ(player.getStatistics().shown, 2u);
    EXPECT_EQ(player.getStatistics().late, 0u);
}

TEST(TrajectoryPlayer, AMalformedFrameIsSkippedAndPlaybackGoesOn)
{
    const std::string path = scratchFolder("skip") + "/broken.lammpstrj";
    std::string frame2 = lammpsFrame(2, 20);
    frame2.replace(frame2.find("ITEM: ATOMS id type x y z vx\n") + 29, 1, "X"); // a bad number
    writeFile(path,
              lammpsFrame(0, 20) + lammpsFrame(1, 20) + frame2 + lammpsFrame(3, 20) + lammpsFrame(4, 20));
    Playback playback(path, FrameCache::DEFAULT_BUDGET_BYTES);
    TrajectoryPlayer& player = *playback.player;
    std::vector<std::string> errors;
    player.setErrorHandler([&errors](const std::string& error) { errors.push_back(error); });
    player.setLoop(false);
    player.setPlaying(true);
    double time = 0.0;
    playPictures(player, 4, time);
    EXPECT_EQ(player.getPosition(), 4.0);
    ASSERT_EQ(errors.size(), 1u);
    EXPECT_EQ(errors[0].rfind(path + ":", 0), 0u) << errors[0];
    EXPECT_EQ(player.getStatistics().failed, 1u);
    std::string error;
    expectAnalytic(*playback.cloud, *playback.source->readFrame(4, error), 4.0);
}

TEST(FrameCache, TwoHundredFramesInABoundedBudget)
{
    const std::string path = scratchFolder("budget") + "/long.lammpstrj";
    writeFile(path, lammpsDump(200, 2000));
    osg::ref_ptr<FrameSource> source = openQuietly(path);
    source->waitForIndex();
    ASSERT_EQ(source->getNumFrames(), 200u);
    std::string error;
    const uint64_t frameBytes = FrameCache::getFrameBytes(*source->getFirstFrame());
    const uint64_t budget = 5 * frameBytes;
    osg::ref_ptr<FrameCache> cache = new FrameCache(source.get(), budget);
    // The worker decodes the frames ahead of the position by itself, as many as the budget holds.
    cache->setPlayback(0, 1, false, 0, 199);
    const auto start = std::chrono::steady_clock::now();
    while (cache->getStatistics().decoded < 5 &&
           std::chrono::steady_clock::now() - start < std::chrono::seconds(300))
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    std::this_thread::sleep_for(std::chrono::milliseconds(50)); // it would go on past the budget now
    EXPECT_EQ(cache->getStatistics().decoded, 5u);
    EXPECT_LE(cache->getStatistics().bytes, budget);
    uint64_t residentAt20 = 0;
    for (std::size_t f = 0; f < 200; ++f)
    {
        cache->setPlayback(f, 1, false, 0, 199);
        osg::ref_ptr<const PointData> frame = cache->getFrame(f, error);
        ASSERT_TRUE(frame.valid()) << error;
        ASSERT_EQ(frame->getTimestep(), int64_t(100 * f));
        EXPECT_LE(cache->getStatistics().bytes, budget);
        if (f == 20)
            residentAt20 = peakResidentKiB();
    }
    const FrameCacheStatistics statistics = cache->getStatistics();
    EXPECT_LE(statistics.peakBytes, budget);
    EXPECT_GE(statistics.decoded, 200u);
    EXPECT_EQ(statistics.hits + statistics.misses, 200u);
    // The process's peak memory stays where it was after 20 frames: nothing grows with the frames
    // (200 frames of 2000 atoms hold 200 x 48 kB = 9.6 MB of columns). Not under the sanitizers,
    // whose quarantine keeps freed memory resident on purpose.
#if !defined(__SANITIZE_ADDRESS__) && !defined(__SANITIZE_THREAD__)
    EXPECT_LT(peakResidentKiB() - residentAt20, 4096u);
#else
    (void)residentAt20;
#endif
}
