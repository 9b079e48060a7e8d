#include <osgGlyphs/GlyphStateCache>

#include "Resources.h"
#include "ShaderSource.h"

#include <osg/Notify>
#include <osgDB/FileNameUtils>

#include <set>
#include <sstream>

using namespace osgGlyphs;

namespace
{

/** The state of one expansion: what is included so far, and the text. */
struct Expansion
{
    const std::map<std::string, std::string>& generated;
    std::set<std::string> included;
    std::ostringstream text;
    std::vector<std::string> files;
};

bool isDirective(const std::string& line, const char* directive)
{
    const std::size_t start = line.find_first_not_of(" \t");
    return start != std::string::npos &&
           line.compare(start, std::string::traits_type::length(directive), directive) == 0;
}

bool hasVersionDirective(const std::string& source)
{
    std::istringstream lines(source);
    std::string line;
    while (std::getline(lines, line))
        if (isDirective(line, "#version"))
            return true;
    return false;
}

/** Appends the source of name to the expansion, with its includes expanded: "file" from the same
 * folder, "folder/file" from that folder of the shader root. */
void expand(const std::string& name, Expansion& expansion)
{
    if (!expansion.included.insert(name).second)
        return;
    const auto found = expansion.generated.find(name);
    std::string origin = name;
    const std::string source =
        found != expansion.generated.end() ? found->second : detail::readResource(name, origin);
    if (source.empty())
    {
        OSG_WARN << "osgGlyphs: shader source " << name << " not found" << std::endl;
        return;
    }
    const std::size_t index = expansion.files.size();
    expansion.files.push_back(origin);
    // #version must come first: the shader's own file is numbered from the line after it.
    bool numbered = index > 0 || !hasVersionDirective(source);
    if (numbered)
        expansion.text << "#line 1 " << index << '\n';

    const std::string folder = osgDB::getFilePath(name);
    std::istringstream lines(source);
    std::string line;
    for (unsigned int number = 1; std::getline(lines, line); ++number)
    {
        if (isDirective(line, "#include \""))
        {
            const std::size_t begin = line.find('"') + 1;
            const std::size_t end = line.find('"', begin);
            const std::string file = line.substr(begin, end - begin);
            expand(file.find('/') == std::string::npos ? folder + "/" + file : file, expansion);
            expansion.text << "#line " << number + 1 << ' ' << index << '\n';
            continue;
        }
        expansion.text << line << '\n';
        if (!numbered && isDirective(line, "#version"))
        {
            expansion.text << "#line " << number + 1 << ' ' << index << '\n';
            numbered = true;
        }
    }
}

}

detail::ExpandedShaderSource detail::expandShaderSource(const std::string& name,
                                                        const std::map<std::string, std::string>& generated)
{
    Expansion expansion{generated, {}, {}, {}};
    expand(name, expansion);
    return ExpandedShaderSource{expansion.text.str(), expansion.files};
}

std::string osgGlyphs::readShaderSource(const std::string& name,
                                        const std::map<std::string, std::string>& generated)
{
    return detail::expandShaderSource(name, generated).text;
}

void osgGlyphs::registerEmbeddedShaders(const std::string& folder, const char* (*lookup)(const std::string&))
{
    detail::registerEmbeddedResources(folder, lookup);
}
