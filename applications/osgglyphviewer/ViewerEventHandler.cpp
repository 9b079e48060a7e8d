#include "ViewerEventHandler.h"

#include "DatasetLoading.h"

#include <osgGlyphs/GlyphStateCache>
#include <osgViewer/View>

#include <iostream>

bool ViewerEventHandler::handle(const osgGA::GUIEventAdapter& ea, osgGA::GUIActionAdapter& aa)
{
    if (ea.getEventType() == osgGA::GUIEventAdapter::FRAME)
    {
        checkPrograms(aa);
        followFile(ea.getTime(), aa);
    }
    if (ea.getHandled() || ea.getEventType() != osgGA::GUIEventAdapter::KEYDOWN)
        return false;
    switch (ea.getKey())
    {
    case 'l':
        _scene->setLit(!_scene->getLit());
        std::cout << PROGRAM << ": glyphs " << (_scene->getLit() ? "lit" : "unlit") << std::endl;
        aa.requestRedraw();
        return false; // leaves the key to osgGA::StateSetManipulator's lighting toggle
    case 'n':
        stepFrame(1);
        aa.requestRedraw();
        return true;
    case 'p':
        stepFrame(-1);
        aa.requestRedraw();
        return true;
    case 'r':
        osgGlyphs::GlyphStateCache::instance()->reloadShaders();
        _reloaded = true;
        _reportedError.clear();
        std::cout << PROGRAM << ": reloaded the glyph shaders" << std::endl;
        aa.requestRedraw();
        return true;
    default:
        return false;
    }
}

void ViewerEventHandler::checkPrograms(osgGA::GUIActionAdapter& aa)
{
    const std::string error = osgGlyphs::GlyphStateCache::instance()->getProgramError();
    if (error.empty() || error == _reportedError)
        return;
    std::cerr << PROGRAM << ": " << error << std::endl;
    _reportedError = error;
    osgViewer::View* view = dynamic_cast<osgViewer::View*>(&aa);
    if (_reloaded || !view || !view->getViewerBase())
        return;
    _exitCode = 1;
    view->getViewerBase()->setDone(true);
}

void ViewerEventHandler::followFile(double time, osgGA::GUIActionAdapter& aa)
{
    if (!_scene->isFollowing() || time < _nextPoll)
        return;
    _nextPoll = time + FOLLOW_POLL_SECONDS;
    const bool onLastFrame = _scene->getFrame() + 1 == _scene->getNumFrames();
    std::size_t added = 0;
    std::string error;
    if (!_scene->followFile(added, error))
    {
        if (error != _reportedError)
            std::cerr << PROGRAM << ": " << error << std::endl;
        _reportedError = error;
        return;
    }
    if (added == 0)
        return;
    const std::size_t newest = _scene->getNumFrames() - 1;
    std::cout << PROGRAM << ": frame " << newest << " completed" << std::endl;
    if (onLastFrame && _scene->setFrame(newest, error))
        aa.requestRedraw();
}

void ViewerEventHandler::stepFrame(int step)
{
    const std::size_t count = _scene->getNumFrames();
    if (count < 2)
    {
        std::cout << PROGRAM << ": there is only one frame" << std::endl;
        return;
    }
    const std::size_t frame = (_scene->getFrame() + count + step) % count;
    std::string error;
    if (_scene->setFrame(frame, error))
        std::cout << PROGRAM << ": frame " << frame << " of 0.." << count - 1 << std::endl;
    else
        std::cerr << PROGRAM << ": " << error << std::endl;
}

void ViewerEventHandler::getUsage(osg::ApplicationUsage& usage) const
{
    usage.addKeyboardMouseBinding("l", "Toggle lighting: glyphs lit or unlit, and OpenGL lighting");
    usage.addKeyboardMouseBinding("n", "Next frame of a multi-frame file");
    usage.addKeyboardMouseBinding("p", "Previous frame of a multi-frame file");
    usage.addKeyboardMouseBinding("r",
                                  "Reload the glyph shaders (from OSG_FILE_PATH, else the embedded ones)");
}
