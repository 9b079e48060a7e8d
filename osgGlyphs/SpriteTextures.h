/* osgGlyphs - private: the sprite textures of the texture techniques. Not installed. */

#ifndef OSGGLYPHS_SPRITETEXTURES_H
#define OSGGLYPHS_SPRITETEXTURES_H 1

#include <osg/Texture2D>

namespace osgGlyphs
{
namespace detail
{

/** texture-blend's textures: the circle mask (white inside the circle), or the sphere lit by
 * a headlight in grey. Alpha is the circle in both. */
osg::ref_ptr<osg::Texture2D> createSpriteTexture(bool lighting);

}
}

#endif
