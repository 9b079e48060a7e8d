#include <osgGlyphs/GlyphCloud>

#include "GlyphMeshes.h"
#include "HalfFloat.h"

#include <osg/Camera>
#include <osg/Notify>
#include <osg/RenderInfo>
#include <osg/Viewport>

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

/** Shares an array in a shallow copy and clones it in a deep one. */
template <class ArrayType>
osg::ref_ptr<ArrayType> copyArray(const osg::ref_ptr<ArrayType>& array, const osg::CopyOp& copyop)
{
    return array.valid() ? static_cast<ArrayType*>(copyop(array.get())) : nullptr;
}

/** The same per-glyph values four times, for the paper's billboards of four vertices. */
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

}

void GlyphCloud::configureDrawing()
{
    dirtyGLObjects(); // display lists, where used, hold the previous arrays
    const GlyphTechnique technique = getEffectiveTechnique();
    osg::Array* vectors = hasVectorShape() ? _vectors.get() : nullptr;
    osg::Array* colors = _colorMode == GlyphColorMode::RGBA ? _colors.get() : nullptr;
    osg::Array* radiusScalar =
        _compressedAttributes ? static_cast<osg::Array*>(_packed.get()) : _unpacked.get();
    getVertexAttribArrayList().clear();
    setNormalArray(nullptr);
    removePrimitiveSet(0, getNumPrimitiveSets());
    auto attach = [&](unsigned int index, osg::Array* array, osg::Array::Binding binding)
    {
        if (array)
            array->setBinding(binding);
        setVertexAttribArray(index, array);
    };

    switch (technique)
    {
    case GlyphTechnique::Instanced:
    case GlyphTechnique::Polygons:
    {
        // One instance per glyph: the per-glyph arrays advance once per instance.
        if (technique == GlyphTechnique::Instanced)
        {
            setVertexArray(new osg::Vec3Array(4)); // the quad's corners come from gl_VertexID
            addPrimitiveSet(new osg::DrawArrays(GL_TRIANGLE_STRIP, 0, 4, _numGlyphs));
        }
        else
        {
            if (!_meshVertices.valid())
            {
                const detail::GlyphMesh mesh = detail::createGlyphMesh(_shape, _polygonSlices, _polygonStacks,
                                                                       _arrowParams.x(), _arrowParams.y());
                _meshVertices = mesh.vertices;
                _meshNormals = mesh.normals;
                _meshTriangles = mesh.triangles;
            }
            setVertexArray(_meshVertices.get());
            setNormalArray(_meshNormals.get(), osg::Array::BIND_PER_VERTEX);
            osg::ref_ptr<osg::DrawElementsUInt> triangles = new osg::DrawElementsUInt(*_meshTriangles);
            triangles->setNumInstances(_numGlyphs);
            addPrimitiveSet(triangles.get());
        }
        attach(GlyphStateSets::POSITION_ATTRIBUTE, _positions.get(), osg::Array::BIND_PER_VERTEX);
        attach(GlyphStateSets::PACKED_ATTRIBUTE, radiusScalar, osg::Array::BIND_PER_VERTEX);
        attach(GlyphStateSets::COLOR_ATTRIBUTE, colors, osg::Array::BIND_PER_VERTEX);
        attach(GlyphStateSets::VECTOR_ATTRIBUTE, vectors, osg::Array::BIND_PER_VERTEX);
        break;
    }
    case GlyphTechnique::PaperQuad:
    {
        // The paper's data path: four vertices per glyph, each with a copy of its attributes.
        setVertexArray(repeatFourTimes(_positions.get(), _numGlyphs).get());
        osg::ref_ptr<osg::Vec2Array> corners = new osg::Vec2Array;
        corners->reserve(4 * _numGlyphs);
        for (unsigned int i = 0; i < _numGlyphs; ++i)
            for (const osg::Vec2& corner :
                 {osg::Vec2(-1, -1), osg::Vec2(1, -1), osg::Vec2(1, 1), osg::Vec2(-1, 1)})
                corners->push_back(corner);
        attach(GlyphStateSets::CORNER_ATTRIBUTE, corners.get(), osg::Array::BIND_PER_VERTEX);
        osg::ref_ptr<osg::Array> repeatedRadiusScalar;
        if (_compressedAttributes)
            repeatedRadiusScalar = repeatFourTimes(_packed.get(), _numGlyphs);
        else
            repeatedRadiusScalar = repeatFourTimes(_unpacked.get(), _numGlyphs);
        attach(GlyphStateSets::PACKED_ATTRIBUTE, repeatedRadiusScalar.get(), osg::Array::BIND_PER_VERTEX);
        attach(GlyphStateSets::COLOR_ATTRIBUTE, repeatFourTimes(_colors.get(), colors ? _numGlyphs : 0).get(),
               osg::Array::BIND_PER_VERTEX);
        attach(GlyphStateSets::VECTOR_ATTRIBUTE,
               repeatFourTimes(_vectors.get(), vectors ? _numGlyphs : 0).get(), osg::Array::BIND_PER_VERTEX);
        addPrimitiveSet(new osg::DrawArrays(GL_QUADS, 0, 4 * _numGlyphs));
        break;
    }
    default:
        // One vertex per glyph.
        setVertexArray(_positions.get());
        attach(GlyphStateSets::PACKED_ATTRIBUTE, radiusScalar, osg::Array::BIND_PER_VERTEX);
        attach(GlyphStateSets::COLOR_ATTRIBUTE, colors, osg::Array::BIND_PER_VERTEX);
        attach(GlyphStateSets::VECTOR_ATTRIBUTE, vectors, osg::Array::BIND_PER_VERTEX);
        addPrimitiveSet(new osg::DrawArrays(GL_POINTS, 0, _numGlyphs));
        break;
    }
}

