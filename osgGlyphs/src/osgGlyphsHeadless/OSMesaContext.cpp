#include "HeadlessBackends.h"

#include <osg/Notify>

#include <GL/osmesa.h>

#include <dlfcn.h>
#include <mutex>
#include <vector>

namespace
{

/** libOSMesa.so.8, opened on first use and never closed: its contexts may outlive any object. */
struct OSMesaLibrary
{
    void* handle = nullptr;
    std::string error;

    static const OSMesaLibrary& get()
    {
        static OSMesaLibrary library;
        static std::once_flag opened;
        std::call_once(opened, [] { library.open(); });
        return library;
    }

private:
    void open()
    {
        // RTLD_NOLOAD first: a process that linked or preloaded libOSMesa already has it.
        handle = dlopen("libOSMesa.so.8", RTLD_NOW | RTLD_NOLOAD);
        if (!handle)
            handle = dlopen("libOSMesa.so.8", RTLD_NOW | RTLD_LOCAL);
        if (!handle)
            error = dlerror();
    }
};

/** The libOSMesa functions this backend calls, resolved by name. */
struct OSMesaFunctions
{
    decltype(&::OSMesaCreateContextAttribs) createContextAttribs;
    decltype(&::OSMesaDestroyContext) destroyContext;
    decltype(&::OSMesaMakeCurrent) makeCurrent;
    decltype(&::OSMesaGetCurrentContext) getCurrentContext;
    decltype(&::OSMesaPixelStore) pixelStore;
    decltype(&::OSMesaGetProcAddress) getProcAddress;

    static const OSMesaFunctions& get()
    {
        using osgGlyphsHeadless::detail::findOSMesaFunction;
        static const OSMesaFunctions functions = {
            reinterpret_cast<decltype(&::OSMesaCreateContextAttribs)>(
                findOSMesaFunction("OSMesaCreateContextAttribs")),
            reinterpret_cast<decltype(&::OSMesaDestroyContext)>(findOSMesaFunction("OSMesaDestroyContext")),
            reinterpret_cast<decltype(&::OSMesaMakeCurrent)>(findOSMesaFunction("OSMesaMakeCurrent")),
            reinterpret_cast<decltype(&::OSMesaGetCurrentContext)>(
                findOSMesaFunction("OSMesaGetCurrentContext")),
            reinterpret_cast<decltype(&::OSMesaPixelStore)>(findOSMesaFunction("OSMesaPixelStore")),
            reinterpret_cast<decltype(&::OSMesaGetProcAddress)>(findOSMesaFunction("OSMesaGetProcAddress"))};
        return functions;
    }

    bool complete() const
    {
        return createContextAttribs && destroyContext && makeCurrent && getCurrentContext && pixelStore &&
               getProcAddress;
    }
};

/** A context of Mesa's off-screen library, rendering into a buffer this object owns. */
class OSMesaGraphicsContext : public osgGlyphsHeadless::HeadlessContext
{
public:
    explicit OSMesaGraphicsContext(osg::GraphicsContext::Traits* traits) : HeadlessContext(traits) {}

    osgGlyphsHeadless::HeadlessBackend getBackend() const override
    {
        return osgGlyphsHeadless::HeadlessBackend::OSMesa;
    }

    void* getProcAddress(const char* name) const override
    {
        return reinterpret_cast<void*>(_mesa.getProcAddress(name));
    }

    bool realizeImplementation() override
    {
        if (_context)
            return true; // osgViewer realizes its contexts more than once.

        OSMesaGraphicsContext* shared = dynamic_cast<OSMesaGraphicsContext*>(_traits->sharedContext.get());
        const int attributes[] = {OSMESA_FORMAT,
                                  OSMESA_RGBA,
                                  OSMESA_DEPTH_BITS,
                                  static_cast<int>(_traits->depth),
                                  OSMESA_STENCIL_BITS,
                                  static_cast<int>(_traits->stencil),
                                  OSMESA_ACCUM_BITS,
                                  0,
                                  OSMESA_PROFILE,
                                  OSMESA_COMPAT_PROFILE,
                                  OSMESA_CONTEXT_MAJOR_VERSION,
                                  1, // 1 asks for the highest version
                                  0};
        if (!_mesa.complete())
            return setFailure("OSMesa: libOSMesa.so.8 lacks a function this backend needs");
        _context = _mesa.createContextAttribs(attributes, shared ? shared->_context : nullptr);
        if (!_context)
            return setFailure("OSMesa: OSMesaCreateContextAttribs failed");
        _pixels.assign(static_cast<size_t>(_traits->width) * static_cast<size_t>(_traits->height), 0u);
        if (!inspectRenderer("OSMesa"))
        {
            closeImplementation();
            return false;
        }
        return true;
    }

    bool isRealizedImplementation() const override { return _context != nullptr; }

    void closeImplementation() override
    {
        if (_context)
        {
            if (_mesa.getCurrentContext() == _context)
                releaseContextImplementation();
            _mesa.destroyContext(_context);
            _context = nullptr;
        }
        _pixels.clear();
    }

    bool makeCurrentImplementation() override
    {
        if (!_context ||
            !_mesa.makeCurrent(_context, _pixels.data(), GL_UNSIGNED_BYTE, _traits->width, _traits->height))
        {
            return false;
        }
        _mesa.pixelStore(OSMESA_Y_UP, 1);
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
        return _mesa.makeCurrent(nullptr, nullptr, GL_UNSIGNED_BYTE, 0, 0) == GL_TRUE;
    }

    void swapBuffersImplementation() override
    {
        if (auto finish = reinterpret_cast<void (*)()>(_mesa.getProcAddress("glFinish")))
            finish();
    }

protected:
    ~OSMesaGraphicsContext() override { closeImplementation(); }

private:
    const OSMesaFunctions& _mesa = OSMesaFunctions::get();
    ::OSMesaContext _context = nullptr;
    std::vector<GLuint> _pixels;
};

} // namespace

osgGlyphsHeadless::HeadlessContext*
osgGlyphsHeadless::detail::createOSMesaContext(osg::GraphicsContext::Traits* traits)
{
    return new OSMesaGraphicsContext(traits);
}

void* osgGlyphsHeadless::detail::findOSMesaFunction(const char* name)
{
    const OSMesaLibrary& library = OSMesaLibrary::get();
    return library.handle ? dlsym(library.handle, name) : nullptr;
}

std::string osgGlyphsHeadless::detail::getOSMesaLoadError()
{
    return OSMesaLibrary::get().error;
}
