// osgglyphviewer: the timeline of a trajectory, drawn over the view; a click or drag on it seeks.

#ifndef OSGGLYPHVIEWER_TIMELINE_H
#define OSGGLYPHVIEWER_TIMELINE_H 1

#include <osgGlyphsData/FramePlayer>

#include <osg/Camera>
#include <osgGA/GUIEventHandler>

#include <string>

/** One line on the player's state: "frame 12 of 31 · timestep 1200 · playing at 10 frames/s". */
std::string describePlayback(const osgGlyphsData::FramePlayer& player);

/** The timeline at the bottom of the view: a bar with the played part filled and a marker at
 * the picture shown, and the line of describePlayback() above it. It follows the player every
 * frame and the viewport of reference when it changes size.
 *
 * As an event handler, a left click on the bar seeks to the frame under the mouse, and dragging
 * along it scrubs; those events are handled, so that the camera manipulator and picking do not
 * see them. */
class Timeline : public osgGA::GUIEventHandler
{
public:
    Timeline(osgGlyphsData::FramePlayer* player, osg::Camera* reference, const osg::Vec4& background);

    /** The HUD camera to add to the scene. */
    osg::Camera* getHud() const { return _hud.get(); }

    bool handle(const osgGA::GUIEventAdapter& ea, osgGA::GUIActionAdapter& aa) override;

    /** The bar's extent in window pixels (from the bottom left), for tests and the layout. */
    struct Bar
    {
        float x0 = 0.0f, x1 = 0.0f, y0 = 0.0f, y1 = 0.0f;
    };
    static Bar layoutBar(int width, int height);

protected:
    ~Timeline() override = default;

    /** Seeks to the frame at window x; true when (x, y) is on the bar or a drag goes on. */
    bool seekAt(float x, float y, bool dragging);

    osg::ref_ptr<osgGlyphsData::FramePlayer> _player;
    osg::ref_ptr<osg::Camera> _hud;
    osg::observer_ptr<osg::Camera> _reference;
    bool _dragging = false;
};

#endif
