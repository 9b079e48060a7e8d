// osgglyphplayer: the smallest program that plays a trajectory in an OSG scene, meant to be read
// and copied. The frames are read on demand (the first at once, the others indexed and decoded
// ahead on worker threads) and shown in one GlyphCloud by an update callback.
//
//   osgglyphplayer melt.lammpstrj.gz                       plays in a window (space: pause)
//   osgglyphplayer melt.lammpstrj --output f%02d.png       every frame headless, one PNG each

#include <osgGlyphsData/FrameSource>
#include <osgGlyphsData/TrajectoryPlayer>
#include <osgGlyphsHeadless/OffscreenViewer>

#include <osg/ArgumentParser>
#include <osg/ComputeBoundsVisitor>
#include <osg/Group>
#include <osgDB/WriteFile>
#include <osgGA/TrackballManipulator>
#include <osgViewer/Viewer>

#include <iostream>

namespace
{

/** Space plays and pauses. */
class PauseKey : public osgGA::GUIEventHandler
{
public:
    explicit PauseKey(osgGlyphsData::TrajectoryPlayer* player) : _player(player) {}
    bool handle(const osgGA::GUIEventAdapter& ea, osgGA::GUIActionAdapter&) override
    {
        if (ea.getEventType() != osgGA::GUIEventAdapter::KEYDOWN || ea.getKey() != ' ')
            return false;
        _player->setPlaying(!_player->isPlaying());
        return true;
    }

private:
    osg::ref_ptr<osgGlyphsData::TrajectoryPlayer> _player;
};

int renderFrames(osg::Group* scene, osgGlyphsData::TrajectoryPlayer* player, const std::string& pattern)
{
    osg::ref_ptr<osgGlyphsHeadless::OffscreenViewer> viewer =
        new osgGlyphsHeadless::OffscreenViewer(640, 480);
    if (!viewer->valid())
    {
        std::cerr << "osgglyphplayer: " << viewer->getContextError() << std::endl;
        return 1;
    }
    viewer->setSceneData(scene);
    viewer->setCameraManipulator(new osgGA::TrackballManipulator); // frames the first frame
    player->getCache()->getSource()->waitForIndex();
    for (std::size_t frame = 0; frame < player->getNumFrames(); ++frame)
    {
        std::string error, name;
        if (!player->showNow(frame, error)) // waits for the frame, unlike playback
            std::cerr << "osgglyphplayer: " << error << std::endl;
        viewer->frame();
        if (!osgGlyphsData::formatFramePath(pattern, frame, name) ||
            !osgDB::writeImageFile(*viewer->getColorImage(), name))
            return 1;
        std::cout << "osgglyphplayer: wrote " << name << std::endl;
    }
    return 0;
}

}

int main(int argc, char** argv)
{
    osg::ArgumentParser arguments(&argc, argv);
    std::string output;
    arguments.read("--output", output);
    if (arguments.argc() < 2)
    {
        std::cerr << "usage: osgglyphplayer <trajectory> [--output frame%02d.png]" << std::endl;
        return 2;
    }

    // 1. The frames of the file: only the first is read now.
    std::string error;
    osg::ref_ptr<osgGlyphsData::FrameSource> source =
        osgGlyphsData::FrameSource::open(arguments[1], osgGlyphsData::FrameSourceOptions(), error);
    // 2. How columns become glyphs (positions, colour by speed); the colour range of the first frame.
    osgGlyphsData::GlyphMapper mapper(osgGlyphsData::GlyphMappingOptions{});
    if (!source || !mapper.prepare(*osgGlyphsData::sampleFrames(*source, 1), 0, error))
    {
        std::cerr << "osgglyphplayer: " << error << std::endl;
        return 1;
    }
    // 3. One cloud for every frame, and the player that shows the frames in it.
    osg::ref_ptr<osgGlyphs::GlyphCloud> cloud = mapper.createCloud(*source->getFirstFrame(), error);
    osg::ref_ptr<osgGlyphsData::TrajectoryPlayer> player =
        new osgGlyphsData::TrajectoryPlayer(new osgGlyphsData::FrameCache(source.get()), mapper, cloud.get());
    player->setFramesPerSecond(10.0);
    // 4. The player is the update callback of a node above the cloud.
    osg::ref_ptr<osg::Group> scene = new osg::Group;
    scene->addChild(cloud.get());
    scene->setUpdateCallback(player.get());

    if (!output.empty())
        return renderFrames(scene.get(), player.get(), output);
    player->setPlaying(true);
    osgViewer::Viewer viewer;
    viewer.setSceneData(scene.get());
    viewer.addEventHandler(new PauseKey(player.get()));
    return viewer.run();
}
