// osgglyphviewer: the viewer's own keys.

#ifndef OSGGLYPHVIEWER_VIEWEREVENTHANDLER_H
#define OSGGLYPHVIEWER_VIEWEREVENTHANDLER_H 1

#include "ViewerScene.h"

#include <osgGA/GUIEventHandler>
#include <osgText/Text>

/** The keys of osgglyphviewer's window:
 * - l: glyphs lit or unlit. The event is left unhandled, so that an osgGA::StateSetManipulator
 *   added after this handler toggles OpenGL lighting of the other geometry with the same key;
 * - n, p: the next and the previous frame of a multi-frame file (wrapping around);
 * - space, +, -, [, ], B, L, Home, End: a trajectory's playback (see getUsage());
 * - r: re-reads the glyph shaders (osgGlyphs::GlyphStateCache::reloadShaders);
 * - a left click without a drag picks the glyph under the mouse: it is selected (drawn tinted),
 *   its point's columns in the current frame show in the pick text, and its pick line
 *   (formatPick) is printed; a click on no glyph clears both.
 *
 * After every frame it looks for a glyph program that failed to compile or link and prints its
 * line: with the shaders the viewer started with, that ends the viewer (exit code 1); after r,
 * the window stays open for the next attempt. */
class ViewerEventHandler : public osgGA::GUIEventHandler
{
public:
    explicit ViewerEventHandler(ViewerScene* scene) : _scene(scene) {}

    bool handle(const osgGA::GUIEventAdapter& ea, osgGA::GUIActionAdapter& aa) override;

    void getUsage(osg::ApplicationUsage& usage) const override;

    /** The HUD text that shows the picked point. */
    void setPickText(osgText::Text* text) { _pickText = text; }

    /** 1 when a glyph program failed with the shaders the viewer started with, else 0. */
    int getExitCode() const { return _exitCode; }

protected:
    ~ViewerEventHandler() override = default;

    void stepFrame(int step);
    /** The keys of a trajectory's playback; false for another key, or without a trajectory. */
    bool handlePlaybackKey(int key);
    void checkPrograms(osgGA::GUIActionAdapter& aa);
    /** --follow: reads the frames the file completed, and shows the newest while the last is shown. */
    void followFile(double time, osgGA::GUIActionAdapter& aa);
    void pickAt(const osgGA::GUIEventAdapter& ea, osgGA::GUIActionAdapter& aa);
    /** Selects the picked glyph in the current frame and shows its point, or clears both. */
    void showPick();

    osg::ref_ptr<ViewerScene> _scene;
    bool _reloaded = false;
    std::string _reportedError;
    int _exitCode = 0;
    double _nextPoll = 0.0;
    osg::ref_ptr<osgText::Text> _pickText;
    float _pushX = 0.0f, _pushY = 0.0f;
    bool _picked = false;
    unsigned int _pickedIndex = 0;
};

#endif