GlyphCloud::GlyphCloud()
{
    initialize();
}

GlyphCloud::GlyphCloud(const GlyphCloud& other, const osg::CopyOp& copyop)
    : osg::Geometry(other, copyop), _positions(copyArray(other._positions, copyop)),
      _radii(copyArray(other._radii, copyop)), _colors(copyArray(other._colors, copyop)),
      _scalars(copyArray(other._scalars, copyop)), _vectors(copyArray(other._vectors, copyop)),
      _colorMap(other._colorMap), _radius(other._radius), _color(other._color), _colorMode(other._colorMode),
      _shape(other._shape), _technique(other._technique), _anchor(other._anchor),
      _lengthScale(other._lengthScale), _uniformLength(other._uniformLength),
      _arrowParams(other._arrowParams), _polygonSlices(other._polygonSlices),
      _polygonStacks(other._polygonStacks), _lit(other._lit),
      _compressedAttributes(other._compressedAttributes), _autoRange(other._autoRange),
      _rangeMin(other._rangeMin), _rangeMax(other._rangeMax), _material(other._material)
{
    initialize();
}

void GlyphCloud::initialize()
{
    // Per-cloud uniforms are set while drawing; a display list compiles that code and does not
    // replay them, so the cloud would draw with another cloud's values (or none).
    setSupportsDisplayList(false);
    setUseVertexBufferObjects(true);
    _packed = new osg::UIntArray;
    _packed->setPreserveDataType(true); // an integer attribute: glVertexAttribIPointer
    _unpacked = new osg::Vec2Array;
    // Uniforms are per cloud: each copy gets its own.
    _radiusScaleUniform = new osg::Uniform("osgGlyphs_radiusScale", 1.0f);
    _baseColorUniform = new osg::Uniform("osgGlyphs_baseColor", _color);
    _scalarToColormapUniform = new osg::Uniform("osgGlyphs_scalarToColormap", osg::Vec2(0.0f, 0.0f));
    _materialUniform = new osg::Uniform("osgGlyphs_material", _material);
    _vectorParamsUniform = new osg::Uniform("osgGlyphs_vectorParams", osg::Vec3());
    _arrowParamsUniform = new osg::Uniform("osgGlyphs_arrowParams", _arrowParams);
    _viewportUniform = new osg::Uniform("osgGlyphs_viewport", osg::Vec4(0.0f, 0.0f, 1.0f, 1.0f));
    _singleSampleUniform = new osg::Uniform("osgGlyphs_singleSample", false);
    updateVectorUniforms();
    if (!_colorMap)
        _colorMap = ColorMap::getBuiltin("viridis");
    updatePackedAttributes();
    updateStateSet();
}

void GlyphCloud::setPositions(osg::Vec3Array* positions)
{
    _positions = positions;
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
        dirtyGlyphs();
    }
    updateStateSet(); // texture-multi's texture is of the one colour
}

void GlyphCloud::setColors(osg::Vec4ubArray* colors)
{
    _colors = colors;
    _scalars = nullptr;
    _colorMode = colors ? GlyphColorMode::RGBA : GlyphColorMode::Uniform;
    if (colors)
        colors->setNormalize(true);
    dirtyGlyphs();
    updateStateSet();
}

void GlyphCloud::setScalars(osg::FloatArray* scalars)
{
    _scalars = scalars;
    _colors = nullptr;
    _colorMode = scalars ? GlyphColorMode::Scalar : GlyphColorMode::Uniform;
    dirtyGlyphs();
    updateStateSet();
}

