#include "HeadlessBackends.h"

#include <osg/GLExtensions>
#include <osg/Notify>

#include <GL/osmesa.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <dlfcn.h>

using namespace osgGlyphsHeadless;

namespace
{

thread_local const HeadlessContext* s_currentContext = nullptr;

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

HeadlessBackend backendFromEnvironment()
{
    HeadlessBackend backend = HeadlessBackend::OSMesa;
    if (const char* value = std::getenv("OSGGLYPHS_HEADLESS"))
    {
        if (!parseHeadlessBackend(value, backend) || backend == HeadlessBackend::Default)
        {
            OSG_WARN << "osgGlyphs: OSGGLYPHS_HEADLESS=\"" << value
                     << "\" is not a backend (osmesa or egl); using osmesa." << std::endl;
            backend = HeadlessBackend::OSMesa;
        }
    }
    return backend;
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

bool HeadlessContext::isOSMesaReachable(std::string& reason)
{
    // Every gl* function that Debian's OSG libraries call directly is exported by both
    // libOSMesa and glvnd's libGL, so one of them tells which library the loader searches first.
    void* global = dlsym(RTLD_DEFAULT, "glGetString");
    void* mesa = reinterpret_cast<void*>(&OSMesaGetCurrentContext);
    if (objectDefining(global) != objectDefining(mesa))
    {
        reason = "glGetString resolves to " + objectDefining(global) + ", not to " + objectDefining(mesa) +
                 ": link osgGlyphs (or libOSMesa) before OpenGL and OpenSceneGraph, or use EGL";
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
                                                      HeadlessBackend backend)
{
    osg::ref_ptr<osg::GraphicsContext::Traits> completed = new osg::GraphicsContext::Traits(*traits);
    detail::completeHeadlessTraits(*completed);

    const bool chosenByDefault = backend == HeadlessBackend::Default;
    if (chosenByDefault)
        backend = backendFromEnvironment();

    if (backend == HeadlessBackend::OSMesa)
    {
        std::string reason;
        if (isOSMesaReachable(reason))
            return detail::createOSMesaContext(completed.get());
        if (!chosenByDefault)
        {
            OSG_WARN << "osgGlyphs: the OSMesa backend cannot be used in this process: " << reason
                     << std::endl;
            return nullptr;
        }
        OSG_WARN << "osgGlyphs: falling back to EGL, because " << reason << std::endl;
    }
    return detail::createEGLContext(completed.get());
}

osg::ref_ptr<HeadlessContext> HeadlessContext::create(int width, int height, HeadlessBackend backend)
{
    osg::ref_ptr<osg::GraphicsContext::Traits> traits = new osg::GraphicsContext::Traits;
    traits->width = width;
    traits->height = height;
    return create(traits.get(), backend);
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
