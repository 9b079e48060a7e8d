#include <osgGlyphs/ScreenEffects>

#include <osgGlyphs/GlyphCloud>

#include "ScreenPass.h"

#include <osg/NodeVisitor>
#include <osgUtil/CullVisitor>

#include <algorithm>
#include <cmath>

using namespace osgGlyphs;

namespace
{

/** The automatic occlusion radius in mean glyph radii, as per-glyph occlusion reaches. */
const float OCCLUSION_RADIUS_IN_GLYPH_RADII = 2.0f;
/** Without glyph clouds, the automatic occlusion radius as a fraction of the bounding radius. */
const float OCCLUSION_RADIUS_IN_BOUNDING_RADII = 0.02f;
/** Radii read per cloud for the mean: evenly spread, enough for a mean. */
const unsigned int MEAN_RADIUS_SAMPLES = 4096;

/** The mean radius of the glyphs of the clouds below a node, and how many clouds have glyphs. */
class MeanGlyphRadius : public osg::NodeVisitor
{
public:
    MeanGlyphRadius() : osg::NodeVisitor(TRAVERSE_ALL_CHILDREN) {}

    void apply(osg::Drawable& drawable) override
    {
        const auto* cloud = dynamic_cast<const GlyphCloud*>(&drawable);
        if (!cloud || cloud->getNumGlyphs() == 0)
            return;
        const osg::FloatArray* radii = cloud->getRadii();
        if (!radii || radii->empty())
        {
            add(cloud->getRadius());
            return;
        }
        const std::size_t step = std::max<std::size_t>(1, radii->size() / MEAN_RADIUS_SAMPLES);
        for (std::size_t i = 0; i < radii->size(); i += step)
            add((*radii)[i]);
    }

    float mean() const { return _count ? float(_sum / _count) : 0.0f; }

private:
    void add(float radius)
    {
        if (std::isfinite(radius) && radius > 0.0f)
        {
            _sum += radius;
            ++_count;
        }
    }

    double _sum = 0.0;
    unsigned long _count = 0;
};

}

ScreenEffects::ScreenEffects() = default;

ScreenEffects::ScreenEffects(const ScreenEffects& other, const osg::CopyOp& copyop)
    : osg::Group(other, copyop), _ambientOcclusion(other._ambientOcclusion),
      _occlusionRadius(other._occlusionRadius), _occlusionStrength(other._occlusionStrength),
      _occlusionSamples(other._occlusionSamples), _outlines(other._outlines),
      _outlineWidth(other._outlineWidth), _outlineColor(other._outlineColor)
{
}

ScreenEffects::~ScreenEffects() = default;

void ScreenEffects::setOcclusionSamples(unsigned int samples)
{
    _occlusionSamples = std::min(std::max(samples, 1u), MAX_OCCLUSION_SAMPLES);
}

void ScreenEffects::setOutlineWidth(float pixels)
{
    _outlineWidth = std::isfinite(pixels) ? std::max(pixels, 1.0f) : 1.0f;
}

float ScreenEffects::computeOcclusionRadius() const
{
    if (_occlusionRadius > 0.0f)
        return _occlusionRadius;
    const osg::BoundingSphere& bound = getBound();
    std::lock_guard<std::mutex> lock(_mutex);
    if (_automaticRadius <= 0.0f || _automaticRadiusBound != bound)
    {
        MeanGlyphRadius mean;
        const_cast<ScreenEffects*>(this)->osg::Group::traverse(mean);
        _automaticRadius = mean.mean() > 0.0f ? OCCLUSION_RADIUS_IN_GLYPH_RADII * mean.mean()
                                              : OCCLUSION_RADIUS_IN_BOUNDING_RADII * bound.radius();
        _automaticRadiusBound = bound;
    }
    return _automaticRadius;
}

namespace
{

/** Whether a camera renders depth only, as shadow maps do: effects there are wasted. */
bool rendersDepthOnly(const osg::Camera* camera)
{
    if (!camera)
        return false;
    const osg::Camera::BufferAttachmentMap& attachments = camera->getBufferAttachmentMap();
    return attachments.count(osg::Camera::DEPTH_BUFFER) && !attachments.count(osg::Camera::COLOR_BUFFER) &&
           !attachments.count(osg::Camera::COLOR_BUFFER0);
}

}

void ScreenEffects::traverse(osg::NodeVisitor& nv)
{
    osgUtil::CullVisitor* cv =
        nv.getVisitorType() == osg::NodeVisitor::CULL_VISITOR ? nv.asCullVisitor() : nullptr;
    if (cv && hasEffects() && !rendersDepthOnly(cv->getCurrentCamera()))
        cullWithEffects(*cv);
    else
        osg::Group::traverse(nv);
}

detail::ScreenPass* ScreenEffects::getPass(osgUtil::CullVisitor& cv)
{
    std::lock_guard<std::mutex> lock(_mutex);
    for (auto view = _views.begin(); view != _views.end();)
        view = view->second.visitor.valid() ? std::next(view) : _views.erase(view);
    ViewPasses& view = _views[&cv];
    if (!view.visitor.valid() || view.traversal != cv.getTraversalNumber())
    {
        view.visitor = &cv;
        view.traversal = cv.getTraversalNumber();
        view.used = 0;
    }
    if (view.used == view.passes.size())
        view.passes.push_back(new detail::ScreenPass(*this));
    return view.passes[view.used++].get();
}

void ScreenEffects::cullWithEffects(osgUtil::CullVisitor& cv)
{
    detail::ScreenEffectsSettings settings;
    settings.ambientOcclusion = _ambientOcclusion;
    settings.occlusionRadius = _ambientOcclusion ? computeOcclusionRadius() : 1.0f;
    settings.occlusionStrength = std::min(std::max(_occlusionStrength, 0.0f), 1.0f);
    settings.occlusionSamples = int(_occlusionSamples);
    settings.outlines = _outlines;
    settings.outlineWidth = _outlineWidth;
    settings.outlineColor = _outlineColor;
    getPass(cv)->cull(cv, getBound(), settings);
}

void ScreenEffects::resizeGLObjectBuffers(unsigned int maxSize)
{
    osg::Group::resizeGLObjectBuffers(maxSize);
    std::lock_guard<std::mutex> lock(_mutex);
    for (auto& view : _views)
        for (const auto& pass : view.second.passes)
            pass->resizeGLObjectBuffers(maxSize);
}

void ScreenEffects::releaseGLObjects(osg::State* state) const
{
    osg::Group::releaseGLObjects(state);
    std::lock_guard<std::mutex> lock(_mutex);
    for (const auto& view : _views)
        for (const auto& pass : view.second.passes)
            pass->releaseGLObjects(state);
}
