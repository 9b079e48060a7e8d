/* osgGlyphs - private: the library's text resources (shaders, colour maps). Not installed. */

#ifndef OSGGLYPHS_RESOURCES_H
#define OSGGLYPHS_RESOURCES_H 1

#include <string>

namespace osgGlyphs
{
namespace detail
{

/** Embedded copies, generated at build time from shaders/ and share/colormaps/. */
const char* getEmbeddedShader(const std::string& name);
const char* getEmbeddedColorMap(const std::string& name);

/** Makes the embedded files of names under folder ("osgGlyphsPaper/...") available; lookup
 * receives the whole name. osgGlyphs' own shaders are registered from the start. */
void registerEmbeddedResources(const std::string& folder, const char* (*lookup)(const std::string&));

/** The text of a resource such as "osgGlyphs/impostor.frag" or "osgGlyphs/colormaps/viridis.txt":
 * a file of that name in a folder of OSG's data path (OSG_FILE_PATH) if there is one, else the
 * installed copy (<prefix>/share/osgGlyphs/shaders/<name>, next to an installed library), else
 * the embedded copy, else an empty string. Never a file of the working folder. */
std::string readResource(const std::string& name);

/** readResource(), and where the text came from: the file read, or the name for an embedded copy. */
std::string readResource(const std::string& name, std::string& origin);

}
}

#endif
