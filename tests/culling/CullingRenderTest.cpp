// Culling never changes the picture: dense clouds drawn with occlusion culling are pixel-identical
// in colour and depth to the same clouds drawn without it, over an orbit with a jump of the
// camera to the opposite side, for every shape, after in-place edits, under a clip plane and in
// a second view; and culling does skip chunks, so that these comparisons test something.

#include "../harness/RenderHarness.h"

#include <osgGlyphs/GlyphCloud>

#include <osg/ClipPlane>
#include <osg/Geode>
#include <osg/LightSource>

#include <cmath>
#include <random>

using namespace osgGlyphsTest;
using osgGlyphs::GlyphCloud;
using osgGlyphs::GlyphCulling;
using osgGlyphs::GlyphShape;

namespace
{

const int WIDTH = 320, HEIGHT = 240;
const unsigned int COUNT = 20000;

/** COUNT random glyphs in the unit cube at 0.4 x their mean spacing: they touch and hide each
 * other, as atoms and grains do. Vector shapes get random directions two radii long. */
osg::ref_ptr<GlyphCloud> createDenseCloud(GlyphShape shape)
{
    std::mt19937 random(7);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    osg::ref_ptr<osg::Vec3Array> positions = new osg::Vec3Array;
    osg::ref_ptr<osg::Vec3Array> vectors = new osg::Vec3Array;
    osg::ref_ptr<osg::FloatArray> scalars = new osg::FloatArray;
    const float radius = 0.4f / std::cbrt(float(COUNT));
    for (unsigned int i = 0; i < COUNT; ++i)
    {
        positions->push_back(osg::Vec3(unit(random), unit(random), unit(random)));
        osg::Vec3 direction(unit(random) - 0.5f, unit(random) - 0.5f, unit(random) - 0.5f);
        direction.normalize();
        vectors->push_back(direction * (2.0f * radius));
        scalars->push_back(unit(random));
    }
    osg::ref_ptr<GlyphCloud> cloud = new GlyphCloud;
    cloud->setPositions(positions.get());
    cloud->setRadius(radius);
    cloud->setScalars(scalars.get());
    cloud->setVectors(vectors.get());
    cloud->setShape(shape);
    cloud->setCullingChunkSize(128);
    return cloud;
}

osg::ref_ptr<osg::Group> createScene(GlyphCloud* cloud)
{
    osg::ref_ptr<osg::Group> root = new osg::Group;
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    geode->addDrawable(cloud);
    root->addChild(geode.get());
    return root;
}

/** Looks at the cube's centre from azimuth degrees. */
void orbit(Renderer& renderer, double azimuth)
{
    const osg::Vec3d centre(0.5, 0.5, 0.5);
    const double a = osg::DegreesToRadians(azimuth), e = osg::DegreesToRadians(20.0);
    const osg::Vec3d direction(std::cos(e) * std::cos(a), std::cos(e) * std::sin(a), std::sin(e));
    renderer.setLookAt(centre - direction * 2.2, centre, osg::Vec3d(0.0, 0.0, 1.0));
}

/** How many pixels differ at all in colour or depth. */
int countDifferences(const Frame& a, const Frame& b)
{
    int different = 0;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x)
        {
            const bool differs = a.colorAt(x, y) != b.colorAt(x, y) || a.depthAt(x, y) != b.depthAt(x, y);
            different += differs;
        }
    return different;
}

osgGlyphs::GlyphCullingStatistics statisticsOf(const GlyphCloud& cloud, Renderer& renderer)
{
    return cloud.getCullingStatistics(
        renderer.getViewer()->getCamera()->getGraphicsContext()->getState()->getContextID());
}

/** Renders the scene with the cloud's culling set to each mode in turn. */
Frame renderWith(Renderer& renderer, osg::Node* scene, GlyphCloud& cloud, GlyphCulling culling)
{
    cloud.setCulling(culling);
    return renderer.render(scene);
}

