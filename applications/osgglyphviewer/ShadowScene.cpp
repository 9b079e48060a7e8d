#include "ShadowScene.h"

#include <osg/Geode>
#include <osg/LightSource>
#include <osg/ShapeDrawable>
#include <osgGlyphs/GlyphStateCache>
#include <osgShadow/ViewDependentShadowMap>

#include <algorithm>

namespace
{

/** A box of the ground just below the bounds, PLANE_SCALE times as wide as their widest side. */
osg::ref_ptr<osg::Node> createGroundPlane(const osg::BoundingBox& bounds)
{
    const float PLANE_SCALE = 4.0f;
    const float size = std::max({bounds.xMax() - bounds.xMin(), bounds.yMax() - bounds.yMin(),
                                 bounds.zMax() - bounds.zMin(), bounds.radius() * 1e-3f, 1e-6f});
    const float thickness = 0.01f * size;
    const float top = bounds.zMin() - 0.02f * size;
    const osg::Vec3 centre(bounds.center().x(), bounds.center().y(), top - 0.5f * thickness);
    osg::ref_ptr<osg::ShapeDrawable> plane =
        new osg::ShapeDrawable(new osg::Box(centre, PLANE_SCALE * size, PLANE_SCALE * size, thickness));
    plane->setColor(osg::Vec4(0.75f, 0.75f, 0.75f, 1.0f));
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    geode->setName("ground plane");
    geode->addDrawable(plane.get());
    return geode;
}

osg::ref_ptr<osg::LightSource> createLight()
{
    osg::Vec3 toLight(0.4f, 0.3f, 1.0f);
    toLight.normalize();
    osg::ref_ptr<osg::LightSource> source = new osg::LightSource;
    osg::Light* light = source->getLight();
    light->setLightNum(0);
    light->setPosition(osg::Vec4(toLight, 0.0f));
    light->setAmbient(osg::Vec4(0.25f, 0.25f, 0.25f, 1.0f));
    light->setDiffuse(osg::Vec4(0.8f, 0.8f, 0.8f, 1.0f));
    light->setSpecular(osg::Vec4(1.0f, 1.0f, 1.0f, 1.0f));
    return source;
}

}

osg::ref_ptr<osgShadow::ShadowedScene> createShadowScene(const osg::BoundingBox& dataBounds)
{
    osg::ref_ptr<osgShadow::ShadowedScene> scene =
        new osgShadow::ShadowedScene(new osgShadow::ViewDependentShadowMap);
    scene->setName("--shadows");
    // The glyphs, and ordinary geometry through setSurfaceShading, receive through the glyphs'
    // shadow look-up: ViewDependentShadowMap's own shaders index gl_TexCoord with a uniform, which
    // GLSL 1.30+ compilers reject, and its fixed-function texturing paints shadows black.
    osgGlyphs::setGlyphShadows(*scene->getOrCreateStateSet(), true);
    osgGlyphs::setSurfaceShading(*scene->getOrCreateStateSet());
    scene->addChild(createLight().get());
    if (dataBounds.valid())
        scene->addChild(createGroundPlane(dataBounds).get());
    return scene;
}
