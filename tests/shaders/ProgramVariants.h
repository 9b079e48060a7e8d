/* Test support: every GLSL program osgGlyphs builds, and the sources GL receives for each
 * combination of the defines OSG may insert into it. */

#ifndef OSGGLYPHS_TESTS_PROGRAMVARIANTS_H
#define OSGGLYPHS_TESTS_PROGRAMVARIANTS_H 1

#include <osg/Program>

#include <map>
#include <set>
#include <string>
#include <vector>

namespace shadervariants
{

/** Define names and values, as a StateSet's define list holds the ones that are on. */
using DefineMap = std::map<std::string, std::string>;

/** A program the library builds, and the define lists its own StateSets give it. */
struct LibraryProgram
{
    std::string name;
    osg::ref_ptr<osg::Program> program;
    /** One entry per distinct list; a program no StateSet of the library selects has one, empty. */
    std::vector<DefineMap> stateSetDefines;
};

/** Every glyph technique's program (osgGlyphs' and osgGlyphsPaper's registered techniques, through
 * GlyphStateCache) with the define lists of its GlyphVariant StateSets, and GlyphStateCache's
 * other programs (surface shading, screen effects, k-buffer resolve, peeling composition). */
std::vector<LibraryProgram> collectLibraryPrograms();

/** One option of a program: the defines it chooses between. Each value is the set of defines on. */
struct Factor
{
    std::string name;
    std::vector<DefineMap> values;
};

/** Defines that change together: the values they may take, each the set of them that is on. */
struct DefineGroup
{
    std::set<std::string> names;
    /** Empty: the values the define lists of a program's StateSets give these names. */
    std::vector<DefineMap> values;
};

/** Sets of defines that the library never sets together on a variant StateSet (the shapes, the
 * colour modes), found from the define lists of every program. */
std::vector<DefineGroup> findExclusiveGroups(const std::vector<LibraryProgram>& programs);

/** The defines that other parts of the library set only together, or never together. */
std::vector<DefineGroup> getSceneGroups();

/** The options that change the program's sources: each group whose defines the sources use (the
 * values of the ones used), and each other imported define the sources use, on or off. A define
 * the sources only import (#pragma import_defines) and never use changes nothing. */
std::vector<Factor> getFactors(const LibraryProgram& program, const std::vector<DefineGroup>& groups);

/** Every combination of the factors' values. */
std::vector<DefineMap> crossProduct(const std::vector<Factor>& factors);

/** A set of combinations that holds every value of every factor together with every value of
 * every other factor (all pairs), far fewer than crossProduct(). */
std::vector<DefineMap> allPairs(const std::vector<Factor>& factors);

/** The source GL receives for the shader with the defines on: OSG 3.6.5's
 * osg::State::convertVertexShaderSourceToOsgBuiltIns() and getDefineString() of the shader's
 * imported defines, put together as osg::Shader::PerContextShader::compileShader() does. */
std::string assembleStage(const osg::Shader& shader, const DefineMap& defines);

}

#endif
