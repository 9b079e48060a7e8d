#include <osgGlyphs/GlyphCloud>

#include "../occlusion/GlyphOcclusion.h"

using namespace osgGlyphs;

osg::ref_ptr<osg::Vec4ubArray> GlyphCloud::computeOcclusion(const GlyphOcclusionSettings& settings) const
{
    return detail::computeGlyphOcclusion(
        _numGlyphs, [this](unsigned int i, detail::GlyphSolid& solid) { return getGlyphSolid(i, solid); },
        settings);
}
