#include "GlyphTestScenes.h"

#include <osgGlyphs/GlyphStateCache>

#include <osg/Geometry>
#include <osgDB/FileUtils>
#include <osgUtil/IntersectionVisitor>
#include <osgUtil/LineSegmentIntersector>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>

namespace osgGlyphsTest
{

osg::ref_ptr<osgGlyphs::GlyphCloud> createSphereCloud(const std::vector<SphereSpec>& spheres, bool lit)
{
    osg::ref_ptr<osg::Vec3Array> positions = new osg::Vec3Array;
    osg::ref_ptr<osg::FloatArray> radii = new osg::FloatArray;
    osg::ref_ptr<osg::Vec4ubArray> colors = new osg::Vec4ubArray;
    for (const SphereSpec& sphere : spheres)
    {
        positions->push_back(sphere.center);
        radii->push_back(sphere.radius);
        colors->push_back(sphere.color);
    }
    osg::ref_ptr<osgGlyphs::GlyphCloud> cloud = new osgGlyphs::GlyphCloud;
    cloud->setPositions(positions.get());
    cloud->setRadii(radii.get());
    cloud->setColors(colors.get());
    cloud->setLit(lit);
    return cloud;
}

void addSpheres(AnalyticScene& scene, const std::vector<SphereSpec>& spheres)
{
    for (const SphereSpec& sphere : spheres)
        scene.addSphere(sphere.center, sphere.radius);
}

osg::ref_ptr<osg::Geometry> createFlatQuad(const osg::Vec3& center, const osg::Vec3& u, const osg::Vec3& v,
                                           const osg::Vec4& color)
{
    osg::ref_ptr<osg::Geometry> quad = osg::createTexturedQuadGeometry(center - u - v, u * 2.0f, v * 2.0f);
    osg::ref_ptr<osg::Vec4Array> colors = new osg::Vec4Array(1, &color);
    quad->setColorArray(colors.get(), osg::Array::BIND_OVERALL);
    quad->getOrCreateStateSet()->setMode(GL_LIGHTING, osg::StateAttribute::OFF);
    return quad;
}

osg::ref_ptr<osg::Geode> group(std::initializer_list<osg::Drawable*> drawables)
{
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    for (osg::Drawable* drawable : drawables)
        geode->addDrawable(drawable);
    return geode;
}

int labelOfColor(const osg::Vec4ub& color, const std::vector<osg::Vec4ub>& palette, int tolerance)
{
    for (size_t i = 0; i < palette.size(); ++i)
    {
        bool same = true;
        for (int c = 0; c < 3; ++c)
            same = same && std::abs(int(color[c]) - int(palette[i][c])) <= tolerance;
        if (same)
            return static_cast<int>(i);
    }
    return -1;
}

Agreement compareWithTruth(const Frame& frame, const AnalyticScene& truth,
                           const std::vector<osg::Vec4ub>& palette, double depthTolerance,
                           double grazingCosine)
{
    Agreement result;
    for (int y = 0; y < frame.height(); ++y)
    {
        for (int x = 0; x < frame.width(); ++x)
        {
            const int label = truth.certainLabel(frame, x, y);
            if (label == AnalyticScene::AMBIGUOUS)
                continue;
            ++result.certain;
            const int shown = frame.isCovered(x, y) ? labelOfColor(frame.colorAt(x, y), palette) : -1;
            result.wrongLabel += shown != label ? 1 : 0;
            if (label < 0 || shown != label)
                continue;
            ++result.covered;
            const RayHit hit = truth.castPixel(frame, x, y);
            osg::Vec3d origin, direction;
            frame.pixelRay(x + 0.5, y + 0.5, origin, direction);
            if (std::fabs(hit.normal * direction) < grazingCosine)
                continue;
            const double error = std::fabs(frame.depthAt(x, y) - frame.windowDepth(hit.point));
            result.worstDepthError = std::max(result.worstDepthError, error);
            result.wrongDepth += error > depthTolerance ? 1 : 0;
        }
    }
    return result;
}

CentreAgreement compareEveryPixelCentre(const Frame& frame, const AnalyticScene& truth,
                                        const std::vector<osg::Vec4ub>& palette, double depthTolerance)
{
    CentreAgreement result;
    for (int y = 0; y < frame.height(); ++y)
    {
        for (int x = 0; x < frame.width(); ++x)
        {
            const RayHit hit = truth.castPixel(frame, x, y);
            result.hits += hit.hit() ? 1 : 0;
            result.wrongCoverage += hit.hit() != frame.isCovered(x, y) ? 1 : 0;
            if (!hit.hit() || !frame.isCovered(x, y))
                continue;
            result.wrongLabel += labelOfColor(frame.colorAt(x, y), palette) != hit.label ? 1 : 0;
            result.wrongDepth +=
                std::fabs(frame.depthAt(x, y) - frame.windowDepth(hit.point)) > depthTolerance ? 1 : 0;
        }
    }
    return result;
}

std::string writeShaderOverride(const std::string& folder, const std::string& name, const std::string& text)
{
    const std::string directory = outputPath(folder);
    osgDB::makeDirectory(directory + "/osgGlyphs");
    std::ofstream(directory + "/osgGlyphs/" + name) << text;
    return directory;
}

Frame renderWithShaderFolder(Renderer& renderer, osg::Node* scene, const std::string& folder)
{
    osgDB::getDataFilePathList().push_front(folder);
    osgGlyphs::GlyphStateCache::instance()->reloadShaders();
    const Frame frame = renderer.render(scene);
    osgDB::getDataFilePathList().pop_front();
    osgGlyphs::GlyphStateCache::instance()->reloadShaders();
    return frame;
}

NotifyCapture::NotifyCapture() : _previous(osg::getNotifyHandler())
{
    osg::setNotifyHandler(this);
}

void NotifyCapture::notify(osg::NotifySeverity severity, const char* message)
{
    std::lock_guard<std::mutex> lock(_mutex);
    if (severity <= osg::WARN)
        _text << message;
}

std::string NotifyCapture::stop()
{
    osg::ref_ptr<NotifyCapture> self = this; // setNotifyHandler drops the registry's reference
    osg::setNotifyHandler(_previous.get());
    std::lock_guard<std::mutex> lock(_mutex);
    return _text.str();
}

double CoverageComparison::depthPercentile(double fraction)
{
    if (depthErrors.empty())
        return 0.0;
    std::sort(depthErrors.begin(), depthErrors.end());
    return depthErrors[std::min(depthErrors.size() - 1, std::size_t(fraction * depthErrors.size()))];
}

CoverageComparison compareCoveredCentres(const Frame& frame, const AnalyticScene& truth, double size)
{
    CoverageComparison result;
    const osg::Matrixd toWindow = frame.view * frame.projection * osg::Matrixd::translate(1.0, 1.0, 1.0) *
                                  osg::Matrixd::scale(0.5 * frame.width(), 0.5 * frame.height(), 0.5);
    const osg::Matrixd fromWindow = osg::Matrixd::inverse(toWindow);
    for (int y = 0; y < frame.height(); ++y)
        for (int x = 0; x < frame.width(); ++x)
        {
            const RayHit hit = truth.castPixel(frame, x, y);
            const bool covered = frame.isCovered(x, y);
            result.truthCentres += hit.hit() ? 1 : 0;
            result.unionCentres += hit.hit() || covered ? 1 : 0;
            if (!hit.hit() || !covered)
                continue;
            ++result.intersection;
            const osg::Vec3d drawn = osg::Vec3d(x + 0.5, y + 0.5, frame.depthAt(x, y)) * fromWindow;
            osg::Vec3d origin, direction;
            frame.pixelRay(x + 0.5, y + 0.5, origin, direction);
            result.depthErrors.push_back(std::fabs((drawn - origin) * direction - hit.distance) / size);
        }
    return result;
}

PickingAgreement comparePicksWithTruth(osg::Node& scene, const AnalyticScene& truth)
{
    PickingAgreement result;
    for (int i = 0; i < 400; ++i)
    {
        const osg::Vec3d start(-4.0 + 8.0 * (i % 20) / 19.0, -10.0, -2.8 + 5.6 * (i / 20) / 19.0);
        const osg::Vec3d end = start + osg::Vec3d(0.05 * std::sin(i), 20.0, 0.05 * std::cos(i));
        osg::ref_ptr<osgUtil::LineSegmentIntersector> picker =
            new osgUtil::LineSegmentIntersector(start, end);
        picker->setIntersectionLimit(osgUtil::Intersector::LIMIT_NEAREST);
        osgUtil::IntersectionVisitor visitor(picker.get());
        scene.accept(visitor);
        osg::Vec3d direction = end - start;
        direction.normalize();
        const RayHit expected = truth.cast(start, direction);
        if (picker->containsIntersections() != expected.hit())
        {
            ++result.wrongHit;
            continue;
        }
        if (!expected.hit())
            continue;
        ++result.hits;
        const osgUtil::LineSegmentIntersector::Intersection& hit = picker->getFirstIntersection();
        result.wrongLabel += int(hit.primitiveIndex) != expected.label ? 1 : 0;
        result.worstDistance =
            std::max(result.worstDistance, (hit.getWorldIntersectPoint() - expected.point).length());
        const double cosine = hit.getWorldIntersectNormal() * expected.normal;
        result.worstNormalCosine = std::min(result.worstNormalCosine, cosine);
    }
    return result;
}

osg::ref_ptr<osg::LightSource> createColouredLight()
{
    osg::ref_ptr<osg::LightSource> source = new osg::LightSource;
    osg::Light* light = source->getLight();
    light->setLightNum(0);
    light->setPosition(osg::Vec4(-0.45f, -0.65f, 0.6f, 0.0f));
    light->setAmbient(osg::Vec4(0.05f, 0.05f, 0.08f, 1.0f));
    light->setDiffuse(osg::Vec4(0.85f, 0.8f, 0.7f, 1.0f));
    light->setSpecular(osg::Vec4(0.7f, 0.7f, 0.6f, 1.0f));
    return source;
}

EyeLight eyeLightOf(const osg::Light& light, const Frame& frame)
{
    const osg::Vec4& position = light.getPosition();
    EyeLight eyeLight;
    eyeLight.position = osg::Vec4d(
        osg::Matrixd::transform3x3(osg::Vec3d(position.x(), position.y(), position.z()), frame.view), 0.0);
    for (int c = 0; c < 3; ++c)
    {
        eyeLight.ambient[c] = light.getAmbient()[c];
        eyeLight.diffuse[c] = light.getDiffuse()[c];
        eyeLight.specular[c] = light.getSpecular()[c];
    }
    return eyeLight;
}

LitAgreement compareLitWithTruth(const Frame& frame, const AnalyticScene& truth,
                                 const std::vector<osg::Vec4ub>& labelColors, const EyeLight& light,
                                 const osg::Vec3d& material, int tolerance,
                                 const std::function<bool(const RayHit&)>& keep)
{
    LitAgreement result;
    for (int y = 0; y < frame.height(); ++y)
        for (int x = 0; x < frame.width(); ++x)
        {
            const int label = truth.certainLabel(frame, x, y);
            if (label < 0)
                continue;
            osg::Vec3d origin, direction;
            frame.pixelRay(x + 0.5, y + 0.5, origin, direction);
            const RayHit hit = truth.cast(origin, direction);
            if (keep && !keep(hit))
                continue;
            const osg::Vec4ub& color = labelColors[label];
            const osg::Vec3d lit =
                shadeLikeGlyphs(osg::Vec3d(color.r(), color.g(), color.b()) / 255.0, hit.point * frame.view,
                                osg::Matrixd::transform3x3(hit.normal, frame.view),
                                -osg::Matrixd::transform3x3(direction, frame.view), light, material);
            osg::Vec4ub expected(0, 0, 0, 255);
            for (int c = 0; c < 3; ++c)
                expected[c] = static_cast<unsigned char>(std::lround(std::clamp(lit[c], 0.0, 1.0) * 255.0));
            ++result.checked;
            result.wrong += colorNear(frame, x, y, expected, tolerance) ? 0 : 1;
        }
    return result;
}

}
