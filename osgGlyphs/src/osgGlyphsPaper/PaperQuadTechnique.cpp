#include <osgGlyphsPaper/Techniques>

#include <osgGlyphs/GlyphCloud>

using namespace osgGlyphs;
using namespace osgGlyphsPaper;

namespace
{

const unsigned int CORNER_ATTRIBUTE = FIRST_TECHNIQUE_ATTRIBUTE;

/** The same per-glyph values four times, for billboards of four vertices. */
template <class ArrayType>
osg::ref_ptr<ArrayType> repeatFourTimes(const ArrayType* array, unsigned int count)
{
    if (!array)
        return nullptr;
    osg::ref_ptr<ArrayType> repeated = new ArrayType;
    repeated->reserve(4 * count);
    for (unsigned int i = 0; i < count; ++i)
        repeated->insert(repeated->end(), 4, (*array)[i]);
    repeated->setNormalize(array->getNormalize());
    repeated->setPreserveDataType(array->getPreserveDataType());
    return repeated;
}

osg::ref_ptr<osg::Array> repeatFourTimes(const osg::Array* array, unsigned int count)
{
    if (const osg::UIntArray* words = dynamic_cast<const osg::UIntArray*>(array))
        return repeatFourTimes(words, count);
    if (const osg::Vec3Array* vectors = dynamic_cast<const osg::Vec3Array*>(array))
        return repeatFourTimes(vectors, count);
    if (const osg::Vec3sArray* quantised = dynamic_cast<const osg::Vec3sArray*>(array))
        return repeatFourTimes(quantised, count);
    return repeatFourTimes(dynamic_cast<const osg::Vec2Array*>(array), count);
}

}

bool PaperQuadTechnique::supportsShape(GlyphShape shape) const
{
    return shape == GlyphShape::Sphere || shape == GlyphShape::Cone;
}

std::vector<GlyphShaderFile> PaperQuadTechnique::getShaderFiles() const
{
    return {{osg::Shader::VERTEX, "osgGlyphsPaper/paper-quad.vert"},
            {osg::Shader::FRAGMENT, "osgGlyphsPaper/paper-quad.frag"}};
}

std::vector<GlyphAttributeBinding> PaperQuadTechnique::getTechniqueAttributes() const
{
    return {{"osgGlyphs_corner", CORNER_ATTRIBUTE, "vec2", ""}};
}

void PaperQuadTechnique::buildPrimitives(GlyphCloud& cloud, const GlyphArrays& arrays) const
{
    // The paper's data path: four vertices per glyph, each with a copy of its attributes.
    GlyphArrays copies;
    osg::ref_ptr<osg::Array> positions = repeatFourTimes(arrays.positions, arrays.count);
    osg::ref_ptr<osg::Array> radiusScalar = repeatFourTimes(arrays.radiusScalar, arrays.count);
    osg::ref_ptr<osg::Vec4ubArray> colors = repeatFourTimes(arrays.colors, arrays.count);
    osg::ref_ptr<osg::Vec3Array> vectors = repeatFourTimes(arrays.vectors, arrays.count);
    copies.positions = positions.get();
    copies.radiusScalar = radiusScalar.get();
    copies.colors = colors.get();
    copies.vectors = vectors.get();
    copies.count = 4 * arrays.count;
    attachGlyphArrays(cloud, copies, GlyphAttributeRate::PerVertex);

    osg::ref_ptr<osg::Vec2Array> corners = new osg::Vec2Array;
    corners->reserve(4 * arrays.count);
    for (unsigned int i = 0; i < arrays.count; ++i)
        for (const osg::Vec2& corner :
             {osg::Vec2(-1, -1), osg::Vec2(1, -1), osg::Vec2(1, 1), osg::Vec2(-1, 1)})
            corners->push_back(corner);
    corners->setBinding(osg::Array::BIND_PER_VERTEX);
    cloud.setVertexAttribArray(CORNER_ATTRIBUTE, corners.get());
    cloud.addPrimitiveSet(new osg::DrawArrays(GL_QUADS, 0, 4 * arrays.count));
}
