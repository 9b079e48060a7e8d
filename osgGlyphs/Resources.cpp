#include "Resources.h"

#include <osg/Notify>
#include <osgDB/FileUtils>
#include <osgDB/fstream>

#include <sstream>

std::string osgGlyphs::detail::readResource(const std::string& name)
{
    const std::string path = osgDB::findDataFile(name);
    if (!path.empty())
    {
        osgDB::ifstream file(path.c_str());
        std::ostringstream text;
        text << file.rdbuf();
        if (file)
        {
            OSG_INFO << "osgGlyphs: using " << path << " instead of the built-in " << name << std::endl;
            return text.str();
        }
        OSG_WARN << "osgGlyphs: cannot read " << path << "; using the built-in " << name << std::endl;
    }
    const std::string colormapPrefix = "osgGlyphs/colormaps/";
    const char* embedded = name.compare(0, colormapPrefix.size(), colormapPrefix) == 0
                               ? getEmbeddedColorMap(name.substr(colormapPrefix.size()))
                               : getEmbeddedShader(name);
    return embedded ? embedded : std::string();
}
