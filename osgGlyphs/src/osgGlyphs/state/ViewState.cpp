#include "ViewState.h"

#include <osg/GraphicsContext>
#include <osg/UserDataContainer>
#include <osgUtil/RenderStage>

namespace
{

const char* const VIEW_STATE_NAME = "osgGlyphs view state";

osg::ref_ptr<osg::StateSet> createViewStateSet()
{
    osg::ref_ptr<osg::StateSet> stateSet = new osg::StateSet;
    stateSet->setName(VIEW_STATE_NAME);
    stateSet->addUniform(new osg::Uniform("osgGlyphs_viewport", osg::Vec4(0.0f, 0.0f, 1.0f, 1.0f)));
    stateSet->addUniform(new osg::Uniform("osgGlyphs_singleSample", false));
    return stateSet;
}

/** Sets the uniform's value when it differs, so that an unchanged view applies nothing new. */
template <class Value>
void update(osg::Uniform& uniform, const Value& value)
{
    Value current;
    if (!uniform.get(current) || current != value)
        uniform.set(value);
}

}

osg::StateSet* osgGlyphs::detail::getViewStateSet(osgUtil::CullVisitor& cv)
{
    // Clouds of one render stage share its view state. (A per-thread cache keyed by the stage's
    // and the visitor's addresses could hand a later stage at the same address a dead one's.)
    osgUtil::RenderStage* stage = cv.getCurrentRenderStage();
    osg::UserDataContainer* container = stage->getOrCreateUserDataContainer();
    osg::StateSet* stateSet = dynamic_cast<osg::StateSet*>(container->getUserObject(VIEW_STATE_NAME));
    if (!stateSet)
    {
        osg::ref_ptr<osg::StateSet> created = createViewStateSet();
        container->addUserObject(created.get());
        stateSet = created.get();
    }
    if (const osg::Viewport* viewport = cv.getViewport())
        update(*stateSet->getUniform("osgGlyphs_viewport"),
               osg::Vec4(viewport->x(), viewport->y(), viewport->width(), viewport->height()));
    update(*stateSet->getUniform("osgGlyphs_singleSample"),
           isSingleSampled(cv.getCurrentCamera(), cv.getState()));
    return stateSet;
}

bool osgGlyphs::detail::isSingleSampled(const osg::Camera* camera, const osg::State* state)
{
    if (camera && camera->getRenderTargetImplementation() == osg::Camera::FRAME_BUFFER_OBJECT &&
        !camera->getBufferAttachmentMap().empty())
    {
        for (const auto& attachment : camera->getBufferAttachmentMap())
            if (attachment.second._multisampleSamples > 0)
                return false;
        return true;
    }
    const osg::GraphicsContext* context = state ? state->getGraphicsContext() : nullptr;
    return context && context->getTraits() && context->getTraits()->samples == 0;
}