class CullingRender : public ::testing::TestWithParam<GlyphShape>
{
};

}

TEST_P(CullingRender, OrbitWithAJumpMatchesTheUnculledCloud)
{
    Renderer renderer(WIDTH, HEIGHT);
    renderer.setPerspective(40.0, 0.5, 5.0);
    osg::ref_ptr<GlyphCloud> cloud = createDenseCloud(GetParam());
    osg::ref_ptr<osg::Group> scene = createScene(cloud.get());
    unsigned int occluded = 0;
    // The jump to 225 degrees sees the far side of the cube first.
    for (double azimuth : {30.0, 40.0, 50.0, 225.0, 235.0})
    {
        orbit(renderer, azimuth);
        const Frame culled = renderWith(renderer, scene.get(), *cloud, GlyphCulling::Occlusion);
        const osgGlyphs::GlyphCullingStatistics statistics = statisticsOf(*cloud, renderer);
        occluded += statistics.chunksOccluded;
        EXPECT_GT(statistics.rounds, 1u) << "occlusion culling was not tried";
        const Frame frustum = renderWith(renderer, scene.get(), *cloud, GlyphCulling::Frustum);
        const Frame off = renderWith(renderer, scene.get(), *cloud, GlyphCulling::Off);
        EXPECT_EQ(countDifferences(culled, frustum), 0) << "azimuth " << azimuth;
        // Off draws in the caller's order: only exact depth ties between two glyphs may differ.
        EXPECT_LE(countDifferences(culled, off), WIDTH * HEIGHT / 2000) << "azimuth " << azimuth;
        if (azimuth == 225.0)
            saveFrame(culled, std::string("culling_") + osgGlyphs::getShapeName(GetParam()));
    }
    EXPECT_GT(occluded, 0u) << "no chunk was ever occluded: the comparison tested nothing";
}

INSTANTIATE_TEST_SUITE_P(Shapes, CullingRender,
                         ::testing::Values(GlyphShape::Sphere, GlyphShape::Cone, GlyphShape::Arrow,
                                           GlyphShape::Cylinder),
                         [](const ::testing::TestParamInfo<GlyphShape>& instance)
                         { return std::string(osgGlyphs::getShapeName(instance.param)); });

TEST(CullingRenderEdits, MovedGlyphsAndAClipPlaneMatchTheUnculledCloud)
{
    Renderer renderer(WIDTH, HEIGHT);
    renderer.setPerspective(40.0, 0.5, 5.0);
    osg::ref_ptr<GlyphCloud> cloud = createDenseCloud(GlyphShape::Sphere);
    osg::ref_ptr<osg::Group> scene = createScene(cloud.get());
    orbit(renderer, 30.0);
    renderWith(renderer, scene.get(), *cloud, GlyphCulling::Occlusion);

    // Half the glyphs move in place, to the front of the cube: chunks must follow them.
    osg::Vec3Array& positions = *cloud->getPositions();
    for (unsigned int i = 0; i < positions.size(); i += 2)
        positions[i] += osg::Vec3(-0.3f, -0.2f, 0.1f);
    positions.dirty();
    cloud->dirtyGlyphs();
    Frame culled = renderWith(renderer, scene.get(), *cloud, GlyphCulling::Occlusion);
    EXPECT_GT(statisticsOf(*cloud, renderer).chunksOccluded, 0u);
    EXPECT_EQ(countDifferences(culled, renderWith(renderer, scene.get(), *cloud, GlyphCulling::Frustum)), 0);

    // A clip plane cuts the front away: what was hidden behind it shows.
    scene->getOrCreateStateSet()->setAttributeAndModes(
        new osg::ClipPlane(0, osg::Plane(1.0, 1.0, 0.0, -0.9)));
    culled = renderWith(renderer, scene.get(), *cloud, GlyphCulling::Occlusion);
    EXPECT_EQ(countDifferences(culled, renderWith(renderer, scene.get(), *cloud, GlyphCulling::Frustum)), 0);
    EXPECT_LE(countDifferences(culled, renderWith(renderer, scene.get(), *cloud, GlyphCulling::Off)),
              WIDTH * HEIGHT / 2000);
}

