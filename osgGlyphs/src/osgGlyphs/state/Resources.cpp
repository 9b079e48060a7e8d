#include "Resources.h"

#include <osg/Notify>
#include <osgDB/FileNameUtils>
#include <osgDB/FileUtils>
#include <osgDB/fstream>

#include <dlfcn.h>

#include <map>
#include <mutex>
#include <sstream>

namespace
{

/** <prefix>/share/osgGlyphs/shaders of an installed library, found from where the library was
 * loaded; empty when it was not loaded from an installed tree (a build tree has no such folder). */
const std::string& getInstalledShaderDir()
{
    static const std::string dir = []
    {
        Dl_info info;
        if (!dladdr(reinterpret_cast<const void*>(&getInstalledShaderDir), &info) || !info.dli_fname)
            return std::string();
        const std::string candidate =
            osgDB::getFilePath(osgDB::getRealPath(info.dli_fname)) + "/" + OSGGLYPHS_SHADER_DIR_FROM_LIBRARY;
        return osgDB::fileType(candidate) == osgDB::DIRECTORY ? osgDB::getRealPath(candidate) : std::string();
    }();
    return dir;
}

/** A file of that name ("osgGlyphs/sphere.glsl") in a folder of OSG's data path, else in the
 * installed shader folder. Unlike osgDB::findDataFile(), never the working folder and never the
 * bare file name: a user's folder is no place for the library's shaders. An empty entry of the
 * data path, which would stand for the working folder, is skipped too. */
std::string findResourceFile(const std::string& name)
{
    for (const std::string& folder : osgDB::getDataFilePathList())
    {
        const std::string path = folder.empty() ? std::string() : osgDB::concatPaths(folder, name);
        if (!path.empty() && osgDB::fileType(path) == osgDB::REGULAR_FILE)
            return path;
    }
    if (getInstalledShaderDir().empty())
        return std::string();
    const std::string installed = getInstalledShaderDir() + "/" + name;
    return osgDB::fileExists(installed) ? installed : std::string();
}

using EmbeddedLookup = const char* (*)(const std::string&);

struct EmbeddedResources
{
    std::mutex mutex;
    std::map<std::string, EmbeddedLookup> lookups{{"osgGlyphs", &osgGlyphs::detail::getEmbeddedShader}};
};

EmbeddedResources& getEmbeddedResources()
{
    static EmbeddedResources resources;
    return resources;
}

const char* findEmbedded(const std::string& name)
{
    const std::string colormapPrefix = "osgGlyphs/colormaps/";
    if (name.compare(0, colormapPrefix.size(), colormapPrefix) == 0)
        return osgGlyphs::detail::getEmbeddedColorMap(name.substr(colormapPrefix.size()));
    EmbeddedResources& resources = getEmbeddedResources();
    std::lock_guard<std::mutex> lock(resources.mutex);
    const auto found = resources.lookups.find(name.substr(0, name.find('/')));
    return found == resources.lookups.end() ? nullptr : found->second(name);
}

}

void osgGlyphs::detail::registerEmbeddedResources(const std::string& folder, EmbeddedLookup lookup)
{
    EmbeddedResources& resources = getEmbeddedResources();
    std::lock_guard<std::mutex> lock(resources.mutex);
    resources.lookups[folder] = lookup;
}

std::string osgGlyphs::detail::readResource(const std::string& name)
{
    std::string origin;
    return readResource(name, origin);
}

std::string osgGlyphs::detail::readResource(const std::string& name, std::string& origin)
{
    const std::string path = findResourceFile(name);
    origin = name;
    if (!path.empty())
    {
        osgDB::ifstream file(path.c_str());
        std::ostringstream text;
        text << file.rdbuf();
        if (file)
        {
            OSG_INFO << "osgGlyphs: using " << path << " instead of the built-in " << name << std::endl;
            origin = path;
            return text.str();
        }
        OSG_WARN << "osgGlyphs: cannot read " << path << "; using the built-in " << name << std::endl;
    }
    const char* embedded = findEmbedded(name);
    return embedded ? embedded : std::string();
}
