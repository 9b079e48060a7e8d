// osgUtil::Optimizer on scenes with glyph clouds: every optimisation, alone and in its stock sets,
// leaves the render as it was, and the library's shared textures survive it and later viewers.

#include "GlyphTestScenes.h"

#include <osgGlyphs/GlyphCloud>

#include <osg/MatrixTransform>
#include <osg/Texture1D>
#include <osgGlyphs/ColorMap>
#include <osgUtil/Optimizer>

using namespace osgGlyphsTest;
using osgGlyphs::GlyphCloud;
using osgUtil::Optimizer;

namespace
{

const int WIDTH = 160, HEIGHT = 120;

/** Lit spheres coloured through the built-in colour map, and cones. */
osg::ref_ptr<GlyphCloud> createCloud(osgGlyphs::GlyphShape shape, const osg::Vec3& offset)
{
    osg::ref_ptr<osg::Vec3Array> positions = new osg::Vec3Array;
    osg::ref_ptr<osg::Vec3Array> vectors = new osg::Vec3Array;
    osg::ref_ptr<osg::FloatArray> scalars = new osg::FloatArray;
    for (int i = 0; i < 5; ++i)
    {
        positions->push_back(offset + osg::Vec3(-1.6f + 0.8f * i, 0.0f, 0.3f * (i % 2)));
        vectors->push_back(osg::Vec3(0.2f * i - 0.4f, 0.3f, 0.6f));
        scalars->push_back(0.25f * i);
    }
    osg::ref_ptr<GlyphCloud> cloud = new GlyphCloud;
    cloud->setPositions(positions.get());
    cloud->setRadius(0.3f);
    cloud->setScalars(scalars.get());
    cloud->setVectors(vectors.get());
    cloud->setShape(shape);
    return cloud;
}

/** Clouds under static transforms (a rotation, a uniform scale and a move, one under two
 * nested transforms), one shared by two transforms, and one under none. */
osg::ref_ptr<osg::Group> createScene()
{
    osg::ref_ptr<osg::Group> root = new osg::Group;
    auto transform = [](const osg::Matrixd& matrix)
    {
        osg::ref_ptr<osg::MatrixTransform> node = new osg::MatrixTransform(matrix);
        node->setDataVariance(osg::Object::STATIC);
        return node;
    };
    osg::ref_ptr<osg::MatrixTransform> outer = transform(
        osg::Matrixd::rotate(0.4, osg::Vec3d(0.0, 0.0, 1.0)) * osg::Matrixd::translate(0.0, 0.0, 1.2));
    osg::ref_ptr<osg::MatrixTransform> inner = transform(osg::Matrixd::scale(0.7, 0.7, 0.7));
    inner->addChild(createCloud(osgGlyphs::GlyphShape::Sphere, osg::Vec3()).get());
    outer->addChild(inner.get());
    root->addChild(outer.get());

    osg::ref_ptr<GlyphCloud> shared = createCloud(osgGlyphs::GlyphShape::Cone, osg::Vec3());
    for (double z : {-0.4, -1.4})
    {
        osg::ref_ptr<osg::MatrixTransform> moved = transform(osg::Matrixd::translate(0.5, 0.0, z));
        moved->addChild(shared.get());
        root->addChild(moved.get());
    }
    root->addChild(createCloud(osgGlyphs::GlyphShape::Sphere, osg::Vec3(0.0f, 2.0f, 2.2f)).get());
    return root;
}

int countDifferences(const Frame& a, const Frame& b)
{
    int different = 0;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x)
            different += a.colorAt(x, y) != b.colorAt(x, y) || a.depthAt(x, y) != b.depthAt(x, y);
    return different;
}

int countCovered(const Frame& frame)
{
    int covered = 0;
    for (int y = 0; y < frame.height(); ++y)
        for (int x = 0; x < frame.width(); ++x)
            covered += frame.isCovered(x, y);
    return covered;
}

struct NamedOptions
{
    const char* name;
    unsigned int options;
};

