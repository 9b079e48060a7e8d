#include "SerializerFixtures.h"

#include <osgGlyphs/ColorMap>
#include <osgGlyphs/DepthPeeling>
#include <osgGlyphs/ImpostorTechniques>
#include <osgGlyphs/ScreenEffects>
#include <osgGlyphsPaper/Techniques>

#include <osg/Geode>

#include <string>

using osgGlyphs::GlyphCloud;

namespace osgGlyphsFixtures
{

namespace
{

enum class Colouring
{
    FloatScalars,
    ScalarSteps, // scalars on their 16-bit steps, written as the steps
    Rgba
};

struct Recipe
{
    const char* name;
    osgGlyphs::GlyphShape shape;
    osg::ref_ptr<osgGlyphs::GlyphTechnique> technique;
    Colouring colouring;
    bool compressedPositions;
    osgGlyphs::GlyphAnchor anchor;
    osgGlyphs::GlyphCulling culling;
};

template <class ArrayType>
osg::ref_ptr<ArrayType> makeArray(std::initializer_list<typename ArrayType::ElementDataType> values)
{
    return new ArrayType(values.begin(), values.end());
}

osg::ref_ptr<osgGlyphs::GlyphTechnique> polygons()
{
    osg::ref_ptr<osgGlyphsPaper::PolygonsTechnique> technique = new osgGlyphsPaper::PolygonsTechnique;
    technique->setResolution(12, 6);
    return technique;
}

void setColouring(GlyphCloud& cloud, Colouring colouring, float shift)
{
    if (colouring == Colouring::Rgba)
    {
        cloud.setColors(
            makeArray<osg::Vec4ubArray>({osg::Vec4ub(250, 10, 20, 255), osg::Vec4ub(1, 2, 3, 4),
                                         osg::Vec4ub(128, 127, 126, 0), osg::Vec4ub(9, 99, 199, 200)}));
        return;
    }
    osg::ref_ptr<osg::FloatArray> scalars =
        makeArray<osg::FloatArray>({-2.5f + shift, 0.1234567f, 3.75f, 7.25f - shift});
    if (colouring == Colouring::ScalarSteps)
    {
        const osg::Vec2 range = cloud.getScalarQuantisationRange();
        for (float& s : *scalars)
            s = GlyphCloud::dequantiseScalar(GlyphCloud::quantiseScalar(s, range), range);
    }
    cloud.setScalars(scalars.get());
}

osg::ref_ptr<GlyphCloud> createCloud(const Recipe& recipe, int index)
{
    const float shift = 0.5f * static_cast<float>(index);
    osg::ref_ptr<GlyphCloud> cloud = new GlyphCloud;
    cloud->setName(recipe.name);
    // osg::Node's properties, which osgDB reads before the cloud's.
    cloud->setNodeMask(0x00ff0f00u + static_cast<unsigned int>(index));
    cloud->addDescription(std::string("fixture ") + recipe.name);
    cloud->getOrCreateStateSet()->setRenderBinDetails(3 + index, "DepthSortedBin");
    cloud->setShape(recipe.shape);
    cloud->setTechnique(recipe.technique.get());
    // The single colour first: it drops per-glyph colours and scalars.
    cloud->setColor(osg::Vec4(0.1f, 0.2f + 0.05f * shift, 0.3f, 0.9f));
    cloud->setPositions(
        makeArray<osg::Vec3Array>({osg::Vec3(-1.5f + shift, 0.1f, 0.3f), osg::Vec3(0.2f, -0.4f - shift, 0.0f),
                                   osg::Vec3(1.4f, 0.3f, -0.5f + shift), osg::Vec3(0.6f, 1.1f, 0.2f)}));
    cloud->setRadius(0.3f + shift); // before the radii, which it drops
    cloud->setRadii(makeArray<osg::FloatArray>({0.11f, 0.17f + shift, 0.123456f, 0.2f}));
    cloud->setVectors(
        makeArray<osg::Vec3Array>({osg::Vec3(0.3f, 0.2f, 1.1f), osg::Vec3(-1.0f, 0.1f, 0.4f),
                                   osg::Vec3(0.5f, 0.5f + shift, -0.9f), osg::Vec3(0.0f, -0.7f, 0.2f)}));
    cloud->setColorMap(new osgGlyphs::ColorMap(std::string("map-") + recipe.name,
                                               {osg::Vec4(0.1f, 0.2f, 0.3f, 1.0f),
                                                osg::Vec4(0.9f, 0.5f + 0.01f * shift, 0.1f, 1.0f),
                                                osg::Vec4(0.25f, 0.75f, 0.5f, 0.5f)}));
    cloud->setScalarRange(-1.5f - shift, 4.25f);
    setColouring(*cloud, recipe.colouring, shift);
    cloud->setLit(false);
    cloud->setMaterial(0.31f, 0.27f + 0.01f * shift, 17.0f);
    cloud->setLengthScale(0.75f + shift);
    cloud->setUniformLength(true);
    cloud->setAnchor(recipe.anchor);
    cloud->setArrowHead(0.4f, 1.7f + shift);
    cloud->setCompressedAttributes(false);
    cloud->setOrigin(osg::Vec3d(0.25 + shift, -0.125, 1e6 + 0.5));
    cloud->setCulling(recipe.culling);
    cloud->setCullingChunkSize(64u + static_cast<unsigned int>(index));
    cloud->setOcclusion(
        makeArray<osg::Vec4ubArray>({osg::Vec4ub(1, 2, 3, 4), osg::Vec4ub(128, 127, 255, 0),
                                     osg::Vec4ub(9, 8, 7, 200), osg::Vec4ub(40, 50, 60, 70)}));
    cloud->setOpacity(0.35f + 0.01f * shift);
    cloud->setCompressedPositions(recipe.compressedPositions);
    return cloud;
}

}

osg::ref_ptr<osg::Group> createClouds()
{
    using osgGlyphs::GlyphAnchor;
    using osgGlyphs::GlyphCulling;
    using osgGlyphs::GlyphShape;
    const Recipe recipes[] = {
        {"sphere-geometry-shader", GlyphShape::Sphere, new osgGlyphs::GeometryShaderTechnique,
         Colouring::ScalarSteps, true, GlyphAnchor::Tail, GlyphCulling::Off},
        {"cone-paper-quad", GlyphShape::Cone, new osgGlyphsPaper::PaperQuadTechnique, Colouring::FloatScalars,
         false, GlyphAnchor::Head, GlyphCulling::Frustum},
        {"arrow-instanced", GlyphShape::Arrow, new osgGlyphs::InstancedTechnique, Colouring::Rgba, true,
         GlyphAnchor::Tail, GlyphCulling::Frustum},
        {"cylinder-polygons", GlyphShape::Cylinder, polygons(), Colouring::FloatScalars, true,
         GlyphAnchor::Head, GlyphCulling::Off},
        {"sphere-point-sprite", GlyphShape::Sphere, new osgGlyphs::PointSpriteTechnique, Colouring::Rgba,
         false, GlyphAnchor::Head, GlyphCulling::Off},
        {"sphere-texture-blend", GlyphShape::Sphere, new osgGlyphsPaper::TextureBlendTechnique,
         Colouring::ScalarSteps, false, GlyphAnchor::Tail, GlyphCulling::Frustum},
        {"sphere-texture-multi", GlyphShape::Sphere, new osgGlyphsPaper::TextureMultiTechnique,
         Colouring::FloatScalars, true, GlyphAnchor::Head, GlyphCulling::Frustum},
        {"sphere-points-floor", GlyphShape::Sphere, new osgGlyphsPaper::PointsFloorTechnique, Colouring::Rgba,
         true, GlyphAnchor::Tail, GlyphCulling::Off},
    };
    osg::ref_ptr<osg::Group> clouds = new osg::Group;
    clouds->setName("clouds");
    int index = 0;
    for (const Recipe& recipe : recipes)
    {
        osg::ref_ptr<osg::Geode> geode = new osg::Geode;
        geode->addDrawable(createCloud(recipe, index++).get());
        clouds->addChild(geode.get());
    }
    return clouds;
}

osg::ref_ptr<osgGlyphs::ScreenEffects> createScreenEffects()
{
    osg::ref_ptr<osgGlyphs::ScreenEffects> effects = new osgGlyphs::ScreenEffects;
    effects->setAmbientOcclusion(true);
    effects->setOcclusionRadius(0.3f);
    effects->setOcclusionStrength(0.7f);
    effects->setOcclusionSamples(24);
    effects->setOutlines(true);
    effects->setOutlineWidth(2.5f);
    effects->setOutlineColor(osg::Vec4(0.2f, 0.0f, 0.1f, 0.9f));
    return effects;
}

osg::ref_ptr<osgGlyphs::DepthPeeling> createDepthPeeling()
{
    osg::ref_ptr<osgGlyphs::DepthPeeling> peeling = new osgGlyphs::DepthPeeling;
    peeling->setNumLayers(3);
    peeling->setMethod(osgGlyphs::DepthPeeling::PEEL_PASSES);
    return peeling;
}

osg::ref_ptr<osg::Group> createEffects()
{
    osg::ref_ptr<osgGlyphs::ScreenEffects> effects = createScreenEffects();
    effects->setName("effects");
    osg::ref_ptr<osgGlyphs::DepthPeeling> peeling = createDepthPeeling();
    peeling->setName("peeling");
    peeling->setEnabled(false);
    effects->addChild(peeling.get());
    return effects;
}

osg::ref_ptr<osgGlyphsTiles::TileRoot> createTileRoot()
{
    osg::ref_ptr<osgGlyphsTiles::TileRoot> root = new osgGlyphsTiles::TileRoot;
    root->setName("tile-root");
    root->setGlyphBudget(123456789012ull);
    return root;
}

}
