/* osgglyphs_shader_variants [--pairs] FOLDER: writes the sources GL receives for every variant of
 * every GLSL program osgGlyphs builds, one folder per variant (FOLDER/<program>/<number>/, a file
 * per stage named after its shader file), and FOLDER/variants.tsv: the folder, the program, the
 * defines on and a note, one line per variant. Every combination of the options that change the sources,
 * or with --pairs a set that holds every pair of option values. Exits 1 when the library reports a
 * problem (a shader file not found) while it builds its programs. */

#include "ProgramVariants.h"

#include <osgGlyphs/GlyphStateCache>

#include <osg/Notify>
#include <osgDB/FileNameUtils>
#include <osgDB/FileUtils>

#include <cstdio>
#include <fstream>
#include <iostream>

using namespace shadervariants;

namespace
{

/** Passes OSG's messages to stderr and remembers whether any was a warning or worse. */
class WarningRecorder : public osg::NotifyHandler
{
public:
    void notify(osg::NotifySeverity severity, const char* message) override
    {
        std::cerr << message;
        _warned = _warned || severity <= osg::WARN;
    }
    bool hasWarned() const { return _warned; }

private:
    bool _warned = false;
};

const char* getExtension(osg::Shader::Type type)
{
    switch (type)
    {
    case osg::Shader::VERTEX:
        return "vert";
    case osg::Shader::TESSCONTROL:
        return "tesc";
    case osg::Shader::TESSEVALUATION:
        return "tese";
    case osg::Shader::GEOMETRY:
        return "geom";
    case osg::Shader::FRAGMENT:
        return "frag";
    case osg::Shader::COMPUTE:
        return "comp";
    default:
        return "unknown";
    }
}

std::string getStageFileName(const osg::Shader& shader)
{
    return osgDB::getStrippedName(shader.getName()) + "." + getExtension(shader.getType());
}

bool writeFile(const std::string& path, const std::string& text)
{
    std::ofstream file(path, std::ios::binary);
    file << text;
    return static_cast<bool>(file.flush());
}

std::string joinDefines(const DefineMap& defines)
{
    std::string joined;
    for (const auto& entry : defines)
        joined +=
            (joined.empty() ? "" : " ") + entry.first + (entry.second.empty() ? "" : "=" + entry.second);
    return joined;
}

/** glslang 12 has GL_ARB_shader_storage_buffer_object's atomic functions from #version 420 only;
 * Mesa has them wherever the extension is enabled (its specification needs OpenGL 4.0 and names
 * no GLSL version). The k-buffer variants, which DepthPeeling draws only where OpenGL 4.3 is, are
 * validated at #version 430, which every such context has. Returns whether the source changed. */
bool raiseKBufferVersion(std::string& source, const DefineMap& defines)
{
    const std::string directive = "#version ";
    if (!defines.count(osgGlyphs::GLYPH_K_BUFFER_DEFINE) ||
        source.compare(0, directive.size(), directive) != 0)
        return false;
    const std::size_t end = source.find_first_not_of("0123456789", directive.size());
    if (std::stoi(source.substr(directive.size(), end - directive.size())) >= 420)
        return false;
    source.replace(directive.size(), end - directive.size(), "430");
    return true;
}

/** Writes one folder per combination; false when a file cannot be written. */
bool writeVariants(const std::string& folder, const LibraryProgram& program,
                   const std::vector<DefineMap>& combinations, std::ostream& table)
{
    for (std::size_t n = 0; n < combinations.size(); ++n)
    {
        char number[24];
        std::snprintf(number, sizeof(number), "%04zu", n);
        const std::string relative = program.name + "/" + number;
        if (!osgDB::makeDirectory(folder + "/" + relative))
            return false;
        bool raised = false;
        for (unsigned int i = 0; i < program.program->getNumShaders(); ++i)
        {
            const osg::Shader& shader = *program.program->getShader(i);
            std::string source = assembleStage(shader, combinations[n]);
            raised = raiseKBufferVersion(source, combinations[n]) || raised;
            if (!writeFile(folder + "/" + relative + "/" + getStageFileName(shader), source))
                return false;
        }
        table << relative << '\t' << program.program->getName() << '\t' << joinDefines(combinations[n])
              << '\t' << (raised ? "validated at #version 430 (k-buffer)" : "") << '\n';
    }
    return true;
}

}

int main(int argc, char** argv)
{
    const bool pairs = argc == 3 && std::string(argv[1]) == "--pairs";
    if (argc != 2 && !pairs)
    {
        std::cerr << "usage: osgglyphs_shader_variants [--pairs] FOLDER" << std::endl;
        return 2;
    }
    const std::string folder = argv[argc - 1];
    osg::ref_ptr<WarningRecorder> recorder = new WarningRecorder;
    osg::setNotifyHandler(recorder.get());

    const std::vector<LibraryProgram> programs = collectLibraryPrograms();
    std::vector<DefineGroup> groups = findExclusiveGroups(programs);
    for (const DefineGroup& group : getSceneGroups())
        groups.push_back(group);
    std::ofstream table(folder + "/variants.tsv");
    std::size_t total = 0, totalProduct = 0;
    for (const LibraryProgram& program : programs)
    {
        const std::vector<Factor> factors = getFactors(program, groups);
        const std::vector<DefineMap> combinations = pairs ? allPairs(factors) : crossProduct(factors);
        if (!writeVariants(folder, program, combinations, table))
        {
            std::cerr << "osgglyphs_shader_variants: cannot write under " << folder << std::endl;
            return 1;
        }
        std::size_t product = 1;
        for (const Factor& factor : factors)
            product *= factor.values.size();
        std::cout << program.name << ": " << combinations.size() << " variants (full product " << product
                  << ") of " << factors.size() << " options:";
        for (const Factor& factor : factors)
            std::cout << ' ' << factor.name << " (" << factor.values.size() << ')';
        std::cout << std::endl;
        total += combinations.size();
        totalProduct += product;
    }
    std::cout << "osgglyphs_shader_variants: " << total << " programs (full product " << totalProduct
              << ") in " << folder << std::endl;
    return recorder->hasWarned() || !table.flush() ? 1 : 0;
}
