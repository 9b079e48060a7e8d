#include "HeadlessBackends.h"

#include <osg/GLExtensions>
#include <osg/Notify>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <dlfcn.h>

using namespace osgGlyphsHeadless;

namespace
{

thread_local HeadlessContext* s_currentContext = nullptr;

const char* const OSG_EXTENSION_LOOKUP_SYMBOL = "_ZN3osg21getGLExtensionFuncPtrEPKc";

using ExtensionLookup = void* (*)(const char*);

/** OSG's own osg::getGLExtensionFuncPtr, the next definition after this library's. */
ExtensionLookup osgExtensionLookup()
{
    static ExtensionLookup next =
        reinterpret_cast<ExtensionLookup>(dlsym(RTLD_NEXT, OSG_EXTENSION_LOOKUP_SYMBOL));
    return next;
}

/** Every backend and its name, for getHeadlessBackendName() and parseHeadlessBackend(). */
const struct
{
    HeadlessBackend backend;
    const char* name;
} BACKEND_NAMES[] = {
    {HeadlessBackend::Default, "default"},
    {HeadlessBackend::OSMesa, "osmesa"},
    {HeadlessBackend::EGL, "egl"},
};

std::string objectDefining(void* address)
{
    Dl_info info{};
    if (address && dladdr(address, &info) && info.dli_fname)
        return info.dli_fname;
    return "nowhere";
}

/** OSGGLYPHS_HEADLESS's backend; Default when it is unset or names none. */
HeadlessBackend backendFromEnvironment()
{
    HeadlessBackend backend = HeadlessBackend::Default;
    if (const char* value = std::getenv("OSGGLYPHS_HEADLESS"))
    {
        if (!parseHeadlessBackend(value, backend))
        {
            OSG_WARN << "osgGlyphs: OSGGLYPHS_HEADLESS=\"" << value
                     << "\" is not a backend (osmesa, egl or default); trying EGL, then OSMesa." << std::endl;
            backend = HeadlessBackend::Default;
        }
    }
    return backend;
}

using GetString = const GLubyte* (*)(GLenum);

std::string glString(GetString getString, GLenum name)
{
    const GLubyte* text = getString ? getString(name) : nullptr;
    return text ? reinterpret_cast<const char*>(text) : "";
}

} // namespace

/* OSG resolves GL extension functions by name through this function, and libosg calls it
 * through its PLT: this definition, which the loader finds before libosg's, sends each
 * lookup to the headless backend that is current on the calling thread, and every other
 * lookup (a window's GLX context, say) to OSG's own implementation. */
namespace osg
{
OSGGLYPHSHEADLESS_EXPORT void* getGLExtensionFuncPtr(const char* funcName);
}

void* osg::getGLExtensionFuncPtr(const char* funcName)
{
    if (const HeadlessContext* context = s_currentContext)
        return context->getProcAddress(funcName);
    ExtensionLookup next = osgExtensionLookup();
    return next ? next(funcName) : dlsym(RTLD_DEFAULT, funcName);
}

const char* osgGlyphsHeadless::getHeadlessBackendName(HeadlessBackend backend)
{
    for (const auto& entry : BACKEND_NAMES)
    {
        if (entry.backend == backend)
            return entry.name;
    }
    return "default";
}

bool osgGlyphsHeadless::parseHeadlessBackend(const std::string& name, HeadlessBackend& backend)
{
    std::string lower(name);
    std::transform(lower.begin(), lower.end(), lower.begin(),
                   [](unsigned char c) { return std::tolower(c); });
    for (const auto& entry : BACKEND_NAMES)
    {
        if (lower == entry.name)
        {
            backend = entry.backend;
            return true;
        }
    }
    return false;
}

std::string HeadlessRendererInfo::describe() const
{
    return platform + ": " + vendor + ", " + renderer + ", OpenGL " + version;
}

bool HeadlessContext::isOSMesaReachable(std::string& reason)
{
    // Every gl* function that Debian's OSG libraries call directly is exported by both
    // libOSMesa and glvnd's libGL, so one of them tells which library the loader searches first.
    void* global = dlsym(RTLD_DEFAULT, "glGetString");
    void* mesa = detail::findOSMesaFunction("OSMesaGetCurrentContext");
    if (!mesa)
    {
        reason = "libOSMesa.so.8 cannot be loaded (" + detail::getOSMesaLoadError() + ")";
        return false;
    }
    if (objectDefining(global) != objectDefining(mesa))
    {
        reason = "glGetString resolves to " + objectDefining(global) + ", not to " + objectDefining(mesa) +
                 ": load libOSMesa before libGL (LD_PRELOAD=libOSMesa.so.8, or link it first), or use EGL";
        return false;
    }
    void* lookup = dlsym(RTLD_DEFAULT, OSG_EXTENSION_LOOKUP_SYMBOL);
    void* self = reinterpret_cast<void*>(&HeadlessContext::getCurrent);
    if (objectDefining(lookup) != objectDefining(self))
    {
        reason = "osg::getGLExtensionFuncPtr resolves to " + objectDefining(lookup) + ", not to " +
                 objectDefining(self) + ": link osgGlyphs before OpenSceneGraph, or use EGL";
        return false;
    }
    return true;
}

