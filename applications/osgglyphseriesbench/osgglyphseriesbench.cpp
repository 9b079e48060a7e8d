// osgglyphseriesbench: times the playback of a series of tile archives (osgglyphconvert
// --frame-range ... out.osgt), headless, against showing one of its frames; and writes the moving
// trajectories such series are converted from.
//
//   osgglyphseriesbench trajectory OUT.dcd [--particles n] [--frames f] [--step s]
//   osgglyphseriesbench sizes ARCHIVE.osga
//   osgglyphseriesbench play INDEX.osgt [--rounds r] [--renders k] [--size w h] [--glyph-budget n]
//                                       [--play-fps p]
//
// play alternates, round by round (the first only warms up), k renders of frame 0 standing still,
// its tiles in view paged in, and k renders while the series plays (at p frames a second; by default
// as fast as it can, a new frame asked for at every render; a frame is shown once its root tile is
// in, then refines): the ratio of the render rates, the glyphs each drew, the frames shown per
// second, and the renders that waited for a frame. sizes splits an archive's bytes into its glyphs'
// positions, by level, their radii and scalars, and the rest (the tiles' structure, the index). Ratios within
// one run, not absolute times across runs; share/bench/series_bench.sh runs the whole benchmark.

#include "MovingTrajectory.h"

#include <osgGlyphs/GlyphCloud>
#include <osgGlyphsHeadless/OffscreenViewer>
#include <osgGlyphsTiles/TileBuilder>
#include <osgGlyphsTiles/TileSeries>
#include <osgGlyphsTiles/TileSeriesPlayer>

#include <osg/ArgumentParser>
#include <osg/NodeVisitor>
#include <osg/PagedLOD>
#include <osgDB/Archive>
#include <osgDB/ReadFile>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>

