#include <osgGlyphs/GlyphCloud>

#include "HalfFloat.h"

#include <osg/Notify>
#include <osg/RenderInfo>

#include <algorithm>
#include <cmath>
#include <limits>

using namespace osgGlyphs;

namespace
{

bool isFinite(const osg::Vec3& v)
{
    return std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z());
}

/** A packed word: the half-float radius in the low 16 bits, the quantised scalar above. */
uint32_t pack(uint16_t halfRadius, uint32_t quantisedScalar)
{
    return static_cast<uint32_t>(halfRadius) | (quantisedScalar << 16);
}

const uint16_t HALF_ONE = 0x3c00;

}

GlyphCloud::GlyphCloud()
{
    initialize();
}

GlyphCloud::GlyphCloud(const GlyphCloud& other, const osg::CopyOp& copyop)
    : osg::Geometry(other, copyop), _colorMap(other._colorMap), _radius(other._radius), _color(other._color),
      _colorMode(other._colorMode), _shape(other._shape), _technique(other._technique),
      _anchor(other._anchor), _lengthScale(other._lengthScale), _uniformLength(other._uniformLength),
      _arrowParams(other._arrowParams), _lit(other._lit), _autoRange(other._autoRange),
      _rangeMin(other._rangeMin), _rangeMax(other._rangeMax), _material(other._material)
{
    // osg::Geometry copied (or shared) the arrays it draws; pick them up again by their role.
    _positions = dynamic_cast<osg::Vec3Array*>(getVertexArray());
    _packed = dynamic_cast<osg::UIntArray*>(getVertexAttribArray(GlyphStateSets::PACKED_ATTRIBUTE));
    _colors = dynamic_cast<osg::Vec4ubArray*>(getVertexAttribArray(GlyphStateSets::COLOR_ATTRIBUTE));
    _vectors = dynamic_cast<osg::Vec3Array*>(getVertexAttribArray(GlyphStateSets::VECTOR_ATTRIBUTE));
    if (!_vectors && other._vectors.valid())
        _vectors = osg::clone(other._vectors.get(), copyop); // held but not drawn by a sphere cloud
    _radii = other._radii.valid() ? osg::clone(other._radii.get(), copyop) : nullptr;
    _scalars = other._scalars.valid() ? osg::clone(other._scalars.get(), copyop) : nullptr;
    _drawArrays = getNumPrimitiveSets() ? dynamic_cast<osg::DrawArrays*>(getPrimitiveSet(0)) : nullptr;
    initialize();
}

void GlyphCloud::initialize()
{
    setUseDisplayList(false);
    setUseVertexBufferObjects(true);
    if (!_drawArrays)
    {
        removePrimitiveSet(0, getNumPrimitiveSets());
        _drawArrays = new osg::DrawArrays(GL_POINTS, 0, 0);
        addPrimitiveSet(_drawArrays.get());
    }
    if (!_packed)
    {
        _packed = new osg::UIntArray;
        _packed->setPreserveDataType(true); // an integer attribute: glVertexAttribIPointer
        _packed->setBinding(osg::Array::BIND_PER_VERTEX);
        setVertexAttribArray(GlyphStateSets::PACKED_ATTRIBUTE, _packed.get());
    }
    // Uniforms are per cloud: each copy gets its own.
    _radiusScaleUniform = new osg::Uniform("osgGlyphs_radiusScale", 1.0f);
    _baseColorUniform = new osg::Uniform("osgGlyphs_baseColor", _color);
    _scalarToColormapUniform = new osg::Uniform("osgGlyphs_scalarToColormap", osg::Vec2(0.0f, 0.0f));
    _materialUniform = new osg::Uniform("osgGlyphs_material", _material);
    _vectorParamsUniform = new osg::Uniform("osgGlyphs_vectorParams", osg::Vec3());
    _arrowParamsUniform = new osg::Uniform("osgGlyphs_arrowParams", _arrowParams);
    updateVectorUniforms();
    if (!_colorMap)
        _colorMap = ColorMap::getBuiltin("viridis");
    updatePackedAttributes();
    updateStateSet();
}

void GlyphCloud::setPositions(osg::Vec3Array* positions)
{
    _positions = positions;
    setVertexArray(positions);
    dirtyGlyphs();
}

void GlyphCloud::setRadius(float radius)
{
    _radius = radius;
    _radii = nullptr;
    dirtyGlyphs();
}

