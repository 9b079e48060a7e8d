/* osgGlyphs - private: per-context state that lets go of its GL objects when OSG deletes or
 * discards those of its context. Not installed. */

#ifndef OSGGLYPHS_CONTEXTRELEASE_H
#define OSGGLYPHS_CONTEXTRELEASE_H 1

#include <osg/GLObjects>

namespace osgGlyphs
{
namespace detail
{

/** Lives in a context's osg::ContextData (osg::get<>): when OSG deletes or discards that
 * context's GL objects (the context closes, or releaseGLObjects reaches it), it calls
 * releaseContext(); a later context may reuse the ID. Nothing is deleted lazily: there are no
 * deferred objects to flush. */
class ContextRelease : public osg::GraphicsObjectManager
{
public:
    ContextRelease(const std::string& name, unsigned int contextID)
        : osg::GraphicsObjectManager(name, contextID)
    {
    }

    void flushDeletedGLObjects(double, double&) override {}
    void flushAllDeletedGLObjects() override {}
    void deleteAllGLObjects() override { releaseContext(); }
    void discardAllGLObjects() override { releaseContext(); }

protected:
    /** Releases what this context holds. */
    virtual void releaseContext() = 0;
};

}
}

#endif
