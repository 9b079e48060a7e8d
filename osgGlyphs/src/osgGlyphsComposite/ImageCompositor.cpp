#include <osgGlyphsComposite/ImageCompositor>

#include <IceT.h>
#include <IceTMPI.h>
#include <mpi.h>

#include <osg/GLExtensions>
#include <osg/Program>
#include <osg/RenderInfo>
#include <osg/State>

#include <chrono>
#include <cstring>

using namespace osgGlyphsComposite;

namespace
{

double secondsSince(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/** A GL function through OSG's lookup, which reaches the context's driver (see HeadlessContext). */
template <typename Function>
Function lookUp(const char* name)
{
    return reinterpret_cast<Function>(osg::getGLExtensionFuncPtr(name));
}

}

ImageCompositor::ImageCompositor(const MPIShare* share) : _share(share ? share : new MPIShare)
{
    IceTCommunicator communicator = icetCreateMPICommunicator(MPI_COMM_WORLD);
    IceTContext context = icetCreateContext(communicator);
    icetDestroyMPICommunicator(communicator); // the context keeps its own duplicate
    _context = context;
    icetSetColorFormat(ICET_IMAGE_COLOR_RGBA_UBYTE);
    icetSetDepthFormat(ICET_IMAGE_DEPTH_FLOAT);
    icetCompositeMode(ICET_COMPOSITE_MODE_Z_BUFFER);
    icetStrategy(ICET_STRATEGY_SEQUENTIAL); // one tile: the single-image strategy does the work
    icetSingleImageStrategy(ICET_SINGLE_IMAGE_STRATEGY_RADIXK);
    icetDisable(ICET_FLOATING_VIEWPORT);
    icetDisable(ICET_INTERLACE_IMAGES);     // the same pairing of pixels on every frame
    icetDisable(ICET_COMPOSITE_ONE_BUFFER); // rank 0 gets depth too, for --depth-output
    icetDiagnostics(ICET_DIAG_ERRORS | ICET_DIAG_ALL_NODES);
}

ImageCompositor::~ImageCompositor()
{
    if (_context)
        icetDestroyContext(static_cast<IceTContext>(_context));
}

void ImageCompositor::operator()(osg::RenderInfo& renderInfo) const
{
    using Finish = void(GL_APIENTRY*)();
    auto start = std::chrono::steady_clock::now();
    if (auto finish = lookUp<Finish>("glFinish"))
        finish();
    _timing.finish = secondsSince(start);

    start = std::chrono::steady_clock::now();
    osgGlyphsHeadless::FrameCapture::operator()(renderInfo);
    _timing.readBack = secondsSince(start);

    composite(static_cast<unsigned int>(_color->s()), static_cast<unsigned int>(_color->t()));

    start = std::chrono::steady_clock::now();
    if (isDisplayProcess())
        writeBack(renderInfo);
    _timing.writeBack = secondsSince(start);
}

void ImageCompositor::composite(unsigned int width, unsigned int height) const
{
    auto start = std::chrono::steady_clock::now();
    MPI_Barrier(MPI_COMM_WORLD); // what the slowest draw costs the others is not compositing
    _timing.wait = secondsSince(start);
    start = std::chrono::steady_clock::now();
    icetSetContext(static_cast<IceTContext>(_context));
    if (width != _tileWidth || height != _tileHeight)
    {
        icetResetTiles();
        icetAddTile(0, 0, static_cast<IceTInt>(width), static_cast<IceTInt>(height), 0);
        _tileWidth = width;
        _tileHeight = height;
    }
    // Background pixels (depth 1) are put back from rank 0's own image below: the background
    // colour given to IceT does not matter, nor how IceT converts it to bytes.
    const IceTFloat background[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    const IceTInt viewport[4] = {0, 0, static_cast<IceTInt>(width), static_cast<IceTInt>(height)};
    const IceTDouble identity[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    const IceTImage image =
        icetCompositeImage(_color->data(), _depth->data(), viewport, identity, identity, background);
    _timing.composite = secondsSince(start);
    if (!isDisplayProcess())
        return;
    const IceTUByte* colors = icetImageGetColorcub(image);
    const IceTFloat* depths = icetImageGetDepthcf(image);
    unsigned char* ownColors = _color->data();
    float* ownDepths = reinterpret_cast<float*>(_depth->data());
    const std::size_t pixels = static_cast<std::size_t>(width) * height;
    for (std::size_t i = 0; i < pixels; ++i)
    {
        if (depths[i] < 1.0f)
            std::memcpy(ownColors + 4 * i, colors + 4 * i, 4);
        ownDepths[i] = depths[i];
    }
    _color->dirty();
    _depth->dirty();
}

void ImageCompositor::writeBack(osg::RenderInfo& renderInfo) const
{
    using WindowPos = void(GL_APIENTRY*)(GLint, GLint);
    using DrawPixels = void(GL_APIENTRY*)(GLsizei, GLsizei, GLenum, GLenum, const void*);
    const auto windowPos = lookUp<WindowPos>("glWindowPos2i");
    const auto drawPixels = lookUp<DrawPixels>("glDrawPixels");
    if (!windowPos || !drawPixels)
        return;
    // Fixed-function pixels straight into the colour buffer: no program, test, blend or texture.
    osg::State& state = *renderInfo.getState();
    static const osg::ref_ptr<osg::Program> noProgram = new osg::Program;
    state.applyAttribute(noProgram.get());
    for (GLenum mode : {GLenum(GL_DEPTH_TEST), GLenum(GL_BLEND), GLenum(GL_LIGHTING), GLenum(GL_FOG),
                        GLenum(GL_ALPHA_TEST), GLenum(GL_STENCIL_TEST), GLenum(GL_SCISSOR_TEST)})
        state.applyMode(mode, false);
    for (unsigned int unit = 0; unit < 2; ++unit)
    {
        state.applyTextureMode(unit, GL_TEXTURE_1D, false);
        state.applyTextureMode(unit, GL_TEXTURE_2D, false);
    }
    const osg::Viewport* viewport = renderInfo.getCurrentCamera()->getViewport();
    windowPos(viewport ? static_cast<GLint>(viewport->x()) : 0,
              viewport ? static_cast<GLint>(viewport->y()) : 0);
    drawPixels(_color->s(), _color->t(), GL_RGBA, GL_UNSIGNED_BYTE, _color->data());
}