void GlyphCloud::setRadii(osg::FloatArray* radii)
{
    _radii = radii;
    dirtyGlyphs();
}

void GlyphCloud::setColor(const osg::Vec4& color)
{
    _color = color;
    _baseColorUniform->set(color);
    if (_colorMode != GlyphColorMode::Uniform)
    {
        _colorMode = GlyphColorMode::Uniform;
        _colors = nullptr;
        _scalars = nullptr;
        setVertexAttribArray(GlyphStateSets::COLOR_ATTRIBUTE, nullptr);
        dirtyGlyphs();
        updateStateSet();
    }
}

void GlyphCloud::setColors(osg::Vec4ubArray* colors)
{
    _colors = colors;
    _scalars = nullptr;
    _colorMode = colors ? GlyphColorMode::RGBA : GlyphColorMode::Uniform;
    if (colors)
    {
        colors->setNormalize(true);
        colors->setBinding(osg::Array::BIND_PER_VERTEX);
    }
    setVertexAttribArray(GlyphStateSets::COLOR_ATTRIBUTE, colors);
    dirtyGlyphs();
    updateStateSet();
}

void GlyphCloud::setScalars(osg::FloatArray* scalars)
{
    _scalars = scalars;
    _colors = nullptr;
    setVertexAttribArray(GlyphStateSets::COLOR_ATTRIBUTE, nullptr);
    _colorMode = scalars ? GlyphColorMode::Scalar : GlyphColorMode::Uniform;
    dirtyGlyphs();
    updateStateSet();
}

void GlyphCloud::setShape(GlyphShape shape)
{
    _shape = shape;
    setVertexAttribArray(GlyphStateSets::VECTOR_ATTRIBUTE, hasVectorShape() ? _vectors.get() : nullptr);
    dirtyGlyphs();
    updateStateSet();
}

void GlyphCloud::setTechnique(GlyphTechnique technique)
{
    _technique = technique;
    updateStateSet();
}

void GlyphCloud::setVectors(osg::Vec3Array* vectors)
{
    _vectors = vectors;
    if (vectors)
        vectors->setBinding(osg::Array::BIND_PER_VERTEX);
    // Only vector shapes upload the vectors.
    setVertexAttribArray(GlyphStateSets::VECTOR_ATTRIBUTE, hasVectorShape() ? vectors : nullptr);
    dirtyGlyphs();
}

void GlyphCloud::setLengthScale(float lengthScale)
{
    _lengthScale = lengthScale;
    updateVectorUniforms();
    dirtyBound();
}

void GlyphCloud::setUniformLength(bool uniformLength)
{
    _uniformLength = uniformLength;
    updateVectorUniforms();
    dirtyBound();
}

void GlyphCloud::setAnchor(GlyphAnchor anchor)
{
    _anchor = anchor;
    updateVectorUniforms();
    dirtyBound();
}

void GlyphCloud::setArrowHead(float lengthRatio, float radiusRatio)
{
    _arrowParams.set(lengthRatio, radiusRatio);
    _arrowParamsUniform->set(_arrowParams);
    dirtyBound();
}

void GlyphCloud::updateVectorUniforms()
{
    const float anchor = _anchor == GlyphAnchor::Tail ? 0.0f : _anchor == GlyphAnchor::Head ? 1.0f : 0.5f;
    _vectorParamsUniform->set(osg::Vec3(_lengthScale, _uniformLength ? 1.0f : 0.0f, anchor));
}

void GlyphCloud::setColorMap(ColorMap* colorMap)
{
    _colorMap = colorMap ? colorMap : ColorMap::getBuiltin("viridis");
    updateStateSet();
}

void GlyphCloud::setScalarRange(float min, float max)
{
    _autoRange = false;
    _rangeMin = min;
    _rangeMax = max;
    updateScalarMapping();
}

void GlyphCloud::resetScalarRange()
{
    _autoRange = true;
    _rangeMin = _dataMin;
    _rangeMax = _dataMax;
    updateScalarMapping();
}

void GlyphCloud::setLit(bool lit)
{
    _lit = lit;
    updateStateSet();
}

void GlyphCloud::setMaterial(float ambient, float specular, float shininess)
{
    _material.set(ambient, specular, shininess);
    _materialUniform->set(_material);
}

void GlyphCloud::dirtyGlyphs()
{
    updatePackedAttributes();
    dirtyBound();
}

