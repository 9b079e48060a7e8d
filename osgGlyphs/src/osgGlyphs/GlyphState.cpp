#include <osgGlyphs/GlyphState>

#include "ShaderSource.h"
#include "SpriteTextures.h"

#include <osg/ContextData>
#include <osg/GLObjects>
#include <osg/Point>
#include <osg/PointSprite>
#include <osg/Uniform>
#include <osg/VertexAttribDivisor>

using namespace osgGlyphs;

namespace
{

const char* const COLOR_SCALAR_DEFINE = "OSGGLYPHS_COLOR_SCALAR";
const char* const COLOR_RGBA_DEFINE = "OSGGLYPHS_COLOR_RGBA";

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

/** The define that selects a technique's code, or nullptr for the geometry-shader default. */
const char* techniqueDefine(GlyphTechnique technique)
{
    switch (technique)
    {
    case GlyphTechnique::Instanced:
        return "OSGGLYPHS_TECHNIQUE_INSTANCED";
    case GlyphTechnique::PointSprite:
        return "OSGGLYPHS_TECHNIQUE_SPRITE";
    case GlyphTechnique::PaperQuad:
        return "OSGGLYPHS_TECHNIQUE_PAPER";
    case GlyphTechnique::Polygons:
        return "OSGGLYPHS_TECHNIQUE_POLYGONS";
    case GlyphTechnique::TextureBlend:
        return "OSGGLYPHS_TECHNIQUE_TEXTURE_BLEND";
    case GlyphTechnique::TextureMulti:
        return "OSGGLYPHS_TECHNIQUE_TEXTURE_MULTI";
    case GlyphTechnique::PointsFloor:
        return "OSGGLYPHS_TECHNIQUE_POINTS";
    default:
        return nullptr;
    }
}

/** The colour map of a Scalar variant: its own or the default. */
const ColorMap* getColorMap(const GlyphVariant& variant)
{
    return variant.colorMap ? variant.colorMap : ColorMap::getBuiltin("viridis");
}

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

const char* osgGlyphs::getTechniqueName(GlyphTechnique technique)
{
    switch (technique)
    {
    case GlyphTechnique::GeometryShader:
        return "geometry-shader";
    case GlyphTechnique::Instanced:
        return "instanced";
    case GlyphTechnique::PointSprite:
        return "point-sprite";
    case GlyphTechnique::PaperQuad:
        return "paper-quad";
    case GlyphTechnique::Polygons:
        return "polygons";
    case GlyphTechnique::TextureBlend:
        return "texture-blend";
    case GlyphTechnique::TextureMulti:
        return "texture-multi";
    case GlyphTechnique::PointsFloor:
        return "points-floor";
    }
    return "unknown";
}

std::vector<GlyphTechnique> osgGlyphs::getTechniques()
{
    return {GlyphTechnique::GeometryShader, GlyphTechnique::Instanced,  GlyphTechnique::PointSprite,
            GlyphTechnique::PaperQuad,      GlyphTechnique::Polygons,   GlyphTechnique::TextureBlend,
            GlyphTechnique::TextureMulti,   GlyphTechnique::PointsFloor};
}

std::vector<std::string> osgGlyphs::getTechniqueNames()
{
    std::vector<std::string> names;
    for (GlyphTechnique technique : getTechniques())
        names.push_back(getTechniqueName(technique));
    return names;
}

bool osgGlyphs::parseTechnique(const std::string& name, GlyphTechnique& technique)
{
    if (name == "default")
    {
        technique = DEFAULT_GLYPH_TECHNIQUE;
        return true;
    }
    for (GlyphTechnique candidate : getTechniques())
    {
        if (name == getTechniqueName(candidate))
        {
            technique = candidate;
            return true;
        }
    }
    return false;
}

bool osgGlyphs::isTechniqueSupported(GlyphTechnique technique, GlyphShape shape)
{
    switch (technique)
    {
    case GlyphTechnique::PaperQuad:
        return shape == GlyphShape::Sphere || shape == GlyphShape::Cone;
    case GlyphTechnique::TextureBlend:
    case GlyphTechnique::TextureMulti:
        return shape == GlyphShape::Sphere; // the paper's textures are of spheres
    default:
        return true;
    }
}

const char* osgGlyphs::getShapeName(GlyphShape shape)
{
    switch (shape)
    {
    case GlyphShape::Cone:
        return "cone";
    case GlyphShape::Arrow:
        return "arrow";
    case GlyphShape::Cylinder:
        return "cylinder";
    default:
        return "sphere";
    }
}

bool osgGlyphs::parseShape(const std::string& name, GlyphShape& shape)
{
    for (GlyphShape candidate :
         {GlyphShape::Sphere, GlyphShape::Cone, GlyphShape::Arrow, GlyphShape::Cylinder})
    {
        if (name == getShapeName(candidate))
        {
            shape = candidate;
            return true;
        }
    }
    return false;
}

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

osg::Program* GlyphStateSets::getProgramLocked(bool geometryStage)
{
    osg::ref_ptr<osg::Program>& program = _programs[geometryStage ? 1 : 0];
    if (program)
        return program.get();
    program = new osg::Program;
    program->setName(geometryStage ? "osgGlyphs geometry-shader" : "osgGlyphs");
    for (const ShaderStage& stage : GLYPH_STAGES)
    {
        if (stage.type == osg::Shader::GEOMETRY && !geometryStage)
            continue;
        osg::ref_ptr<osg::Shader> shader = new osg::Shader(stage.type, detail::loadShaderSource(stage.file));
        shader->setName(stage.file);
        program->addShader(shader.get());
    }
    program->addBindAttribLocation("osgGlyphs_packed", PACKED_ATTRIBUTE);
    program->addBindAttribLocation("osgGlyphs_radiusScalar", PACKED_ATTRIBUTE); // uncompressed
    program->addBindAttribLocation("osgGlyphs_color", COLOR_ATTRIBUTE);
    program->addBindAttribLocation("osgGlyphs_vector", VECTOR_ATTRIBUTE);
    program->addBindAttribLocation("osgGlyphs_position", POSITION_ATTRIBUTE);
    program->addBindAttribLocation("osgGlyphs_corner", CORNER_ATTRIBUTE);
    return program.get();
}

osg::Program* GlyphStateSets::getProgram(GlyphTechnique technique)
{
    std::lock_guard<std::mutex> lock(_mutex);
    return getProgramLocked(technique == GlyphTechnique::GeometryShader);
}

osg::StateSet* GlyphStateSets::get(const GlyphVariant& variant)
{
    std::lock_guard<std::mutex> lock(_mutex);
    osg::ref_ptr<osg::StateSet>& stateSet = _stateSets[variant];
    if (stateSet)
        return stateSet.get();

    stateSet = new osg::StateSet;
    stateSet->setAttributeAndModes(getProgramLocked(variant.technique == GlyphTechnique::GeometryShader));
    if (const char* define = shapeDefine(variant.shape))
        stateSet->setDefine(define);
    if (const char* define = techniqueDefine(variant.technique))
        stateSet->setDefine(define);
    switch (variant.technique)
    {
    case GlyphTechnique::Instanced:
    case GlyphTechnique::Polygons:
        for (unsigned int index : {POSITION_ATTRIBUTE, PACKED_ATTRIBUTE, COLOR_ATTRIBUTE, VECTOR_ATTRIBUTE})
            stateSet->setAttribute(new osg::VertexAttribDivisor(index, 1));
        break;
    case GlyphTechnique::PointSprite:
    case GlyphTechnique::TextureBlend:
    case GlyphTechnique::TextureMulti:
        stateSet->setMode(GL_VERTEX_PROGRAM_POINT_SIZE, osg::StateAttribute::ON);
        stateSet->setTextureAttributeAndModes(MASK_UNIT, new osg::PointSprite, osg::StateAttribute::ON);
        break;
    default:
        break;
    }
    if (variant.technique == GlyphTechnique::TextureBlend)
    {
        stateSet->setTextureAttribute(MASK_UNIT, detail::createSpriteTexture(false));
        stateSet->setTextureAttribute(LIGHTING_UNIT, detail::createSpriteTexture(true));
        stateSet->addUniform(new osg::Uniform("osgGlyphs_maskTexture", static_cast<int>(MASK_UNIT)));
        stateSet->addUniform(new osg::Uniform("osgGlyphs_lightingTexture", static_cast<int>(LIGHTING_UNIT)));
    }
    if (variant.technique == GlyphTechnique::TextureMulti)
    {
        stateSet->setTextureAttribute(LIT_SPRITES_UNIT, getLitSpritesLocked(variant));
        stateSet->addUniform(new osg::Uniform("osgGlyphs_litSprites", static_cast<int>(LIT_SPRITES_UNIT)));
    }
    if (variant.lit)
        stateSet->setDefine(GLYPH_LIT_DEFINE);
    if (!variant.compressedAttributes)
        stateSet->setDefine("OSGGLYPHS_FLOAT_ATTRIBUTES");
    if (variant.colorMode == GlyphColorMode::RGBA)
        stateSet->setDefine(COLOR_RGBA_DEFINE);
    if (variant.colorMode == GlyphColorMode::Scalar)
    {
        stateSet->setDefine(COLOR_SCALAR_DEFINE);
        stateSet->setTextureAttribute(COLORMAP_UNIT, getColorMap(variant)->getTexture());
        stateSet->addUniform(new osg::Uniform("osgGlyphs_colormap", static_cast<int>(COLORMAP_UNIT)));
    }
    return stateSet.get();
}

osg::Texture* GlyphStateSets::getLitSpritesLocked(const GlyphVariant& variant)
{
    const ColorMap* colorMap = variant.colorMode == GlyphColorMode::Scalar ? getColorMap(variant) : nullptr;
    const osg::Vec4 color = variant.colorMode == GlyphColorMode::Uniform ? variant.color : osg::Vec4();
    osg::ref_ptr<osg::Texture>& sprites = _litSprites[LitSpritesKey(variant.colorMode, colorMap, color)];
    if (!sprites)
        sprites = detail::createLitSprites(variant.colorMode, colorMap, color);
    return sprites.get();
}

void GlyphStateSets::reloadShaders()
{
    std::lock_guard<std::mutex> lock(_mutex);
    for (const osg::ref_ptr<osg::Program>& program : _programs)
    {
        for (unsigned int i = 0; program && i < program->getNumShaders(); ++i)
        {
            osg::Shader* shader = program->getShader(i);
            shader->setShaderSource(detail::loadShaderSource(shader->getName()));
            shader->dirtyShader();
        }
    }
}

void GlyphStateSets::observeContext(unsigned int contextID)
{
    osg::get<GlyphContextObserver>(contextID);
}

void GlyphStateSets::releaseGLObjects(osg::State* state) const
{
    std::lock_guard<std::mutex> lock(_mutex);
    for (const osg::ref_ptr<osg::Program>& program : _programs)
        if (program)
            program->releaseGLObjects(state);
    for (const auto& entry : _stateSets)
        entry.second->releaseGLObjects(state);
}

void GlyphStateSets::resizeGLObjectBuffers(unsigned int maxSize)
{
    std::lock_guard<std::mutex> lock(_mutex);
    for (auto& entry : _stateSets)
        entry.second->resizeGLObjectBuffers(maxSize);
}
