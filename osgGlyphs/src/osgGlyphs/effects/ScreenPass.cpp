#include "ScreenPass.h"

#include <osgGlyphs/GlyphStateCache>

#include <osg/BlendFunc>
#include <osg/Geode>

#include <algorithm>

using namespace osgGlyphs;
using namespace osgGlyphs::detail;

namespace
{

const char* const AMBIENT_OCCLUSION_DEFINE = "OSGGLYPHS_SCREEN_AMBIENT_OCCLUSION";
const char* const OUTLINES_DEFINE = "OSGGLYPHS_SCREEN_OUTLINES";
const char* const OCCLUSION_PASS_DEFINE = "OSGGLYPHS_SCREEN_OCCLUSION_PASS";

/** Culls a group's children in place of the camera's (it has none): the group stays their only
 * parent, so their world matrices and node paths are the scene's. */
class CullContent : public osg::NodeCallback
{
public:
    explicit CullContent(osg::Group& content) : _content(content) {}
    void operator()(osg::Node*, osg::NodeVisitor* nv) override { _content.osg::Group::traverse(*nv); }

private:
    osg::Group& _content;
};

osg::ref_ptr<osg::Texture2D> createTarget(GLint internalFormat, GLenum sourceFormat, GLenum sourceType)
{
    osg::ref_ptr<osg::Texture2D> texture = new osg::Texture2D;
    texture->setInternalFormat(internalFormat);
    texture->setSourceFormat(sourceFormat);
    texture->setSourceType(sourceType);
    texture->setFilter(osg::Texture::MIN_FILTER, osg::Texture::NEAREST);
    texture->setFilter(osg::Texture::MAG_FILTER, osg::Texture::NEAREST);
    texture->setWrap(osg::Texture::WRAP_S, osg::Texture::CLAMP_TO_EDGE);
    texture->setWrap(osg::Texture::WRAP_T, osg::Texture::CLAMP_TO_EDGE);
    texture->setResizeNonPowerOfTwoHint(false);
    texture->setDataVariance(osg::Object::DYNAMIC);
    return texture;
}

osg::ref_ptr<osg::Geometry> createFullScreenTriangle()
{
    osg::ref_ptr<osg::Geometry> triangle = new osg::Geometry;
    osg::ref_ptr<osg::Vec3Array> corners = new osg::Vec3Array;
    corners->push_back(osg::Vec3(-1.0f, -1.0f, 0.0f));
    corners->push_back(osg::Vec3(3.0f, -1.0f, 0.0f));
    corners->push_back(osg::Vec3(-1.0f, 3.0f, 0.0f));
    triangle->setVertexArray(corners.get());
    triangle->addPrimitiveSet(new osg::DrawArrays(GL_TRIANGLES, 0, 3));
    triangle->setUseDisplayList(false);
    triangle->setUseVertexBufferObjects(true);
    triangle->setCullingActive(false);
    triangle->setDataVariance(osg::Object::DYNAMIC);
    return triangle;
}

/** A pre-render camera of its own viewport that draws into textures, culled with the matrices it is
 * given: no near and far planes of its own, and no clear settings from the view. */
osg::ref_ptr<osg::Camera> createTargetCamera(const std::string& name, int order)
{
    osg::ref_ptr<osg::Camera> camera = new osg::Camera;
    camera->setName(name);
    camera->setRenderOrder(osg::Camera::PRE_RENDER, order);
    camera->setRenderTargetImplementation(osg::Camera::FRAME_BUFFER_OBJECT);
    camera->setReferenceFrame(osg::Transform::ABSOLUTE_RF);
    camera->setComputeNearFarMode(osg::CullSettings::DO_NOT_COMPUTE_NEAR_FAR);
    camera->setInheritanceMask(camera->getInheritanceMask() & ~osg::CullSettings::COMPUTE_NEAR_FAR_MODE &
                               ~osg::CullSettings::CLEAR_COLOR & ~osg::CullSettings::CLEAR_MASK &
                               ~osg::CullSettings::DRAW_BUFFER & ~osg::CullSettings::READ_BUFFER);
    camera->setDataVariance(osg::Object::DYNAMIC);
    return camera;
}

/** A StateSet of the effects' program that reads the textures of the units given. */
osg::ref_ptr<osg::StateSet> createEffectsStateSet(const std::string& name)
{
    osg::ref_ptr<osg::StateSet> stateSet = new osg::StateSet;
    stateSet->setName(name);
    stateSet->setDataVariance(osg::Object::DYNAMIC);
    stateSet->setAttributeAndModes(GlyphStateCache::instance()->getScreenEffectsProgram());
    stateSet->setMode(GL_BLEND, osg::StateAttribute::OFF);
    stateSet->setMode(GL_CULL_FACE, osg::StateAttribute::OFF);
    return stateSet;
}

/** Sets the value of a uniform that the composite and the occlusion pass share. */
template <class Value>
void setUniform(osg::StateSet& composite, osg::StateSet& occlusion, const char* name, const Value& value)
{
    osg::Uniform* uniform = composite.getUniform(name);
    if (!uniform)
    {
        osg::ref_ptr<osg::Uniform> created = new osg::Uniform(name, value);
        composite.addUniform(created.get());
        occlusion.addUniform(created.get());
        return;
    }
    Value current;
    if (!uniform->get(current) || current != value)
        uniform->set(value);
}

void setDefine(osg::StateSet& stateSet, const char* name, bool on)
{
    if (on)
        stateSet.setDefine(name);
    else
        stateSet.removeDefine(name);
}

}

