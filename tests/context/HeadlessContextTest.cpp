// Proves that each headless backend renders through Mesa: OSG's direct gl* calls, its
// extension lookups by name, and a shader-drawn pixel all reach the context's implementation.
// This executable loads libOSMesa before libGL (tests/CMakeLists.txt), so both backends work.

#include "GlyphTestScenes.h"
#include "RenderHarness.h"

#include <osgGlyphsHeadless/HeadlessContext>

#include <osg/GLExtensions>
#include <osg/Geode>
#include <osg/Geometry>
#include <osg/Program>

#include <cstring>
#include <dlfcn.h>

using namespace osgGlyphsTest;
using osgGlyphsHeadless::HeadlessBackend;

namespace
{

/** A quad over the whole viewport, coloured only by a fragment shader. */
osg::ref_ptr<osg::Node> createShaderQuad()
{
    osg::ref_ptr<osg::Geometry> quad =
        osg::createTexturedQuadGeometry(osg::Vec3(-1, -1, 0), osg::Vec3(2, 0, 0), osg::Vec3(0, 2, 0));
    osg::ref_ptr<osg::Program> program = new osg::Program;
    program->addShader(new osg::Shader(osg::Shader::VERTEX, "#version 330 compatibility\n"
                                                            "void main() { gl_Position = gl_Vertex; }\n"));
    program->addShader(new osg::Shader(osg::Shader::FRAGMENT,
                                       "#version 330 compatibility\n"
                                       "out vec4 color;\n"
                                       "void main() { color = vec4(0.25, 0.5, 0.75, 1.0); }\n"));
    quad->getOrCreateStateSet()->setAttributeAndModes(program.get());
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    geode->addDrawable(quad.get());
    return geode;
}

/** Records, while the context is current, where OSG's by-name lookup sends an extension function. */
struct ExtensionProbe : public osg::Camera::DrawCallback
{
    void operator()(osg::RenderInfo&) const override
    {
        address = osg::getGLExtensionFuncPtr("glClipControl");
        Dl_info info{};
        library = (address && dladdr(address, &info) && info.dli_fname) ? info.dli_fname : "";
    }
    mutable void* address = nullptr;
    mutable std::string library;
};

class HeadlessBackends : public ::testing::TestWithParam<HeadlessBackend>
{
};

} // namespace

TEST(HeadlessContext, OSMesaIsReachableFromThisProcess)
{
    std::string reason;
    EXPECT_TRUE(osgGlyphsHeadless::HeadlessContext::isOSMesaReachable(reason)) << reason;
}

TEST(HeadlessContext, ParsesBackendNames)
{
    HeadlessBackend backend = HeadlessBackend::Default;
    EXPECT_TRUE(osgGlyphsHeadless::parseHeadlessBackend("EGL", backend));
    EXPECT_EQ(backend, HeadlessBackend::EGL);
    EXPECT_TRUE(osgGlyphsHeadless::parseHeadlessBackend("osmesa", backend));
    EXPECT_EQ(backend, HeadlessBackend::OSMesa);
    EXPECT_FALSE(osgGlyphsHeadless::parseHeadlessBackend("glx", backend));
}

TEST_P(HeadlessBackends, RenderThroughMesa)
{
    Renderer renderer(64, 48, GetParam());
    ASSERT_TRUE(renderer.getViewer()->valid());
    EXPECT_EQ(renderer.getViewer()->getContext()->getBackend(), GetParam());
    osg::ref_ptr<ExtensionProbe> probe = new ExtensionProbe;
    renderer.getViewer()->getCamera()->setInitialDrawCallback(probe.get());

    const Frame frame = renderer.render(createShaderQuad().get());

    // glGetString looked up by name, as OSG looks up extension functions.
    const osgGlyphsHeadless::FrameCapture* capture = renderer.getViewer()->getFrameCapture();
    EXPECT_NE(capture->getGLVersion().find("Mesa"), std::string::npos) << capture->getGLVersion();
    EXPECT_NE(capture->getGLRenderer().find("llvmpipe"), std::string::npos) << capture->getGLRenderer();

    // OSG's own view of the context, gathered through its direct gl* calls.
    const unsigned int contextID = renderer.getViewer()->getContext()->getState()->getContextID();
    const osg::GLExtensions* extensions = osg::GLExtensions::Get(contextID, false);
    ASSERT_NE(extensions, nullptr);
    EXPECT_GE(extensions->glVersion, 4.5f);
    EXPECT_GE(extensions->glslLanguageVersion, 4.5f);

    // An extension function absent from libOSMesa's exports still reaches Mesa, not glvnd's stub.
    ASSERT_NE(probe->address, nullptr);
    if (GetParam() == HeadlessBackend::OSMesa)
    {
        EXPECT_EQ(probe->library.find("libGL.so"), std::string::npos) << probe->library;
    }

    // The shader-drawn pixel, read back.
    EXPECT_TRUE(colorNear(frame, 10, 10, osg::Vec4ub(64, 128, 191, 255), 1));
    EXPECT_TRUE(colorNear(frame, 63, 47, osg::Vec4ub(64, 128, 191, 255), 1));
}

