#include <osgGlyphs/GlyphState>

#include "ShaderSource.h"

#include <osg/ContextData>
#include <osg/GLObjects>
#include <osg/Uniform>

using namespace osgGlyphs;

namespace
{

const char* const COLOR_SCALAR_DEFINE = "OSGGLYPHS_COLOR_SCALAR";
const char* const COLOR_RGBA_DEFINE = "OSGGLYPHS_COLOR_RGBA";
const char* const PAPER_DEFINE = "OSGGLYPHS_PAPER";

/** The define that selects a shape's code, or nullptr for spheres. */
const char* shapeDefine(GlyphShape shape)
{
    switch (shape)
    {
    case GlyphShape::Cone:
        return "OSGGLYPHS_SHAPE_CONE";
    case GlyphShape::Arrow:
        return "OSGGLYPHS_SHAPE_ARROW";
    case GlyphShape::Cylinder:
        return "OSGGLYPHS_SHAPE_CYLINDER";
    default:
        return nullptr;
    }
}

struct ShaderStage
{
    osg::Shader::Type type;
    const char* file;
};

const ShaderStage GLYPH_STAGES[] = {{osg::Shader::VERTEX, "glyph.vert"},
                                    {osg::Shader::GEOMETRY, "glyph.geom"},
                                    {osg::Shader::FRAGMENT, "glyph.frag"}};

/** Lives in a context's osg::ContextData: when OSG deletes or discards that context's GL
 * objects, it releases the shared glyph state of that context, which no scene graph under
 * the context's cameras may reach any more (a later context could reuse the ID). */
class GlyphContextObserver : public osg::GraphicsObjectManager
{
public:
    explicit GlyphContextObserver(unsigned int contextID)
        : osg::GraphicsObjectManager("osgGlyphs::GlyphContextObserver", contextID)
    {
    }
    void flushDeletedGLObjects(double, double&) override {}
    void flushAllDeletedGLObjects() override {}
    void deleteAllGLObjects() override { release(); }
    void discardAllGLObjects() override { release(); }

private:
    void release()
    {
        osg::ref_ptr<osg::State> state = new osg::State;
        state->setContextID(getContextID());
        GlyphStateSets::instance()->releaseGLObjects(state.get());
    }
};

}

const char* const osgGlyphs::GLYPH_LIT_DEFINE = "OSGGLYPHS_LIT";

void osgGlyphs::setGlyphLighting(osg::StateSet& stateSet, bool lit)
{
    stateSet.setDefine(GLYPH_LIT_DEFINE, osg::StateAttribute::OVERRIDE |
                                             (lit ? osg::StateAttribute::ON : osg::StateAttribute::OFF));
}

GlyphStateSets* GlyphStateSets::instance()
{
    static osg::ref_ptr<GlyphStateSets> s_instance = new GlyphStateSets;
    return s_instance.get();
}

osg::Program* GlyphStateSets::getProgramLocked()
{
    if (_program)
        return _program.get();
    _program = new osg::Program;
    _program->setName("osgGlyphs");
    for (const ShaderStage& stage : GLYPH_STAGES)
    {
        osg::ref_ptr<osg::Shader> shader = new osg::Shader(stage.type, detail::loadShaderSource(stage.file));
        shader->setName(stage.file);
        _program->addShader(shader.get());
    }
    _program->addBindAttribLocation("osgGlyphs_packed", PACKED_ATTRIBUTE);
    _program->addBindAttribLocation("osgGlyphs_color", COLOR_ATTRIBUTE);
    _program->addBindAttribLocation("osgGlyphs_vector", VECTOR_ATTRIBUTE);
    return _program.get();
}

osg::Program* GlyphStateSets::getProgram()
{
    std::lock_guard<std::mutex> lock(_mutex);
    return getProgramLocked();
}

osg::StateSet* GlyphStateSets::get(const GlyphVariant& variant)
{
    std::lock_guard<std::mutex> lock(_mutex);
    osg::ref_ptr<osg::StateSet>& stateSet = _stateSets[variant];
    if (stateSet)
        return stateSet.get();

    stateSet = new osg::StateSet;
    stateSet->setAttributeAndModes(getProgramLocked());
    if (const char* define = shapeDefine(variant.shape))
        stateSet->setDefine(define);
    if (variant.technique == GlyphTechnique::Paper && variant.shape == GlyphShape::Cone)
        stateSet->setDefine(PAPER_DEFINE);
    if (variant.lit)
        stateSet->setDefine(GLYPH_LIT_DEFINE);
    if (variant.colorMode == GlyphColorMode::RGBA)
        stateSet->setDefine(COLOR_RGBA_DEFINE);
    if (variant.colorMode == GlyphColorMode::Scalar)
    {
        stateSet->setDefine(COLOR_SCALAR_DEFINE);
        const ColorMap* colorMap = variant.colorMap ? variant.colorMap : ColorMap::getBuiltin("viridis");
        stateSet->setTextureAttribute(COLORMAP_UNIT, colorMap->getTexture());
        stateSet->addUniform(new osg::Uniform("osgGlyphs_colormap", static_cast<int>(COLORMAP_UNIT)));
    }
    return stateSet.get();
}

void GlyphStateSets::reloadShaders()
{
    std::lock_guard<std::mutex> lock(_mutex);
    for (unsigned int i = 0; _program && i < _program->getNumShaders(); ++i)
    {
        osg::Shader* shader = _program->getShader(i);
        shader->setShaderSource(detail::loadShaderSource(shader->getName()));
        shader->dirtyShader();
    }
}

void GlyphStateSets::observeContext(unsigned int contextID)
{
    osg::get<GlyphContextObserver>(contextID);
}

void GlyphStateSets::releaseGLObjects(osg::State* state) const
{
    std::lock_guard<std::mutex> lock(_mutex);
    if (_program)
        _program->releaseGLObjects(state);
    for (const auto& entry : _stateSets)
        entry.second->releaseGLObjects(state);
}

void GlyphStateSets::resizeGLObjectBuffers(unsigned int maxSize)
{
    std::lock_guard<std::mutex> lock(_mutex);
    for (auto& entry : _stateSets)
        entry.second->resizeGLObjectBuffers(maxSize);
}