void GlyphCloud::setShape(GlyphShape shape)
{
    _shape = shape;
    _meshVertices = nullptr;
    dirtyGlyphs();
    updateStateSet();
}

void GlyphCloud::setTechnique(GlyphTechnique technique)
{
    _technique = technique;
    configureDrawing();
    updateStateSet();
}

void GlyphCloud::setPolygonResolution(unsigned int slices, unsigned int stacks)
{
    _polygonSlices = slices;
    _polygonStacks = stacks;
    _meshVertices = nullptr;
    configureDrawing();
}

GlyphTechnique GlyphCloud::getEffectiveTechnique() const
{
    return isTechniqueSupported(_technique, _shape) ? _technique : DEFAULT_GLYPH_TECHNIQUE;
}

void GlyphCloud::setVectors(osg::Vec3Array* vectors)
{
    _vectors = vectors;
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
    if (_meshVertices.valid() && _shape == GlyphShape::Arrow)
    {
        _meshVertices = nullptr; // the polygons technique's arrow mesh bakes the ratios in
        configureDrawing();
    }
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
    if (updateQuantisationRange() && _scalars.valid())
        updatePackedAttributes(false); // the 16 bits now span another interval
    else
        updateScalarMapping();
}

void GlyphCloud::resetScalarRange()
{
    _autoRange = true;
    _rangeMin = _dataMin;
    _rangeMax = _dataMax;
    if (updateQuantisationRange() && _scalars.valid())
        updatePackedAttributes(false);
    else
        updateScalarMapping();
}

void GlyphCloud::setLit(bool lit)
{
    _lit = lit;
    updateStateSet();
}

