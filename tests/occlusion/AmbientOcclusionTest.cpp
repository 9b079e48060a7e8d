// Per-glyph ambient occlusion: a lone glyph is open all round, a glyph inside a closed shell of
// glyphs is (almost) fully occluded, a sphere lying on a plane of spheres receives less light on
// its contact side, vector glyphs occlude along their whole length, and the shaders dim the
// contact side of a rendered sphere with every impostor technique.

#include "RenderHarness.h"

#include <osgGlyphs/GlyphCloud>
#include <osgGlyphs/GlyphStateCache>
#include <osgGlyphs/GlyphTechnique>

#include <osg/Group>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

using namespace osgGlyphsTest;
using osgGlyphs::GlyphCloud;

namespace
{

/** The light a surface point of unit normal n receives, as the shaders decode it. */
float lightReceived(const osg::Vec4ub& value, const osg::Vec3& n)
{
    const osg::Vec3 vector(value.r() / 255.0f * 2.0f - 1.0f, value.g() / 255.0f * 2.0f - 1.0f,
                           value.b() / 255.0f * 2.0f - 1.0f);
    return std::min(std::max(value.a() / 255.0f + vector * n, 0.0f), 1.0f);
}

osg::ref_ptr<GlyphCloud> sphereCloud(const std::vector<osg::Vec3>& centres, float radius)
{
    osg::ref_ptr<GlyphCloud> cloud = new GlyphCloud;
    cloud->setPositions(new osg::Vec3Array(centres.begin(), centres.end()));
    cloud->setRadius(radius);
    return cloud;
}

/** The test sphere at the origin, first, and a plane of spheres under it, touching it. */
std::vector<osg::Vec3> sphereOnPlane(float radius)
{
    std::vector<osg::Vec3> centres{osg::Vec3(0.0f, 0.0f, 0.0f)};
    for (int y = -6; y <= 6; ++y)
        for (int x = -6; x <= 6; ++x)
            centres.emplace_back(x * 2.0f * radius, y * 2.0f * radius, -2.0f * radius);
    return centres;
}

const osg::Vec3 UP(0.0f, 0.0f, 1.0f), DOWN(0.0f, 0.0f, -1.0f), SIDE(1.0f, 0.0f, 0.0f);

}

TEST(AmbientOcclusion, LoneSphereIsOpenAllRound)
{
    osg::ref_ptr<GlyphCloud> cloud = sphereCloud({osg::Vec3(1.0f, 2.0f, 3.0f)}, 0.5f);
    osg::ref_ptr<osg::Vec4ubArray> occlusion = cloud->computeOcclusion();
    ASSERT_EQ(occlusion->size(), 1u);
    for (const osg::Vec3& n : {UP, DOWN, SIDE, -SIDE})
        EXPECT_NEAR(lightReceived((*occlusion)[0], n), 1.0f, 0.02f);
}

TEST(AmbientOcclusion, SphereInsideClosedShellIsOccluded)
{
    // 400 spheres of radius 0.5 on a sphere of radius 3: they overlap and close it.
    std::vector<osg::Vec3> centres{osg::Vec3()};
    const unsigned int shell = 400;
    const double golden = M_PI * (3.0 - std::sqrt(5.0));
    for (unsigned int k = 0; k < shell; ++k)
    {
        const double h = 1.0 - (2.0 * k + 1.0) / shell, ring = std::sqrt(1.0 - h * h);
        centres.emplace_back(3.0 * ring * std::cos(golden * k), 3.0 * ring * std::sin(golden * k), 3.0 * h);
    }
    osg::ref_ptr<GlyphCloud> cloud = sphereCloud(centres, 0.5f);
    osgGlyphs::GlyphOcclusionSettings settings;
    settings.reach = 4.0f;
    osg::ref_ptr<osg::Vec4ubArray> occlusion = cloud->computeOcclusion(settings);
    EXPECT_LE((*occlusion)[0].a(), 3) << "the mean light reaching the enclosed sphere";
    for (const osg::Vec3& n : {UP, DOWN, SIDE, -SIDE})
        EXPECT_LT(lightReceived((*occlusion)[0], n), 0.03f);
    // The shell's own spheres see outwards: the side facing away from the centre is lit.
    EXPECT_GT(lightReceived((*occlusion)[1], UP), 3.0f * lightReceived((*occlusion)[1], DOWN));
}