void GlyphCloud::updatePackedAttributes()
{
    const size_t numPositions = _positions.valid() ? _positions->size() : 0;
    size_t count = numPositions;
    auto limit = [&](const osg::Array* array, const char* what)
    {
        if (array && array->getNumElements() != numPositions)
        {
            OSG_WARN << "osgGlyphs::GlyphCloud \"" << getName() << "\": the " << what << " array has "
                     << array->getNumElements() << " values for " << numPositions
                     << " positions; only the first " << std::min<size_t>(count, array->getNumElements())
                     << " glyphs are drawn" << std::endl;
            count = std::min<size_t>(count, array->getNumElements());
        }
    };
    limit(_radii.get(), "radius");
    limit(_colors.get(), "colour");
    limit(_scalars.get(), "scalar");
    if (hasVectorShape())
    {
        if (!_vectors.valid() && numPositions)
            OSG_INFO << "osgGlyphs::GlyphCloud \"" << getName()
                     << "\": vector glyphs without vectors; nothing is drawn" << std::endl;
        count = _vectors.valid() ? count : 0;
        limit(_vectors.get(), "vector");
    }

    // The range the scalars are quantised over: their finite minimum and maximum.
    _dataMin = std::numeric_limits<float>::max();
    _dataMax = std::numeric_limits<float>::lowest();
    if (_scalars.valid())
    {
        for (size_t i = 0; i < count; ++i)
        {
            const float s = (*_scalars)[i];
            if (std::isfinite(s))
            {
                _dataMin = std::min(_dataMin, s);
                _dataMax = std::max(_dataMax, s);
            }
        }
    }
    if (_dataMin > _dataMax)
        _dataMin = _dataMax = 0.0f;

    // Radii are stored relative to the largest, which keeps half floats precise at any scale.
    _radiusScale = _radius;
    if (_radii.valid())
    {
        _radiusScale = 0.0f;
        for (size_t i = 0; i < count; ++i)
        {
            if (std::isfinite((*_radii)[i]))
                _radiusScale = std::max(_radiusScale, (*_radii)[i]);
        }
    }
    const bool radiusValid = std::isfinite(_radiusScale) && _radiusScale > 0.0f;

    unsigned int badPositions = 0, badRadii = 0, badScalars = 0, badVectors = 0, zeroVectors = 0;
    const double quantisationScale =
        _dataMax > _dataMin ? 65535.0 / (double(_dataMax) - double(_dataMin)) : 0.0;
    std::vector<uint32_t> packed(count);
    for (size_t i = 0; i < count; ++i)
    {
        uint16_t halfRadius = HALF_ONE;
        if (_radii.valid())
        {
            const float r = (*_radii)[i];
            halfRadius = (std::isfinite(r) && r > 0.0f) ? detail::toHalf(r / _radiusScale) : 0;
        }
        badRadii += (halfRadius == 0 || !radiusValid) ? 1 : 0;

        uint32_t quantised = 0;
        if (_scalars.valid())
        {
            const float s = (*_scalars)[i];
            if (std::isfinite(s))
                quantised = static_cast<uint32_t>(std::lround((double(s) - _dataMin) * quantisationScale));
            else
            {
                ++badScalars;
                halfRadius = 0;
            }
        }
        if (!isFinite((*_positions)[i]))
        {
            ++badPositions;
            halfRadius = 0;
        }
        if (hasVectorShape())
        {
            const osg::Vec3& v = (*_vectors)[i];
            if (!isFinite(v))
            {
                ++badVectors;
                halfRadius = 0;
            }
            else if (v.length2() == 0.0f)
            {
                ++zeroVectors; // no direction: not drawn, and not an error
                halfRadius = 0;
            }
        }
        packed[i] = pack(radiusValid ? halfRadius : 0, quantised);
    }
    _numSkipped = 0;
    for (uint32_t word : packed)
        _numSkipped += (word & 0xffffu) == 0 ? 1 : 0;
    // Re-upload only when the packed words changed.
    if (!std::equal(packed.begin(), packed.end(), _packed->begin(), _packed->end()))
    {
        _packed->assign(packed.begin(), packed.end());
        _packed->dirty();
    }
    _numGlyphs = static_cast<unsigned int>(count);

    auto report = [&](unsigned int bad, const char* problem)
    {
        if (bad)
            OSG_WARN << "osgGlyphs::GlyphCloud \"" << getName() << "\": " << bad << " of " << count
                     << " glyphs " << problem << "; they are skipped" << std::endl;
    };
    report(badPositions, "have a non-finite position (NaN or inf)");
    report(radiusValid ? badRadii : static_cast<unsigned int>(count),
           "have a radius that is not finite and > 0");
    report(badScalars, "have a non-finite scalar (NaN or inf)");
    report(badVectors, "have a non-finite vector (NaN or inf)");
    if (zeroVectors)
        OSG_INFO << "osgGlyphs::GlyphCloud \"" << getName() << "\": " << zeroVectors << " of " << count
                 << " glyphs have a zero vector and no direction; they are not drawn" << std::endl;

    _drawArrays->setCount(static_cast<GLsizei>(count));
    _radiusScaleUniform->set(_radiusScale);
    if (_autoRange)
    {
        _rangeMin = _dataMin;
        _rangeMax = _dataMax;
    }
    updateScalarMapping();
}

