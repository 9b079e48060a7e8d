/* osgGlyphs - private: the shapes of a GSD file's particle types (particles/type_shapes), as the
 * HOOMD schema writes them: one JSON object per type. Not installed. */

#ifndef OSGGLYPHS_FORMATS_GSDSHAPES_H
#define OSGGLYPHS_FORMATS_GSDSHAPES_H 1

#include <osg/Vec3>

#include <string>

namespace osgGlyphsData
{
namespace formats
{

/** What a type's shape is, for drawing. */
enum class GsdShapeKind
{
    /** No shape, or one drawn as a sphere of the particles' diameters (Sphere, polygons, ...). */
    Other,
    /** {"type": "Ellipsoid", "a": .., "b": .., "c": ..}: semi-axes a, b, c along the body axes. */
    Ellipsoid
};

/** Reads one type's shape from its JSON text (empty text: Other). False, with what is wrong in
 * error, for text that is not a JSON object, or an Ellipsoid without finite, positive a, b and c. */
bool parseGsdShape(const std::string& json, GsdShapeKind& kind, osg::Vec3& semiAxes, std::string& error);

}
}

#endif
