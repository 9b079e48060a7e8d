/* osgGlyphs - private: the EGL devices of this process, for EGLContext.cpp. Not installed. */

#ifndef OSGGLYPHS_EGLDEVICELIST_H
#define OSGGLYPHS_EGLDEVICELIST_H 1

#include <osgGlyphsHeadless/EGLDevices>

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <vector>

namespace osgGlyphsHeadless
{
namespace detail
{

/** The handles of eglQueryDevicesEXT, in its order; empty without EGL_EXT_device_enumeration. */
std::vector<EGLDeviceEXT> queryEGLDevices();

/** Whether the EGL client (EGL_NO_DISPLAY) extension string names extension. */
bool hasEGLClientExtension(const char* extension);

} // namespace detail
}

#endif
