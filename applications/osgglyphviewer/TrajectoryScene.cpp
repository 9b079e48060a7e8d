#include "TrajectoryScene.h"

#include "BondOptions.h"
#include "DatasetLoading.h"
#include "MovieOutput.h"
#include "ViewerText.h"

#include <osgGlyphsData/FrameSource>

#include <chrono>
#include <iostream>
#include <thread>

namespace
{

/** The frames the colour range is taken over by default: offscreen sequences sample the
 * trajectory so that every picture has one key; a window shows the first frame at once. */
unsigned int rangeSampleFrames(const PlaybackOptions& playback)
{
    if (playback.rangeSample > 0)
        return playback.rangeSample;
    return playback.hasFrameRange || !playback.movie.empty() ? 8 : 1;
}

/** Waits, reading the file again every poll, until it has count frames (--follow). */
bool waitForFrames(osgGlyphsData::FrameSource& source, std::size_t count, double timeout, std::string& error)
{
    source.waitForIndex();
    const auto start = std::chrono::steady_clock::now();
    if (source.getNumFrames() < count)
        std::cerr << PROGRAM << ": waiting for frame " << count - 1 << " of " << source.getSource()
                  << std::endl;
    while (source.getNumFrames() < count)
    {
        if (std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() > timeout)
        {
            error = source.getSource() + ": no frame " + std::to_string(count - 1) + " after " +
                    std::to_string(static_cast<int>(timeout)) + " s of --follow";
            return false;
        }
        std::this_thread::sleep_for(std::chrono::duration<double>(FOLLOW_POLL_SECONDS));
        std::size_t added = 0;
        if (!source.poll(added, error))
            return false;
    }
    return true;
}

std::string describeColumns(const osgGlyphsData::PointData& points, unsigned int index)
{
    std::string text;
    for (std::size_t column = 0; index < points.getNumPoints() && column < points.getNumColumns(); ++column)
    {
        const std::string& name = points.getColumnNames()[column];
        const double value = points.getValue(column, index);
        const std::vector<std::string>& labels = points.getColumnLabels(name);
        const bool label = !labels.empty() && value >= 0.0 && value < double(labels.size());
        text += name + " = " + (label ? labels[std::size_t(value)] : formatFullValue(value)) + "\n";
    }
    return text;
}

std::string frameCount(std::size_t frames, bool complete)
{
    return std::to_string(frames) + (complete ? "" : "+") + " frame" + (frames == 1 && complete ? "" : "s");
}

}

osg::ref_ptr<ViewerScene> createTrajectoryScene(const ViewerOptions& options, std::string& error)
{
    ProgressIndicator progress(options.file);
    osgGlyphsData::FrameSourceOptions sourceOptions;
    sourceOptions.format = options.format;
    sourceOptions.datasets = options.datasets;
    sourceOptions.topology = options.topology;
    sourceOptions.growing = options.follow;
    sourceOptions.progress = [&progress](uint64_t bytesRead, uint64_t totalBytes)
    { progress.update(bytesRead, totalBytes); };
    sourceOptions.warning = [](const std::string& warning)
    { std::cerr << PROGRAM << ": warning: " << warning << std::endl; };
    osg::ref_ptr<osgGlyphsData::FrameSource> source =
        osgGlyphsData::FrameSource::open(options.file, sourceOptions, error);
    progress.finish(source.valid() ? 1 : 0, source.valid() ? source->getFirstFrame()->getNumPoints() : 0);
    if (!source)
        return nullptr;
    if (options.follow && !waitForFrames(*source, options.frame + 1, options.followTimeout, error))
        return nullptr;
    const std::size_t first = options.playback.hasFrameRange ? options.playback.range.first : options.frame;
    if (std::max<std::size_t>(first, options.frame) >= source->getNumFrames())
        source->waitForIndex();
    if (options.frame >= source->getNumFrames())
    {
        error = "--frame " + std::to_string(options.frame) + ": " + options.file + " has " +
                frameCount(source->getNumFrames(), true) + ", counted from 0";
        return nullptr;
    }
    if (first >= source->getNumFrames())
    {
        listPictures(options.playback, source->getNumFrames(), error);
        return nullptr;
    }
    const unsigned int sample = rangeSampleFrames(options.playback);
    if (sample > 1)
        source->waitForIndex(); // spread over the whole trajectory

    osgGlyphsData::GlyphMapper mapper(options.mapping);
    mapper.setMultiFrame(source->getNumFrames() > 1 || !source->isIndexComplete());
    // The frame shown first leads: its columns are the ones the options must find, and its points
    // give the default radius.
    osg::ref_ptr<osgGlyphsData::PointDataset> sampled = osgGlyphsData::sampleFrames(*source, sample, first);
    if (sampled->getNumFrames() == 0)
    {
        source->readFrame(first, error);
        return nullptr;
    }
    if (!mapper.prepare(*sampled, 0, error))
        return nullptr;
    osg::ref_ptr<osgGlyphs::GlyphCloud> cloud = mapper.createCloud(*sampled->getFrame(0), error);
    if (!cloud)
        return nullptr;

    const uint64_t budget = uint64_t(options.playback.cacheMegabytes) << 20;
    osg::ref_ptr<osgGlyphsData::FrameCache> cache = new osgGlyphsData::FrameCache(source.get(), budget);
    osg::ref_ptr<osgGlyphsData::TrajectoryPlayer> player =
        new osgGlyphsData::TrajectoryPlayer(cache.get(), mapper, cloud.get());
    const PlaybackOptions& playback = options.playback;
    applyPlaybackOptions(playback, *player);
    osgGlyphsData::FrameInterpolationOptions interpolation;
    if (playback.smooth)
        interpolation.method = osgGlyphsData::FrameInterpolationOptions::Method::Smooth;
    player->setInterpolation(interpolation);

    // One group holds the cloud for every frame; the player edits the cloud in its update callback.
    osg::ref_ptr<osg::Group> group = new osg::Group;
    group->setName(options.file);
    group->addChild(cloud.get());
    group->setUpdateCallback(player.get());
    std::string bonds;
    if (options.bonds.drawsBondsOf(*sampled->getFrame(0)) &&
        !addBondCloud(*group, *cloud, *sampled->getFrame(0), player.get(), options.bonds, bonds, error))
        return nullptr;
    ViewerScene::FrameSource frames = [group, player](std::size_t frame, std::string& frameError)
    {
        if (!player->showNow(static_cast<double>(frame), frameError))
            return osg::ref_ptr<osg::Node>();
        return osg::ref_ptr<osg::Node>(group);
    };
    osg::ref_ptr<ViewerScene> scene = new ViewerScene(frames, source->getNumFrames(), mapper.getColorKey());
    scene->setPlayer(player.get());
    if (options.follow)
        scene->setFollower([source](std::size_t& added, std::string& pollError)
                           { return source->poll(added, pollError); });
    scene->setPointDescriber(
        [cache](std::size_t frame, unsigned int index)
        {
            std::string ignored;
            osg::ref_ptr<const osgGlyphsData::PointData> points = cache->getFrame(frame, ignored);
            return points.valid() ? describeColumns(*points, index) : std::string();
        });
    const std::string compression = source->getCompressionName();
    scene->setDescription(options.file + ": " +
                          frameCount(source->getNumFrames(), source->isIndexComplete()) + " (" +
                          source->getFormat() + (compression.empty() ? "" : ", " + compression) + "), " +
                          std::to_string(source->getFirstFrame()->getNumPoints()) + " points in frame 0; " +
                          mapper.describe() + (bonds.empty() ? "" : "; " + bonds));
    player->setPlaying(playback.play);
    return scene;
}
