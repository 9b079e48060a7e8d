#include <osgGlyphs/DepthPeeling>
#include <osgGlyphs/GlyphStateCache>

#include "../state/ContextRelease.h"
#include "../state/ViewState.h"
#include "PeelingPasses.h"

#include <osg/ContextData>
#include <osg/GLObjects>
#include <osgUtil/CullVisitor>

#include <algorithm>
#include <mutex>
#include <vector>

using namespace osgGlyphs;

DepthPeeling::DepthPeeling() = default;

DepthPeeling::DepthPeeling(const DepthPeeling& other, const osg::CopyOp& copyop)
    : osg::Group(other, copyop), _numLayers(other._numLayers), _method(other._method),
      _enabled(other._enabled)
{
}

DepthPeeling::~DepthPeeling() = default;

void DepthPeeling::setNumLayers(unsigned int layers)
{
    _numLayers = std::max(layers, 1u);
}

namespace
{

/** The passes of every graphics context, shared by the peeling nodes. */
struct ContextPasses
{
    std::mutex mutex;
    std::vector<osg::ref_ptr<detail::PeelingPasses>> passes;
};

ContextPasses& contextPasses()
{
    static ContextPasses s_passes;
    return s_passes;
}

/** Releases a context's passes, and forgets them, when OSG deletes or discards that context's
 * GL objects: a later context may reuse the ID. */
class PassesObserver : public detail::ContextRelease
{
public:
    explicit PassesObserver(unsigned int contextID)
        : detail::ContextRelease("osgGlyphs::DepthPeeling passes", contextID)
    {
    }

protected:
    void releaseContext() override
    {
        osg::ref_ptr<detail::PeelingPasses> passes;
        {
            ContextPasses& all = contextPasses();
            std::lock_guard<std::mutex> lock(all.mutex);
            if (getContextID() < all.passes.size())
                passes.swap(all.passes[getContextID()]);
        }
        if (!passes)
            return;
        osg::ref_ptr<osg::State> state = new osg::State;
        state->setContextID(getContextID());
        passes->releaseGLObjects(state.get());
    }
};

detail::PeelingPasses* getPasses(unsigned int contextID)
{
    osg::get<PassesObserver>(contextID);
    ContextPasses& all = contextPasses();
    std::lock_guard<std::mutex> lock(all.mutex);
    if (contextID >= all.passes.size())
        all.passes.resize(contextID + 1);
    if (!all.passes[contextID])
        all.passes[contextID] = new detail::PeelingPasses;
    return all.passes[contextID].get();
}

/** Whether the render stage being culled draws colour: not so a shadow map's, which takes the
 * children's depth as they are. */
bool drawsColor(osgUtil::CullVisitor& cv)
{
    const osg::Camera* camera = cv.getCurrentCamera();
    if (!camera || camera->getBufferAttachmentMap().empty())
        return true;
    for (const auto& attachment : camera->getBufferAttachmentMap())
        if (attachment.first != osg::Camera::DEPTH_BUFFER &&
            attachment.first != osg::Camera::STENCIL_BUFFER &&
            attachment.first != osg::Camera::PACKED_DEPTH_STENCIL_BUFFER)
            return true;
    return false;
}

}

void DepthPeeling::traverse(osg::NodeVisitor& nv)
{
    osgUtil::CullVisitor* cv = nv.asCullVisitor();
    if (!cv || !_enabled || !cv->getState() || !drawsColor(*cv))
    {
        osg::Group::traverse(nv);
        return;
    }
    detail::PeelingPasses* passes = getPasses(cv->getState()->getContextID());
    passes->setNumLayers(_numLayers);
    passes->setMethod(!detail::isSingleSampled(cv->getCurrentCamera(), cv->getState()) ? PEEL_PASSES
                                                                                       : _method,
                      cv->getViewport());
    cv->pushStateSet(passes->getPassStateSet());
    cv->getCurrentRenderBin()->setDrawCallback(passes->getDrawCallback().get());
    osg::Group::traverse(nv);
    cv->popStateSet();
}

void DepthPeeling::releaseGLObjects(osg::State* state) const
{
    osg::Group::releaseGLObjects(state);
    ContextPasses& all = contextPasses();
    std::lock_guard<std::mutex> lock(all.mutex);
    for (std::size_t contextID = 0; contextID < all.passes.size(); ++contextID)
        if (all.passes[contextID] && (!state || state->getContextID() == contextID))
            all.passes[contextID]->releaseGLObjects(state);
}

void DepthPeeling::resizeGLObjectBuffers(unsigned int maxSize)
{
    osg::Group::resizeGLObjectBuffers(maxSize);
    // The composition programs are shared by the contexts, outside the scene graph: sized here
    // (the viewer calls this before its threads start), or two contexts' first draws would
    // grow their per-context lists at once.
    GlyphStateCache::instance()->getPeelingCompositeProgram()->resizeGLObjectBuffers(maxSize);
    GlyphStateCache::instance()->getKBufferResolveProgram()->resizeGLObjectBuffers(maxSize);
    ContextPasses& all = contextPasses();
    std::lock_guard<std::mutex> lock(all.mutex);
    if (all.passes.size() < maxSize)
        all.passes.resize(maxSize);
}
