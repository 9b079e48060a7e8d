#include "ProgramVariants.h"

#include <osgGlyphs/GlyphStateCache>
#include <osgGlyphs/GlyphTechnique>
#include <osgGlyphsPaper/Techniques>

#include <algorithm>

using namespace osgGlyphs;
using namespace shadervariants;

namespace
{

// Every value of the public enums of GlyphVariant.
const GlyphShape SHAPES[] = {GlyphShape::Sphere, GlyphShape::Cone, GlyphShape::Arrow, GlyphShape::Cylinder};
const GlyphColorMode COLOR_MODES[] = {GlyphColorMode::Uniform, GlyphColorMode::RGBA, GlyphColorMode::Scalar};

DefineMap getDefinesOn(const osg::StateSet& stateSet)
{
    DefineMap defines;
    for (const auto& entry : stateSet.getDefineList())
        if (entry.second.second & osg::StateAttribute::ON)
            defines[entry.first] = entry.second.first;
    return defines;
}

/** The define lists of the StateSets of every variant the technique can draw. */
std::vector<DefineMap> getVariantDefineLists(const GlyphTechnique& technique)
{
    std::vector<DefineMap> lists;
    for (GlyphShape shape : SHAPES)
        for (GlyphColorMode colorMode : COLOR_MODES)
            for (bool lit : {false, true})
                for (bool compressed : {false, true})
                {
                    if (!technique.supportsShape(shape))
                        continue;
                    GlyphVariant variant;
                    variant.shape = shape;
                    variant.colorMode = colorMode;
                    variant.lit = lit;
                    variant.compressedAttributes = compressed;
                    const DefineMap defines =
                        getDefinesOn(*GlyphStateCache::instance()->getStateSet(technique, variant));
                    if (std::find(lists.begin(), lists.end(), defines) == lists.end())
                        lists.push_back(defines);
                }
    return lists;
}

}

std::vector<LibraryProgram> shadervariants::collectLibraryPrograms()
{
    osgGlyphsPaper::registerTechniques();
    GlyphStateCache* cache = GlyphStateCache::instance();
    std::vector<LibraryProgram> programs;
    for (const std::string& name : getTechniqueNames())
    {
        osg::ref_ptr<GlyphTechnique> technique = createTechnique(name);
        programs.push_back({name, cache->getProgram(*technique), getVariantDefineLists(*technique)});
    }
    programs.push_back({"surface-shading", cache->getSurfaceProgram(), {{}}});
    programs.push_back({"screen-effects", cache->getScreenEffectsProgram(), {{}}});
    programs.push_back({"k-buffer-resolve", cache->getKBufferResolveProgram(), {{}}});
    programs.push_back({"peeling-composition", cache->getPeelingCompositeProgram(), {{}}});
    return programs;
}
