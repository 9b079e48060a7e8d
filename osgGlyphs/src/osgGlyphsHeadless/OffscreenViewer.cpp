#include <osgGlyphsHeadless/OffscreenViewer>

#include <osgDB/DatabasePager>

#include <chrono>
#include <thread>

using namespace osgGlyphsHeadless;

OffscreenViewer::OffscreenViewer(int width, int height, HeadlessBackend backend, int eglDevice)
    : _context(HeadlessContext::create(width, height, backend, eglDevice, &_contextError)),
      _capture(new FrameCapture)
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

unsigned int OffscreenViewer::settlePaging(double timeoutSeconds)
{
    osgDB::DatabasePager* pager = getDatabasePager();
    const auto start = std::chrono::steady_clock::now();
    unsigned int frames = 0;
    auto busy = [pager]
    {
        return pager->getRequestsInProgress() || pager->getFileRequestListSize() > 0 ||
               pager->getDataToMergeListSize() > 0;
    };
    while (pager && busy() &&
           std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() < timeoutSeconds)
    {
        if (pager->getDataToMergeListSize() == 0)
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
        frame();
        ++frames;
    }
    return frames;
}