ScreenPass::ScreenPass(osg::Group& content)
    : _camera(createTargetCamera("osgGlyphs::ScreenEffects children", 0)),
      _occlusionCamera(createTargetCamera("osgGlyphs::ScreenEffects occlusion", 1)),
      _color(createTarget(GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE)),
      _depth(createTarget(GL_DEPTH_COMPONENT32F, GL_DEPTH_COMPONENT, GL_FLOAT)),
      _occlusion(createTarget(GL_R8, GL_RED, GL_UNSIGNED_BYTE)), _triangle(createFullScreenTriangle()),
      _composite(createEffectsStateSet("osgGlyphs::ScreenEffects composite")),
      _occlusionPass(createEffectsStateSet("osgGlyphs::ScreenEffects occlusion"))
{
    _camera->setClearMask(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    _camera->setClearColor(osg::Vec4(0.0f, 0.0f, 0.0f, 0.0f));
    _camera->attach(osg::Camera::COLOR_BUFFER, _color.get());
    _camera->attach(osg::Camera::DEPTH_BUFFER, _depth.get());
    _camera->setCullCallback(new CullContent(content));

    // The occlusion of each pixel, drawn after the children and blurred by the composite.
    _occlusionCamera->setClearMask(GL_COLOR_BUFFER_BIT);
    _occlusionCamera->setClearColor(osg::Vec4(1.0f, 1.0f, 1.0f, 1.0f));
    _occlusionCamera->attach(osg::Camera::COLOR_BUFFER, _occlusion.get());
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    geode->addDrawable(_triangle.get());
    geode->setStateSet(_occlusionPass.get());
    _occlusionCamera->addChild(geode.get());
    _occlusionPass->setDefine(OCCLUSION_PASS_DEFINE);
    _occlusionPass->setDefine(AMBIENT_OCCLUSION_DEFINE);
    _occlusionPass->setMode(GL_DEPTH_TEST, osg::StateAttribute::OFF);

    for (osg::StateSet* stateSet : {_composite.get(), _occlusionPass.get()})
    {
        stateSet->setTextureAttribute(SCREEN_COLOR_TEXTURE_UNIT, _color.get());
        stateSet->setTextureAttribute(SCREEN_DEPTH_TEXTURE_UNIT, _depth.get());
        stateSet->addUniform(new osg::Uniform("osgGlyphs_effectsColor", int(SCREEN_COLOR_TEXTURE_UNIT)));
        stateSet->addUniform(new osg::Uniform("osgGlyphs_effectsDepth", int(SCREEN_DEPTH_TEXTURE_UNIT)));
    }
    // The children's colour is premultiplied by its alpha, their coverage: transparent children
    // (DepthPeeling) blend over what the view drew outside the node.
    _composite->setAttributeAndModes(new osg::BlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA));
    _composite->setTextureAttribute(SCREEN_OCCLUSION_TEXTURE_UNIT, _occlusion.get());
    _composite->addUniform(
        new osg::Uniform("osgGlyphs_effectsOcclusion", int(SCREEN_OCCLUSION_TEXTURE_UNIT)));
}

void ScreenPass::resize(int width, int height)
{
    const osg::Viewport* viewport = _camera->getViewport();
    if (viewport && int(viewport->width()) == width && int(viewport->height()) == height)
        return;
    for (osg::Camera* camera : {_camera.get(), _occlusionCamera.get()})
    {
        camera->setViewport(0, 0, width, height);
        camera->dirtyAttachmentMap();
    }
    for (osg::Texture2D* texture : {_color.get(), _depth.get(), _occlusion.get()})
    {
        texture->setTextureSize(width, height);
        texture->dirtyTextureObject();
    }
}

