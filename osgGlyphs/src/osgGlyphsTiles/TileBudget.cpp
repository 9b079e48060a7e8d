#include <osgGlyphsTiles/TileBudget>

#include <osgGlyphs/GlyphCloud>

#include <osg/PagedLOD>
#include <osg/ValueObject>
#include <osgUtil/CullVisitor>

using namespace osgGlyphsTiles;

const char* const osgGlyphsTiles::CHILD_GLYPHS_USER_VALUE = "osgGlyphs_childGlyphs";

namespace
{

/** Largest factor the LOD is scaled by: beyond it every tile shows its coarsest level. */
const double MAX_SCALE = 1 << 20;
/** Steps of the bisection over the scale's logarithm. */
const int SCALE_STEPS = 24;

/** The glyphs a cull at this LOD scale would draw under node (in view, in its PagedLOD range;
 * the children of a tile whose file is not loaded counted from its CHILD_GLYPHS_USER_VALUE). */
double predictGlyphs(osg::Node& node, osgUtil::CullVisitor& cv, double lodScale)
{
    if (cv.isCulled(node))
        return 0.0;
    if (const osgGlyphs::GlyphCloud* cloud = dynamic_cast<const osgGlyphs::GlyphCloud*>(&node))
        return cloud->getNumGlyphs();
    if (osg::PagedLOD* lod = dynamic_cast<osg::PagedLOD*>(&node))
    {
        if (lod->getNumChildren() == 0 || lod->getNumRanges() < 2)
            return 0.0;
        const double pixels = cv.clampedPixelSize(lod->getBound()) / lodScale;
        if (pixels < lod->getMaxRange(0))
            return predictGlyphs(*lod->getChild(0), cv, lodScale);
        if (lod->getNumChildren() > 1)
            return predictGlyphs(*lod->getChild(1), cv, lodScale);
        double childGlyphs = 0.0;
        return lod->getUserValue(CHILD_GLYPHS_USER_VALUE, childGlyphs)
                   ? childGlyphs
                   : predictGlyphs(*lod->getChild(0), cv, lodScale);
    }
    double glyphs = 0.0;
    if (osg::Group* group = node.asGroup())
        for (unsigned int i = 0; i < group->getNumChildren(); ++i)
            glyphs += predictGlyphs(*group->getChild(i), cv, lodScale);
    return glyphs;
}

}

double TileBudget::computeLODScale(osg::Node& node, osgUtil::CullVisitor& cv)
{
    const float baseScale = cv.getLODScale();
    const double budget = static_cast<double>(_maxGlyphs);
    double scale = 1.0, glyphs = predictGlyphs(node, cv, baseScale);
    if (glyphs > budget)
    {
        // The smallest scale (on a log scale) whose prediction fits the budget.
        double low = 0.0, high = std::log2(MAX_SCALE);
        double highGlyphs = predictGlyphs(node, cv, baseScale * MAX_SCALE);
        for (int step = 0; step < SCALE_STEPS; ++step)
        {
            const double middle = 0.5 * (low + high);
            const double middleGlyphs = predictGlyphs(node, cv, baseScale * std::exp2(middle));
            if (middleGlyphs > budget)
                low = middle;
            else
            {
                high = middle;
                highGlyphs = middleGlyphs;
            }
        }
        scale = std::exp2(high);
        glyphs = highGlyphs;
    }
    _lastGlyphs = static_cast<std::size_t>(glyphs);
    _lastScale = scale;
    return scale;
}

void TileBudget::operator()(osg::Node* node, osg::NodeVisitor* nv)
{
    osgUtil::CullVisitor* cv = nv ? nv->asCullVisitor() : nullptr;
    if (!cv)
    {
        traverse(node, nv);
        return;
    }
    const float baseScale = cv->getLODScale();
    cv->setLODScale(static_cast<float>(baseScale * computeLODScale(*node, *cv)));
    traverse(node, nv);
    cv->setLODScale(baseScale);
}
