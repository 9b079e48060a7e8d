/* osgGlyphs - private: GLSL sources with #include, from the data path or embedded. Not installed. */

#ifndef OSGGLYPHS_SHADERSOURCE_H
#define OSGGLYPHS_SHADERSOURCE_H 1

#include <string>

namespace osgGlyphs
{
namespace detail
{

/** The source of shader osgGlyphs/<name>, with every `#include "file"` line replaced by the
 * source of osgGlyphs/<file> (each file once). Problems are reported through osg::notify. */
std::string loadShaderSource(const std::string& name);

}
}

#endif
