#include "ViewerEventHandler.h"

#include "DatasetLoading.h"
#include "Timeline.h"
#include "ViewerPicking.h"

#include <osgGlyphs/GlyphStateCache>
#include <osgViewer/View>

#include <algorithm>
#include <cmath>
#include <iostream>

bool ViewerEventHandler::handle(const osgGA::GUIEventAdapter& ea, osgGA::GUIActionAdapter& aa)
{
    if (ea.getEventType() == osgGA::GUIEventAdapter::FRAME)
    {
        checkPrograms(aa);
        followFile(ea.getTime(), aa);
    }
    if (ea.getButton() == osgGA::GUIEventAdapter::LEFT_MOUSE_BUTTON && !ea.getHandled())
    {
        if (ea.getEventType() == osgGA::GUIEventAdapter::PUSH)
        {
            _pushX = ea.getX();
            _pushY = ea.getY();
        }
        else if (ea.getEventType() == osgGA::GUIEventAdapter::RELEASE &&
                 std::abs(ea.getX() - _pushX) <= 2.0f && std::abs(ea.getY() - _pushY) <= 2.0f)
            pickAt(ea, aa);
        return false; // the camera manipulator sees the clicks too
    }
    if (ea.getHandled() || ea.getEventType() != osgGA::GUIEventAdapter::KEYDOWN)
        return false;
    if (handlePlaybackKey(ea.getKey()))
    {
        aa.requestRedraw();
        return true;
    }
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
    case 'o':
        _scene->setAmbientOcclusion(!_scene->getAmbientOcclusion());
        std::cout << PROGRAM << ": ambient occlusion " << (_scene->getAmbientOcclusion() ? "on" : "off")
                  << std::endl;
        aa.requestRedraw();
        return true;
    case 'x':
    {
        Transparency* transparency = _scene->getTransparency();
        transparency->setOn(!transparency->isOn());
        std::cout << PROGRAM << ": transparency "
                  << (transparency->isOn() ? "at opacity " + std::to_string(transparency->getOpacity())
                                           : "off")
                  << std::endl;
        aa.requestRedraw();
        return true;
    }
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
    {
        showPick(); // the same point in the newest frame
        aa.requestRedraw();
    }
}

void ViewerEventHandler::pickAt(const osgGA::GUIEventAdapter& ea, osgGA::GUIActionAdapter& aa)
{
    osgViewer::View* view = dynamic_cast<osgViewer::View*>(&aa);
    const osg::Viewport* viewport = view ? view->getCamera()->getViewport() : nullptr;
    if (!viewport || !_scene)
        return;
    const double x = viewport->x() + (ea.getXnormalized() * 0.5 + 0.5) * viewport->width();
    const double y = viewport->y() + (ea.getYnormalized() * 0.5 + 0.5) * viewport->height();
    const GlyphPick pick = pickGlyph(*view, *_scene->getContent(), x, y);
    std::cout << PROGRAM << ": " << formatPick(pick) << std::endl;
    _picked = pick.valid();
    _pickedIndex = pick.index;
    showPick();
    aa.requestRedraw();
}

void ViewerEventHandler::showPick()
{
    if (osgGlyphs::GlyphCloud* cloud = _scene->getCloud())
        cloud->setSelection(_picked ? std::vector<unsigned int>{_pickedIndex} : std::vector<unsigned int>());
    if (_pickText.valid())
        _pickText->setText(_picked ? "glyph " + std::to_string(_pickedIndex) + ", frame " +
                                         std::to_string(_scene->getFrame()) + "\n" +
                                         _scene->describePoint(_pickedIndex)
                                   : std::string());
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
    {
        std::cout << PROGRAM << ": frame " << frame << " of 0.." << count - 1 << std::endl;
        showPick(); // the same point in this frame
    }
    else
        std::cerr << PROGRAM << ": " << error << std::endl;
}

bool ViewerEventHandler::handlePlaybackKey(int key)
{
    osgGlyphsData::FramePlayer* player = _scene ? _scene->getPlayer() : nullptr;
    if (!player || (_scene->getNumFrames() < 2 && player->isIndexComplete()))
        return false; // one frame: space stays the manipulator's home key
    switch (key)
    {
    case ' ':
        player->setPlaying(!player->isPlaying());
        break;
    case '+':
    case '=':
        player->setFramesPerSecond(std::min(player->getFramesPerSecond() * 1.5, 1000.0));
        break;
    case '-':
        player->setFramesPerSecond(std::max(player->getFramesPerSecond() / 1.5, 0.1));
        break;
    case ']':
        player->setStep(player->getStep() * 2);
        break;
    case '[':
        player->setStep(std::abs(player->getStep()) > 1 ? player->getStep() / 2 : player->getStep());
        break;
    case 'L':
        player->setLoop(!player->getLoop());
        break;
    case 'B':
        player->setStep(-player->getStep());
        break;
    case osgGA::GUIEventAdapter::KEY_Home:
        player->seek(0.0);
        break;
    case osgGA::GUIEventAdapter::KEY_End:
        player->seek(static_cast<double>(_scene->getNumFrames() - 1));
        break;
    default:
        return false;
    }
    std::cout << PROGRAM << ": " << describePlayback(*player) << std::endl;
    return true;
}

void ViewerEventHandler::getUsage(osg::ApplicationUsage& usage) const
{
    usage.addKeyboardMouseBinding("Space", "Play or pause a trajectory (with one frame: the camera's home)");
    usage.addKeyboardMouseBinding("+", "Play faster (x1.5)");
    usage.addKeyboardMouseBinding("-", "Play slower (/1.5)");
    usage.addKeyboardMouseBinding("]", "Play every other frame (the step doubles)");
    usage.addKeyboardMouseBinding("[", "Halve the step");
    usage.addKeyboardMouseBinding("B", "Play backwards or forwards");
    usage.addKeyboardMouseBinding("L", "Loop at the end, or stop");
    usage.addKeyboardMouseBinding("Home", "First frame");
    usage.addKeyboardMouseBinding("End", "Last frame");
    usage.addKeyboardMouseBinding("Timeline", "Click or drag on the bar at the bottom to go to a frame");
    usage.addKeyboardMouseBinding("l", "Toggle lighting: glyphs lit or unlit, and OpenGL lighting");
    usage.addKeyboardMouseBinding("x", "Toggle transparency: glyphs at the --opacity (default 0.5), blended "
                                       "in depth order by depth peeling, or opaque");
    usage.addKeyboardMouseBinding("n", "Next frame of a multi-frame file");
    usage.addKeyboardMouseBinding("p", "Previous frame of a multi-frame file");
    usage.addKeyboardMouseBinding("o", "Toggle ambient occlusion per glyph (--ao)");
    usage.addKeyboardMouseBinding("Mouse left click", "Pick a glyph: select it and show its point's values "
                                                      "(every column, in the current frame)");
    usage.addKeyboardMouseBinding("r",
                                  "Reload the glyph shaders (from OSG_FILE_PATH, else the embedded ones)");
}
