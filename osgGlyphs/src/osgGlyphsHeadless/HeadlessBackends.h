/* osgGlyphs - private: the backends behind osgGlyphsHeadless::HeadlessContext. Not installed. */

#ifndef OSGGLYPHS_HEADLESSBACKENDS_H
#define OSGGLYPHS_HEADLESSBACKENDS_H 1

#include <osgGlyphsHeadless/HeadlessContext>

namespace osgGlyphsHeadless
{
namespace detail
{

HeadlessContext* createOSMesaContext(osg::GraphicsContext::Traits* traits);

/** eglDevice as in HeadlessContext::create(). */
HeadlessContext* createEGLContext(osg::GraphicsContext::Traits* traits, int eglDevice);

/** Whether eglDevice, or else OSGGLYPHS_EGL_DEVICE, names a device EGL does not have. */
bool isEGLDeviceRequestInvalid(int eglDevice);

/** A function of libOSMesa.so.8, loaded on first use; nullptr when it cannot be loaded. */
void* findOSMesaFunction(const char* name);

/** Why libOSMesa.so.8 could not be loaded; empty when it was. */
std::string getOSMesaLoadError();

/** Fills in what a headless context needs and a caller may have left out. */
void completeHeadlessTraits(osg::GraphicsContext::Traits& traits);

} // namespace detail
}

#endif
