#include "ViewerEventHandler.h"

#include <osgGlyphs/GlyphStateCache>

#include <iostream>

bool ViewerEventHandler::handle(const osgGA::GUIEventAdapter& ea, osgGA::GUIActionAdapter& aa)
{
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
        std::cout << PROGRAM << ": reloaded the glyph shaders" << std::endl;
        aa.requestRedraw();
        return true;
    default:
        return false;
    }
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
