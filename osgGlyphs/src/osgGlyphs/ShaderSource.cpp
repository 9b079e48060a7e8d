#include "ShaderSource.h"

#include "Resources.h"

#include <osg/Notify>

#include <set>
#include <sstream>

namespace
{

void expand(const std::string& name, std::set<std::string>& included, std::ostringstream& out)
{
    if (!included.insert(name).second)
        return;
    const std::string source = osgGlyphs::detail::readResource("osgGlyphs/" + name);
    if (source.empty())
    {
        OSG_WARN << "osgGlyphs: shader source osgGlyphs/" << name << " not found" << std::endl;
        return;
    }
    std::istringstream lines(source);
    std::string line;
    while (std::getline(lines, line))
    {
        const size_t directive = line.find("#include \"");
        if (directive != std::string::npos && line.find_first_not_of(" \t") == directive)
        {
            const size_t begin = directive + 10;
            const size_t end = line.find('"', begin);
            expand(line.substr(begin, end - begin), included, out);
            continue;
        }
        out << line << '\n';
    }
}

}

std::string osgGlyphs::detail::loadShaderSource(const std::string& name)
{
    std::set<std::string> included;
    std::ostringstream out;
    expand(name, included, out);
    return out.str();
}
