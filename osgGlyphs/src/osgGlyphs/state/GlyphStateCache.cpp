#include <osgGlyphs/GlyphStateCache>

#include <osgGlyphs/GlyphCloud>

#include "../culling/OcclusionContext.h"
#include "ContextRelease.h"
#include "GlyphDefines.h"
#include "GlyphProgram.h"

#include <osg/ContextData>
#include <osg/GLObjects>
#include <osg/Uniform>

#include <atomic>

using namespace osgGlyphs;

namespace
{

/** How many times a context's glyph state was released: after one, a context ID seen before may
 * belong to a new context, with a ContextData of its own. */
std::atomic<unsigned int> s_contextReleases{0};

/** Lives in a context's osg::ContextData: when OSG deletes or discards that context's GL
 * objects, it releases the shared glyph state of that context, which no scene graph under
 * the context's cameras may reach any more (a later context could reuse the ID). */
class GlyphContextObserver : public detail::ContextRelease
{
public:
    explicit GlyphContextObserver(unsigned int contextID)
        : detail::ContextRelease("osgGlyphs::GlyphContextObserver", contextID)
    {
    }

protected:
    ~GlyphContextObserver() override { ++s_contextReleases; }

    void releaseContext() override
    {
        osg::ref_ptr<osg::State> state = new osg::State;
        state->setContextID(getContextID());
        GlyphStateCache::instance()->releaseGLObjects(state.get());
        ++s_contextReleases;
    }
};

/** The generated files the technique's shaders include. */
std::map<std::string, std::string> generatedSources(const GlyphTechnique& technique)
{
    return {{"osgGlyphs/defines.glsl", detail::generateDefinesGlsl()},
            {"osgGlyphs/attributes.glsl", detail::generateAttributesGlsl(technique)}};
}

}

void osgGlyphs::setGlyphLighting(osg::StateSet& stateSet, bool lit)
{
    stateSet.setDefine(GLYPH_LIT_DEFINE, osg::StateAttribute::OVERRIDE |
                                             (lit ? osg::StateAttribute::ON : osg::StateAttribute::OFF));
}

void osgGlyphs::setClipCaps(osg::StateSet& stateSet, bool capped)
{
    stateSet.setDefine(GLYPH_CLIP_CAPS_DEFINE, capped ? osg::StateAttribute::ON : osg::StateAttribute::OFF);
}

void osgGlyphs::setGlyphShadows(osg::StateSet& stateSet, bool receive, unsigned int shadowTextureUnit)
{
    const unsigned int TEXGEN_UNITS = 8; // gl_EyePlaneS[] of the compatibility profile
    if (receive && shadowTextureUnit >= TEXGEN_UNITS)
    {
        OSG_WARN << "osgGlyphs: setGlyphShadows: shadow texture unit " << shadowTextureUnit
                 << " has no TexGen planes (units 0 to " << TEXGEN_UNITS - 1
                 << " do); glyphs receive no shadows" << std::endl;
        receive = false;
    }
    stateSet.setDefine(GLYPH_SHADOWS_DEFINE, receive ? osg::StateAttribute::ON : osg::StateAttribute::OFF);
    if (!receive)
    {
        stateSet.removeUniform("osgGlyphs_shadowMap");
        stateSet.removeUniform("osgGlyphs_shadowUnit");
        return;
    }
    const int unit = static_cast<int>(shadowTextureUnit);
    stateSet.addUniform(new osg::Uniform("osgGlyphs_shadowMap", unit));
    stateSet.addUniform(new osg::Uniform("osgGlyphs_shadowUnit", unit));
}

void osgGlyphs::setSurfaceShading(osg::StateSet& stateSet)
{
    stateSet.setAttributeAndModes(GlyphStateCache::instance()->getSurfaceProgram());
    stateSet.setDefine(GLYPH_LIT_DEFINE);
    stateSet.addUniform(new osg::Uniform("osgGlyphs_material", GlyphCloud::getDefaultMaterial()));
}

void osgGlyphs::setGlyphAmbientOcclusion(osg::StateSet& stateSet, bool on)
{
    if (on)
        stateSet.removeDefine(GLYPH_AMBIENT_OCCLUSION_DEFINE);
    else
        stateSet.setDefine(GLYPH_AMBIENT_OCCLUSION_DEFINE,
                           osg::StateAttribute::OVERRIDE | osg::StateAttribute::OFF);
}

