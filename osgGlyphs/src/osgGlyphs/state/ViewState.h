/* osgGlyphs - private: the values of the view being culled, as uniforms. Not installed. */

#ifndef OSGGLYPHS_VIEWSTATE_H
#define OSGGLYPHS_VIEWSTATE_H 1

#include <osg/StateSet>
#include <osgUtil/CullVisitor>

namespace osgGlyphs
{
namespace detail
{

/** The StateSet of the view the cull visitor culls: the viewport (osgGlyphs_viewport) and
 * whether the target has one sample per pixel (osgGlyphs_singleSample). It belongs to the
 * render stage being filled, and is updated while that stage is culled: a stage is never drawn
 * while it is culled, so views of any size, in any threading model, each draw with their own. */
osg::StateSet* getViewStateSet(osgUtil::CullVisitor& cv);

/** Whether the camera's target has one sample per pixel: an FBO camera's attachments, else
 * the context's traits. Unsure (no context) counts as multisampled. */
bool isSingleSampled(const osg::Camera* camera, const osg::State* state);

}
}

#endif
