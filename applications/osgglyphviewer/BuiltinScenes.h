// osgglyphviewer: the scenes that need no file.

#ifndef OSGGLYPHVIEWER_BUILTINSCENES_H
#define OSGGLYPHVIEWER_BUILTINSCENES_H 1

#include "ViewerScene.h"

/** A scene of one frame that shows content, with the colour key. */
osg::ref_ptr<ViewerScene> createFixedScene(osg::Node* content, const osgGlyphsData::ColorKey& key);

/** The built-in scene, shown without a file or --random: 2000 spheres (seeded) coloured by
 * height, cutting through a fixed-function box and sphere, seen from its own view. */
osg::ref_ptr<ViewerScene> createDefaultScene(const ViewerOptions& options, std::string& error);

/** --random N: osgGlyphsData::createRandomCloud, the random dataset of the paper's benchmarks;
 * of it, the share of sharing (the same glyphs as in the whole cloud). */
osg::ref_ptr<ViewerScene> createRandomScene(const ViewerOptions& options, const SceneSharing& sharing,
                                            std::string& error);

#endif
