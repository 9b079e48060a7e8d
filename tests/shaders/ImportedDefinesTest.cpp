// Every define that the library's GLSL tests (#if, #ifdef, #ifndef, #elif, defined()) and that no
// GLSL source of the library defines itself, so that only a StateSet can set it, is imported by
// the stage that tests it (#pragma import_defines): OSG inserts only imported defines, so a define
// a StateSet sets but the stage does not import would be silently off.

#include "ProgramVariants.h"

#include <gtest/gtest.h>

#include <regex>
#include <set>
#include <sstream>
#include <string>

using namespace shadervariants;

namespace
{

const std::regex CONDITIONAL(R"(^\s*#\s*(if|ifdef|ifndef|elif)\b(.*)$)");
const std::regex DEFINITION(R"(^\s*#\s*define\s+(\w+))");
const std::regex NAME(R"(\bOSGGLYPHS_\w+)");

/** The OSGGLYPHS_ names the source's conditionals test, and the names it #defines itself. */
void scanSource(const std::string& source, std::set<std::string>& tested, std::set<std::string>& defined)
{
    std::istringstream lines(source);
    std::string line;
    std::smatch match;
    while (std::getline(lines, line))
    {
        if (std::regex_search(line, match, DEFINITION))
            defined.insert(match[1]);
        if (!std::regex_search(line, match, CONDITIONAL))
            continue;
        const std::string condition = match[2];
        for (std::sregex_iterator name(condition.begin(), condition.end(), NAME), end; name != end; ++name)
            tested.insert(name->str());
    }
}

std::string listOf(const std::set<std::string>& names)
{
    std::string text;
    for (const std::string& name : names)
        text += (text.empty() ? "" : ", ") + name;
    return text;
}

}

TEST(ImportedDefines, EveryDefineAStageTestsIsImportedOrDefinedInGlsl)
{
    const std::vector<LibraryProgram> programs = collectLibraryPrograms();
    ASSERT_FALSE(programs.empty());
    // Switches the GLSL sets itself (a stage's own, or a generated include's), in any program.
    std::set<std::string> definedInGlsl;
    for (const LibraryProgram& program : programs)
        for (unsigned int i = 0; i < program.program->getNumShaders(); ++i)
        {
            std::set<std::string> tested;
            scanSource(program.program->getShader(i)->getShaderSource(), tested, definedInGlsl);
        }
    std::size_t stages = 0, names = 0;
    for (const LibraryProgram& program : programs)
    {
        for (unsigned int i = 0; i < program.program->getNumShaders(); ++i)
        {
            const osg::Shader& shader = *program.program->getShader(i);
            std::set<std::string> tested, defined;
            scanSource(shader.getShaderSource(), tested, defined);
            std::set<std::string> missing;
            for (const std::string& name : tested)
                if (!shader.getShaderDefines().count(name) && !definedInGlsl.count(name))
                    missing.insert(name);
            EXPECT_TRUE(missing.empty())
                << program.name << ", " << shader.getTypename() << " stage \"" << shader.getName()
                << "\" tests " << listOf(missing) << " without importing it";
            ++stages;
            names += tested.size();
        }
    }
    // The scan finds what it looks for: the glyph programs test their shape, colour and lighting.
    EXPECT_GT(stages, 20u);
    EXPECT_GT(names, 100u);
}
