// osgglyphviewer: the viewer's own keys.

#ifndef OSGGLYPHVIEWER_VIEWEREVENTHANDLER_H
#define OSGGLYPHVIEWER_VIEWEREVENTHANDLER_H 1

#include "ViewerScene.h"

#include <osgGA/GUIEventHandler>

/** The keys of osgglyphviewer's window:
 * - l: glyphs lit or unlit. The event is left unhandled, so that an osgGA::StateSetManipulator
 *   added after this handler toggles OpenGL lighting of the other geometry with the same key;
 * - n, p: the next and the previous frame of a multi-frame file (wrapping around);
 * - r: re-reads the glyph shaders (osgGlyphs::GlyphStateCache::reloadShaders). */
class ViewerEventHandler : public osgGA::GUIEventHandler
{
public:
    explicit ViewerEventHandler(ViewerScene* scene) : _scene(scene) {}

    bool handle(const osgGA::GUIEventAdapter& ea, osgGA::GUIActionAdapter& aa) override;

    void getUsage(osg::ApplicationUsage& usage) const override;

protected:
    ~ViewerEventHandler() override = default;

    void stepFrame(int step);

    osg::ref_ptr<ViewerScene> _scene;
};

#endif