TEST_P(HeadlessBackends, SeveralContextsInOneProcess)
{
    Renderer first(32, 32, GetParam());
    Renderer second(48, 16, GetParam());
    const Frame a = first.render(createShaderQuad().get());
    const Frame b = second.render(createShaderQuad().get());
    const Frame c = first.render(createShaderQuad().get());
    EXPECT_EQ(b.width(), 48);
    EXPECT_TRUE(colorNear(a, 5, 5, osg::Vec4ub(64, 128, 191, 255), 1));
    EXPECT_TRUE(colorNear(b, 40, 10, osg::Vec4ub(64, 128, 191, 255), 1));
    EXPECT_TRUE(colorNear(c, 31, 31, osg::Vec4ub(64, 128, 191, 255), 1));
}

TEST_P(HeadlessBackends, ReportsWhatItRendersThrough)
{
    Renderer renderer(16, 16, GetParam());
    ASSERT_TRUE(renderer.getViewer()->valid());
    renderer.render(createShaderQuad().get());
    const osgGlyphsHeadless::HeadlessRendererInfo& info =
        renderer.getViewer()->getContext()->getRendererInfo();
    EXPECT_NE(info.renderer.find("llvmpipe"), std::string::npos) << info.describe();
    EXPECT_NE(info.version.find("Mesa"), std::string::npos) << info.describe();
    if (GetParam() == HeadlessBackend::EGL)
        EXPECT_EQ(info.platform.rfind("EGL device 0: Mesa's software renderer", 0), 0u) << info.platform;
    else
        EXPECT_EQ(info.platform, "OSMesa");
}

TEST(HeadlessContext, EGLDeviceAndOSMesaRenderTheSameBytes)
{
    const std::vector<SphereSpec> spheres = {{{-0.6f, 0.0f, 0.0f}, 0.7f, {220, 60, 40, 255}},
                                             {{0.5f, 0.2f, 0.3f}, 0.6f, {40, 160, 220, 255}},
                                             {{0.0f, -0.5f, -0.4f}, 0.5f, {240, 220, 60, 255}}};
    osg::ref_ptr<osg::Group> scene = new osg::Group;
    scene->addChild(createSphereCloud(spheres, true));
    scene->addChild(group({createFlatQuad(osg::Vec3(0, 0, -0.5f), osg::Vec3(3, 0, 0), osg::Vec3(0, 3, 0),
                                          osg::Vec4(0.5f, 0.5f, 0.5f, 1))
                               .get()}));
    std::vector<Frame> frames;
    for (HeadlessBackend backend : {HeadlessBackend::EGL, HeadlessBackend::OSMesa})
    {
        Renderer renderer(96, 64, backend);
        ASSERT_TRUE(renderer.getViewer()->valid());
        renderer.setLookAt(osg::Vec3d(0.5, -4, 3), osg::Vec3d(), osg::Vec3d(0, 0, 1));
        renderer.setPerspective(40, 1, 20);
        frames.push_back(renderer.render(scene.get()));
    }
    const osg::Image& egl = *frames[0].color;
    const osg::Image& mesa = *frames[1].color;
    ASSERT_EQ(egl.getTotalSizeInBytes(), mesa.getTotalSizeInBytes());
    EXPECT_EQ(std::memcmp(egl.data(), mesa.data(), egl.getTotalSizeInBytes()), 0);
    EXPECT_EQ(
        std::memcmp(frames[0].depth->data(), frames[1].depth->data(), frames[0].depth->getTotalSizeInBytes()),
        0);
    int covered = 0;
    for (int y = 0; y < frames[0].height(); ++y)
        for (int x = 0; x < frames[0].width(); ++x)
            covered += frames[0].isCovered(x, y);
    EXPECT_GT(covered, 96 * 64 / 4); // Not two blank pictures.
}

INSTANTIATE_TEST_SUITE_P(, HeadlessBackends, ::testing::Values(HeadlessBackend::OSMesa, HeadlessBackend::EGL),
                         [](const ::testing::TestParamInfo<HeadlessBackend>& param)
                         { return std::string(osgGlyphsHeadless::getHeadlessBackendName(param.param)); });