GlyphStateCache* GlyphStateCache::instance()
{
    static osg::ref_ptr<GlyphStateCache> s_instance = new GlyphStateCache;
    return s_instance.get();
}

osg::Program* GlyphStateCache::getProgramLocked(const GlyphTechnique& technique)
{
    osg::ref_ptr<osg::Program>& program = _programs[technique.getTechniqueName()];
    if (program)
        return program.get();
    program = new detail::GlyphProgram(technique, generatedSources(technique),
                                       [this](const std::string& error) { reportProgramError(error); });
    for (const GlyphAttributeBinding& attribute : detail::getProgramAttributes(technique))
        program->addBindAttribLocation(attribute.name, attribute.location);
    return program.get();
}

osg::Program* GlyphStateCache::getProgram(const GlyphTechnique& technique)
{
    std::lock_guard<std::mutex> lock(_mutex);
    return getProgramLocked(technique);
}

osg::Program* GlyphStateCache::getFileProgram(const std::string& name, const std::string& vertexFile,
                                              const std::string& fragmentFile, bool withDefines)
{
    std::lock_guard<std::mutex> lock(_mutex);
    osg::ref_ptr<osg::Program>& program = _programs[name];
    if (!program)
    {
        std::map<std::string, std::string> generated;
        if (withDefines)
            generated["osgGlyphs/defines.glsl"] = detail::generateDefinesGlsl();
        program = new detail::GlyphProgram(
            name, {{osg::Shader::VERTEX, vertexFile}, {osg::Shader::FRAGMENT, fragmentFile}}, generated,
            [this](const std::string& error) { reportProgramError(error); });
    }
    return program.get();
}

// The names are not techniques' names: those are single words.
osg::Program* GlyphStateCache::getSurfaceProgram()
{
    return getFileProgram("surface shading", "osgGlyphs/surface.vert", "osgGlyphs/surface.frag", true);
}

osg::Program* GlyphStateCache::getScreenEffectsProgram()
{
    return getFileProgram("screen effects", "osgGlyphs/fullscreen.vert", "osgGlyphs/screen-effects.frag",
                          false);
}

osg::Program* GlyphStateCache::getKBufferResolveProgram()
{
    return getFileProgram("k-buffer resolve", "osgGlyphs/fullscreen.vert", "osgGlyphs/k-buffer-resolve.frag",
                          false);
}

osg::Program* GlyphStateCache::getPeelingCompositeProgram()
{
    return getFileProgram("peeling composition", "osgGlyphs/fullscreen.vert", "osgGlyphs/peel-composite.frag",
                          false);
}

osg::ref_ptr<osg::StateSet> GlyphStateCache::getStateSet(const GlyphTechnique& technique,
                                                         const GlyphVariant& requested)
{
    // Fields the technique does not draw with are reset, so that clouds differing there share.
    GlyphVariant variant = requested;
    variant.lit = requested.lit && technique.usesLighting();
    if (variant.colorMode != GlyphColorMode::Scalar)
        variant.colorMap = nullptr;
    else if (!variant.colorMap)
        variant.colorMap = ColorMap::getBuiltin("viridis");
    if (!technique.usesVariantColor() || variant.colorMode != GlyphColorMode::Uniform)
        variant.color = osg::Vec4();
    const Key key(technique.getTechniqueName(), variant.shape, variant.colorMode, variant.lit,
                  variant.compressedAttributes, variant.colorMap ? variant.colorMap->getSerialNumber() : 0,
                  variant.color);

    std::lock_guard<std::mutex> lock(_mutex);
    osg::observer_ptr<osg::StateSet>& entry = _stateSets[key];
    osg::ref_ptr<osg::StateSet> stateSet;
    if (entry.lock(stateSet))
        return stateSet;
    stateSet = createStateSet(technique, variant);
    entry = stateSet;
    if (_stateSets.size() >= _pruneAt)
    {
        pruneLocked();
        _pruneAt = std::max<std::size_t>(64, 2 * _stateSets.size());
    }
    return stateSet;
}

