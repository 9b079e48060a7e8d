#include <osgGlyphsHeadless/OffscreenViewer>

using namespace osgGlyphsHeadless;

OffscreenViewer::OffscreenViewer(int width, int height, HeadlessBackend backend)
    : _context(HeadlessContext::create(width, height, backend)), _capture(new FrameCapture)
{
    setThreadingModel(osgViewer::ViewerBase::SingleThreaded);
    osg::Camera* camera = getCamera();
    camera->setViewport(0, 0, width, height);
    camera->setProjectionMatrixAsPerspective(30.0, static_cast<double>(width) / height, 1.0, 1000.0);
    camera->setDrawBuffer(GL_FRONT);
    camera->setReadBuffer(GL_FRONT);
    camera->setFinalDrawCallback(_capture.get());
    if (_context.valid())
        camera->setGraphicsContext(_context.get());
}

OffscreenViewer::~OffscreenViewer()
{
    // Release GL objects while the context still exists.
    stopThreading();
    if (_context.valid())
        _context->close();
}
