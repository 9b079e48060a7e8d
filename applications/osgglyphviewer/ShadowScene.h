// osgglyphviewer: --shadows, the data under a shadowed scene with a ground plane.

#ifndef OSGGLYPHVIEWER_SHADOWSCENE_H
#define OSGGLYPHVIEWER_SHADOWSCENE_H 1

#include <osg/BoundingBox>
#include <osgShadow/ShadowedScene>

/** A shadowed scene (osgShadow::ViewDependentShadowMap) whose glyphs receive shadows, lit by its
 * own light 0 from above (+z) and to the side, with a grey ground plane just below the data's
 * bounds, a few times as wide. The caller adds the data; the view's headlight must be off. */
osg::ref_ptr<osgShadow::ShadowedScene> createShadowScene(const osg::BoundingBox& dataBounds);

#endif
