#include "ProgramVariants.h"

#include <osg/State>

using namespace shadervariants;

namespace
{

void replaceAll(std::string& text, const std::string& from, const std::string& to)
{
    for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
        text.replace(at, from.size(), to);
}

/** The first line that begins (after blanks) with #version, ending with its newline, and marks it
 * in the source as a comment; empty if there is none. The search and the comment are those of
 * osg::Shader::PerContextShader::compileShader() in OSG 3.6.5 (src/osg/Shader.cpp). */
std::string takeVersionLine(std::string& source)
{
    std::size_t previous = 0;
    while (previous != std::string::npos)
    {
        const std::size_t start = source.find_first_not_of(" \t", previous);
        const std::size_t end =
            start == std::string::npos ? std::string::npos : source.find_first_of("\n\r", start);
        if (end == std::string::npos)
            return std::string();
        if (end - start >= 8 && source.compare(start, 8, "#version") == 0)
        {
            std::string line = source.substr(start, end - start + 1);
            if (line.back() != '\n')
                line.push_back('\n');
            source.insert(
                start,
                "// following version spec has been automatically reassigned to start of source list: ");
            return line;
        }
        previous = end + 1 < source.size() ? end + 1 : std::string::npos;
    }
    return std::string();
}

}

std::string shadervariants::assembleStage(const osg::Shader& shader, const DefineMap& defines)
{
    osg::ref_ptr<osg::StateSet> stateSet = new osg::StateSet;
    for (const auto& entry : defines)
        stateSet->setDefine(entry.first, entry.second);
    osg::ref_ptr<osg::State> state = new osg::State;
    state->pushStateSet(stateSet.get());

    std::string source = shader.getShaderSource();
    state->convertVertexShaderSourceToOsgBuiltIns(source);
    const std::string defineString = state->getDefineString(shader.getShaderDefines());
    if (defineString.empty())
        return source;
    replaceAll(source, "\r\n", " \n");
    // GL joins the strings OSG passes to glShaderSource.
    return takeVersionLine(source) + defineString + source;
}
