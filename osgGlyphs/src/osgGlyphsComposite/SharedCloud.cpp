#include <osgGlyphsComposite/SharedCloud>

#include <osgUtil/CullVisitor>

using namespace osgGlyphsComposite;

namespace
{

/** Widens the near and far planes of the cull to those of a box relative to the cloud's origin,
 * with the model-view matrix the cloud computes for its own box. */
class SharedNearFar : public osg::DrawableCullCallback
{
public:
    explicit SharedNearFar(const osg::BoundingBox& localBox) : _localBox(localBox) {}

    bool cull(osg::NodeVisitor* visitor, osg::Drawable* drawable, osg::RenderInfo*) const override
    {
        osgUtil::CullVisitor* cv = visitor ? visitor->asCullVisitor() : nullptr;
        auto* cloud = dynamic_cast<osgGlyphs::GlyphCloud*>(drawable);
        if (cv && cloud && _localBox.valid() &&
            cv->getComputeNearFarMode() != osg::CullSettings::DO_NOT_COMPUTE_NEAR_FAR)
        {
            const osg::Matrixd modelView =
                osg::Matrixd::translate(cloud->getOrigin()) * *cv->getModelViewMatrix();
            cv->updateCalculatedNearFar(modelView, _localBox);
        }
        return false;
    }

private:
    osg::BoundingBox _localBox;
};

osg::BoundingBox unite(const osg::BoundingBox& box, const osgGlyphsData::ShareReduction& reduction)
{
    std::vector<double> low(box._min.ptr(), box._min.ptr() + 3), high(box._max.ptr(), box._max.ptr() + 3);
    reduction.minimum(low);
    reduction.maximum(high);
    // Exact: the values are floats, and minimum and maximum only choose among them.
    return osg::BoundingBox(float(low[0]), float(low[1]), float(low[2]), float(high[0]), float(high[1]),
                            float(high[2]));
}

}

osg::BoundingBox osgGlyphsComposite::shareCloud(osgGlyphs::GlyphCloud& cloud,
                                                const osgGlyphsData::ShareReduction& reduction)
{
    osgGlyphs::GlyphCloud::PackingScales scales = cloud.getOwnPackingScales();
    std::vector<double> low{scales.scalarMin}, high{scales.scalarMax, scales.largestRadius};
    reduction.minimum(low);
    reduction.maximum(high);
    scales.scalarMin = static_cast<float>(low[0]);
    scales.scalarMax = static_cast<float>(high[0]);
    scales.largestRadius = static_cast<float>(high[1]);
    cloud.setSharedPackingScales(scales);

    cloud.setInitialBound(osg::BoundingBox());
    const osg::BoundingBox world = unite(cloud.getBoundingBox(), reduction);
    const osg::BoundingBox local = unite(cloud.getLocalBoundingBox(), reduction);
    cloud.setCullCallback(new SharedNearFar(local));
    cloud.setInitialBound(world);
    return world;
}
