// osgglyphviewer: a paged tile archive of osgglyphconvert.

#ifndef OSGGLYPHVIEWER_TILESCENE_H
#define OSGGLYPHVIEWER_TILESCENE_H 1

#include "ViewerScene.h"

/** Whether the file is a tile archive (.osga) or a series of them (its index, .osgt or .osgb). */
bool isTileArchive(const std::string& file);

/** The root of a tile archive, paged by the viewer's DatabasePager, with the colour key of its
 * tiles (their colour map and range, which every tile shares). */
osg::ref_ptr<ViewerScene> createTileScene(const ViewerOptions& options, std::string& error);

#endif
