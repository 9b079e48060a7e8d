#include "FlattenedTransforms.h"

#include <osg/MatrixTransform>
#include <osgUtil/Optimizer>

using namespace osgGlyphs;

namespace
{

using Flattener = osgUtil::Optimizer::FlattenStaticTransformsDuplicatingSharedSubgraphsVisitor;

/** The flattener's stack of accumulated matrices, protected in osgUtil: a member pointer formed
 * in a derived class reaches it on any Flattener. */
struct FlattenerMatrices : Flattener
{
    static const std::vector<osg::Matrix>& of(const Flattener& flattener)
    {
        return flattener.*(&FlattenerMatrices::_matrixStack);
    }
};

}

void osgGlyphs::detail::restoreFlattenedTransform(osg::Drawable& drawable, osg::NodeVisitor& nv)
{
    const Flattener* flattener = dynamic_cast<const Flattener*>(&nv);
    if (!flattener)
        return;
    const std::vector<osg::Matrix>& matrices = FlattenerMatrices::of(*flattener);
    const osg::NodePath& path = nv.getNodePath();
    osg::Group* parent = path.empty() ? nullptr : path.back()->asGroup();
    if (matrices.empty() || !parent || parent->getChildIndex(&drawable) >= parent->getNumChildren())
        return;
    osg::ref_ptr<osg::MatrixTransform> transform = new osg::MatrixTransform(matrices.back());
    transform->setName("osgGlyphs: flattened static transforms");
    // Unspecified, not STATIC: a later flattening leaves it alone.
    transform->setDataVariance(osg::Object::UNSPECIFIED);
    osg::ref_ptr<osg::Drawable> keep = &drawable;
    parent->replaceChild(&drawable, transform.get());
    transform->addChild(&drawable);
}
