// One glyph cloud shared by the two views of an osgViewer::CompositeViewer, each view rendering
// into a headless context of its own, with a cull thread per camera and a draw thread per context:
// the two draw threads draw the same cloud at the same time, each while the next frame is culled.
// Every frame of each view must equal that view rendered alone, single-threaded, to the bit; also
// with the cloud transparent under a DepthPeeling node, whose buffers are per context.

#include "RenderHarness.h"

#include <osgGlyphs/DepthPeeling>
#include <osgGlyphsData/RandomCloud>
#include <osgGlyphsHeadless/FrameCapture>
#include <osgGlyphsHeadless/HeadlessContext>
#include <osgGlyphsHeadless/OffscreenViewer>

#include <osg/MatrixTransform>
#include <osg/io_utils>
#include <osgViewer/CompositeViewer>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <iostream>
#include <sstream>
#include <thread>
#include <vector>

using namespace osgGlyphsTest;

namespace
{

/** The frames each view draws; fewer for the transparent scenes, which draw slower. */
const unsigned int NUM_FRAMES = 300;
const unsigned int NUM_TRANSPARENT_FRAMES = 60;

/** How long the draw threads may take to finish the frames dispatched to them. */
const std::chrono::seconds DRAW_TIMEOUT(120);

/** A view of the scene: its size, and the direction and field of view it frames the scene with. */
struct ViewSpec
{
    const char* name;
    int width;
    int height;
    osg::Vec3d direction; // from the scene's centre to the eye
    double fovy;
};

const ViewSpec VIEWS[] = {
    {"large", 400, 300, osg::Vec3d(0.3, -1.0, 0.6), 40.0},
    {"small", 200, 200, osg::Vec3d(1.0, 0.8, 0.9), 30.0},
};

/** 2000 lit spheres with scalars in the unit cube, the same every time. */
osg::ref_ptr<osgGlyphs::GlyphCloud> createCloud()
{
    osgGlyphsData::RandomCloudOptions options;
    options.count = 2000;
    options.seed = 11;
    options.radius = 0.02f;
    osg::ref_ptr<osgGlyphs::GlyphCloud> cloud = osgGlyphsData::createRandomCloud(options);
    cloud->setLit(true);
    return cloud;
}

/** How the cloud is drawn: opaque, or at opacity 0.5 under a DepthPeeling node of a method. */
struct SceneSpec
{
    int numCopies = 1;
    bool transparent = false;
    osgGlyphs::DepthPeeling::Method method = osgGlyphs::DepthPeeling::K_BUFFER;
};

/** The cloud under numCopies transforms in a grid of 5 x 3 x 2, or alone for 1; transparent, under
 * a DepthPeeling node. */
osg::ref_ptr<osg::Group> createScene(osgGlyphs::GlyphCloud* cloud, const SceneSpec& sceneSpec)
{
    const int numCopies = sceneSpec.numCopies;
    osg::ref_ptr<osg::Group> root;
    if (sceneSpec.transparent)
    {
        cloud->setOpacity(0.5f);
        osg::ref_ptr<osgGlyphs::DepthPeeling> peeling = new osgGlyphs::DepthPeeling;
        peeling->setMethod(sceneSpec.method);
        root = peeling;
    }
    else
        root = new osg::Group;
    if (numCopies == 1)
    {
        root->addChild(cloud);
        return root;
    }
    for (int i = 0; i < numCopies; ++i)
    {
        const osg::Vec3 offset(1.25f * (i % 5), 1.25f * (i / 5 % 3), 1.25f * (i / 15));
        osg::ref_ptr<osg::MatrixTransform> transform =
            new osg::MatrixTransform(osg::Matrix::translate(offset));
        transform->addChild(cloud);
        root->addChild(transform.get());
    }
    return root;
}

/** Frames the scene's bounding sphere; near and far are left to OSG, which computes them in every
 * cull and writes them into the camera's projection. */
void setUpCamera(osg::Camera& camera, const ViewSpec& spec, const osg::BoundingSphere& bound)
{
    const double aspect = static_cast<double>(spec.width) / spec.height;
    const double distance = 1.05 * bound.radius() / std::sin(osg::DegreesToRadians(spec.fovy) / 2.0);
    osg::Vec3d direction = spec.direction;
    direction.normalize();
    camera.setViewport(0, 0, spec.width, spec.height);
    camera.setProjectionMatrixAsPerspective(spec.fovy, aspect, 0.1, 100.0);
    camera.setViewMatrixAsLookAt(osg::Vec3d(bound.center()) + direction * distance, bound.center(),
                                 osg::Vec3d(0.0, 0.0, 1.0));
    camera.setClearColor(osg::Vec4(0.1f, 0.1f, 0.15f, 1.0f));
    camera.setComputeNearFarMode(osg::CullSettings::COMPUTE_NEAR_FAR_USING_BOUNDING_VOLUMES);
}

/** Frames of a view rendered alone. OSG computes near and far in every cull from the camera's
 * projection, which the cull before has clamped: the projection changes in its last bits over the
 * first frames, then settles into a cycle of one or two frames (two for the small view of the 30
 * copies). The reference ends with that cycle: its last frame equals the one two before. */
using Reference = std::vector<Frame>;

/** The most frames the projection may take to settle. */
const unsigned int MAX_REFERENCE_FRAMES = 20;

/** What frame frameNumber of the view is to be. */
const Frame& referenceFrame(const Reference& reference, unsigned int frameNumber)
{
    const std::size_t cycleStart = reference.size() - 2;
    return frameNumber < reference.size() ? reference[frameNumber]
                                          : reference[cycleStart + (frameNumber - cycleStart) % 2];
}

int countCoveredPixels(const osg::Image& depth)
{
    const float* values = reinterpret_cast<const float*>(depth.data());
    int covered = 0;
    for (int i = 0; i < depth.s() * depth.t(); ++i)
        covered += values[i] < 1.0f ? 1 : 0;
    return covered;
}

/** Pixels whose colour or depth differ from the expected frame's. */
int countDifferingPixels(const Frame& expected, const osg::Image& color, const osg::Image& depth)
{
    if (color.s() != expected.width() || color.t() != expected.height())
        return expected.width() * expected.height();
    const float* depths = reinterpret_cast<const float*>(depth.data());
    const float* expectedDepths = reinterpret_cast<const float*>(expected.depth->data());
    int differing = 0;
    for (int i = 0; i < color.s() * color.t(); ++i)
    {
        const bool sameColor =
            std::equal(color.data() + 4 * i, color.data() + 4 * i + 4, expected.color->data() + 4 * i);
        differing += sameColor && depths[i] == expectedDepths[i] ? 0 : 1;
    }
    return differing;
}

bool sameFrames(const Frame& a, const Frame& b)
{
    return countDifferingPixels(a, *b.color, *b.depth) == 0 && a.projection == b.projection &&
           a.view == b.view;
}

/** The view rendered alone in a single-threaded viewer, until a frame equals the one two before. */
Reference renderAlone(osg::Node* scene, const ViewSpec& spec)
{
    Renderer renderer(spec.width, spec.height);
    setUpCamera(*renderer.getViewer()->getCamera(), spec, scene->getBound());
    Reference frames;
    while (frames.size() < 3 || !sameFrames(frames[frames.size() - 3], frames.back()))
    {
        if (frames.size() == MAX_REFERENCE_FRAMES)
            return Reference();
        frames.push_back(renderer.render(scene));
    }
    return frames;
}

/** A frame that differs from the reference. */
struct Mismatch
{
    unsigned int frameNumber;
    int differingPixels; // colour or depth
    int coveredPixels;
    bool matricesDiffer;
};

/** A capture that compares every frame with the view's reference on the draw thread, as it reads
 * it back, and keeps the frames that differ and the first of their images. */
class CheckingCapture : public osgGlyphsHeadless::FrameCapture
{
public:
    explicit CheckingCapture(const Reference& reference) : _reference(reference) {}

