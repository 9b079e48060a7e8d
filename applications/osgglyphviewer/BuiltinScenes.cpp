#include "BuiltinScenes.h"

#include <osgGlyphsData/RandomCloud>

#include <osg/Geode>
#include <osg/ShapeDrawable>

#include <algorithm>
#include <random>

namespace
{

/** Column options need a file: refuses them for the scenes without one. */
bool checkNoColumnOptions(const osgGlyphsData::GlyphMappingOptions& mapping, const char* scene,
                          std::string& error)
{
    const char* option = !mapping.positionColumns.empty() ? "--position"
                         : !mapping.radiusColumn.empty()  ? "--radius-by"
                         : !mapping.colorBy.empty()       ? "--color-by"
                         : !mapping.vectorColumns.empty() ? "--vector"
                                                          : nullptr;
    if (option)
        error = std::string(option) + " names a column of a file, and the " + scene + " scene has none";
    return option == nullptr;
}

osgGlyphsData::ColorKey makeScalarKey(const std::string& title,
                                      const osgGlyphsData::GlyphMappingOptions& mapping, float min, float max)
{
    osgGlyphsData::ColorKey key;
    key.kind = osgGlyphsData::ColorKey::Scalar;
    key.title = title;
    key.colorMap = mapping.colorMap;
    key.min = mapping.hasRange ? mapping.rangeMin : min;
    key.max = mapping.hasRange ? mapping.rangeMax : max;
    return key;
}

}

osg::ref_ptr<ViewerScene> createFixedScene(osg::Node* content, const osgGlyphsData::ColorKey& key)
{
    osg::ref_ptr<osg::Node> node = content;
    ViewerScene::FrameSource source = [node](std::size_t, std::string&) { return node; };
    return new ViewerScene(source, 1, key);
}

osg::ref_ptr<ViewerScene> createDefaultScene(const ViewerOptions& options, std::string& error)
{
    if (!checkNoColumnOptions(options.mapping, "built-in", error))
        return nullptr;
    if (options.mapping.shape != osgGlyphs::GlyphShape::Sphere)
    {
        const bool vectors = osgGlyphs::isVectorShape(options.mapping.shape);
        error = std::string("--glyph ") + osgGlyphs::getShapeName(options.mapping.shape) + " needs " +
                (vectors ? "vectors" : "semi-axes") + ", and the built-in scene has none (try --random N)";
        return nullptr;
    }
    const unsigned int count = 2000;
    std::mt19937 random(7);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    osg::ref_ptr<osg::Vec3Array> positions = new osg::Vec3Array;
    osg::ref_ptr<osg::FloatArray> radii = new osg::FloatArray;
    osg::ref_ptr<osg::FloatArray> scalars = new osg::FloatArray;
    for (unsigned int i = 0; i < count; ++i)
    {
        const osg::Vec3 p(2.0f * unit(random), 2.0f * unit(random), 2.0f * unit(random));
        positions->push_back(p);
        radii->push_back(0.06f + 0.05f * (unit(random) + 1.0f));
        scalars->push_back(p.z());
    }
    osg::ref_ptr<osgGlyphs::GlyphCloud> cloud = new osgGlyphs::GlyphCloud;
    cloud->setPositions(positions.get());
    if (options.mapping.radius > 0.0f)
        cloud->setRadius(options.mapping.radius);
    else
        cloud->setRadii(radii.get());
    cloud->setScalars(scalars.get());
    osgGlyphsData::applyGlyphStyle(*cloud, options.mapping);

    // Drawables as children of a group, which osgUtil::IntersectionVisitor picks through their
    // accept() (it hands a Geode's drawables to the intersectors directly).
    osg::ref_ptr<osg::Group> group = new osg::Group;
    group->addChild(cloud.get());
    osg::ref_ptr<osg::ShapeDrawable> box =
        new osg::ShapeDrawable(new osg::Box(osg::Vec3(0.0f, 0.0f, -1.0f), 3.0f, 3.0f, 0.2f));
    box->setColor(osg::Vec4(0.75f, 0.75f, 0.75f, 1.0f));
    group->addChild(box.get());
    osg::ref_ptr<osg::ShapeDrawable> sphere =
        new osg::ShapeDrawable(new osg::Sphere(osg::Vec3(0.0f, 0.0f, 0.3f), 0.8f));
    sphere->setColor(osg::Vec4(0.85f, 0.3f, 0.25f, 1.0f));
    group->addChild(sphere.get());

    const auto range = std::minmax_element(scalars->begin(), scalars->end());
    osg::ref_ptr<ViewerScene> scene =
        createFixedScene(group.get(), makeScalarKey("z", options.mapping, *range.first, *range.second));
    CameraView view;
    view.eye.set(3.5, -12.5, 5.0); // far enough back for the whole cube of spheres
    view.center.set(0.0, 0.0, 0.0);
    view.up.set(0.0, 0.0, 1.0);
    scene->setHomeView(view);
    scene->setDescription("built-in scene: 2000 spheres coloured by z, a box and a sphere");
    return scene;
}

osg::ref_ptr<ViewerScene> createRandomScene(const ViewerOptions& options, const SceneSharing& sharing,
                                            std::string& error)
{
    if (!checkNoColumnOptions(options.mapping, "random", error))
        return nullptr;
    osgGlyphsData::RandomCloudOptions random;
    random.count = options.randomCount;
    random.seed = options.seed;
    random.shape = options.mapping.shape;
    random.radius = options.mapping.radius;
    random.lengthScale = options.mapping.lengthScale;
    random.share = sharing.share;
    osg::ref_ptr<osgGlyphs::GlyphCloud> cloud = osgGlyphsData::createRandomCloud(random, error);
    if (!cloud)
        return nullptr;
    osgGlyphsData::applyGlyphStyle(*cloud, options.mapping);
    if (sharing.shareCloud)
        sharing.shareCloud(*cloud);
    osg::ref_ptr<ViewerScene> scene =
        createFixedScene(cloud.get(), makeScalarKey("random value", options.mapping, 0.0f, 1.0f));
    scene->setDescription("random dataset: " + std::to_string(random.count) + " " +
                          osgGlyphs::getShapeName(random.shape) + "s in the unit cube, seed " +
                          std::to_string(random.seed) + ", radius " + std::to_string(cloud->getRadius()));
    return scene;
}