void GlyphCloud::updateScalarMapping()
{
    // colormap coordinate = (value - rangeMin) / (rangeMax - rangeMin), where
    // value = dataMin + quantised * (dataMax - dataMin) and quantised is in [0, 1].
    const double span = double(_rangeMax) - double(_rangeMin);
    osg::Vec2 mapping(0.0f, 0.5f);
    if (span != 0.0 && std::isfinite(span))
        mapping.set(static_cast<float>((double(_dataMax) - _dataMin) / span),
                    static_cast<float>((double(_dataMin) - _rangeMin) / span));
    _scalarToColormapUniform->set(mapping);
}

void GlyphCloud::updateStateSet()
{
    GlyphVariant variant;
    variant.shape = _shape;
    variant.technique = _technique;
    variant.colorMode = _colorMode;
    variant.lit = _lit;
    variant.colorMap = _colorMode == GlyphColorMode::Scalar ? _colorMap.get() : nullptr;
    setStateSet(GlyphStateSets::instance()->get(variant));
}

double GlyphCloud::getGPUBytesPerGlyph() const
{
    if (_numGlyphs == 0)
        return 0.0;
    double bytes = 0.0;
    for (const osg::Array* array :
         {static_cast<const osg::Array*>(_positions.get()), static_cast<const osg::Array*>(_packed.get()),
          static_cast<const osg::Array*>(_colors.get())})
        bytes += array ? array->getTotalDataSize() : 0;
    return bytes / _numGlyphs;
}

osg::BoundingBox GlyphCloud::computeBoundingBox() const
{
    const float anchor = _anchor == GlyphAnchor::Tail ? 0.0f : _anchor == GlyphAnchor::Head ? 1.0f : 0.5f;
    const float widest = _shape == GlyphShape::Arrow ? std::max(_arrowParams.y(), 1.0f) : 1.0f;
    osg::BoundingBox box;
    for (unsigned int i = 0; i < _numGlyphs; ++i)
    {
        const uint16_t halfRadius = static_cast<uint16_t>((*_packed)[i] & 0xffffu);
        if (halfRadius == 0)
            continue;
        const float radius = detail::fromHalf(halfRadius) * _radiusScale * widest;
        const osg::Vec3 pad(radius, radius, radius);
        const osg::Vec3& p = (*_positions)[i];
        if (!hasVectorShape())
        {
            box.expandBy(p - pad);
            box.expandBy(p + pad);
            continue;
        }
        // The glyph lies within its radius of the segment from tail to head.
        const osg::Vec3& v = (*_vectors)[i];
        const float magnitude = v.length();
        const osg::Vec3 axis = v / magnitude;
        const float length = _uniformLength ? _lengthScale : _lengthScale * magnitude;
        const osg::Vec3 tail = p - axis * (length * anchor);
        for (const osg::Vec3& end : {tail, tail + axis * length})
        {
            box.expandBy(end - pad);
            box.expandBy(end + pad);
        }
    }
    return box;
}

void GlyphCloud::drawImplementation(osg::RenderInfo& renderInfo) const
{
    GlyphStateSets::observeContext(renderInfo.getContextID()); // a map lookup once registered
    // The program is shared between clouds; each cloud sets its own values before drawing.
    if (const osg::Program::PerContextProgram* program = renderInfo.getState()->getLastAppliedProgramObject())
    {
        program->apply(*_radiusScaleUniform);
        program->apply(*_baseColorUniform);
        program->apply(*_scalarToColormapUniform);
        program->apply(*_materialUniform);
        program->apply(*_vectorParamsUniform);
        program->apply(*_arrowParamsUniform);
    }
    osg::Geometry::drawImplementation(renderInfo);
}
