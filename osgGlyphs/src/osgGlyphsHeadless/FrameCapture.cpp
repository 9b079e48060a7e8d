#include <osgGlyphsHeadless/FrameCapture>

#include <osg/GLExtensions>
#include <osg/RenderInfo>
#include <osg/Viewport>

using namespace osgGlyphsHeadless;

FrameCapture::FrameCapture() : _color(new osg::Image), _depth(new osg::Image) {}

FrameCapture::FrameCapture(const FrameCapture& other, const osg::CopyOp& copyop)
    : osg::Object(other, copyop), osg::Camera::DrawCallback(other, copyop),
      _captureDepth(other._captureDepth), _color(new osg::Image(*other._color, copyop)),
      _depth(new osg::Image(*other._depth, copyop))
{
}

void FrameCapture::operator()(osg::RenderInfo& renderInfo) const
{
    const osg::Camera* camera = renderInfo.getCurrentCamera();
    const osg::Viewport* viewport = camera ? camera->getViewport() : nullptr;
    if (!viewport)
        return;

    using GetString = const GLubyte*(GL_APIENTRY*)(GLenum);
    if (auto getString = reinterpret_cast<GetString>(osg::getGLExtensionFuncPtr("glGetString")))
    {
        auto text = [&](GLenum name)
        {
            const GLubyte* value = getString(name);
            return value ? std::string(reinterpret_cast<const char*>(value)) : std::string();
        };
        _glVersion = text(GL_VERSION);
        _glRenderer = text(GL_RENDERER);
    }

    // The matrices this draw used, from its state: in a threaded viewer the cull of the next frame
    // writes the camera's own (the computed near and far) while this frame draws.
    const osg::State& state = *renderInfo.getState();
    _projection = state.getProjectionMatrix();
    _view = state.getInitialViewMatrix();

    const int x = static_cast<int>(viewport->x()), y = static_cast<int>(viewport->y());
    const int width = static_cast<int>(viewport->width()), height = static_cast<int>(viewport->height());
    _color->readPixels(x, y, width, height, GL_RGBA, GL_UNSIGNED_BYTE);
    if (_captureDepth)
        _depth->readPixels(x, y, width, height, GL_DEPTH_COMPONENT, GL_FLOAT);
    ++_numCaptures;
}
