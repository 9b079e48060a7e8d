/* osgGlyphs - private: keeps clouds where osgUtil's transform flattening would leave them. Not
 * installed. */

#ifndef OSGGLYPHS_FLATTENEDTRANSFORMS_H
#define OSGGLYPHS_FLATTENEDTRANSFORMS_H 1

#include <osg/Drawable>
#include <osg/NodeVisitor>

namespace osgGlyphs
{
namespace detail
{

/** When nv is osgUtil::Optimizer's FlattenStaticTransformsDuplicatingSharedSubgraphsVisitor and
 * has turned static transforms above the drawable into groups, puts their combined matrix back
 * between the drawable and its parent as an osg::MatrixTransform: that visitor moves only
 * osg::Geometry vertices, and a cloud's glyphs (radii, vectors) cannot take a general matrix. */
void restoreFlattenedTransform(osg::Drawable& drawable, osg::NodeVisitor& nv);

}
}

#endif
