#include "ProgramVariants.h"

#include <osgGlyphs/GlyphStateCache>

#include <algorithm>
#include <cctype>

using namespace shadervariants;

namespace
{

bool isIdentifierChar(char c)
{
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
}

/** Whether the name occurs as a whole word in the source outside #pragma lines. */
bool usesName(const std::string& source, const std::string& name)
{
    for (std::size_t at = source.find(name); at != std::string::npos; at = source.find(name, at + 1))
    {
        const std::size_t end = at + name.size();
        if ((at > 0 && isIdentifierChar(source[at - 1])) ||
            (end < source.size() && isIdentifierChar(source[end])))
            continue;
        const std::size_t newline = source.rfind('\n', at);
        const std::size_t text =
            source.find_first_not_of(" \t", newline == std::string::npos ? 0 : newline + 1);
        if (source.compare(text, 7, "#pragma") != 0)
            return true;
    }
    return false;
}

/** The defines that some stage imports and some stage uses. */
std::set<std::string> getUsedImports(const osg::Program& program)
{
    std::set<std::string> imported;
    for (unsigned int i = 0; i < program.getNumShaders(); ++i)
        for (const std::string& name : program.getShader(i)->getShaderDefines())
            imported.insert(name);
    std::set<std::string> used;
    for (const std::string& name : imported)
        for (unsigned int i = 0; i < program.getNumShaders(); ++i)
            if (usesName(program.getShader(i)->getShaderSource(), name))
                used.insert(name);
    return used;
}

bool setTogether(const std::vector<LibraryProgram>& programs, const std::string& a, const std::string& b)
{
    for (const LibraryProgram& program : programs)
        for (const DefineMap& defines : program.stateSetDefines)
            if (defines.count(a) && defines.count(b))
                return true;
    return false;
}

DefineMap project(const DefineMap& defines, const std::set<std::string>& names)
{
    DefineMap projected;
    for (const auto& entry : defines)
        if (names.count(entry.first))
            projected.insert(entry);
    return projected;
}

std::string joinNames(const std::set<std::string>& names)
{
    std::string joined;
    for (const std::string& name : names)
        joined += (joined.empty() ? "" : "|") + name;
    return joined;
}

}

std::vector<DefineGroup> shadervariants::findExclusiveGroups(const std::vector<LibraryProgram>& programs)
{
    std::set<std::string> variantDefines;
    for (const LibraryProgram& program : programs)
        for (const DefineMap& defines : program.stateSetDefines)
            for (const auto& entry : defines)
                variantDefines.insert(entry.first);
    std::vector<std::set<std::string>> groups;
    for (const std::string& name : variantDefines)
    {
        auto group = std::find_if(groups.begin(), groups.end(),
                                  [&](const std::set<std::string>& members)
                                  {
                                      return std::none_of(members.begin(), members.end(),
                                                          [&](const std::string& member)
                                                          { return setTogether(programs, name, member); });
                                  });
        if (group == groups.end())
            groups.push_back({name});
        else
            group->insert(name);
    }
    std::vector<DefineGroup> exclusive;
    for (const std::set<std::string>& group : groups)
        if (group.size() > 1)
            exclusive.push_back({group, {}});
    return exclusive;
}

std::vector<DefineGroup> shadervariants::getSceneGroups()
{
    using namespace osgGlyphs;
    // One DepthPeeling pass sets one of them (peeling/PeelingPasses.cpp); nested nodes share the
    // passes of their camera.
    const DefineGroup peeling{{GLYPH_DEPTH_PEEL_DEFINE, GLYPH_K_BUFFER_DEFINE},
                              {{}, {{GLYPH_DEPTH_PEEL_DEFINE, ""}}, {{GLYPH_K_BUFFER_DEFINE, ""}}}};
    // ScreenEffects' occlusion pass computes the ambient occlusion (effects/ScreenPass.cpp).
    const std::string occlusion = "OSGGLYPHS_SCREEN_AMBIENT_OCCLUSION",
                      pass = "OSGGLYPHS_SCREEN_OCCLUSION_PASS";
    const DefineGroup screenEffects{{occlusion, pass},
                                    {{}, {{occlusion, ""}}, {{occlusion, ""}, {pass, ""}}}};
    return {peeling, screenEffects};
}

std::vector<Factor> shadervariants::getFactors(const LibraryProgram& program,
                                               const std::vector<DefineGroup>& groups)
{
    std::set<std::string> used = getUsedImports(*program.program);
    std::vector<Factor> factors;
    for (const DefineGroup& group : groups)
    {
        std::set<std::string> usedMembers;
        for (const std::string& name : group.names)
            if (used.erase(name))
                usedMembers.insert(name);
        if (usedMembers.empty())
            continue;
        Factor factor{joinNames(usedMembers), {}};
        for (const DefineMap& defines : group.values.empty() ? program.stateSetDefines : group.values)
        {
            const DefineMap value = project(defines, usedMembers);
            if (std::find(factor.values.begin(), factor.values.end(), value) == factor.values.end())
                factor.values.push_back(value);
        }
        factors.push_back(factor);
    }
    for (const std::string& name : used)
        factors.push_back({name, {{}, {{name, ""}}}});
    return factors;
}
