#include <osgGlyphs/GlyphStateCache>

#include "Resources.h"

#include <osg/Notify>
#include <osgDB/FileNameUtils>

#include <set>
#include <sstream>

using namespace osgGlyphs;

namespace
{

/** Appends the source of name to out, with its includes expanded: "file" from the same folder,
 * "folder/file" from that folder of the shader root. */
void expand(const std::string& name, const std::map<std::string, std::string>& generated,
            std::set<std::string>& included, std::ostringstream& out)
{
    if (!included.insert(name).second)
        return;
    const auto found = generated.find(name);
    const std::string source = found != generated.end() ? found->second : detail::readResource(name);
    if (source.empty())
    {
        OSG_WARN << "osgGlyphs: shader source " << name << " not found" << std::endl;
        return;
    }
    const std::string folder = osgDB::getFilePath(name);
    std::istringstream lines(source);
    std::string line;
    while (std::getline(lines, line))
    {
        const size_t directive = line.find("#include \"");
        if (directive != std::string::npos && line.find_first_not_of(" \t") == directive)
        {
            const size_t begin = directive + 10;
            const size_t end = line.find('"', begin);
            const std::string file = line.substr(begin, end - begin);
            expand(file.find('/') == std::string::npos ? folder + "/" + file : file, generated, included,
                   out);
            continue;
        }
        out << line << '\n';
    }
}

}

std::string osgGlyphs::readShaderSource(const std::string& name,
                                        const std::map<std::string, std::string>& generated)
{
    std::set<std::string> included;
    std::ostringstream out;
    expand(name, generated, included, out);
    return out.str();
}

void osgGlyphs::registerEmbeddedShaders(const std::string& folder, const char* (*lookup)(const std::string&))
{
    detail::registerEmbeddedResources(folder, lookup);
}