namespace
{

const char* const PROGRAM = "osgglyphseriesbench";

double seconds(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/** The process's peak resident memory (VmHWM) in MB. */
double peakMegabytes()
{
    std::ifstream status("/proc/self/status");
    for (std::string line; std::getline(status, line);)
        if (line.compare(0, 6, "VmHWM:") == 0)
            return std::stod(line.substr(6)) / 1024.0;
    return 0.0;
}

int writeTrajectory(osg::ArgumentParser& arguments)
{
    MovingTrajectoryOptions options;
    double particles = double(options.particles);
    arguments.read("--particles", particles);
    arguments.read("--frames", options.frames);
    arguments.read("--step", options.step);
    arguments.read("--seed", options.seed);
    options.particles = static_cast<uint64_t>(particles);
    if (arguments.argc() != 3)
    {
        std::cerr << PROGRAM << " trajectory OUT.dcd [--particles n] [--frames f] [--step s]" << std::endl;
        return 2;
    }
    const auto start = std::chrono::steady_clock::now();
    std::string error;
    if (!writeMovingTrajectory(arguments[2], options, error))
    {
        std::cerr << PROGRAM << ": " << error << std::endl;
        return 1;
    }
    std::printf("%s: wrote %s: %llu particles x %u frames in %.1f s\n", PROGRAM, arguments[2],
                static_cast<unsigned long long>(options.particles), options.frames, seconds(start));
    return 0;
}

struct Rates
{
    double still = 0.0;   // renders per second of frame 0
    double playing = 0.0; // renders per second while playing
    double shown = 0.0;   // frames shown per second while playing
    double lateShare = 0.0;
    double stillGlyphs = 0.0;   // glyphs drawn per render of frame 0
    double playingGlyphs = 0.0; // and while playing
};

/** Renders count frames; returns the seconds taken and adds the glyphs each drew to glyphs. */
double renderFrames(osgViewer::Viewer& viewer, const osgGlyphsTiles::TileSeries& series, int count,
                    double& glyphs)
{
    glyphs = 0.0;
    const auto start = std::chrono::steady_clock::now();
    for (int i = 0; i < count; ++i)
    {
        viewer.frame();
        if (const osgGlyphsTiles::TileRoot* root = series.getShownRoot())
            glyphs += double(root->getBudget()->getLastGlyphs()) / count;
    }
    return seconds(start);
}

int play(osg::ArgumentParser& arguments)
{
    int rounds = 3, renders = 30, width = 800, height = 600;
    double budget = -1.0, playRate = 1e6;
    arguments.read("--play-fps", playRate);
    arguments.read("--rounds", rounds);
    arguments.read("--renders", renders);
    arguments.read("--size", width, height);
    arguments.read("--glyph-budget", budget);
    if (arguments.argc() != 3 || rounds < 2 || renders < 1)
    {
        std::cerr << PROGRAM
                  << " play INDEX.osgt [--rounds r>=2] [--renders k] [--size w h] [--glyph-budget n]"
                  << std::endl;
        return 2;
    }
    std::string error;
    if (!osgGlyphsTiles::findTileSerializers(error))
    {
        std::cerr << PROGRAM << ": " << error << std::endl;
        return 1;
    }
    osg::ref_ptr<osgGlyphsTiles::TileSeries> series =
        dynamic_cast<osgGlyphsTiles::TileSeries*>(osgDB::readNodeFile(arguments[2]));
    if (!series || series->getNumFrames() < 2)
    {
        std::cerr << PROGRAM << ": " << arguments[2] << ": not a series of two frames or more" << std::endl;
        return 1;
    }
    if (budget >= 0.0)
        series->setGlyphBudget(static_cast<std::size_t>(budget));
    osg::ref_ptr<osgGlyphsTiles::TileSeriesPlayer> player =
        new osgGlyphsTiles::TileSeriesPlayer(series.get());
    series->setUpdateCallback(player.get());
    player->setErrorHandler([](const std::string& message)
                            { std::cerr << PROGRAM << ": " << message << std::endl; });
    if (!player->showNow(0.0, error))
    {
        std::cerr << PROGRAM << ": " << error << std::endl;
        return 1;
    }
    osg::ref_ptr<osgGlyphsHeadless::OffscreenViewer> viewer =
        new osgGlyphsHeadless::OffscreenViewer(width, height);
    if (!viewer->valid())
    {
        std::cerr << PROGRAM << ": " << viewer->getContextError() << std::endl;
        return 1;
    }
    viewer->setSceneData(series.get());
    const osg::BoundingSphere bound = series->getBound();
    const double distance = 2.4 * bound.radius();
    viewer->getCamera()->setViewMatrixAsLookAt(bound.center() + osg::Vec3d(0.55, -0.7, 0.45) * distance,
                                               bound.center(), osg::Vec3d(0.0, 0.0, 1.0));
    Rates total;
    for (int round = 0; round < rounds; ++round)
    {
        // Standing still on frame 0, paged in.
        player->setPlaying(false);
        player->showNow(0.0, error);
        viewer->settlePaging();
        Rates rates;
        rates.still = renders / renderFrames(*viewer, *series, renders, rates.stillGlyphs);
        // Playing from frame 0 (as fast as frames come by default).
        player->setFramesPerSecond(playRate);
        player->setLoop(true);
        const osgGlyphsData::FramePlayerStatistics before = player->getStatistics();
        player->setPlaying(true);
        const double elapsed = renderFrames(*viewer, *series, renders, rates.playingGlyphs);
        const osgGlyphsData::FramePlayerStatistics after = player->getStatistics();
        rates.playing = renders / elapsed;
        rates.shown = double(after.shown - before.shown) / elapsed;
        rates.lateShare = double(after.late - before.late) / renders;
        std::printf("%s: round %d%s: still %.2f renders/s, playing %.2f renders/s (%.0f%%), %.2f frames "
                    "shown/s, %.0f%% of renders waited for a frame; %.0f glyphs drawn still, %.0f playing\n",
                    PROGRAM, round, round == 0 ? " (warm-up)" : "", rates.still, rates.playing,
                    100.0 * rates.playing / rates.still, rates.shown, 100.0 * rates.lateShare,
                    rates.stillGlyphs, rates.playingGlyphs);
        if (round == 0)
            continue;
        total.still += rates.still / (rounds - 1);
        total.playing += rates.playing / (rounds - 1);
        total.shown += rates.shown / (rounds - 1);
        total.lateShare += rates.lateShare / (rounds - 1);
        total.stillGlyphs += rates.stillGlyphs / (rounds - 1);
        total.playingGlyphs += rates.playingGlyphs / (rounds - 1);
    }
    std::printf(
        "%s: %s, %zu frames, %dx%d, glyph budget %zu: playing renders at %.0f%% of the still "
        "rate (%.2f vs %.2f renders/s) drawing %.0f%% of its glyphs, %.2f frames shown/s, %.0f%% of renders "
        "waited for a frame; peak memory %.0f MB\n",
        PROGRAM, arguments[2], series->getNumFrames(), width, height,
        series->getShownRoot() ? series->getShownRoot()->getGlyphBudget() : 0,
        100.0 * total.playing / total.still, total.playing, total.still,
        100.0 * total.playingGlyphs / std::max(total.stillGlyphs, 1.0), total.shown, 100.0 * total.lateShare,
        peakMegabytes());
    return 0;
}

/** The glyphs of the clouds under a node, and how many bytes their positions take. */
class GlyphCount : public osg::NodeVisitor
{
public:
    GlyphCount() : osg::NodeVisitor(TRAVERSE_ACTIVE_CHILDREN) {}
    void apply(osg::Drawable& drawable) override
    {
        if (const osgGlyphs::GlyphCloud* cloud = dynamic_cast<const osgGlyphs::GlyphCloud*>(&drawable))
        {
            glyphs += cloud->getNumGlyphs();
            positionBytes += cloud->getNumGlyphs() * (cloud->getCompressedPositions() ? 6.0 : 12.0);
            for (const osg::Array* array : {static_cast<const osg::Array*>(cloud->getRadii()),
                                            static_cast<const osg::Array*>(cloud->getScalars())})
                attributeBytes += array ? array->getTotalDataSize() : 0;
        }
    }
    double glyphs = 0.0, positionBytes = 0.0, attributeBytes = 0.0;
};

}

int sizes(osg::ArgumentParser& arguments)
{
    std::string error;
    if (arguments.argc() != 3 || !osgGlyphsTiles::findTileSerializers(error))
    {
        std::cerr << PROGRAM << " sizes ARCHIVE.osga " << error << std::endl;
        return 2;
    }
    osg::ref_ptr<osgDB::Archive> archive = osgDB::openArchive(arguments[2], osgDB::Archive::READ);
    if (!archive)
    {
        std::cerr << PROGRAM << ": " << arguments[2] << ": not an OSG archive" << std::endl;
        return 1;
    }
    osgDB::Archive::FileNameList files;
    archive->getFileNames(files);
    GlyphCount leaves, coarse; // leaf tiles hold no PagedLOD; a tile with PagedLODs holds coarse levels
    for (const std::string& file : files)
    {
        osg::ref_ptr<osg::Node> node = archive->readNode(file).takeNode();
        if (!node)
            continue;
        // A file holds the children of a PagedLOD: its clouds are each child's coarse level, or the
        // leaf's glyphs where the child is a plain cloud.
        const osg::Group* group = node->asGroup();
        for (unsigned int i = 0; group && i < group->getNumChildren(); ++i)
        {
            osg::Node* child = const_cast<osg::Node*>(group->getChild(i));
            child->accept(dynamic_cast<osg::PagedLOD*>(child) ? coarse : leaves);
        }
    }
    const double bytes = double(std::filesystem::file_size(arguments[2]));
    const double glyphs = leaves.glyphs;
    const double attributes = leaves.attributeBytes + coarse.attributeBytes;
    std::printf("%s: %s: %zu files, %.0f leaf glyphs, %.0f coarse (%.1f%%); %.2f bytes a leaf glyph: %.2f of "
                "leaf positions, %.2f of coarse positions, %.2f of radii and scalars, %.2f of the rest (the "
                "tiles' structure, the index)\n",
                PROGRAM, arguments[2], files.size(), glyphs, coarse.glyphs, 100.0 * coarse.glyphs / glyphs,
                bytes / glyphs, leaves.positionBytes / glyphs, coarse.positionBytes / glyphs,
                attributes / glyphs,
                (bytes - leaves.positionBytes - coarse.positionBytes - attributes) / glyphs);
    return 0;
}

int main(int argc, char** argv)
{
    osg::ArgumentParser arguments(&argc, argv);
    const std::string mode = argc > 1 ? argv[1] : "";
    if (mode == "trajectory")
        return writeTrajectory(arguments);
    if (mode == "play")
        return play(arguments);
    if (mode == "sizes")
        return sizes(arguments);
    std::cerr << "usage: " << PROGRAM
              << " trajectory OUT.dcd [--particles n] [--frames f] [--step s]\n       " << PROGRAM
              << " play INDEX.osgt [--rounds r] [--renders k] [--size w h] [--glyph-budget n]" << std::endl;
    return 2;
}