TEST(AmbientOcclusion, SphereOnPlaneIsDarkerOnItsContactSide)
{
    osg::ref_ptr<GlyphCloud> cloud = sphereCloud(sphereOnPlane(0.5f), 0.5f);
    osg::ref_ptr<osg::Vec4ubArray> occlusion = cloud->computeOcclusion();
    const osg::Vec4ub value = (*occlusion)[0];
    EXPECT_GT(lightReceived(value, UP), 0.9f);
    EXPECT_LT(lightReceived(value, DOWN), 0.4f);
    EXPECT_LT(lightReceived(value, SIDE), lightReceived(value, UP));
    EXPECT_GT(lightReceived(value, SIDE), lightReceived(value, DOWN));
}

TEST(AmbientOcclusion, OccluderOutOfReachDoesNotOcclude)
{
    osgGlyphs::GlyphOcclusionSettings settings;
    settings.reach = 1.0f;
    // A wide sphere whose surface is 1.5 below the small one's.
    osg::ref_ptr<GlyphCloud> cloud = sphereCloud({osg::Vec3(), osg::Vec3(0.0f, 0.0f, -3.5f)}, 0.5f);
    const std::vector<float> radii{0.5f, 1.5f};
    cloud->setRadii(new osg::FloatArray(radii.begin(), radii.end()));
    EXPECT_NEAR(lightReceived((*cloud->computeOcclusion(settings))[0], DOWN), 1.0f, 0.02f);
    settings.reach = 2.0f;
    EXPECT_LT(lightReceived((*cloud->computeOcclusion(settings))[0], DOWN), 0.95f);
}

TEST(AmbientOcclusion, CylinderOccludesAlongItsWholeLength)
{
    // A cylinder 6 long along x, centred on its data point at the origin, and a short one lying
    // on it near its far end: 2.5 from the long one's data point, beyond the reach of a sphere
    // of the long one's radius there, but on its surface.
    osg::ref_ptr<GlyphCloud> cloud =
        sphereCloud({osg::Vec3(0.0f, 0.0f, 0.0f), osg::Vec3(2.5f, 0.0f, 0.7f)}, 0.3f);
    const std::vector<osg::Vec3> vectors{osg::Vec3(6.0f, 0.0f, 0.0f), osg::Vec3(0.6f, 0.0f, 0.0f)};
    cloud->setVectors(new osg::Vec3Array(vectors.begin(), vectors.end()));
    cloud->setShape(osgGlyphs::GlyphShape::Cylinder);
    osgGlyphs::GlyphOcclusionSettings settings;
    settings.reach = 1.0f;
    osg::ref_ptr<osg::Vec4ubArray> occlusion = cloud->computeOcclusion(settings);
    EXPECT_LT(lightReceived((*occlusion)[1], DOWN), 0.8f) << "the short cylinder lies on the long one";
    EXPECT_GT(lightReceived((*occlusion)[1], UP), 0.95f);
    EXPECT_GT(lightReceived((*occlusion)[0], DOWN), 0.95f) << "nothing lies under the long cylinder";
    EXPECT_LT(lightReceived((*occlusion)[0], UP), lightReceived((*occlusion)[0], DOWN));
}

