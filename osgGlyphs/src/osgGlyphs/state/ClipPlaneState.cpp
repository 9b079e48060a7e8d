#include "ClipPlaneState.h"
#include "GlyphDefines.h"

#include <osg/Uniform>
#include <osgUtil/StateGraph>

#include <array>
#include <vector>

using namespace osgGlyphs;

unsigned int osgGlyphs::detail::getClipPlaneMask(osgUtil::CullVisitor& cv)
{
    std::vector<const osg::StateSet*> path; // leaf first
    for (const osgUtil::StateGraph* graph = cv.getCurrentStateGraph(); graph; graph = graph->_parent)
        if (graph->getStateSet())
            path.push_back(graph->getStateSet());
    unsigned int mask = 0;
    for (unsigned int plane = 0; plane < MAX_GLYPH_CLIP_PLANES; ++plane)
    {
        // osg::State::pushModeList: an OVERRIDE above wins over what is not PROTECTED below.
        const osg::StateAttribute::GLMode mode = GL_CLIP_PLANE0 + plane;
        osg::StateAttribute::GLModeValue value = osg::StateAttribute::OFF;
        bool set = false;
        for (auto stateSet = path.rbegin(); stateSet != path.rend(); ++stateSet)
        {
            const osg::StateAttribute::GLModeValue own = (*stateSet)->getMode(mode);
            if (own & osg::StateAttribute::INHERIT)
                continue;
            if (!set || !(value & osg::StateAttribute::OVERRIDE) || (own & osg::StateAttribute::PROTECTED))
                value = own;
            set = true;
        }
        if (value & osg::StateAttribute::ON)
            mask |= 1u << plane;
    }
    return mask;
}

osg::StateSet* osgGlyphs::detail::getClipPlaneStateSet(unsigned int mask)
{
    static const auto stateSets = []
    {
        std::array<osg::ref_ptr<osg::StateSet>, 1u << MAX_GLYPH_CLIP_PLANES> all;
        for (unsigned int m = 0; m < all.size(); ++m)
        {
            all[m] = new osg::StateSet;
            all[m]->setName("osgGlyphs clip planes");
            all[m]->addUniform(new osg::Uniform("osgGlyphs_clipPlanes", static_cast<int>(m)));
            if (m != 0)
                all[m]->setDefine(CLIP_PLANES_DEFINE);
        }
        return all;
    }();
    return stateSets[mask & (stateSets.size() - 1)].get();
}
