#include "HeadlessBackends.h"

#include <osg/Notify>

#include <GL/osmesa.h>

#include <vector>

namespace
{

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
        return reinterpret_cast<void*>(OSMesaGetProcAddress(name));
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
        _context = OSMesaCreateContextAttribs(attributes, shared ? shared->_context : nullptr);
        if (!_context)
        {
            OSG_WARN << "osgGlyphs: OSMesaCreateContextAttribs failed" << std::endl;
            return false;
        }
        _pixels.assign(static_cast<size_t>(_traits->width) * static_cast<size_t>(_traits->height), 0u);
        return true;
    }

    bool isRealizedImplementation() const override { return _context != nullptr; }

    void closeImplementation() override
    {
        if (_context)
        {
            if (OSMesaGetCurrentContext() == _context)
                releaseContextImplementation();
            OSMesaDestroyContext(_context);
            _context = nullptr;
        }
        _pixels.clear();
    }

    bool makeCurrentImplementation() override
    {
        if (!_context ||
            !OSMesaMakeCurrent(_context, _pixels.data(), GL_UNSIGNED_BYTE, _traits->width, _traits->height))
        {
            return false;
        }
        OSMesaPixelStore(OSMESA_Y_UP, 1);
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
        return OSMesaMakeCurrent(nullptr, nullptr, GL_UNSIGNED_BYTE, 0, 0) == GL_TRUE;
    }

    void swapBuffersImplementation() override { glFinish(); }

protected:
    ~OSMesaGraphicsContext() override { closeImplementation(); }

private:
    ::OSMesaContext _context = nullptr;
    std::vector<GLuint> _pixels;
};

} // namespace

osgGlyphsHeadless::HeadlessContext*
osgGlyphsHeadless::detail::createOSMesaContext(osg::GraphicsContext::Traits* traits)
{
    return new OSMesaGraphicsContext(traits);
}
