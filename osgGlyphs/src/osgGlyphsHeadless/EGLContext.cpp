#include "HeadlessBackends.h"

#include <osg/Notify>

#include <EGL/egl.h>
#include <EGL/eglext.h>

namespace
{

/** An EGL context on Mesa's surfaceless platform, drawing into a pbuffer surface. */
class EGLGraphicsContext : public osgGlyphsHeadless::HeadlessContext
{
public:
    explicit EGLGraphicsContext(osg::GraphicsContext::Traits* traits) : HeadlessContext(traits) {}

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

        _display = eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        EGLint major = 0, minor = 0;
        if (_display == EGL_NO_DISPLAY || !eglInitialize(_display, &major, &minor))
            return fail("no EGL display on the surfaceless platform");

        const EGLint configAttributes[] = {EGL_SURFACE_TYPE,
                                           EGL_PBUFFER_BIT,
                                           EGL_RENDERABLE_TYPE,
                                           EGL_OPENGL_BIT,
                                           EGL_RED_SIZE,
                                           8,
                                           EGL_GREEN_SIZE,
                                           8,
                                           EGL_BLUE_SIZE,
                                           8,
                                           EGL_ALPHA_SIZE,
                                           8,
                                           EGL_DEPTH_SIZE,
                                           static_cast<EGLint>(_traits->depth),
                                           EGL_STENCIL_SIZE,
                                           static_cast<EGLint>(_traits->stencil),
                                           EGL_NONE};
        EGLConfig config = nullptr;
        EGLint count = 0;
        if (!eglChooseConfig(_display, configAttributes, &config, 1, &count) || count < 1)
            return fail("no RGBA8/depth/stencil pbuffer configuration");

        const EGLint surfaceAttributes[] = {EGL_WIDTH, _traits->width, EGL_HEIGHT, _traits->height, EGL_NONE};
        _surface = eglCreatePbufferSurface(_display, config, surfaceAttributes);
        if (_surface == EGL_NO_SURFACE)
            return fail("eglCreatePbufferSurface failed");

        if (!eglBindAPI(EGL_OPENGL_API))
            return fail("desktop OpenGL is not available through EGL");
        const EGLint contextAttributes[] = {EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                            EGL_CONTEXT_OPENGL_COMPATIBILITY_PROFILE_BIT, EGL_NONE};
        EGLGraphicsContext* shared = dynamic_cast<EGLGraphicsContext*>(_traits->sharedContext.get());
        _context =
            eglCreateContext(_display, config, shared ? shared->_context : EGL_NO_CONTEXT, contextAttributes);
        if (_context == EGL_NO_CONTEXT)
            return fail("eglCreateContext failed for a compatibility-profile context");
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
        if (_context == EGL_NO_CONTEXT || !eglMakeCurrent(_display, _surface, _surface, _context))
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

    void swapBuffersImplementation() override { glFinish(); }

protected:
    ~EGLGraphicsContext() override { closeImplementation(); }

private:
    bool fail(const char* what)
    {
        OSG_WARN << "osgGlyphs: EGL headless context: " << what << " (EGL error 0x" << std::hex
                 << eglGetError() << std::dec << ")" << std::endl;
        closeImplementation();
        return false;
    }

    EGLDisplay _display = EGL_NO_DISPLAY;
    EGLSurface _surface = EGL_NO_SURFACE;
    EGLContext _context = EGL_NO_CONTEXT;
};

} // namespace

osgGlyphsHeadless::HeadlessContext*
osgGlyphsHeadless::detail::createEGLContext(osg::GraphicsContext::Traits* traits)
{
    return new EGLGraphicsContext(traits);
}
