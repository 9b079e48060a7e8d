/* osgGlyphs - private: the pass of a ScreenEffects node in one view. Not installed. */

#ifndef OSGGLYPHS_SCREENPASS_H
#define OSGGLYPHS_SCREENPASS_H 1

#include <osg/Camera>
#include <osg/Geometry>
#include <osg/Group>
#include <osg/Texture2D>
#include <osgUtil/CullVisitor>

namespace osgGlyphs
{
namespace detail
{

/** The values of the effects a pass applies (see ScreenEffects). */
struct ScreenEffectsSettings
{
    bool ambientOcclusion = false;
    float occlusionRadius = 1.0f;
    float occlusionStrength = 1.0f;
    int occlusionSamples = 16;
    bool outlines = false;
    float outlineWidth = 1.0f;
    osg::Vec4 outlineColor;
};

/** A group's children drawn, in one view, into a colour and a depth texture of the viewport's
 * size by a pre-render camera; with ambient occlusion, a second one that draws each pixel's
 * occlusion into a third texture; and a full-screen triangle that composites them back into the
 * view with the effects (the occlusion blurred over the 4x4 pixels its sample pattern repeats
 * over). The pass's objects change in the cull traversal: they are DYNAMIC, so
 * that the next frame is not culled while this one is drawn. */
class ScreenPass : public osg::Referenced
{
public:
    /** The pass of content's children; content must outlive it. */
    explicit ScreenPass(osg::Group& content);

    /** Culls the children, of that bound, into the textures and the composite into the current
     * render bin. */
    void cull(osgUtil::CullVisitor& cv, const osg::BoundingSphere& bound,
              const ScreenEffectsSettings& settings);

    void resizeGLObjectBuffers(unsigned int maxSize);
    void releaseGLObjects(osg::State* state) const;

protected:
    ~ScreenPass() override = default;

    void resize(int width, int height);
    /** The projection of the children: the view's, with near and far planes around the bound. */
    bool computeProjection(osgUtil::CullVisitor& cv, const osg::BoundingSphere& bound,
                           osg::Matrixd& projection) const;
    void updateComposite(const osg::Viewport& viewport, const osg::Matrixd& projection,
                         const ScreenEffectsSettings& settings);

    osg::ref_ptr<osg::Camera> _camera;
    osg::ref_ptr<osg::Camera> _occlusionCamera;
    osg::ref_ptr<osg::Texture2D> _color;
    osg::ref_ptr<osg::Texture2D> _depth;
    osg::ref_ptr<osg::Texture2D> _occlusion;
    osg::ref_ptr<osg::Geometry> _triangle;
    osg::ref_ptr<osg::StateSet> _composite;
    osg::ref_ptr<osg::StateSet> _occlusionPass;
};

}
}

#endif
