#include <osgGlyphsPaper/Techniques>

#include <osgGlyphs/GlyphStateCache>

namespace osgGlyphs
{
namespace detail
{
/** The embedded copies of shaders/osgGlyphsPaper, generated at build time. */
const char* getEmbeddedPaperShader(const std::string& name);
}
}

namespace
{

/** The shaders are there as soon as the library is: a technique used without registerTechniques()
 * still finds them. */
struct EmbeddedShaderRegistration
{
    EmbeddedShaderRegistration()
    {
        osgGlyphs::registerEmbeddedShaders("osgGlyphsPaper", &osgGlyphs::detail::getEmbeddedPaperShader);
    }
} s_embeddedShaders;

}

void osgGlyphsPaper::registerTechniques()
{
    for (osgGlyphs::GlyphTechnique* technique : std::initializer_list<osgGlyphs::GlyphTechnique*>{
             new PaperQuadTechnique, new PolygonsTechnique, new TextureBlendTechnique,
             new TextureMultiTechnique, new PointsFloorTechnique})
        osgGlyphs::registerTechnique(technique);
}
