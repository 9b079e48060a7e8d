#include "BenchMeasurement.h"

#include "BenchText.h"

#include <osgGlyphs/DepthPeeling>
#include <osgGlyphs/GlyphCloud>
#include <osgGlyphs/GlyphStateCache>
#include <osgGlyphs/ScreenEffects>
#include <osgGlyphsData/RandomCloud>
#include <osgGlyphsHeadless/OffscreenViewer>
#include <osgGlyphsTiles/TileBuilder>

#include <osgDB/ReadFile>

#include <osg/GLExtensions>
#include <osg/Geode>
#include <osg/Timer>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <vector>

namespace
{

/** The glyphs of a case and their GPU bytes per glyph. */
osg::ref_ptr<osgGlyphs::GlyphCloud> createCloud(const BenchCase& c, float radius,
                                                const BenchSettings& settings, double& bytesPerGlyph,
                                                double& occlusionSeconds)
{
    osgGlyphsData::RandomCloudOptions options;
    options.count = c.n;
    options.seed = settings.seed;
    options.shape = c.shape;
    options.radius = radius;
    options.smallestAxis = settings.smallestAxis;
    osg::ref_ptr<osgGlyphs::GlyphCloud> cloud = osgGlyphsData::createRandomCloud(options);
    cloud->setTechnique(osgGlyphs::createTechnique(c.technique).get());
    cloud->setCompressedAttributes(settings.compressedAttributes);
    cloud->setCompressedPositions(settings.compressedPositions);
    cloud->setUseVertexBufferObjects(settings.dataPath == DataPath::VBO);
    cloud->setUseDisplayList(settings.dataPath == DataPath::DisplayList);
    cloud->setCulling(c.culling);
    if (c.ambientOcclusion)
    {
        const osg::Timer_t start = osg::Timer::instance()->tick();
        cloud->setOcclusion(cloud->computeOcclusion().get());
        occlusionSeconds = osg::Timer::instance()->delta_s(start, osg::Timer::instance()->tick());
    }
    bytesPerGlyph = cloud->getGPUBytesPerGlyph();
    return cloud;
}

void applyScreenEffects(ScreenEffectsChoice choice, osgGlyphs::ScreenEffects& effects)
{
    effects.setAmbientOcclusion(choice == ScreenEffectsChoice::AmbientOcclusion ||
                                choice == ScreenEffectsChoice::Both);
    effects.setOutlines(choice == ScreenEffectsChoice::Outlines || choice == ScreenEffectsChoice::Both);
}

double timeFrame(osgGlyphsHeadless::OffscreenViewer& viewer, unsigned int frame)
{
    placeBenchCamera(*viewer.getCamera(), frame);
    const auto start = std::chrono::steady_clock::now();
    viewer.frame();
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

/** The fraction of pixels the scene drew on (the clear colour is transparent black). */
double getCoverage(const osg::Image& image)
{
    const unsigned char* pixels = image.data();
    const size_t count = static_cast<size_t>(image.s()) * image.t();
    if (!pixels || count == 0)
        return 0.0;
    size_t covered = 0;
    for (size_t i = 0; i < count; ++i)
        covered += (pixels[4 * i] | pixels[4 * i + 1] | pixels[4 * i + 2] | pixels[4 * i + 3]) != 0;
    return static_cast<double>(covered) / count;
}

#ifndef GL_FRAGMENT_SHADER_INVOCATIONS_ARB
#define GL_FRAGMENT_SHADER_INVOCATIONS_ARB 0x82F4
#endif

/** Counts the fragments the camera's scene shades (ARB_pipeline_statistics_query): its pre-draw
 * callback begins the query, its post-draw callback ends and reads it. */
class FragmentCounter : public osg::Camera::DrawCallback
{
public:
    explicit FragmentCounter(bool begin, FragmentCounter* beginner = nullptr)
        : _begin(begin), _beginner(beginner)
    {
    }

    void operator()(osg::RenderInfo& renderInfo) const override
    {
        FragmentCounter& counter = _begin ? const_cast<FragmentCounter&>(*this) : *_beginner;
        const unsigned int contextID = renderInfo.getState()->getContextID();
        osg::GLExtensions* ext = renderInfo.getState()->get<osg::GLExtensions>();
        if (!osg::isGLExtensionSupported(contextID, "GL_ARB_pipeline_statistics_query") || !ext->glGenQueries)
            return;
        if (_begin)
        {
            if (!counter._query)
                ext->glGenQueries(1, &counter._query);
            ext->glBeginQuery(GL_FRAGMENT_SHADER_INVOCATIONS_ARB, counter._query);
            return;
        }
        ext->glEndQuery(GL_FRAGMENT_SHADER_INVOCATIONS_ARB);
        GLuint64 fragments = 0;
        ext->glGetQueryObjectui64v(counter._query, GL_QUERY_RESULT, &fragments);
        counter._fragments = double(fragments);
    }

    double getFragments() const { return _fragments; }

private:
    bool _begin;
    FragmentCounter* _beginner;
    GLuint _query = 0;
    double _fragments = -1.0;
};

/** Fragments shaded per pixel drawn on, in one more frame; negative where GL cannot count. */
double measureOverdraw(osgGlyphsHeadless::OffscreenViewer& viewer, double coverage, unsigned int frame)
{
    osg::Camera* camera = viewer.getCamera();
    osg::ref_ptr<FragmentCounter> begin = new FragmentCounter(true);
    camera->setPreDrawCallback(begin.get());
    camera->setPostDrawCallback(new FragmentCounter(false, begin.get()));
    placeBenchCamera(*viewer.getCamera(), frame);
    viewer.frame();
    camera->setPreDrawCallback(nullptr);
    camera->setPostDrawCallback(nullptr);
    const osg::Viewport* viewport = camera->getViewport();
    const double covered = coverage * viewport->width() * viewport->height();
    return begin->getFragments() >= 0.0 && covered > 0.0 ? begin->getFragments() / covered : -1.0;
}

/** A fresh viewer of the settings' size, realized, reading back colour only. */
osg::ref_ptr<osgGlyphsHeadless::OffscreenViewer> createViewer(const BenchSettings& settings, osg::Node* scene)
{
    osg::ref_ptr<osgGlyphsHeadless::OffscreenViewer> viewer =
        new osgGlyphsHeadless::OffscreenViewer(settings.width, settings.height, settings.backend);
    if (!viewer->valid())
    {
        std::cerr << "osgglyphbench: " << viewer->getContextError() << std::endl;
        return nullptr;
    }
    viewer->getFrameCapture()->setCaptureDepth(false);
    viewer->getCamera()->setClearColor(osg::Vec4(0.0f, 0.0f, 0.0f, 0.0f));
    viewer->setSceneData(scene);
    viewer->realize();
    return viewer;
}

/** Times one warm-up frame and then settings.frames frames; false with a one-line error without
 * a context or when a glyph program failed to compile or link in the warm-up frame. */
bool measure(const BenchSettings& settings, osg::Node* scene, double& firstFrameMs,
             std::vector<double>& frameMs, osg::ref_ptr<osgGlyphsHeadless::OffscreenViewer>& viewer,
             std::string& error)
{
    viewer = createViewer(settings, scene);
    if (!viewer)
    {
        error = "no headless GL context";
        return false;
    }
    firstFrameMs = timeFrame(*viewer, 0);
    error = osgGlyphs::GlyphStateCache::instance()->getProgramError();
    if (!error.empty())
        return false;
    frameMs.clear();
    for (unsigned int frame = 1; frame <= settings.frames; ++frame)
        frameMs.push_back(timeFrame(*viewer, frame));
    return true;
}

}

double median(std::vector<double> values)
{
    std::sort(values.begin(), values.end());
    const size_t middle = values.size() / 2;
    return values.size() % 2 ? values[middle] : 0.5 * (values[middle - 1] + values[middle]);
}

bool measureArchive(const BenchSettings& settings, BenchResult& result, unsigned int& pagingFrames,
                    std::string& error)
{
    result = BenchResult{"archive", osgGlyphs::GlyphShape::Sphere, 0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0f};
    result.culling = osgGlyphs::GlyphCulling::Occlusion;
    if (!osgGlyphsTiles::findTileSerializers(error))
        return false;
    osg::ref_ptr<osg::Node> scene = osgDB::readNodeFile(settings.archive);
    if (!scene)
    {
        error = "--archive: cannot read " + settings.archive;
        return false;
    }
    osg::ref_ptr<osgGlyphsHeadless::OffscreenViewer> viewer = createViewer(settings, scene.get());
    if (!viewer)
    {
        error = "no headless GL context";
        return false;
    }
    result.firstFrameMs = timeFrame(*viewer, 0);
    pagingFrames = viewer->settlePaging();
    error = osgGlyphs::GlyphStateCache::instance()->getProgramError();
    if (!error.empty())
        return false;
    std::vector<double> frameMs;
    for (unsigned int frame = 1; frame <= settings.frames; ++frame)
        frameMs.push_back(timeFrame(*viewer, frame));
    result.msMedian = median(frameMs);
    result.msMin = *std::min_element(frameMs.begin(), frameMs.end());
    result.msMax = *std::max_element(frameMs.begin(), frameMs.end());
    return true;
}

bool measureCase(const BenchCase& c, float radius, const BenchSettings& settings, BenchResult& result,
                 std::string& renderer, std::string& error)
{
    result = BenchResult{c.technique, c.shape, c.n, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, radius, c.culling};
    result.ambientOcclusion = c.ambientOcclusion;
    result.screenEffects = c.screenEffects;
    result.opacity = c.opacity;
    result.transparency = c.transparency;
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    osg::ref_ptr<osgGlyphs::GlyphCloud> cloud =
        createCloud(c, radius, settings, result.bytesPerGlyph, result.occlusionSeconds);
    geode->addDrawable(cloud.get());
    osg::ref_ptr<osg::Group> content = geode;
    if (c.opacity < 1.0f)
    {
        cloud->setOpacity(c.opacity);
        osg::ref_ptr<osgGlyphs::DepthPeeling> peeling = new osgGlyphs::DepthPeeling;
        peeling->setNumLayers(settings.peelLayers);
        peeling->setMethod(c.transparency);
        peeling->addChild(geode.get());
        content = peeling;
    }
    osg::ref_ptr<osg::Group> scene = new osgGlyphs::ScreenEffects;
    scene->addChild(content.get());
    applyScreenEffects(c.screenEffects, static_cast<osgGlyphs::ScreenEffects&>(*scene));
    std::vector<double> frameMs;
    osg::ref_ptr<osgGlyphsHeadless::OffscreenViewer> viewer;
    if (!measure(settings, scene.get(), result.firstFrameMs, frameMs, viewer, error))
        return false;
    result.msMedian = median(frameMs);
    result.msMin = *std::min_element(frameMs.begin(), frameMs.end());
    result.msMax = *std::max_element(frameMs.begin(), frameMs.end());
    result.coverage = getCoverage(*viewer->getColorImage());
    renderer = viewer->getFrameCapture()->getGLRenderer();
    const osgGlyphs::GlyphCullingStatistics statistics =
        cloud->getCullingStatistics(viewer->getCamera()->getGraphicsContext()->getState()->getContextID());
    if (statistics.rounds > 0 && cloud->getNumGlyphs() > 0)
        result.submitted = double(statistics.glyphsSubmitted) / cloud->getNumGlyphs();
    result.overdraw = measureOverdraw(*viewer, result.coverage, settings.frames);
    return true;
}

void printFrameOverhead(const BenchSettings& settings)
{
    double firstFrameMs = 0.0;
    std::vector<double> frameMs;
    osg::ref_ptr<osgGlyphsHeadless::OffscreenViewer> viewer;
    osg::ref_ptr<osg::Group> empty = new osg::Group;
    std::string error;
    if (measure(settings, empty.get(), firstFrameMs, frameMs, viewer, error))
        std::cout << "Empty frame (clear + colour read-back, " << settings.width << "x" << settings.height
                  << "): median " << formatMs(median(frameMs)) << " ms, with "
                  << viewer->getFrameCapture()->getGLRenderer() << std::endl;
}

void placeBenchCamera(osg::Camera& camera, unsigned int frame)
{
    const osg::Vec3d centre(0.5, 0.5, 0.5);
    const double distance = 0.5 * std::sqrt(3.0) / std::sin(osg::DegreesToRadians(15.0));
    const double azimuth = osg::DegreesToRadians(30.0 + frame);
    const double elevation = osg::DegreesToRadians(20.0);
    const osg::Vec3d direction(std::cos(elevation) * std::cos(azimuth),
                               std::cos(elevation) * std::sin(azimuth), std::sin(elevation));
    camera.setViewMatrixAsLookAt(centre - direction * distance, centre, osg::Vec3d(0.0, 0.0, 1.0));
}