namespace
{

float luminance(const osg::Vec4ub& c)
{
    return (c.r() + c.g() + c.b()) / 3.0f;
}

/** The sphere on its plane seen level from the side under the headlight: the luminance of the
 * test sphere at a point above and one below its equator, symmetric to the light. */
std::pair<float, float> renderTopAndBottom(const std::string& technique, osg::Node* scene)
{
    Renderer renderer(240, 240);
    renderer.setLookAt(osg::Vec3d(0.0, -10.0, 0.0), osg::Vec3d(0.0, 0.0, 0.0), osg::Vec3d(0.0, 0.0, 1.0));
    renderer.setPerspective(20.0, 1.0, 40.0);
    const Frame frame = renderer.render(scene);
    saveFrame(frame, "ambient_occlusion_" + technique);
    const double angle = osg::DegreesToRadians(40.0);
    const osg::Vec3d top = frame.project(osg::Vec3d(0.0, -0.5 * std::cos(angle), 0.5 * std::sin(angle)));
    const osg::Vec3d bottom = frame.project(osg::Vec3d(0.0, -0.5 * std::cos(angle), -0.5 * std::sin(angle)));
    return {luminance(frame.colorAt(int(top.x()), int(top.y()))),
            luminance(frame.colorAt(int(bottom.x()), int(bottom.y())))};
}

}

class AmbientOcclusionRender : public ::testing::TestWithParam<std::string>
{
};

TEST_P(AmbientOcclusionRender, ContactSideIsDarker)
{
    osg::ref_ptr<GlyphCloud> cloud = sphereCloud(sphereOnPlane(0.5f), 0.5f);
    cloud->setTechnique(osgGlyphs::createTechnique(GetParam()).get());
    osg::ref_ptr<osg::Group> scene = new osg::Group;
    scene->addChild(cloud.get());

    const std::pair<float, float> plain = renderTopAndBottom(GetParam() + "_off", scene.get());
    ASSERT_GT(plain.first, 60.0f) << "the test sphere is lit";
    EXPECT_NEAR(plain.first, plain.second, 3.0f) << "without occlusion the headlight lights both alike";

    cloud->setOcclusion(cloud->computeOcclusion().get());
    const std::pair<float, float> occluded = renderTopAndBottom(GetParam(), scene.get());
    EXPECT_NEAR(occluded.first, plain.first, 0.1f * plain.first) << "the open side keeps its light";
    EXPECT_LT(occluded.second, 0.6f * occluded.first) << "the contact side is darker";

    // A parent StateSet turns it off for the subgraph.
    osgGlyphs::setGlyphAmbientOcclusion(*scene->getOrCreateStateSet(), false);
    const std::pair<float, float> overridden = renderTopAndBottom(GetParam() + "_overridden", scene.get());
    EXPECT_NEAR(overridden.second, plain.second, 2.0f);
}

INSTANTIATE_TEST_SUITE_P(Techniques, AmbientOcclusionRender,
                         ::testing::Values("geometry-shader", "point-sprite", "instanced"),
                         [](const ::testing::TestParamInfo<std::string>& instance)
                         {
                             std::string name = instance.param;
                             name.erase(std::remove(name.begin(), name.end(), '-'), name.end());
                             return name;
                         });

TEST(AmbientOcclusion, ShortArrayIsNotUsed)
{
    osg::ref_ptr<GlyphCloud> cloud = sphereCloud({osg::Vec3(), osg::Vec3(2.0f, 0.0f, 0.0f)}, 0.5f);
    cloud->setOcclusion(new osg::Vec4ubArray(1));
    EXPECT_EQ(cloud->getGlyphArrays().occlusion, nullptr);
    EXPECT_FALSE(cloud->getCloudStateSet()->getDefinePair(osgGlyphs::GLYPH_AMBIENT_OCCLUSION_DEFINE));
    cloud->setOcclusion(cloud->computeOcclusion().get());
    EXPECT_NE(cloud->getGlyphArrays().occlusion, nullptr);
    EXPECT_TRUE(cloud->getCloudStateSet()->getDefinePair(osgGlyphs::GLYPH_AMBIENT_OCCLUSION_DEFINE));
}