    void operator()(osg::RenderInfo& renderInfo) const override
    {
        FrameCapture::operator()(renderInfo);
        // Each context draws its frames in order: this is the frame after the ones checked.
        const unsigned int frameNumber = _numChecked.load(std::memory_order_relaxed);
        const Frame& expected = referenceFrame(_reference, frameNumber);
        const osg::Image& color = *getColorImage();
        const osg::Image& depth = *getDepthImage();
        const int differing = countDifferingPixels(expected, color, depth);
        const bool matricesDiffer =
            getProjectionMatrix() != expected.projection || getViewMatrix() != expected.view;
        if (differing > 0 || matricesDiffer)
        {
            _mismatches.push_back({frameNumber, differing, countCoveredPixels(depth), matricesDiffer});
            if (!_firstMismatch.color.valid())
            {
                _firstMismatch.color = new osg::Image(color, osg::CopyOp::DEEP_COPY_ALL);
                _firstMismatch.depth = new osg::Image(depth, osg::CopyOp::DEEP_COPY_ALL);
            }
        }
        _numChecked.fetch_add(1, std::memory_order_release);
    }

    /** Frames checked so far; once it is read as the number of frames, everything else may be. */
    unsigned int getNumChecked() const { return _numChecked.load(std::memory_order_acquire); }
    const std::vector<Mismatch>& getMismatches() const { return _mismatches; }
    const Frame& getFirstMismatch() const { return _firstMismatch; }

private:
    const Reference _reference;
    mutable std::vector<Mismatch> _mismatches;
    mutable Frame _firstMismatch;
    mutable std::atomic<unsigned int> _numChecked{0};
};

/** "3 of 300 frames differ: frame 17 (1520 pixels differ, 0 covered of 10230) ...". */
std::string describe(const CheckingCapture& capture, const Reference& reference)
{
    const std::vector<Mismatch>& mismatches = capture.getMismatches();
    std::ostringstream text;
    text << mismatches.size() << " of " << capture.getNumChecked()
         << " frames differ from the single-threaded render";
    int vanished = 0;
    for (const Mismatch& mismatch : mismatches)
        vanished += mismatch.coveredPixels == 0 ? 1 : 0;
    text << " (the glyphs vanished in " << vanished << "; the reference covers "
         << countCoveredPixels(*reference.back().depth) << " pixels)";
    for (std::size_t i = 0; i < mismatches.size() && i < 8; ++i)
        text << (i ? "; " : ": ") << "frame " << mismatches[i].frameNumber << ": "
             << mismatches[i].differingPixels << " pixels differ, " << mismatches[i].coveredPixels
             << " covered" << (mismatches[i].matricesDiffer ? ", other matrices" : "");
    return text.str();
}

/** Renders NUM_FRAMES (NUM_TRANSPARENT_FRAMES) frames of the cloud, numCopies times per view, in both views
 * at once, and checks every one against each view rendered alone. */
void renderTwoViewsInParallel(const SceneSpec& sceneSpec, const std::string& name)
{
    const int numViews = sizeof(VIEWS) / sizeof(VIEWS[0]);
    std::vector<Reference> references;
    for (const ViewSpec& spec : VIEWS)
    {
        references.push_back(renderAlone(createScene(createCloud().get(), sceneSpec).get(), spec));
        ASSERT_FALSE(references.back().empty())
            << spec.name << ": alone, no frame equals the one two before in " << MAX_REFERENCE_FRAMES;
        ASSERT_GT(countCoveredPixels(*references.back().back().depth), 1000)
            << spec.name << ": the reference is empty";
    }

    osg::ref_ptr<osgGlyphs::GlyphCloud> cloud = createCloud();
    osg::ref_ptr<osg::Group> scene = createScene(cloud.get(), sceneSpec);
    osg::ref_ptr<osgViewer::CompositeViewer> viewer = new osgViewer::CompositeViewer;
    viewer->setThreadingModel(osgViewer::ViewerBase::CullThreadPerCameraDrawThreadPerContext);
    std::vector<osg::ref_ptr<CheckingCapture>> captures;
    for (int v = 0; v < numViews; ++v)
    {
        const ViewSpec& spec = VIEWS[v];
        osg::ref_ptr<osgGlyphsHeadless::HeadlessContext> context =
            osgGlyphsHeadless::HeadlessContext::create(spec.width, spec.height);
        ASSERT_TRUE(context.valid());
        osg::ref_ptr<osgViewer::View> view = new osgViewer::View;
        osg::Camera* camera = view->getCamera();
        camera->setGraphicsContext(context.get());
        setUpCamera(*camera, spec, scene->getBound());
        camera->setDrawBuffer(GL_FRONT);
        camera->setReadBuffer(GL_FRONT);
        captures.push_back(new CheckingCapture(references[v]));
        camera->setFinalDrawCallback(captures.back().get());
        view->setSceneData(scene.get());
        viewer->addView(view.get());
    }

    const auto start = std::chrono::steady_clock::now();
    const unsigned int numFrames = sceneSpec.transparent ? NUM_TRANSPARENT_FRAMES : NUM_FRAMES;
    for (unsigned int frame = 0; frame < numFrames; ++frame)
        viewer->frame();
    // frame() returns before its draws are done: wait for the last ones.
    const auto deadline = std::chrono::steady_clock::now() + DRAW_TIMEOUT;
    for (const osg::ref_ptr<CheckingCapture>& capture : captures)
    {
        while (capture->getNumChecked() < numFrames && std::chrono::steady_clock::now() < deadline)
            std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    viewer->stopThreading();

    for (int v = 0; v < numViews; ++v)
    {
        const CheckingCapture& capture = *captures[v];
        const std::string summary = describe(capture, references[v]);
        std::cout << name << ", view " << VIEWS[v].name << " (" << VIEWS[v].width << "x" << VIEWS[v].height
                  << "): " << summary << "; " << numFrames << " frames in " << seconds << " s" << std::endl;
        ASSERT_EQ(capture.getNumChecked(), numFrames) << VIEWS[v].name << ": frames not drawn in time";
        if (!capture.getMismatches().empty())
        {
            const std::string prefix = name + "_" + VIEWS[v].name;
            saveFrame(references[v].back(), prefix + "_expected");
            saveFrame(capture.getFirstMismatch(), prefix + "_first_mismatch");
            ADD_FAILURE() << "view " << VIEWS[v].name << ": " << summary << "; the first mismatch is in "
                          << outputPath(prefix + "_first_mismatch.png");
        }
    }
}

}

TEST(SharedCloudTwoViews, EveryFrameOfEachViewIsItsSingleThreadedRender)
{
    renderTwoViewsInParallel(SceneSpec{}, "shared_cloud_two_views");
}

TEST(SharedCloudTwoViews, ThirtyTransformsOfTheCloudInEachView)
{
    renderTwoViewsInParallel(SceneSpec{30}, "shared_cloud_two_views_30_transforms");
}

TEST(SharedCloudTwoViews, TransparentThroughAKBuffer)
{
    renderTwoViewsInParallel(SceneSpec{1, true, osgGlyphs::DepthPeeling::K_BUFFER},
                             "shared_cloud_two_views_k_buffer");
}

TEST(SharedCloudTwoViews, TransparentThroughPeelPasses)
{
    renderTwoViewsInParallel(SceneSpec{1, true, osgGlyphs::DepthPeeling::PEEL_PASSES},
                             "shared_cloud_two_views_peel_passes");
}
