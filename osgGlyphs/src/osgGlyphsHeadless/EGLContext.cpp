#include "EGLDeviceList.h"
#include "HeadlessBackends.h"

#include <osg/Notify>

#include <algorithm>
#include <cstdlib>
#include <sstream>

namespace
{

/** A display of the device platform or of Mesa's surfaceless one, and how it was chosen. */
struct EGLDisplayChoice
{
    EGLDisplay display = EGL_NO_DISPLAY;
    std::string platform;
    std::string error;
};

bool isDeviceExplicitlyRequested(int eglDevice)
{
    return eglDevice >= 0 || std::getenv(osgGlyphsHeadless::getEGLDeviceVariable()) != nullptr;
}

EGLDisplay initializedDisplay(EGLenum platform, void* nativeDisplay)
{
    EGLDisplay display = eglGetPlatformDisplay(platform, nativeDisplay, nullptr);
    EGLint major = 0, minor = 0;
    if (display == EGL_NO_DISPLAY || !eglInitialize(display, &major, &minor))
        return EGL_NO_DISPLAY;
    return display;
}

/** The chosen EGL device's display; else, unless a device was requested, Mesa's surfaceless one. */
EGLDisplayChoice chooseDisplay(int eglDevice)
{
    using namespace osgGlyphsHeadless;
    EGLDisplayChoice result;
    const std::vector<EGLDeviceEXT> devices = detail::queryEGLDevices();
    const EGLDeviceChoice device = chooseEGLDevice(static_cast<int>(devices.size()), eglDevice);
    if (device.valid())
    {
        const EGLDeviceDescription description = listEGLDevices()[static_cast<size_t>(device.index)];
        result.platform = "EGL device " + description.describe() + " of " + std::to_string(devices.size()) +
                          ", chosen by " + device.reason;
        result.display =
            initializedDisplay(EGL_PLATFORM_DEVICE_EXT, devices[static_cast<size_t>(device.index)]);
        if (result.display != EGL_NO_DISPLAY || isDeviceExplicitlyRequested(eglDevice))
        {
            if (result.display == EGL_NO_DISPLAY)
                result.error = result.platform + ": eglInitialize failed";
            return result;
        }
        OSG_NOTICE << "osgGlyphs: " << result.platform
                   << " cannot be initialized; trying Mesa's surfaceless platform" << std::endl;
    }
    else if (isDeviceExplicitlyRequested(eglDevice))
    {
        result.error = device.error;
        return result;
    }

    result.platform = "EGL surfaceless platform";
    if (!detail::hasEGLClientExtension("EGL_MESA_platform_surfaceless"))
        result.error = "EGL offers neither a device nor Mesa's surfaceless platform";
    else if ((result.display = initializedDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY)) ==
             EGL_NO_DISPLAY)
        result.error = "no EGL display on Mesa's surfaceless platform";
    return result;
}

EGLint configAttribute(EGLDisplay display, EGLConfig config, EGLint name)
{
    EGLint value = 0;
    eglGetConfigAttrib(display, config, name, &value);
    return value;
}

/** The pbuffer configuration of exactly RGBA8 with the fewest depth and stencil bits that
 * satisfy the traits. Chosen from eglGetConfigs, since eglChooseConfig of Mesa 22's device
 * platform finds no configuration for some attribute lists it offers. */
EGLConfig chooseConfig(EGLDisplay display, const osg::GraphicsContext::Traits& traits)
{
    EGLint count = 0;
    if (!eglGetConfigs(display, nullptr, 0, &count) || count <= 0)
        return nullptr;
    std::vector<EGLConfig> configs(static_cast<size_t>(count));
    eglGetConfigs(display, configs.data(), count, &count);
    configs.resize(static_cast<size_t>(std::max<EGLint>(count, 0)));

    EGLConfig best = nullptr;
    EGLint bestBits = 0;
    for (EGLConfig config : configs)
    {
        auto attribute = [&](EGLint name) { return configAttribute(display, config, name); };
        const bool usable = (attribute(EGL_SURFACE_TYPE) & EGL_PBUFFER_BIT) &&
                            (attribute(EGL_RENDERABLE_TYPE) & EGL_OPENGL_BIT) &&
                            attribute(EGL_RED_SIZE) == 8 && attribute(EGL_GREEN_SIZE) == 8 &&
                            attribute(EGL_BLUE_SIZE) == 8 && attribute(EGL_ALPHA_SIZE) == 8 &&
                            attribute(EGL_DEPTH_SIZE) >= static_cast<EGLint>(traits.depth) &&
                            attribute(EGL_STENCIL_SIZE) >= static_cast<EGLint>(traits.stencil) &&
                            attribute(EGL_SAMPLES) == 0;
        const EGLint bits = attribute(EGL_DEPTH_SIZE) + attribute(EGL_STENCIL_SIZE);
        if (usable && (!best || bits < bestBits))
            best = config, bestBits = bits;
    }
    return best;
}