osg::ref_ptr<osg::StateSet> GlyphStateCache::createStateSet(const GlyphTechnique& technique,
                                                            const GlyphVariant& variant)
{
    osg::ref_ptr<osg::StateSet> stateSet = new osg::StateSet;
    stateSet->setName(std::string("osgGlyphs ") + technique.getTechniqueName());
    stateSet->setAttributeAndModes(getProgramLocked(technique));
    // Impostors face the camera: a culling of front faces, as shadow cameras OVERRIDE, removes them.
    stateSet->setMode(GL_CULL_FACE, osg::StateAttribute::OFF | osg::StateAttribute::PROTECTED);
    for (const std::string& define : detail::getVariantDefines(variant))
        stateSet->setDefine(define);
    if (variant.colorMode == GlyphColorMode::Scalar)
    {
        stateSet->setTextureAttribute(COLORMAP_TEXTURE_UNIT, variant.colorMap->getTexture());
        stateSet->addUniform(new osg::Uniform("osgGlyphs_colormap", static_cast<int>(COLORMAP_TEXTURE_UNIT)));
    }
    // The depth pyramid of occlusion culling is bound while a cloud draws (ChunkDrawer).
    stateSet->addUniform(
        new osg::Uniform("osgGlyphs_depthPyramid", static_cast<int>(DEPTH_PYRAMID_TEXTURE_UNIT)));
    technique.configureStateSet(*stateSet, variant);
    return stateSet;
}

unsigned int GlyphStateCache::getNumStateSets() const
{
    std::lock_guard<std::mutex> lock(_mutex);
    unsigned int alive = 0;
    for (const auto& entry : _stateSets)
        alive += entry.second.valid() ? 1 : 0;
    return alive;
}

void GlyphStateCache::prune()
{
    std::lock_guard<std::mutex> lock(_mutex);
    pruneLocked();
}

void GlyphStateCache::pruneLocked()
{
    for (auto entry = _stateSets.begin(); entry != _stateSets.end();)
        entry = entry->second.valid() ? std::next(entry) : _stateSets.erase(entry);
}

void GlyphStateCache::reloadShaders()
{
    {
        std::lock_guard<std::mutex> lock(_mutex);
        for (const auto& entry : _programs)
            static_cast<detail::GlyphProgram&>(*entry.second).reloadShaders();
    }
    std::lock_guard<std::mutex> lock(_programErrorMutex);
    _programError.clear();
}

std::string GlyphStateCache::getProgramError() const
{
    std::lock_guard<std::mutex> lock(_programErrorMutex);
    return _programError;
}

void GlyphStateCache::reportProgramError(const std::string& error)
{
    OSG_WARN << "osgGlyphs: " << error << std::endl;
    std::lock_guard<std::mutex> lock(_programErrorMutex);
    if (_programError.empty())
        _programError = error;
}

void GlyphStateCache::observeContext(unsigned int contextID)
{
    // The context registry takes a lock: each thread looks again only for another context, or
    // once a context was released. Keyed by the visitor's address and traversal instead, a
    // later viewer whose visitor came at the same address missed its new context's observer.
    thread_local std::pair<unsigned int, unsigned int> observed(~0u, ~0u);
    const std::pair<unsigned int, unsigned int> context(contextID, s_contextReleases.load());
    if (observed == context)
        return;
    osg::get<GlyphContextObserver>(contextID);
    // Made before the context's first draw: its draw thread only looks it up, while cull
    // threads look up the context's other objects.
    osg::get<detail::OcclusionContext>(contextID);
    observed = context;
}

void GlyphStateCache::releaseGLObjects(osg::State* state) const
{
    std::lock_guard<std::mutex> lock(_mutex);
    for (const auto& entry : _programs)
        entry.second->releaseGLObjects(state);
    for (const auto& entry : _stateSets)
    {
        osg::ref_ptr<osg::StateSet> stateSet;
        if (entry.second.lock(stateSet))
            stateSet->releaseGLObjects(state);
    }
}

void GlyphStateCache::resizeGLObjectBuffers(unsigned int maxSize)
{
    std::lock_guard<std::mutex> lock(_mutex);
    for (auto& entry : _programs)
        entry.second->resizeGLObjectBuffers(maxSize);
    for (auto& entry : _stateSets)
    {
        osg::ref_ptr<osg::StateSet> stateSet;
        if (entry.second.lock(stateSet))
            stateSet->resizeGLObjectBuffers(maxSize);
    }
}