osg::ref_ptr<HeadlessContext> HeadlessContext::create(osg::GraphicsContext::Traits* traits,
                                                      HeadlessBackend backend, int eglDevice,
                                                      std::string* error)
{
    osg::ref_ptr<osg::GraphicsContext::Traits> completed = new osg::GraphicsContext::Traits(*traits);
    detail::completeHeadlessTraits(*completed);
    const auto fail = [error](const std::string& why) -> osg::ref_ptr<HeadlessContext>
    {
        if (error)
            *error = why;
        else
            OSG_WARN << "osgGlyphs: " << why << std::endl;
        return nullptr;
    };
    const auto realized = [&fail](osg::ref_ptr<HeadlessContext> context)
    { return context->realize() ? context : fail(context->getFailure()); };

    if (backend == HeadlessBackend::Default)
        backend = backendFromEnvironment();

    std::string reason;
    if (backend == HeadlessBackend::OSMesa && !isOSMesaReachable(reason))
        return fail("the OSMesa backend cannot be used in this process: " + reason);
    if (backend == HeadlessBackend::OSMesa)
        return realized(detail::createOSMesaContext(completed.get()));
    if (backend == HeadlessBackend::EGL)
        return realized(detail::createEGLContext(completed.get(), eglDevice));

    osg::ref_ptr<HeadlessContext> egl = detail::createEGLContext(completed.get(), eglDevice);
    if (egl->realize())
        return egl;
    if (detail::isEGLDeviceRequestInvalid(eglDevice))
        return fail(egl->getFailure()); // A device that does not exist is the caller's mistake, not EGL's.
    if (!isOSMesaReachable(reason))
        return fail(egl->getFailure() + "; and OSMesa cannot be used: " + reason);
    OSG_NOTICE << "osgGlyphs: " << egl->getFailure() << "; rendering through OSMesa." << std::endl;
    return realized(detail::createOSMesaContext(completed.get()));
}

osg::ref_ptr<HeadlessContext> HeadlessContext::create(int width, int height, HeadlessBackend backend,
                                                      int eglDevice, std::string* error)
{
    osg::ref_ptr<osg::GraphicsContext::Traits> traits = new osg::GraphicsContext::Traits;
    traits->width = width;
    traits->height = height;
    return create(traits.get(), backend, eglDevice, error);
}

bool HeadlessContext::setFailure(const std::string& failure)
{
    _failure = failure;
    return false;
}

bool HeadlessContext::inspectRenderer(const std::string& platform)
{
    _failure.clear();
    // OSG keeps the GL functions it looked up per context ID, and reuses the ID of a closed
    // context: functions of another backend's context would be called through this one.
    if (!_traits->sharedContext.valid())
        osg::GLExtensions::Set(getState()->getContextID(), nullptr);
    HeadlessContext* previous = s_currentContext;
    if (!makeCurrentImplementation())
        return setFailure(platform + ": the new context cannot be made current");
    const GetString own = reinterpret_cast<GetString>(getProcAddress("glGetString"));
    _rendererInfo.platform = platform;
    _rendererInfo.vendor = glString(own, GL_VENDOR);
    _rendererInfo.renderer = glString(own, GL_RENDERER);
    _rendererInfo.version = glString(own, GL_VERSION);
    // What OSG's libraries see: they call glGetString and ~100 other gl* functions directly.
    const std::string seenByOSG = glString(&::glGetString, GL_RENDERER);
    releaseContextImplementation();
    if (previous && previous != this)
        previous->makeCurrentImplementation();

    if (seenByOSG != _rendererInfo.renderer || seenByOSG.empty())
    {
        const std::string renderer = _rendererInfo.renderer;
        _rendererInfo = HeadlessRendererInfo();
        return setFailure(
            platform + " renders through \"" + renderer + "\", but OSG's gl* calls resolve to " +
            objectDefining(dlsym(RTLD_DEFAULT, "glGetString")) + " and reach \"" + seenByOSG + "\"" +
            (getBackend() == HeadlessBackend::EGL
                 ? ": libOSMesa is loaded before libGL; do not link or preload it to render through EGL"
                 : ": load libOSMesa before libGL (LD_PRELOAD=libOSMesa.so.8), or use EGL"));
    }
    OSG_INFO << "osgGlyphs: headless context: " << _rendererInfo.describe() << std::endl;
    return true;
}

const HeadlessContext* HeadlessContext::getCurrent()
{
    return s_currentContext;
}

HeadlessContext::HeadlessContext(osg::GraphicsContext::Traits* traits)
{
    _traits = traits;
    setState(new osg::State);
    getState()->setGraphicsContext(this);
    if (_traits->sharedContext.valid())
    {
        getState()->setContextID(_traits->sharedContext->getState()->getContextID());
        incrementContextIDUsageCount(getState()->getContextID());
    }
    else
    {
        getState()->setContextID(osg::GraphicsContext::createNewContextID());
    }
}

HeadlessContext::~HeadlessContext()
{
    if (s_currentContext == this)
        s_currentContext = nullptr;
}

void HeadlessContext::setCurrentOnThisThread(bool current)
{
    if (current)
        s_currentContext = this;
    else if (s_currentContext == this)
        s_currentContext = nullptr;
}

void detail::completeHeadlessTraits(osg::GraphicsContext::Traits& traits)
{
    traits.x = 0;
    traits.y = 0;
    traits.windowDecoration = false;
    traits.doubleBuffer = false;
    traits.pbuffer = true;
    traits.red = traits.green = traits.blue = traits.alpha = 8;
    traits.depth = 24;
    traits.stencil = 8;
}
