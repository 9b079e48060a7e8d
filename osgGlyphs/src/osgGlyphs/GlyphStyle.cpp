#include <osgGlyphs/GlyphCulling>
#include <osgGlyphs/GlyphStyle>

#include "EnumNames.h"

using namespace osgGlyphs;

namespace
{

const std::pair<GlyphShape, const char*> SHAPE_NAMES[] = {
    {GlyphShape::Sphere, "sphere"},       {GlyphShape::Cone, "cone"},
    {GlyphShape::Arrow, "arrow"},         {GlyphShape::Cylinder, "cylinder"},
    {GlyphShape::Ellipsoid, "ellipsoid"}, {GlyphShape::Superquadric, "superquadric"}};

const std::pair<GlyphAnchor, const char*> ANCHOR_NAMES[] = {
    {GlyphAnchor::Tail, "tail"}, {GlyphAnchor::Center, "center"}, {GlyphAnchor::Head, "head"}};

const std::pair<GlyphCulling, const char*> CULLING_NAMES[] = {
    {GlyphCulling::Off, "off"}, {GlyphCulling::Frustum, "frustum"}, {GlyphCulling::Occlusion, "occlusion"}};

}

const char* osgGlyphs::getShapeName(GlyphShape shape)
{
    return detail::nameOf(SHAPE_NAMES, shape);
}

bool osgGlyphs::parseShape(const std::string& name, GlyphShape& shape)
{
    return detail::parseName(SHAPE_NAMES, name, shape);
}

const char* osgGlyphs::getAnchorName(GlyphAnchor anchor)
{
    return detail::nameOf(ANCHOR_NAMES, anchor);
}

bool osgGlyphs::parseAnchor(const std::string& name, GlyphAnchor& anchor)
{
    return detail::parseName(ANCHOR_NAMES, name, anchor);
}

const char* osgGlyphs::getCullingName(GlyphCulling culling)
{
    return detail::nameOf(CULLING_NAMES, culling);
}

bool osgGlyphs::parseCulling(const std::string& name, GlyphCulling& culling)
{
    return detail::parseName(CULLING_NAMES, name, culling);
}

float osgGlyphs::getAnchorFraction(GlyphAnchor anchor)
{
    return anchor == GlyphAnchor::Tail ? 0.0f : anchor == GlyphAnchor::Head ? 1.0f : 0.5f;
}