void GlyphCloud::setCompressedAttributes(bool compressed)
{
    _compressedAttributes = compressed;
    updatePackedAttributes(false);
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

void GlyphCloud::updatePackedAttributes(bool reportSkipped)
{
    const size_t numPositions = _positions.valid() ? _positions->size() : 0;
    size_t count = numPositions;
    auto limit = [&](const osg::Array* array, const char* what)
    {
        if (array && array->getNumElements() != numPositions)
        {
            if (reportSkipped)
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

    // The scalars' finite minimum and maximum.
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
    if (_autoRange)
    {
        _rangeMin = _dataMin;
        _rangeMax = _dataMax;
    }
    updateQuantisationRange();

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
        _quantisedMax > _quantisedMin ? 65535.0 / (double(_quantisedMax) - double(_quantisedMin)) : 0.0;
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
                quantised = static_cast<uint32_t>(
                    std::lround(std::clamp((double(s) - _quantisedMin) * quantisationScale, 0.0, 65535.0)));
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
    updateUnpackedAttributes(packed);
    _numGlyphs = static_cast<unsigned int>(count);

    auto report = [&](unsigned int bad, const char* problem)
    {
        if (bad && reportSkipped)
            OSG_WARN << "osgGlyphs::GlyphCloud \"" << getName() << "\": " << bad << " of " << count
                     << " glyphs " << problem << "; they are skipped" << std::endl;
    };
    report(badPositions, "have a non-finite position (NaN or inf)");
    report(radiusValid ? badRadii : static_cast<unsigned int>(count),
           "have a radius that is not finite and > 0");
    report(badScalars, "have a non-finite scalar (NaN or inf)");
    report(badVectors, "have a non-finite vector (NaN or inf)");
    if (zeroVectors && reportSkipped)
        OSG_INFO << "osgGlyphs::GlyphCloud \"" << getName() << "\": " << zeroVectors << " of " << count
                 << " glyphs have a zero vector and no direction; they are not drawn" << std::endl;

    _radiusScaleUniform->set(_radiusScale);
    updateScalarMapping();
    configureDrawing();
}

void GlyphCloud::updateUnpackedAttributes(const std::vector<uint32_t>& packed)
{
    if (_compressedAttributes)
    {
        _unpacked->clear();
        _unpacked->trim();
        return;
    }
    // The packed values without their rounding: radius / radius scale, and the scalar in [0, 1]
    // over the quantisation range (beyond it where the data is).
    const double span = double(_quantisedMax) - double(_quantisedMin);
    std::vector<osg::Vec2> unpacked(packed.size());
    for (size_t i = 0; i < packed.size(); ++i)
    {
        if ((packed[i] & 0xffffu) == 0)
            continue; // not drawn: radius 0
        const float relative = _radii.valid() ? (*_radii)[i] / _radiusScale : 1.0f;
        const float scalar = _scalars.valid() && span > 0.0
                                 ? static_cast<float>(((*_scalars)[i] - double(_quantisedMin)) / span)
                                 : 0.0f;
        unpacked[i].set(relative, scalar);
    }
    if (!std::equal(unpacked.begin(), unpacked.end(), _unpacked->begin(), _unpacked->end()))
    {
        _unpacked->assign(unpacked.begin(), unpacked.end());
        _unpacked->dirty();
    }
}

bool GlyphCloud::updateQuantisationRange()
{
    // The data's range, narrowed to the colour range where that is narrower: values beyond the
    // colour range clamp to the same colour anyway, and the 16 bits span what is seen.
    float lo = _dataMin, hi = _dataMax;
    const float rangeLo = std::min(_rangeMin, _rangeMax), rangeHi = std::max(_rangeMin, _rangeMax);
    if (std::isfinite(rangeLo) && std::isfinite(rangeHi) && std::max(lo, rangeLo) < std::min(hi, rangeHi))
    {
        lo = std::max(lo, rangeLo);
        hi = std::min(hi, rangeHi);
    }
    const bool changed = lo != _quantisedMin || hi != _quantisedMax;
    _quantisedMin = lo;
    _quantisedMax = hi;
    return changed;
}

void GlyphCloud::updateScalarMapping()
{
    // colormap coordinate = (value - rangeMin) / (rangeMax - rangeMin), where
    // value = quantisedMin + quantised * (quantisedMax - quantisedMin) and quantised is in [0, 1].
    const double span = double(_rangeMax) - double(_rangeMin);
    osg::Vec2 mapping(0.0f, 0.5f);
    if (span != 0.0 && std::isfinite(span))
        mapping.set(static_cast<float>((double(_quantisedMax) - _quantisedMin) / span),
                    static_cast<float>((double(_quantisedMin) - _rangeMin) / span));
    _scalarToColormapUniform->set(mapping);
}

void GlyphCloud::updateStateSet()
{
    GlyphVariant variant;
    variant.shape = _shape;
    variant.technique = getEffectiveTechnique();
    variant.colorMode = _colorMode;
    variant.lit = _lit;
    variant.compressedAttributes = _compressedAttributes;
    variant.colorMap = _colorMode == GlyphColorMode::Scalar ? _colorMap.get() : nullptr;
    if (variant.technique == GlyphTechnique::TextureMulti && _colorMode == GlyphColorMode::Uniform)
        variant.color = _color;
    setStateSet(GlyphStateSets::instance()->get(variant));
}

double GlyphCloud::getGPUBytesPerGlyph() const
{
    if (_numGlyphs == 0)
        return 0.0;
    // What the technique uploads: its vertex arrays (copies, for the paper's billboards; a
    // shared mesh or quad for the instanced ones) and the per-glyph attributes.
    double bytes = 0.0;
    for (const osg::Array* array : {getVertexArray(), getNormalArray()})
        bytes += array ? array->getTotalDataSize() : 0;
    for (const osg::ref_ptr<osg::Array>& array : getVertexAttribArrayList())
        bytes += array.valid() ? array->getTotalDataSize() : 0;
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
        const float relative = _compressedAttributes ? detail::fromHalf(halfRadius) : (*_unpacked)[i].x();
        const float radius = relative * _radiusScale * widest;
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

namespace
{

/** Whether the target of this draw has one sample per pixel: an FBO camera's attachments, else
 * the context's traits. Unsure (no context) counts as multisampled. */
bool isSingleSampled(osg::RenderInfo& renderInfo)
{
    const osg::Camera* camera = renderInfo.getCurrentCamera();
    if (camera && camera->getRenderTargetImplementation() == osg::Camera::FRAME_BUFFER_OBJECT &&
        !camera->getBufferAttachmentMap().empty())
    {
        for (const auto& attachment : camera->getBufferAttachmentMap())
            if (attachment.second._multisampleSamples > 0)
                return false;
        return true;
    }
    const osg::GraphicsContext* context = renderInfo.getState()->getGraphicsContext();
    return context && context->getTraits() && context->getTraits()->samples == 0;
}

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
        if (const osg::Viewport* viewport = renderInfo.getState()->getCurrentViewport())
        {
            _viewportUniform->set(
                osg::Vec4(viewport->x(), viewport->y(), viewport->width(), viewport->height()));
            program->apply(*_viewportUniform);
        }
        _singleSampleUniform->set(isSingleSampled(renderInfo));
        program->apply(*_singleSampleUniform);
    }
    osg::Geometry::drawImplementation(renderInfo);
}