/** An EGL context drawing into a pbuffer surface, on an EGL device or Mesa's surfaceless platform. */
class EGLGraphicsContext : public osgGlyphsHeadless::HeadlessContext
{
public:
    EGLGraphicsContext(osg::GraphicsContext::Traits* traits, int eglDevice)
        : HeadlessContext(traits), _eglDevice(eglDevice)
    {
    }

    osgGlyphsHeadless::HeadlessBackend getBackend() const override
    {
        return osgGlyphsHeadless::HeadlessBackend::EGL;
    }

    void* getProcAddress(const char* name) const override
    {
        return reinterpret_cast<void*>(eglGetProcAddress(name));
    }

    bool realizeImplementation() override
    {
        if (_context != EGL_NO_CONTEXT)
            return true; // osgViewer realizes its contexts more than once.

        EGLGraphicsContext* shared = dynamic_cast<EGLGraphicsContext*>(_traits->sharedContext.get());
        EGLDisplayChoice choice;
        if (shared && shared->_display != EGL_NO_DISPLAY)
            choice.display = shared->_display, choice.platform = shared->getRendererInfo().platform;
        else
            choice = chooseDisplay(_eglDevice);
        if (choice.display == EGL_NO_DISPLAY)
            return fail(choice.error);
        _display = choice.display;

        EGLConfig config = chooseConfig(_display, *_traits);
        if (!config)
            return fail(choice.platform + ": no RGBA8 pbuffer configuration with depth and stencil");

        const EGLint surfaceAttributes[] = {EGL_WIDTH, _traits->width, EGL_HEIGHT, _traits->height, EGL_NONE};
        _surface = eglCreatePbufferSurface(_display, config, surfaceAttributes);
        if (_surface == EGL_NO_SURFACE)
            return fail(choice.platform + ": eglCreatePbufferSurface failed");

        if (!eglBindAPI(EGL_OPENGL_API))
            return fail(choice.platform + ": desktop OpenGL is not available through EGL");
        const EGLint contextAttributes[] = {EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                            EGL_CONTEXT_OPENGL_COMPATIBILITY_PROFILE_BIT, EGL_NONE};
        _context =
            eglCreateContext(_display, config, shared ? shared->_context : EGL_NO_CONTEXT, contextAttributes);
        if (_context == EGL_NO_CONTEXT)
            return fail(choice.platform + ": eglCreateContext failed for a compatibility-profile context");
        if (!inspectRenderer(choice.platform))
            return fail(getFailure());
        return true;
    }

    bool isRealizedImplementation() const override { return _context != EGL_NO_CONTEXT; }

    void closeImplementation() override
    {
        if (_display == EGL_NO_DISPLAY)
            return;
        if (eglGetCurrentContext() == _context && _context != EGL_NO_CONTEXT)
            releaseContextImplementation();
        if (_context != EGL_NO_CONTEXT)
            eglDestroyContext(_display, _context);
        if (_surface != EGL_NO_SURFACE)
            eglDestroySurface(_display, _surface);
        _context = EGL_NO_CONTEXT;
        _surface = EGL_NO_SURFACE;
        _display = EGL_NO_DISPLAY; // The display stays initialized: other contexts may share it.
    }

    bool makeCurrentImplementation() override
    {
        // eglBindAPI is per thread: osgViewer's threading models make current from other threads.
        if (_context == EGL_NO_CONTEXT || !eglBindAPI(EGL_OPENGL_API) ||
            !eglMakeCurrent(_display, _surface, _surface, _context))
            return false;
        setCurrentOnThisThread(true);
        return true;
    }

    bool makeContextCurrentImplementation(osg::GraphicsContext*) override
    {
        return makeCurrentImplementation();
    }

    bool releaseContextImplementation() override
    {
        setCurrentOnThisThread(false);
        return eglMakeCurrent(_display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT) == EGL_TRUE;
    }

    void swapBuffersImplementation() override
    {
        if (auto finish = reinterpret_cast<void (*)()>(eglGetProcAddress("glFinish")))
            finish();
    }

protected:
    ~EGLGraphicsContext() override { closeImplementation(); }

private:
    bool fail(const std::string& what)
    {
        std::ostringstream text;
        text << what;
        const EGLint error = eglGetError();
        if (error != EGL_SUCCESS)
            text << " (EGL error 0x" << std::hex << error << ")";
        closeImplementation();
        return setFailure(text.str());
    }

    int _eglDevice;
    EGLDisplay _display = EGL_NO_DISPLAY;
    EGLSurface _surface = EGL_NO_SURFACE;
    EGLContext _context = EGL_NO_CONTEXT;
};

} // namespace

osgGlyphsHeadless::HeadlessContext*
osgGlyphsHeadless::detail::createEGLContext(osg::GraphicsContext::Traits* traits, int eglDevice)
{
    return new EGLGraphicsContext(traits, eglDevice);
}

bool osgGlyphsHeadless::detail::isEGLDeviceRequestInvalid(int eglDevice)
{
    if (!isDeviceExplicitlyRequested(eglDevice))
        return false;
    return !chooseEGLDevice(static_cast<int>(queryEGLDevices().size()), eglDevice).valid();
}