bool ScreenPass::computeProjection(osgUtil::CullVisitor& cv, const osg::BoundingSphere& bound,
                                   osg::Matrixd& projection) const
{
    const osg::Matrixd& modelView = *cv.getModelViewMatrix();
    const osg::Vec3d center = osg::Vec3d(bound.center()) * modelView;
    const osg::Vec3d scale = modelView.getScale();
    const double radius = bound.radius() * std::max(scale.x(), std::max(scale.y(), scale.z()));
    osgUtil::CullVisitor::value_type zNear = -center.z() - radius, zFar = -center.z() + radius;
    if (zFar <= 0.0)
        return false;
    projection = *cv.getProjectionMatrix();
    return cv.clampProjectionMatrix(projection, zNear, zFar);
}

void ScreenPass::updateComposite(const osg::Viewport& viewport, const osg::Matrixd& projection,
                                 const ScreenEffectsSettings& settings)
{
    osg::StateSet& stateSet = *_composite;
    setDefine(stateSet, AMBIENT_OCCLUSION_DEFINE, settings.ambientOcclusion);
    setDefine(stateSet, OUTLINES_DEFINE, settings.outlines);
    setUniform(stateSet, *_occlusionPass, "osgGlyphs_effectsViewport",
               osg::Vec4(viewport.x(), viewport.y(), viewport.width(), viewport.height()));
    setUniform(stateSet, *_occlusionPass, "osgGlyphs_effectsProjection", osg::Matrixf(projection));
    setUniform(stateSet, *_occlusionPass, "osgGlyphs_effectsInverseProjection",
               osg::Matrixf(osg::Matrixd::inverse(projection)));
    setUniform(stateSet, *_occlusionPass, "osgGlyphs_occlusionRadius", settings.occlusionRadius);
    setUniform(stateSet, *_occlusionPass, "osgGlyphs_occlusionStrength", settings.occlusionStrength);
    setUniform(stateSet, *_occlusionPass, "osgGlyphs_occlusionSamples", settings.occlusionSamples);
    setUniform(stateSet, *_occlusionPass, "osgGlyphs_outlineWidth", settings.outlineWidth);
    setUniform(stateSet, *_occlusionPass, "osgGlyphs_outlineColor", settings.outlineColor);
}

void ScreenPass::cull(osgUtil::CullVisitor& cv, const osg::BoundingSphere& bound,
                      const ScreenEffectsSettings& settings)
{
    const osg::Viewport* viewport = cv.getViewport();
    osg::Matrixd projection;
    if (!viewport || viewport->width() < 1.0 || viewport->height() < 1.0 || !bound.valid() ||
        !computeProjection(cv, bound, projection))
        return;
    resize(int(viewport->width()), int(viewport->height()));

    // The view's own near and far planes, when it computes them, must hold the children.
    const osg::Vec3 extent(bound.radius(), bound.radius(), bound.radius());
    cv.updateCalculatedNearFar(*cv.getModelViewMatrix(),
                               osg::BoundingBox(bound.center() - extent, bound.center() + extent));

    _camera->setViewMatrix(*cv.getModelViewMatrix());
    _camera->setProjectionMatrix(projection);
    _camera->accept(cv);
    updateComposite(*viewport, projection, settings);
    if (settings.ambientOcclusion)
        _occlusionCamera->accept(cv);

    cv.pushStateSet(_composite.get());
    cv.addDrawableAndDepth(_triangle.get(), cv.getModelViewMatrix(), 0.0f);
    cv.popStateSet();
}

void ScreenPass::resizeGLObjectBuffers(unsigned int maxSize)
{
    for (osg::Camera* camera : {_camera.get(), _occlusionCamera.get()})
        camera->resizeGLObjectBuffers(maxSize);
    for (osg::Texture2D* texture : {_color.get(), _depth.get(), _occlusion.get()})
        texture->resizeGLObjectBuffers(maxSize);
    _triangle->resizeGLObjectBuffers(maxSize);
    _composite->resizeGLObjectBuffers(maxSize);
    _occlusionPass->resizeGLObjectBuffers(maxSize);
}

void ScreenPass::releaseGLObjects(osg::State* state) const
{
    for (const osg::Camera* camera : {_camera.get(), _occlusionCamera.get()})
        camera->releaseGLObjects(state);
    for (const osg::Texture2D* texture : {_color.get(), _depth.get(), _occlusion.get()})
        texture->releaseGLObjects(state);
    _triangle->releaseGLObjects(state);
    _composite->releaseGLObjects(state);
    _occlusionPass->releaseGLObjects(state);
}
