// Culling never changes the picture: dense clouds drawn with occlusion culling are pixel-identical
// in colour and depth to the same clouds drawn without it, over an orbit with a jump of the
// camera to the opposite side, for every shape, after in-place edits, under a clip plane and in
// a second view; and culling does skip chunks, so that these comparisons test something. The
// culling record of each glyph is checked against the rendered depth: every pixel of a glyph found
// hidden lies behind it (exact ray-sphere intersections).

#include "../harness/RenderHarness.h"

#include <osgGlyphs/GlyphCloud>
#include <osgGlyphs/GlyphStateCache>

#include <osg/ClipPlane>
#include <osg/Geode>
#include <osg/LightSource>
#include <osg/ShapeDrawable>

#include <cmath>
#include <map>
#include <random>

using namespace osgGlyphsTest;
using osgGlyphs::GlyphCloud;
using osgGlyphs::GlyphCulling;
using osgGlyphs::GlyphShape;

namespace
{

const int WIDTH = 320, HEIGHT = 240;
const unsigned int COUNT = 20000;

/** count random glyphs in the unit cube at 0.4 (spacing) x their mean spacing: they touch and hide
 * each other, as atoms and grains do. Vector shapes get random directions two radii long. */
osg::ref_ptr<GlyphCloud> createDenseCloud(GlyphShape shape, unsigned int count = COUNT, float spacing = 0.4f)
{
    std::mt19937 random(7);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    osg::ref_ptr<osg::Vec3Array> positions = new osg::Vec3Array;
    osg::ref_ptr<osg::Vec3Array> vectors = new osg::Vec3Array;
    osg::ref_ptr<osg::FloatArray> scalars = new osg::FloatArray;
    const float radius = spacing / std::cbrt(float(count));
    for (unsigned int i = 0; i < count; ++i)
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
    if (shape == GlyphShape::Ellipsoid || shape == GlyphShape::Superquadric)
    {
        // The other semi-axes a quarter to all of the largest, in uniformly random turns
        // (Shoemake's quaternions); superquadrics from boxes to octahedra.
        osg::ref_ptr<osg::Vec3Array> semiAxes = new osg::Vec3Array;
        osg::ref_ptr<osg::Vec4Array> turns = new osg::Vec4Array;
        osg::ref_ptr<osg::Vec2Array> exponents = new osg::Vec2Array;
        for (unsigned int i = 0; i < count; ++i)
        {
            semiAxes->push_back(osg::Vec3(1.0f, 0.25f + 0.75f * unit(random), 0.25f + 0.75f * unit(random)) *
                                radius);
            const float u = unit(random), a = 2.0f * osg::PIf * unit(random),
                        b = 2.0f * osg::PIf * unit(random);
            const float sine = std::sqrt(1.0f - u), cosine = std::sqrt(u);
            turns->push_back(osg::Vec4(sine * std::sin(a), sine * std::cos(a), cosine * std::sin(b),
                                       cosine * std::cos(b)));
            exponents->push_back(osg::Vec2(0.1f + 1.9f * unit(random), 0.1f + 1.9f * unit(random)));
        }
        cloud->setSemiAxes(semiAxes.get());
        cloud->setOrientations(turns.get());
        if (shape == GlyphShape::Superquadric)
            cloud->setExponents(exponents.get());
    }
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

/** At how many pixel centres of its silhouette (exact ray-sphere intersections) a sphere lies
 * behind the frame's depth, as a hidden glyph must, and at how many it does not (it shows). */
struct HiddenCheck
{
    unsigned int hidden = 0;
    unsigned int shown = 0;
};

void checkHidden(const Frame& frame, const osg::Vec3d& centre, double radius, HiddenCheck& check)
{
    const osg::Vec3d window = frame.project(centre);
    // The camera's right vector: the silhouette's radius in pixels, with a margin.
    const osg::Vec3d right(frame.view(0, 0), frame.view(1, 0), frame.view(2, 0));
    const osg::Vec3d edge = frame.project(centre + right * (1.5 * radius));
    const int reach = int(std::ceil(std::hypot(edge.x() - window.x(), edge.y() - window.y()))) + 2;
    for (int y = std::max(0, int(window.y()) - reach);
         y <= std::min(frame.height() - 1, int(window.y()) + reach); ++y)
        for (int x = std::max(0, int(window.x()) - reach);
             x <= std::min(frame.width() - 1, int(window.x()) + reach); ++x)
        {
            osg::Vec3d origin, direction;
            frame.pixelRay(x + 0.5, y + 0.5, origin, direction);
            const osg::Vec3d m = origin - centre;
            const double b = m * direction, c = m * m - radius * radius;
            if (b * b - c < 0.0)
                continue;
            const double t = std::max(0.0, -b - std::sqrt(b * b - c));
            if (frame.depthAt(x, y) <= frame.windowDepth(origin + direction * t) + 1e-6)
                ++check.hidden;
            else
                ++check.shown;
        }
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
        EXPECT_EQ(countDifferingPixels(culled, frustum), 0) << "azimuth " << azimuth;
        // Off draws in the caller's order: only exact depth ties between two glyphs may differ.
        EXPECT_LE(countDifferingPixels(culled, off), WIDTH * HEIGHT / 2000) << "azimuth " << azimuth;
        if (azimuth == 225.0)
            saveFrame(culled, std::string("culling_") + osgGlyphs::getShapeName(GetParam()));
    }
    EXPECT_GT(occluded, 0u) << "no chunk was ever occluded: the comparison tested nothing";
}

INSTANTIATE_TEST_SUITE_P(Shapes, CullingRender,
                         ::testing::Values(GlyphShape::Sphere, GlyphShape::Cone, GlyphShape::Arrow,
                                           GlyphShape::Cylinder, GlyphShape::Ellipsoid,
                                           GlyphShape::Superquadric),
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
    EXPECT_EQ(countDifferingPixels(culled, renderWith(renderer, scene.get(), *cloud, GlyphCulling::Frustum)),
              0);

    // A clip plane cuts the front away: what was hidden behind it shows.
    scene->getOrCreateStateSet()->setAttributeAndModes(
        new osg::ClipPlane(0, osg::Plane(1.0, 1.0, 0.0, -0.9)));
    culled = renderWith(renderer, scene.get(), *cloud, GlyphCulling::Occlusion);
    EXPECT_EQ(countDifferingPixels(culled, renderWith(renderer, scene.get(), *cloud, GlyphCulling::Frustum)),
              0);
    EXPECT_LE(countDifferingPixels(culled, renderWith(renderer, scene.get(), *cloud, GlyphCulling::Off)),
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
    EXPECT_EQ(countDifferingPixels(culled, renderWith(renderer, scene.get(), *cloud, GlyphCulling::Off)), 0);
}

TEST(CullingRenderEdits, ACloudBehindANearerOneInTheFrontToBackBinIsSkipped)
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
    // The bin's first round lays down the front over the view from all its clouds' chunks,
    // untested: a few of the back cloud's fill cells where the front cloud's chunks meet.
    EXPECT_LT(statistics.glyphsSubmitted, COUNT / 20)
        << "of " << statistics.chunks << " chunks, " << statistics.chunksOccluded << " found hidden";
    EXPECT_GT(statistics.chunksOccluded, statistics.chunks * 9 / 10);
    front->setCulling(GlyphCulling::Frustum);
    EXPECT_EQ(countDifferingPixels(culled, renderWith(renderer, scene.get(), *back, GlyphCulling::Frustum)),
              0);

    // Alone, the back cloud shows: the test above is no accident of the view.
    scene->removeChild(frontGeode.get());
    renderWith(renderer, scene.get(), *back, GlyphCulling::Occlusion);
    EXPECT_GT(statisticsOf(*back, renderer).glyphsSubmitted, COUNT / 10);
}

// The clouds of a FRONT_TO_BACK_BIN are culled together, in rounds over all their chunks, with
// one read-back a round for the whole bin: eight dense octants of spheres and cones and a box in
// the bin, one cloud with a selection, over an orbit with a jump, are pixel-identical in colour
// and depth to the same bin unculled.
TEST(CullingRenderEdits, TheFrontToBackBinCullsItsCloudsTogether)
{
    Renderer renderer(WIDTH, HEIGHT);
    renderer.setPerspective(40.0, 0.5, 6.0);
    osg::ref_ptr<osg::Group> scene = new osg::Group;
    scene->getOrCreateStateSet()->setRenderBinDetails(0, osgGlyphs::FRONT_TO_BACK_BIN);
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    scene->addChild(geode.get());
    std::vector<osg::ref_ptr<GlyphCloud>> clouds;
    for (unsigned int octant = 0; octant < 8; ++octant)
    {
        osg::ref_ptr<GlyphCloud> cloud =
            createDenseCloud(octant % 2 ? GlyphShape::Cone : GlyphShape::Sphere, COUNT / 4);
        const osg::Vec3 offset(0.5f * float(octant & 1), 0.5f * float((octant >> 1) & 1),
                               0.5f * float(octant >> 2));
        for (osg::Vec3& p : *cloud->getPositions())
            p = offset + p * 0.5f;
        for (osg::Vec3& v : *cloud->getVectors())
            v *= 0.5f;
        cloud->getPositions()->dirty();
        cloud->getVectors()->dirty();
        cloud->setRadius(0.5f * cloud->getRadius());
        cloud->dirtyGlyphs();
        geode->addDrawable(cloud.get());
        clouds.push_back(cloud);
    }
    clouds[3]->setSelection({1, 2, 3, 500, 1000});
    geode->addDrawable(new osg::ShapeDrawable(new osg::Box(osg::Vec3(0.3f, 0.3f, 0.9f), 0.3f)));

    for (double azimuth : {30.0, 40.0, 220.0, 230.0})
    {
        orbit(renderer, azimuth);
        for (const auto& cloud : clouds)
            cloud->setCulling(GlyphCulling::Occlusion);
        const Frame culled = renderer.render(scene.get());
        osgGlyphs::GlyphCullingStatistics total;
        for (const auto& cloud : clouds)
        {
            const osgGlyphs::GlyphCullingStatistics statistics = statisticsOf(*cloud, renderer);
            total.glyphsSubmitted += statistics.glyphsSubmitted;
            total.depthReadbacks += statistics.depthReadbacks;
            total.chunksOccluded += statistics.chunksOccluded;
        }
        EXPECT_LE(total.depthReadbacks, 4u) << "one read-back a round for the whole bin";
        EXPECT_LT(total.glyphsSubmitted, 2 * COUNT * 4 / 5) << "of " << 2 * COUNT;
        EXPECT_GT(total.chunksOccluded, 0u);
        for (const auto& cloud : clouds)
            cloud->setCulling(GlyphCulling::Off);
        EXPECT_EQ(countDifferingPixels(culled, renderer.render(scene.get())), 0) << "azimuth " << azimuth;
    }
}

// The culling record says where each glyph went: glyphs in chunks outside the view lie outside
// it, glyphs in chunks found hidden lie behind the depth drawn at their centre, and the glyphs
// sent to the GPU are the statistics' count. A cut-away of the cloud coloured by the record is
// saved for docs/design/culling.md (tests/output/culling_record*.png).
class CullingRecord : public ::testing::TestWithParam<float>
{
};

TEST_P(CullingRecord, SaysWhereEachGlyphWent)
{
    const unsigned int count = 100000;
    const float spacing = GetParam();
    Renderer renderer(2 * WIDTH, 2 * HEIGHT);
    renderer.setPerspective(28.0, 0.5, 5.0);
    osg::ref_ptr<GlyphCloud> cloud = createDenseCloud(GlyphShape::Sphere, count, spacing);
    cloud->setCullingChunkSize(512);
    osg::ref_ptr<osg::Group> scene = createScene(cloud.get());
    orbit(renderer, 30.0);
    cloud->setCullingRecorded(true);
    const Frame view = renderWith(renderer, scene.get(), *cloud, GlyphCulling::Occlusion);
    const osgGlyphs::GlyphCullingStatistics statistics = statisticsOf(*cloud, renderer);
    const unsigned int contextID =
        renderer.getViewer()->getCamera()->getGraphicsContext()->getState()->getContextID();
    const std::vector<unsigned char> record = cloud->getCullingRecord(contextID);
    ASSERT_EQ(record.size(), count);

    const osg::Vec3Array& positions = *cloud->getPositions();
    const float radius = cloud->getRadius();
    osg::Vec3d eye, centre, up;
    view.view.getLookAt(eye, centre, up);
    std::map<unsigned char, unsigned int> counts;
    HiddenCheck hiddenCheck;
    for (unsigned int i = 0; i < count; ++i)
    {
        ++counts[record[i]];
        const osg::Vec3d window = view.project(positions[i]);
        const bool centreInView = window.x() >= 0.0 && window.x() < view.width() && window.y() >= 0.0 &&
                                  window.y() < view.height() && window.z() <= 1.0;
        if (record[i] == osgGlyphs::CULLING_OUTSIDE_VIEW)
        {
            EXPECT_FALSE(centreInView) << "glyph " << i;
        }
        if (record[i] == osgGlyphs::CULLING_OCCLUDED)
            checkHidden(view, positions[i], radius, hiddenCheck);
    }
    unsigned int submitted = 0;
    for (const auto& [outcome, glyphs] : counts)
        submitted += outcome >= osgGlyphs::CULLING_FIRST_ROUND ? glyphs : 0;
    EXPECT_EQ(submitted, statistics.glyphsSubmitted);
    EXPECT_EQ(hiddenCheck.shown, 0u) << "pixels of glyphs culled as hidden that show";
    EXPECT_GT(hiddenCheck.hidden, 100000u);
    EXPECT_GT(counts[osgGlyphs::CULLING_OUTSIDE_VIEW], 0u);
    EXPECT_GT(counts[osgGlyphs::CULLING_OCCLUDED], count / 10);
    EXPECT_GT(counts[osgGlyphs::CULLING_FIRST_ROUND], 0u);
    EXPECT_GT(counts[osgGlyphs::CULLING_FIRST_ROUND + 1], 0u);
    EXPECT_EQ(counts[osgGlyphs::CULLING_NOT_DRAWN], 0u);
    if (spacing != 0.4f)
        return;
    saveFrame(view, "culling_record_view");

    // The same glyphs coloured by the record, cut open along the view and seen from the side:
    // the cloud's front (first round) faces the view's eye, behind it what later rounds drew, and
    // behind that what they found hidden.
    osg::ref_ptr<osg::Vec4ubArray> colors = new osg::Vec4ubArray;
    for (unsigned char outcome : record)
        colors->push_back(outcome == osgGlyphs::CULLING_OUTSIDE_VIEW  ? osg::Vec4ub(150, 150, 150, 255)
                          : outcome == osgGlyphs::CULLING_OCCLUDED    ? osg::Vec4ub(60, 110, 225, 255)
                          : outcome == osgGlyphs::CULLING_FIRST_ROUND ? osg::Vec4ub(235, 95, 40, 255)
                                                                      : osg::Vec4ub(245, 205, 60, 255));
    osg::ref_ptr<GlyphCloud> coloured = new GlyphCloud(*cloud, osg::CopyOp::SHALLOW_COPY);
    coloured->setColors(colors.get());
    osg::ref_ptr<osg::Group> cutAway = createScene(coloured.get());
    osg::Vec3d viewDirection = centre - eye, across = viewDirection ^ osg::Vec3d(0.0, 0.0, 1.0);
    across.normalize();
    const osg::Vec3d middle(0.5, 0.5, 0.5);
    cutAway->getOrCreateStateSet()->setAttributeAndModes(
        new osg::ClipPlane(0, osg::Plane(across, -(across * middle))));
    osgGlyphs::setClipCaps(*cutAway->getOrCreateStateSet(), true);
    Renderer side(2 * WIDTH, 2 * HEIGHT);
    side.setPerspective(35.0, 0.5, 6.0);
    side.setLookAt(middle - across * 2.0 + osg::Vec3d(0.0, 0.0, 0.8), middle, osg::Vec3d(0.0, 0.0, 1.0));
    saveFrame(side.render(cutAway.get()), "culling_record");
}

// 0.4: the viewer's default, the picture of docs/design/culling.md; 0.3: gaps through which later rounds
// show, so that a test too aggressive shows.
INSTANTIATE_TEST_SUITE_P(Spacing, CullingRecord, ::testing::Values(0.4f, 0.3f),
                         [](const ::testing::TestParamInfo<float>& instance)
                         { return instance.param == 0.4f ? std::string("dense") : std::string("gaps"); });
