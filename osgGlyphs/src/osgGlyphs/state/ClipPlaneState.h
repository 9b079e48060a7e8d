/* osgGlyphs - private: which of OSG's clip planes are on where a cloud is culled. Not installed. */

#ifndef OSGGLYPHS_CLIPPLANESTATE_H
#define OSGGLYPHS_CLIPPLANESTATE_H 1

#include <osg/StateSet>
#include <osgUtil/CullVisitor>

namespace osgGlyphs
{
namespace detail
{

/** The clip planes OSG numbers, and glyph shaders cut by (clip.glsl). */
const unsigned int MAX_GLYPH_CLIP_PLANES = 8;

/** Bit i set where the StateSets on the cull visitor's current state graph path, as OSG will apply
 * them (OVERRIDE and PROTECTED included), turn GL_CLIP_PLANE0 + i on. */
unsigned int getClipPlaneMask(osgUtil::CullVisitor& cv);

/** A shared StateSet that gives the glyph programs that mask (osgGlyphs_clipPlanes), and the
 * OSGGLYPHS_CLIP_PLANES define where it is not 0. */
osg::StateSet* getClipPlaneStateSet(unsigned int mask);

}
}

#endif
