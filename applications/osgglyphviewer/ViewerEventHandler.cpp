#include "ViewerEventHandler.h"

#include "DatasetLoading.h"
#include "ViewerPicking.h"

#include <osgGlyphs/GlyphStateCache>
#include <osgViewer/View>

#include <cmath>
#include <iostream>

bool ViewerEventHandler::handle(const osgGA::GUIEventAdapter& ea, osgGA::GUIActionAdapter& aa)
{
    if (ea.getEventType() == osgGA::GUIEventAdapter::FRAME)
    {
        checkPrograms(aa);
        followFile(ea.getTime(), aa);
    }
    if (ea.getButton() == osgGA::GUIEventAdapter::LEFT_MOUSE_BUTTON)
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

void ViewerEventHandler::getUsage(osg::ApplicationUsage& usage) const
{
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
