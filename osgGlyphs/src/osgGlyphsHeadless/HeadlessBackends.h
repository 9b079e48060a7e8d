/* osgGlyphs - private: the backends behind osgGlyphsHeadless::HeadlessContext. Not installed. */

#ifndef OSGGLYPHS_HEADLESSBACKENDS_H
#define OSGGLYPHS_HEADLESSBACKENDS_H 1

#include <osgGlyphsHeadless/HeadlessContext>

namespace osgGlyphsHeadless
{
namespace detail
{

HeadlessContext* createOSMesaContext(osg::GraphicsContext::Traits* traits);
HeadlessContext* createEGLContext(osg::GraphicsContext::Traits* traits);

/** Fills in what a headless context needs and a caller may have left out. */
void completeHeadlessTraits(osg::GraphicsContext::Traits& traits);

} // namespace detail
}

#endif
