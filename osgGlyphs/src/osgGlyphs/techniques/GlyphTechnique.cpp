#include <osgGlyphs/GlyphCloud>
#include <osgGlyphs/GlyphTechnique>
#include <osgGlyphs/ImpostorTechniques>

#include <mutex>

using namespace osgGlyphs;

const char* const osgGlyphs::DEFAULT_GLYPH_TECHNIQUE = "geometry-shader";

namespace
{

/** The techniques known by name, in order of registration. */
struct TechniqueRegistry
{
    std::mutex mutex;
    std::vector<osg::ref_ptr<GlyphTechnique>> prototypes{new GeometryShaderTechnique, new InstancedTechnique,
                                                         new PointSpriteTechnique};
};

TechniqueRegistry& getRegistry()
{
    static TechniqueRegistry registry;
    return registry;
}

}

void GlyphTechnique::buildPrimitives(GlyphCloud& cloud, const GlyphArrays& arrays) const
{
    attachGlyphArrays(cloud, arrays, GlyphAttributeRate::PerVertex);
    cloud.addPrimitiveSet(new osg::DrawArrays(GL_POINTS, 0, arrays.count));
}

void osgGlyphs::registerTechnique(GlyphTechnique* prototype)
{
    TechniqueRegistry& registry = getRegistry();
    std::lock_guard<std::mutex> lock(registry.mutex);
    for (osg::ref_ptr<GlyphTechnique>& existing : registry.prototypes)
    {
        if (std::string(existing->getTechniqueName()) == prototype->getTechniqueName())
        {
            existing = prototype;
            return;
        }
    }
    registry.prototypes.push_back(prototype);
}

osg::ref_ptr<GlyphTechnique> osgGlyphs::createTechnique(const std::string& name)
{
    const std::string wanted = name == "default" ? DEFAULT_GLYPH_TECHNIQUE : name;
    TechniqueRegistry& registry = getRegistry();
    std::lock_guard<std::mutex> lock(registry.mutex);
    for (const osg::ref_ptr<GlyphTechnique>& prototype : registry.prototypes)
        if (wanted == prototype->getTechniqueName())
            return static_cast<GlyphTechnique*>(prototype->clone(osg::CopyOp::DEEP_COPY_ALL));
    return nullptr;
}

std::vector<std::string> osgGlyphs::getTechniqueNames()
{
    TechniqueRegistry& registry = getRegistry();
    std::lock_guard<std::mutex> lock(registry.mutex);
    std::vector<std::string> names;
    for (const osg::ref_ptr<GlyphTechnique>& prototype : registry.prototypes)
        names.push_back(prototype->getTechniqueName());
    return names;
}

GlyphTechnique* osgGlyphs::getDefaultTechnique()
{
    static osg::ref_ptr<GlyphTechnique> s_default = new GeometryShaderTechnique;
    return s_default.get();
}
