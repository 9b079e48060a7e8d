#include "ScreenPass.h"

#include <osgGlyphs/GlyphStateCache>

#include <algorithm>

using namespace osgGlyphs;
using namespace osgGlyphs::detail;

namespace
{

const char* const AMBIENT_OCCLUSION_DEFINE = "OSGGLYPHS_SCREEN_AMBIENT_OCCLUSION";
const char* const OUTLINES_DEFINE = "OSGGLYPHS_SCREEN_OUTLINES";
const unsigned int COLOR_UNIT = 0, DEPTH_UNIT = 1;

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

template <class Value>
void setUniform(osg::StateSet& stateSet, const char* name, const Value& value)
{
    osg::Uniform* uniform = stateSet.getUniform(name);
    if (!uniform)
    {
        stateSet.addUniform(new osg::Uniform(name, value));
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
    : _color(createTarget(GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE)),
      _depth(createTarget(GL_DEPTH_COMPONENT32F, GL_DEPTH_COMPONENT, GL_FLOAT)),
      _triangle(createFullScreenTriangle()), _composite(new osg::StateSet)
{
    _camera = new osg::Camera;
    _camera->setName("osgGlyphs::ScreenEffects pass");
    _camera->setRenderOrder(osg::Camera::PRE_RENDER);
    _camera->setRenderTargetImplementation(osg::Camera::FRAME_BUFFER_OBJECT);
    _camera->setReferenceFrame(osg::Transform::ABSOLUTE_RF);
    _camera->setClearMask(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    _camera->setClearColor(osg::Vec4(0.0f, 0.0f, 0.0f, 0.0f));
    // The projection is set whole in each cull: the view's, with the children's near and far.
    _camera->setComputeNearFarMode(osg::CullSettings::DO_NOT_COMPUTE_NEAR_FAR);
    _camera->setInheritanceMask(_camera->getInheritanceMask() & ~osg::CullSettings::COMPUTE_NEAR_FAR_MODE &
                                ~osg::CullSettings::CLEAR_COLOR & ~osg::CullSettings::CLEAR_MASK &
                                ~osg::CullSettings::DRAW_BUFFER & ~osg::CullSettings::READ_BUFFER);
    _camera->attach(osg::Camera::COLOR_BUFFER, _color.get());
    _camera->attach(osg::Camera::DEPTH_BUFFER, _depth.get());
    _camera->setCullCallback(new CullContent(content));
    _camera->setDataVariance(osg::Object::DYNAMIC);

    _composite->setName("osgGlyphs::ScreenEffects composite");
    _composite->setDataVariance(osg::Object::DYNAMIC);
    _composite->setAttributeAndModes(GlyphStateCache::instance()->getScreenEffectsProgram());
    _composite->setTextureAttribute(COLOR_UNIT, _color.get());
    _composite->setTextureAttribute(DEPTH_UNIT, _depth.get());
    _composite->addUniform(new osg::Uniform("osgGlyphs_effectsColor", int(COLOR_UNIT)));
    _composite->addUniform(new osg::Uniform("osgGlyphs_effectsDepth", int(DEPTH_UNIT)));
    _composite->setMode(GL_BLEND, osg::StateAttribute::OFF);
    _composite->setMode(GL_CULL_FACE, osg::StateAttribute::OFF);
}

void ScreenPass::resize(int width, int height)
{
    const osg::Viewport* viewport = _camera->getViewport();
    if (viewport && int(viewport->width()) == width && int(viewport->height()) == height)
        return;
    _camera->setViewport(0, 0, width, height);
    for (osg::Texture2D* texture : {_color.get(), _depth.get()})
    {
        texture->setTextureSize(width, height);
        texture->dirtyTextureObject();
    }
    _camera->dirtyAttachmentMap();
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
    setUniform(stateSet, "osgGlyphs_effectsViewport",
               osg::Vec4(viewport.x(), viewport.y(), viewport.width(), viewport.height()));
    setUniform(stateSet, "osgGlyphs_effectsProjection", osg::Matrixf(projection));
    setUniform(stateSet, "osgGlyphs_effectsInverseProjection",
               osg::Matrixf(osg::Matrixd::inverse(projection)));
    setUniform(stateSet, "osgGlyphs_occlusionRadius", settings.occlusionRadius);
    setUniform(stateSet, "osgGlyphs_occlusionStrength", settings.occlusionStrength);
    setUniform(stateSet, "osgGlyphs_occlusionSamples", settings.occlusionSamples);
    setUniform(stateSet, "osgGlyphs_outlineWidth", settings.outlineWidth);
    setUniform(stateSet, "osgGlyphs_outlineColor", settings.outlineColor);
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
    cv.pushStateSet(_composite.get());
    cv.addDrawableAndDepth(_triangle.get(), cv.getModelViewMatrix(), 0.0f);
    cv.popStateSet();
}

void ScreenPass::resizeGLObjectBuffers(unsigned int maxSize)
{
    _camera->resizeGLObjectBuffers(maxSize);
    _color->resizeGLObjectBuffers(maxSize);
    _depth->resizeGLObjectBuffers(maxSize);
    _triangle->resizeGLObjectBuffers(maxSize);
    _composite->resizeGLObjectBuffers(maxSize);
}

void ScreenPass::releaseGLObjects(osg::State* state) const
{
    _camera->releaseGLObjects(state);
    _color->releaseGLObjects(state);
    _depth->releaseGLObjects(state);
    _triangle->releaseGLObjects(state);
    _composite->releaseGLObjects(state);
}