TEST(CullingRenderEdits, ChunksOutsideTheViewAreSkipped)
{
    Renderer renderer(WIDTH, HEIGHT);
    renderer.setPerspective(20.0, 0.1, 5.0);
    osg::ref_ptr<GlyphCloud> cloud = createDenseCloud(GlyphShape::Sphere);
    osg::ref_ptr<osg::Group> scene = createScene(cloud.get());
    renderer.setLookAt(osg::Vec3d(0.1, -0.8, 0.1), osg::Vec3d(0.1, 0.5, 0.1), osg::Vec3d(0.0, 0.0, 1.0));
    const Frame culled = renderWith(renderer, scene.get(), *cloud, GlyphCulling::Frustum);
    const osgGlyphs::GlyphCullingStatistics statistics = statisticsOf(*cloud, renderer);
    EXPECT_GT(statistics.chunksOutsideView, statistics.chunks / 2);
    EXPECT_LT(statistics.glyphsSubmitted, COUNT / 2);
    EXPECT_EQ(countDifferences(culled, renderWith(renderer, scene.get(), *cloud, GlyphCulling::Off)), 0);
}

TEST(CullingRenderEdits, ACloudBehindANearerOneInTheFrontToBackBinIsSkippedWhole)
{
    Renderer renderer(WIDTH, HEIGHT);
    renderer.setPerspective(40.0, 0.5, 6.0);
    renderer.setLookAt(osg::Vec3d(0.5, -2.0, 0.5), osg::Vec3d(0.5, 0.5, 0.5), osg::Vec3d(0.0, 0.0, 1.0));
    osg::ref_ptr<GlyphCloud> front = createDenseCloud(GlyphShape::Sphere);
    // A smaller cloud behind the cube, wholly inside its silhouette.
    osg::ref_ptr<GlyphCloud> back = createDenseCloud(GlyphShape::Cone);
    osg::Vec3Array& positions = *back->getPositions();
    for (osg::Vec3& p : positions)
        p = osg::Vec3(0.5f, 1.6f, 0.5f) + osg::Vec3(p.x() - 0.5f, p.y(), p.z() - 0.5f) * 0.4f;
    positions.dirty();
    back->dirtyGlyphs();
    osg::ref_ptr<osg::Group> scene = createScene(back.get());
    osg::ref_ptr<osg::Geode> frontGeode = new osg::Geode;
    frontGeode->addDrawable(front.get());
    scene->addChild(frontGeode.get());
    scene->getOrCreateStateSet()->setRenderBinDetails(0, osgGlyphs::FRONT_TO_BACK_BIN);

    front->setCulling(GlyphCulling::Occlusion);
    const Frame culled = renderWith(renderer, scene.get(), *back, GlyphCulling::Occlusion);
    const osgGlyphs::GlyphCullingStatistics statistics = statisticsOf(*back, renderer);
    EXPECT_EQ(statistics.chunksOutsideView, 0u);
    EXPECT_EQ(statistics.glyphsSubmitted, 0u)
        << "of " << statistics.chunks << " chunks, " << statistics.chunksOccluded << " found hidden";
    front->setCulling(GlyphCulling::Frustum);
    EXPECT_EQ(countDifferences(culled, renderWith(renderer, scene.get(), *back, GlyphCulling::Frustum)), 0);

    // Alone, the back cloud shows: the test above is no accident of the view.
    scene->removeChild(frontGeode.get());
    renderWith(renderer, scene.get(), *back, GlyphCulling::Occlusion);
    EXPECT_GT(statisticsOf(*back, renderer).glyphsSubmitted, COUNT / 10);
}