const NamedOptions OPTIMIZATIONS[] = {{"FLATTEN_STATIC_TRANSFORMS", Optimizer::FLATTEN_STATIC_TRANSFORMS},
                                      {"REMOVE_REDUNDANT_NODES", Optimizer::REMOVE_REDUNDANT_NODES},
                                      {"REMOVE_LOADED_PROXY_NODES", Optimizer::REMOVE_LOADED_PROXY_NODES},
                                      {"COMBINE_ADJACENT_LODS", Optimizer::COMBINE_ADJACENT_LODS},
                                      {"SHARE_DUPLICATE_STATE", Optimizer::SHARE_DUPLICATE_STATE},
                                      {"MERGE_GEOMETRY", Optimizer::MERGE_GEOMETRY},
                                      {"CHECK_GEOMETRY", Optimizer::CHECK_GEOMETRY},
                                      {"MAKE_FAST_GEOMETRY", Optimizer::MAKE_FAST_GEOMETRY},
                                      {"SPATIALIZE_GROUPS", Optimizer::SPATIALIZE_GROUPS},
                                      {"COPY_SHARED_NODES", Optimizer::COPY_SHARED_NODES},
                                      {"TRISTRIP_GEOMETRY", Optimizer::TRISTRIP_GEOMETRY},
                                      {"TESSELLATE_GEOMETRY", Optimizer::TESSELLATE_GEOMETRY},
                                      {"OPTIMIZE_TEXTURE_SETTINGS", Optimizer::OPTIMIZE_TEXTURE_SETTINGS},
                                      {"MERGE_GEODES", Optimizer::MERGE_GEODES},
                                      {"FLATTEN_BILLBOARDS", Optimizer::FLATTEN_BILLBOARDS},
                                      {"TEXTURE_ATLAS_BUILDER", Optimizer::TEXTURE_ATLAS_BUILDER},
                                      {"STATIC_OBJECT_DETECTION", Optimizer::STATIC_OBJECT_DETECTION},
                                      {"FLATTEN_STATIC_TRANSFORMS_DUPLICATING_SHARED_SUBGRAPHS",
                                       Optimizer::FLATTEN_STATIC_TRANSFORMS_DUPLICATING_SHARED_SUBGRAPHS},
                                      {"INDEX_MESH", Optimizer::INDEX_MESH},
                                      {"VERTEX_POSTTRANSFORM", Optimizer::VERTEX_POSTTRANSFORM},
                                      {"VERTEX_PRETRANSFORM", Optimizer::VERTEX_PRETRANSFORM},
                                      {"BUFFER_OBJECT_SETTINGS", Optimizer::BUFFER_OBJECT_SETTINGS},
                                      {"DEFAULT_OPTIMIZATIONS", Optimizer::DEFAULT_OPTIMIZATIONS},
                                      {"ALL_OPTIMIZATIONS", Optimizer::ALL_OPTIMIZATIONS}};

class OptimizedScene : public ::testing::TestWithParam<NamedOptions>
{
};

}

TEST_P(OptimizedScene, RendersAsBefore)
{
    Renderer renderer(WIDTH, HEIGHT);
    renderer.setLookAt(osg::Vec3d(1.0, -9.0, 2.0), osg::Vec3d(0.0, 0.0, 0.3), osg::Vec3d(0.0, 0.0, 1.0));
    const Frame before = renderer.render(createScene().get());
    EXPECT_GT(countCovered(before), WIDTH * HEIGHT / 20);

    osg::ref_ptr<osg::Group> scene = createScene();
    Optimizer optimizer;
    optimizer.optimize(scene.get(), GetParam().options);
    const Frame after = renderer.render(scene.get());
    if (countDifferences(before, after) > 0)
    {
        saveFrame(before, std::string("optimizer_before"));
        saveFrame(after, std::string("optimizer_") + GetParam().name);
    }
    EXPECT_EQ(countDifferences(before, after), 0);
}

INSTANTIATE_TEST_SUITE_P(, OptimizedScene, ::testing::ValuesIn(OPTIMIZATIONS),
                         [](const ::testing::TestParamInfo<NamedOptions>& param)
                         { return param.param.name; });

TEST(OptimizedTextures, TheBuiltinColourMapSurvivesIntoTheNextViewer)
{
    // The first viewer's scene shows the built-in colour map's texture on a quad too (a legend, as
    // applications draw one), where OPTIMIZE_TEXTURE_SETTINGS finds it; the next viewer, in a new
    // context, must still have the texture's image to load.
    const auto render = [](bool withLegend)
    {
        Renderer renderer(WIDTH, HEIGHT);
        renderer.setLookAt(osg::Vec3d(1.0, -9.0, 2.0), osg::Vec3d(0.0, 0.0, 0.3), osg::Vec3d(0.0, 0.0, 1.0));
        osg::ref_ptr<osg::Group> scene = createScene();
        if (withLegend)
        {
            osg::ref_ptr<osg::Geometry> legend = osg::createTexturedQuadGeometry(
                osg::Vec3(-3.0f, 0.0f, -2.5f), osg::Vec3(6.0f, 0.0f, 0.0f), osg::Vec3(0.0f, 0.0f, 0.3f));
            legend->getOrCreateStateSet()->setTextureAttributeAndModes(
                0, osgGlyphs::ColorMap::getBuiltin("viridis")->getTexture());
            scene->addChild(legend.get());
            Optimizer().optimize(scene.get(), Optimizer::DEFAULT_OPTIMIZATIONS);
        }
        return renderer.render(scene.get());
    };
    const Frame reference = render(false);
    render(true);
    const Frame second = render(false);
    saveFrame(second, "optimizer_second_viewer");
    EXPECT_EQ(countDifferences(reference, second), 0);
}
