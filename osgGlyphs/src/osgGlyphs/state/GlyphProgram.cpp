#include "GlyphProgram.h"

#include "ShaderSource.h"

#include <algorithm>
#include <cctype>
#include <regex>
#include <sstream>

using namespace osgGlyphs;
using namespace osgGlyphs::detail;

const char* const osgGlyphs::detail::PROGRAM_ERROR_NOTIFY_PREFIX = "osgGlyphs: glyph program '";

namespace
{

/** The first line of an info log that reports an error, else its first line that says anything. */
std::string firstErrorLine(const std::string& log)
{
    std::istringstream lines(log);
    std::string line, first;
    while (std::getline(lines, line))
    {
        std::string lower = line;
        std::transform(lower.begin(), lower.end(), lower.begin(),
                       [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
        if (lower.find("error") != std::string::npos)
            return line;
        if (first.empty() && line.find_first_not_of(" \t\r") != std::string::npos)
            first = line;
    }
    return first.empty() ? "GL gives no info log" : first;
}

/** An info log line as "<file>:<line>: <message>", when its location is a GLSL source string
 * number (an index into files) and a line, as Mesa ("2:14(3): error: ..."), NVIDIA
 * ("2(14) : error ...") and AMD or Intel ("ERROR: 2:14: ...") write it. */
bool locate(const std::string& line, const std::vector<std::string>& files, std::string& located)
{
    static const std::regex location(R"(^\s*(ERROR:\s*)?(\d+)(:(\d+)(\(\d+\))?|\((\d+)\))\s*:\s*(.*)$)");
    std::smatch match;
    if (!std::regex_match(line, match, location))
        return false;
    const unsigned long index = std::stoul(match[2]);
    if (index >= files.size())
        return false;
    const std::string number = match[4].matched ? match[4].str() : match[6].str();
    located = files[index] + ":" + number + ": " + (match[1].matched ? "error: " : "") + match[7].str();
    return true;
}

}

GlyphProgram::GlyphProgram(const GlyphTechnique& technique,
                           const std::map<std::string, std::string>& generated, const ErrorFunction& onError)
    : GlyphProgram(technique.getTechniqueName(), technique.getShaderFiles(), generated, onError)
{
}

GlyphProgram::GlyphProgram(const std::string& name, const std::vector<GlyphShaderFile>& files,
                           const std::map<std::string, std::string>& generated, const ErrorFunction& onError)
    : _generated(generated), _onError(onError)
{
    setName("osgGlyphs " + name);
    for (const GlyphShaderFile& file : files)
    {
        const ExpandedShaderSource source = expandShaderSource(file.name, _generated);
        osg::ref_ptr<osg::Shader> shader = new osg::Shader(file.type, source.text);
        shader->setName(file.name);
        _files[shader.get()] = source.files;
        addShader(shader.get());
    }
}

GlyphProgram::GlyphProgram(const GlyphProgram& other, const osg::CopyOp& copyop)
    : osg::Program(other, copyop), _generated(other._generated), _onError(other._onError)
{
    std::lock_guard<std::mutex> lock(other._mutex);
    for (unsigned int i = 0; i < getNumShaders(); ++i)
    {
        const auto found = other._files.find(other.getShader(i));
        if (found != other._files.end())
            _files[getShader(i)] = found->second;
    }
}

void GlyphProgram::reloadShaders()
{
    std::lock_guard<std::mutex> lock(_mutex);
    for (unsigned int i = 0; i < getNumShaders(); ++i)
    {
        osg::Shader* shader = getShader(i);
        ExpandedShaderSource source = expandShaderSource(shader->getName(), _generated);
        shader->setShaderSource(source.text);
        shader->dirtyShader();
        _files[shader] = source.files;
    }
    _reported.clear();
}

void GlyphProgram::apply(osg::State& state) const
{
    osg::Program::apply(state);
    if (isFixedFunction())
        return;
    const PerContextProgram* program = getPCP(state);
    if (!program || program->needsLink() || program->isLinked())
        return;
    std::string error;
    {
        std::lock_guard<std::mutex> lock(_mutex);
        if (!_reported.insert(program).second)
            return;
        error = describeFailure(state, *program);
    }
    if (_onError)
        _onError(error);
}

std::string GlyphProgram::describeFailure(osg::State& state, const PerContextProgram& program) const
{
    const std::string what = "glyph program '" + getName() + "' does not ";
    std::string log;
    for (unsigned int i = 0; i < getNumShaders(); ++i)
    {
        const osg::Shader* shader = getShader(i);
        const osg::Shader::PerContextShader* compiled = shader->getPCS(state);
        if (!compiled || compiled->isCompiled())
            continue;
        compiled->getInfoLog(log);
        const std::string line = firstErrorLine(log);
        const auto files = _files.find(shader);
        std::string located;
        if (files == _files.end() || !locate(line, files->second, located))
            located = shader->getName() + ": " + line;
        return what + "compile: " + located;
    }
    program.getInfoLog(log);
    return what + "link: " + firstErrorLine(log);
}
