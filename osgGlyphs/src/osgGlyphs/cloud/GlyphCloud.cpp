#include <osgGlyphs/GlyphCloud>
#include <osgGlyphs/GlyphStateCache>

#include "../culling/ChunkDrawer.h"
#include "../state/ClipPlaneState.h"
#include "../state/GlyphDefines.h"
#include "../state/ViewState.h"
#include "DrawnArrays.h"
#include "FlattenedTransforms.h"
#include "PositionGrid.h"

#include <osg/Depth>
#include <osg/Uniform>
#include <osgUtil/CullVisitor>
#include <osgUtil/IntersectionVisitor>

#include <numeric>

using namespace osgGlyphs;

namespace
{

/** Shares an array in a shallow copy and clones it in a deep one. */
template <class ArrayType>
osg::ref_ptr<ArrayType> copyArray(const osg::ref_ptr<ArrayType>& array, const osg::CopyOp& copyop)
{
    return array.valid() ? static_cast<ArrayType*>(copyop(array.get())) : nullptr;
}

}

GlyphCloud::GlyphCloud()
{
    initialize();
}

GlyphCloud::GlyphCloud(const GlyphCloud& other, const osg::CopyOp& copyop)
    : osg::Geometry(other, copyop), _origin(other._origin), _positions(copyArray(other._positions, copyop)),
      _radii(copyArray(other._radii, copyop)), _colors(copyArray(other._colors, copyop)),
      _scalars(copyArray(other._scalars, copyop)), _vectors(copyArray(other._vectors, copyop)),
      _occlusion(copyArray(other._occlusion, copyop)), _semiAxes(copyArray(other._semiAxes, copyop)),
      _orientations(copyArray(other._orientations, copyop)), _exponents(copyArray(other._exponents, copyop)),
      _colorMap(other._colorMap),
      _technique(other._technique.valid() ? static_cast<GlyphTechnique*>(copyop(other._technique.get()))
                                          : nullptr),
      _radius(other._radius), _color(other._color), _colorMode(other._colorMode), _shape(other._shape),
      _anchor(other._anchor), _lengthScale(other._lengthScale), _uniformLength(other._uniformLength),
      _arrowParams(other._arrowParams), _lit(other._lit), _compressedAttributes(other._compressedAttributes),
      _compressedPositions(other._compressedPositions), _autoRange(other._autoRange),
      _rangeMin(other._rangeMin), _rangeMax(other._rangeMax), _material(other._material),
      _opacity(other._opacity), _culling(other._culling), _cullingChunkSize(other._cullingChunkSize),
      _selection(other._selection), _selectionColor(other._selectionColor)
{
    initialize();
}

void GlyphCloud::initialize()
{
    // Vertex buffer objects by default; display lists where the technique allows them.
    setUseDisplayList(false);
    setUseVertexBufferObjects(true);
    if (!_technique)
        _technique = createTechnique(DEFAULT_GLYPH_TECHNIQUE);
    _selectionElements = new osg::DrawElementsUInt(GL_POINTS);
    _selectionElements->setElementBufferObject(new osg::ElementBufferObject);
    _packed = new osg::UIntArray;
    _packed->setPreserveDataType(true); // an integer attribute: glVertexAttribIPointer
    _unpacked = new osg::Vec2Array;
    _quantisedPositions = new osg::Vec3sArray;
    _ellipsoidRadii = new osg::FloatArray;
    _packedAxes = new osg::Vec4usArray;
    _packedAxes->setNormalize(true);
    _packedRotations = new osg::Vec4sArray;
    _packedRotations->setNormalize(true);
    _drawnArrays = std::make_shared<detail::DrawnArrays>();
    // The cloud's own values, in a StateSet of its own: each copy gets its own.
    _cloudStateSet = new osg::StateSet;
    _cloudStateSet->setName("osgGlyphs cloud");
    _radiusScaleUniform = new osg::Uniform("osgGlyphs_radiusScale", 1.0f);
    _baseColorUniform = new osg::Uniform("osgGlyphs_baseColor", _color);
    _scalarToColormapUniform = new osg::Uniform("osgGlyphs_scalarToColormap", osg::Vec2(0.0f, 0.0f));
    _materialUniform = new osg::Uniform("osgGlyphs_material", _material);
    _vectorParamsUniform = new osg::Uniform("osgGlyphs_vectorParams", osg::Vec3());
    _arrowParamsUniform = new osg::Uniform("osgGlyphs_arrowParams", _arrowParams);
    _opacityUniform = new osg::Uniform("osgGlyphs_opacity", _opacity);
    _positionGridUniform = new osg::Uniform("osgGlyphs_positionGrid", _positionGrid);
    for (osg::Uniform* uniform :
         {_radiusScaleUniform.get(), _baseColorUniform.get(), _scalarToColormapUniform.get(),
          _materialUniform.get(), _vectorParamsUniform.get(), _arrowParamsUniform.get(),
          _opacityUniform.get(), _positionGridUniform.get()})
        _cloudStateSet->addUniform(uniform);
    updateVectorUniforms();
    if (!_colorMap)
        _colorMap = ColorMap::getBuiltin("viridis");
    updateGlyphs();
    updateStateSet();
}

void GlyphCloud::setPositions(osg::Vec3Array* positions)
{
    _positions = positions;
    dirtyGlyphs();
}

void GlyphCloud::setOrigin(const osg::Vec3d& origin)
{
    _origin = origin;
    dirtyBound();
}

void GlyphCloud::setRadius(float radius)
{
    _radius = radius;
    _radii = nullptr;
    _packedRadii = PackedSource(); // the single radius is packed like a new array
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
    updateStateSet(); // a technique's state may be made for the one colour
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

void GlyphCloud::setOcclusion(osg::Vec4ubArray* occlusion)
{
    _occlusion = occlusion;
    if (occlusion)
    {
        occlusion->setNormalize(true);
        if (occlusion->size() < _numGlyphs)
            OSG_WARN << "osgGlyphs: GlyphCloud::setOcclusion: " << occlusion->size() << " values for "
                     << _numGlyphs << " glyphs; drawing without ambient occlusion" << std::endl;
    }
    buildPrimitives();
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
    if (shape == _shape)
        return;
    _shape = shape;
    _packedVectors = PackedSource(); // vectors count for vector shapes only, semi-axes for ellipsoids
    _packedSemiAxes = PackedSource();
    dirtyGlyphs();
    updateStateSet();
}

void GlyphCloud::setTechnique(GlyphTechnique* technique)
{
    _technique = technique ? technique : createTechnique(DEFAULT_GLYPH_TECHNIQUE).get();
    _builtFor = {};
    updateChunkUse();
    buildPrimitives();
    updateStateSet();
}

const GlyphTechnique* GlyphCloud::getEffectiveTechnique() const
{
    return _technique->supportsShape(_shape) ? _technique.get() : getDefaultTechnique();
}

void GlyphCloud::setVectors(osg::Vec3Array* vectors)
{
    _vectors = vectors;
    dirtyGlyphs();
}

void GlyphCloud::setSemiAxes(osg::Vec3Array* semiAxes)
{
    _semiAxes = semiAxes;
    dirtyGlyphs();
}

void GlyphCloud::setOrientations(osg::Vec4Array* orientations)
{
    _orientations = orientations;
    dirtyGlyphs();
}

void GlyphCloud::setExponents(osg::Vec2Array* exponents)
{
    _exponents = exponents;
    dirtyGlyphs();
}

void GlyphCloud::setLengthScale(float lengthScale)
{
    _lengthScale = lengthScale;
    updateVectorUniforms();
    updateChunks();
    buildPrimitives();
    dirtyBound();
}

void GlyphCloud::setUniformLength(bool uniformLength)
{
    _uniformLength = uniformLength;
    updateVectorUniforms();
    updateChunks();
    buildPrimitives();
    dirtyBound();
}

void GlyphCloud::setAnchor(GlyphAnchor anchor)
{
    _anchor = anchor;
    updateVectorUniforms();
    updateChunks();
    buildPrimitives();
    dirtyBound();
}

void GlyphCloud::setArrowHead(float lengthRatio, float radiusRatio)
{
    _arrowParams.set(lengthRatio, radiusRatio);
    _arrowParamsUniform->set(_arrowParams);
    _builtFor = {}; // a technique may bake the arrow's proportions into its primitives
    updateChunks();
    buildPrimitives();
    dirtyBound();
}

void GlyphCloud::updateVectorUniforms()
{
    _vectorParamsUniform->set(
        osg::Vec3(_lengthScale, _uniformLength ? 1.0f : 0.0f, getAnchorFraction(_anchor)));
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
    {
        packScalars();     // the 16 bits now span another interval
        buildPrimitives(); // a technique may copy the packed words
    }
    updateScalarMapping();
}

void GlyphCloud::resetScalarRange()
{
    _autoRange = true;
    _rangeMin = _dataMin;
    _rangeMax = _dataMax;
    if (updateQuantisationRange() && _scalars.valid())
    {
        packScalars();
        buildPrimitives();
    }
    updateScalarMapping();
}

void GlyphCloud::setLit(bool lit)
{
    _lit = lit;
    updateStateSet();
}

void GlyphCloud::setCompressedAttributes(bool compressed)
{
    if (compressed == _compressedAttributes)
        return;
    _compressedAttributes = compressed;
    packRadii();
    packScalars();
    updateChunks(); // the chunk boxes hold the radii as the GPU decodes them
    buildPrimitives();
    updateStateSet();
}

void GlyphCloud::setCompressedPositions(bool compressed)
{
    if (compressed == _compressedPositions)
        return;
    _compressedPositions = compressed;
    packPositions();
    updateChunks(); // the chunk boxes hold the positions as the GPU draws them
    buildPrimitives();
    dirtyBound();
}

void GlyphCloud::setCompressedPositions(const osg::Vec3sArray& quantised, const osg::Vec4& grid)
{
    detail::PositionGrid decoder;
    decoder.offset.set(grid.x(), grid.y(), grid.z());
    decoder.step = grid.w();
    osg::ref_ptr<osg::Vec3Array> positions = new osg::Vec3Array(quantised.size());
    for (std::size_t i = 0; i < quantised.size(); ++i)
        (*positions)[i] = decoder.decode(quantised[i]);
    _compressedPositions = true;
    setPositions(positions.get());
}

osg::ref_ptr<osg::Vec3Array> GlyphCloud::computeDrawnPositions() const
{
    if (!_positions.valid())
        return nullptr;
    osg::ref_ptr<osg::Vec3Array> drawn = new osg::Vec3Array(*_positions, osg::CopyOp::DEEP_COPY_ALL);
    for (unsigned int i = 0; _compressedPositions && i < drawn->size(); ++i)
        if (std::isfinite((*drawn)[i].length2()))
            (*drawn)[i] = drawnPosition(i);
    return drawn;
}

void GlyphCloud::setMaterial(float ambient, float specular, float shininess)
{
    _material.set(ambient, specular, shininess);
    _materialUniform->set(_material);
}

void GlyphCloud::setOpacity(float opacity)
{
    _opacity = opacity;
    _opacityUniform->set(_opacity);
}

void GlyphCloud::setCulling(GlyphCulling culling)
{
    _culling = culling;
    updateChunkUse();
    buildPrimitives();
}

void GlyphCloud::setCullingChunkSize(unsigned int glyphs)
{
    _cullingChunkSize = std::max(1u, glyphs);
    updateChunks();
    buildPrimitives();
}

bool GlyphCloud::canDrawChunks() const
{
    // A display list would keep one frame's choice of chunks, and selection.
    const bool displayList = _useDisplayList && _supportsDisplayList;
    return getEffectiveTechnique()->supportsCulling() && !displayList;
}

std::shared_ptr<const detail::GlyphChunks> GlyphCloud::getCullingChunks() const
{
    return _culling == GlyphCulling::Occlusion && canDrawChunks() ? _chunks : nullptr;
}

GlyphCullingStatistics GlyphCloud::getCullingStatistics(unsigned int contextID) const
{
    return contextID < _cullingStatistics.size() ? _cullingStatistics[contextID] : GlyphCullingStatistics();
}

std::vector<unsigned char> GlyphCloud::getCullingRecord(unsigned int contextID) const
{
    if (contextID >= _chunkRecords.size() || !_chunkRecords[contextID].chunks)
        return {};
    const ChunkRecord& record = _chunkRecords[contextID];
    const detail::GlyphChunks& chunks = *record.chunks;
    std::vector<unsigned char> outcomes(_numGlyphs, CULLING_NOT_DRAWN);
    for (size_t c = 0; c < chunks.chunks.size() && c < record.outcomes.size(); ++c)
        for (unsigned int k = chunks.chunks[c].first; k < chunks.chunks[c].first + chunks.chunks[c].count;
             ++k)
            if (chunks.ids[k] < outcomes.size())
                outcomes[chunks.ids[k]] = record.outcomes[c];
    return outcomes;
}

void GlyphCloud::updateChunkUse()
{
    // The chunks hold the glyphs' data only: they stay valid whichever technique draws them.
    if (!_chunks || _culling == GlyphCulling::Off || !getEffectiveTechnique()->supportsCulling())
        updateChunks();
}

void GlyphCloud::updateChunks()
{
    catchUpWithResizedArrays();
    {
        std::lock_guard<std::mutex> lock(_pickingMutex);
        _pickingChunks.reset();
    }
    if (_culling == GlyphCulling::Off || !getEffectiveTechnique()->supportsCulling())
    {
        _chunks.reset();
        return;
    }
    _chunks = std::make_shared<const detail::GlyphChunks>(detail::buildGlyphChunks(
        _numGlyphs, [this](unsigned int i) { return computeGlyphBox(i); }, _cullingChunkSize));
}

void GlyphCloud::sortSpatially()
{
    if (!_chunks || _chunks->isIdentity(_numGlyphs))
        return;
    // The glyph each index gets: the drawn ones in spatial order, then the others in their order.
    std::vector<unsigned int> order = _chunks->ids;
    std::vector<bool> placed(_numGlyphs, false);
    for (unsigned int id : order)
        placed[id] = true;
    for (unsigned int i = 0; i < _numGlyphs; ++i)
        if (!placed[i])
            order.push_back(i);
    // Every array in place, and what the cloud packed from them with it: nothing is packed again.
    for (osg::Array* array :
         {static_cast<osg::Array*>(_positions.get()), static_cast<osg::Array*>(_radii.get()),
          static_cast<osg::Array*>(_colors.get()), static_cast<osg::Array*>(_scalars.get()),
          static_cast<osg::Array*>(_vectors.get()), static_cast<osg::Array*>(_occlusion.get()),
          static_cast<osg::Array*>(_semiAxes.get()), static_cast<osg::Array*>(_orientations.get()),
          static_cast<osg::Array*>(_exponents.get()), static_cast<osg::Array*>(_packed.get()),
          static_cast<osg::Array*>(_unpacked.get()), static_cast<osg::Array*>(_quantisedPositions.get()),
          static_cast<osg::Array*>(_ellipsoidRadii.get()), static_cast<osg::Array*>(_packedAxes.get()),
          static_cast<osg::Array*>(_packedRotations.get())})
    {
        if (!array || array->getNumElements() < _numGlyphs)
            continue;
        std::vector<unsigned int> all = order;
        for (unsigned int i = _numGlyphs; i < array->getNumElements(); ++i)
            all.push_back(i); // values past the glyphs stay after them
        detail::permuteElements(*array, all);
    }
    std::vector<uint8_t> skipped(_numGlyphs);
    for (unsigned int k = 0; k < _numGlyphs; ++k)
        skipped[k] = _skipped[order[k]];
    _skipped.swap(skipped);
    _packedPositions.set(_positions.get());
    _packedRadii.set(getPackedRadiusSource());
    _packedScalars.set(_scalars.get());
    _packedVectors.set(hasVectorShape() ? _vectors.get() : nullptr);
    _packedSemiAxes.set(hasEllipsoidShape() ? _semiAxes.get() : nullptr);
    _packedOrientations.set(hasEllipsoidShape() ? _orientations.get() : nullptr);
    _packedExponents.set(hasSuperquadricShape() ? _exponents.get() : nullptr);
    // The same chunks of the same glyphs, each now at its own index.
    auto sorted = std::make_shared<detail::GlyphChunks>(*_chunks);
    std::iota(sorted->ids.begin(), sorted->ids.end(), 0u);
    _chunks = sorted;
    {
        std::lock_guard<std::mutex> lock(_pickingMutex);
        _pickingChunks.reset();
    }
    _selection.clear();
    updateSelectionElements();
    buildPrimitives();
}

void GlyphCloud::setSelection(const std::vector<unsigned int>& glyphs)
{
    _selection = glyphs;
    updateSelectionElements();
}

void GlyphCloud::updateSelectionElements()
{
    _selectionElements->clear();
    if (_drawnArrays->isReordered() && !_selection.empty())
    {
        // The drawn arrays hold the drawn glyphs in spatial order: where each glyph went.
        const unsigned int NOT_DRAWN = ~0u;
        std::vector<unsigned int> drawnAt(_numGlyphs, NOT_DRAWN);
        for (unsigned int k = 0; k < _chunks->ids.size(); ++k)
            drawnAt[_chunks->ids[k]] = k;
        for (unsigned int glyph : _selection)
            if (glyph < _numGlyphs && drawnAt[glyph] != NOT_DRAWN)
                _selectionElements->push_back(drawnAt[glyph]);
    }
    else
    {
        for (unsigned int glyph : _selection)
            if (glyph < _numGlyphs)
                _selectionElements->push_back(glyph);
    }
    _selectionElements->dirty();
}

bool GlyphCloud::catchUpWithResizedArrays()
{
    if (countGlyphs(false) == _numGlyphs)
        return false;
    // An array resized in place and not yet announced by dirtyGlyphs(), then another setter: what
    // was packed and the chunks no longer cover the arrays, so they are brought up to date first.
    updateGlyphs(false);
    dirtyBound();
    return true;
}

void GlyphCloud::dirtyGlyphs()
{
    updateGlyphs();
    dirtyBound();
}

void GlyphCloud::updateStateSet()
{
    GlyphVariant variant;
    variant.shape = _shape;
    variant.colorMode = _colorMode;
    variant.lit = _lit;
    variant.compressedAttributes = _compressedAttributes;
    variant.colorMap = _colorMap;
    variant.color = _color;
    _variantStateSet = GlyphStateCache::instance()->getStateSet(*getEffectiveTechnique(), variant);
}

GlyphArrays GlyphCloud::getGlyphArrays() const
{
    GlyphArrays arrays;
    arrays.positions =
        _compressedPositions ? static_cast<osg::Array*>(_quantisedPositions.get()) : _positions.get();
    arrays.radiusScalar = _compressedAttributes ? static_cast<osg::Array*>(_packed.get()) : _unpacked.get();
    arrays.colors = _colorMode == GlyphColorMode::RGBA ? _colors.get() : nullptr;
    arrays.vectors = hasVectorShape() ? _vectors.get() : nullptr;
    arrays.occlusion = _occlusion.valid() && _occlusion->size() >= _numGlyphs ? _occlusion.get() : nullptr;
    arrays.axes = hasEllipsoidShape() ? _packedAxes.get() : nullptr;
    arrays.orientations = hasEllipsoidShape() ? _packedRotations.get() : nullptr;
    arrays.count = _numGlyphs;
    return arrays;
}

void GlyphCloud::buildPrimitives()
{
    if (catchUpWithResizedArrays())
        return; // updateGlyphs() ended here
    const GlyphTechnique* technique = getEffectiveTechnique();
    const bool wasReordered = _drawnArrays->isReordered();
    if (_chunks)
        _drawn = _drawnArrays->update(getGlyphArrays(), _chunks);
    else
    {
        _drawnArrays->clear();
        _drawn = getGlyphArrays();
    }
    if (_drawnArrays->isReordered() || wasReordered)
        updateSelectionElements(); // the selection's pass draws from the drawn arrays
    const GlyphArrays& arrays = _drawn;
    const auto builtFor =
        std::make_tuple(technique, arrays.positions, arrays.radiusScalar, arrays.colors, arrays.vectors,
                        arrays.occlusion, arrays.axes, arrays.orientations, arrays.count);
    for (const auto& [define, on] :
         {std::make_pair(GLYPH_AMBIENT_OCCLUSION_DEFINE, arrays.occlusion != nullptr),
          std::make_pair(detail::COMPRESSED_POSITIONS_DEFINE, _compressedPositions)})
        if (on)
            _cloudStateSet->setDefine(define);
        else
            _cloudStateSet->removeDefine(define);
    if (builtFor == _builtFor && !technique->copiesArrays())
        return; // the same arrays, drawn the same way: changed contents upload by themselves
    _builtFor = builtFor;
    setSupportsDisplayList(technique->supportsDisplayLists());
    dirtyGLObjects();
    getVertexAttribArrayList().clear();
    setVertexArray(nullptr);
    setNormalArray(nullptr);
    removePrimitiveSet(0, getNumPrimitiveSets());
    technique->buildPrimitives(*this, arrays);
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
    for (const osg::ref_ptr<osg::PrimitiveSet>& primitives : getPrimitiveSetList())
        if (const osg::DrawElements* elements = primitives->getDrawElements())
            bytes += elements->getTotalDataSize(); // a technique's indexed mesh
    return bytes / _numGlyphs;
}

void GlyphCloud::accept(osg::NodeVisitor& nv)
{
    detail::restoreFlattenedTransform(*this, nv);
    if (osgUtil::IntersectionVisitor* iv = nv.asIntersectionVisitor(); iv && nv.validNodeMask(*this))
    {
        nv.pushOntoNodePath(this);
        const bool picked = intersect(*iv);
        nv.popFromNodePath();
        if (picked)
            return;
    }
    osgUtil::CullVisitor* cv = nv.asCullVisitor();
    if (!cv || !nv.validNodeMask(*this))
    {
        osg::Geometry::accept(nv);
        return;
    }
    GlyphStateCache::observeContext(cv->getState()->getContextID());
    cv->pushStateSet(_variantStateSet.get());
    cv->pushStateSet(detail::getViewStateSet(*cv));
    cv->pushStateSet(_cloudStateSet.get());
    cv->pushOntoNodePath(this);
    cullRelativeToOrigin(*cv);
    cv->popFromNodePath();
    cv->popStateSet();
    cv->popStateSet();
    cv->popStateSet();
}

// Mirrors osgUtil::CullVisitor::apply(osg::Drawable&) of OSG 3.6.5 (src/osgUtil/CullVisitor.cpp),
// which cannot be called: it tests and sorts by getBoundingBox(), in the parent's coordinates
// under the parent's model-view, where the glyphs are drawn relative to the origin under a
// model-view translated by it in double precision (docs/design/precision.md). Added: that
// model-view, and the clip-plane StateSet. Left out: OSG's warning for a NaN depth (not drawn).
void GlyphCloud::cullRelativeToOrigin(osgUtil::CullVisitor& cv)
{
    if (getCullCallback())
    {
        osg::DrawableCullCallback* callback = getCullCallback()->asDrawableCullCallback();
        if (callback && callback->cull(&cv, this, &cv.getRenderInfo()))
            return;
        if (!callback)
            getCullCallback()->run(this, &cv);
    }
    const osg::BoundingBox& box = getLocalBoundingBox();
    osg::ref_ptr<osg::RefMatrix> modelView =
        new osg::RefMatrix(osg::Matrixd::translate(_origin) * *cv.getModelViewMatrix());
    cv.pushModelViewMatrix(modelView.get(), osg::Transform::RELATIVE_RF);
    const bool culled = (isCullingActive() && cv.isCulled(box)) ||
                        (cv.getComputeNearFarMode() != osg::CullSettings::DO_NOT_COMPUTE_NEAR_FAR &&
                         box.valid() && !cv.updateCalculatedNearFar(*modelView, box));
    if (!culled)
    {
        unsigned int pushed = 0;
        if (getStateSet())
        {
            cv.pushStateSet(getStateSet());
            ++pushed;
        }
        for (auto& stateFrustum : cv.getCurrentCullingSet().getStateFrustumList())
        {
            if (stateFrustum.second.contains(box))
            {
                cv.pushStateSet(stateFrustum.first.get());
                ++pushed;
            }
        }
        cv.pushStateSet(detail::getClipPlaneStateSet(detail::getClipPlaneMask(cv)));
        ++pushed;
        // The distance along the view axis, as osgUtil::CullVisitor measures it to sort.
        const osg::Vec3d centre = box.valid() ? osg::Vec3d(box.center()) * *modelView : osg::Vec3d();
        const float depth = -static_cast<float>(centre.z());
        if (!osg::isNaN(depth))
            cv.addDrawableAndDepth(this, modelView.get(), depth);
        for (; pushed > 0; --pushed)
            cv.popStateSet();
    }
    cv.popModelViewMatrix();
}

void GlyphCloud::drawImplementation(osg::RenderInfo& renderInfo) const
{
    const std::shared_ptr<const detail::GlyphChunks> chunks = _chunks;
    osg::State& state = *renderInfo.getState();
    GlyphCullingStatistics& statistics = _cullingStatistics[state.getContextID()];
    const bool displayList = _useDisplayList && _supportsDisplayList;
    const bool culling = chunks && canDrawChunks();
    bool firstDraw = true;
    // Mirrors osg::Geometry::drawImplementation of OSG 3.6.5 (src/osg/Geometry.cpp), whose
    // drawPrimitivesImplementation is not virtual: the chunks that may be seen replace the
    // primitive sets, and the selection is drawn again. Left out: the check for deprecated
    // arrays, which a cloud never has.
    const bool checkForGLErrors = state.getCheckForGLErrors() == osg::State::ONCE_PER_ATTRIBUTE;
    const bool usingVertexBufferObjects =
        state.useVertexBufferObject(_supportsVertexBufferObjects && _useVertexBufferObjects);
    const bool usingVertexArrayObjects =
        usingVertexBufferObjects && state.useVertexArrayObject(_useVertexArrayObject);
    osg::VertexArrayState* vas = state.getCurrentVertexArrayState();
    vas->setVertexBufferObjectSupported(usingVertexBufferObjects);
    drawVertexArraysImplementation(renderInfo);
    if (checkForGLErrors)
        state.checkGLErrors("GlyphCloud::drawImplementation() after vertex arrays setup.");
    if (culling)
    {
        ChunkRecord* record = _cullingRecorded ? &_chunkRecords[state.getContextID()] : nullptr;
        if (record)
            record->chunks = chunks;
        // In a FRONT_TO_BACK_BIN (culling/FrontToBackBin.cpp) the bin draws its clouds together in
        // rounds of culling, each cloud once a round: drawChunks finds what the bin chose for this
        // round through the context (OcclusionContext::findBinRound). The selection goes with the
        // first round.
        firstDraw = detail::drawChunks(renderInfo, *chunks, _culling, statistics,
                                       record ? &record->outcomes : nullptr);
    }
    else
    {
        statistics = GlyphCullingStatistics();
        drawPrimitivesImplementation(renderInfo);
    }
    if (!displayList && firstDraw)
        drawSelection(state, usingVertexBufferObjects);
    if (usingVertexBufferObjects && !usingVertexArrayObjects)
    {
        vas->unbindVertexBufferObject();
        vas->unbindElementBufferObject();
    }
    if (checkForGLErrors)
        state.checkGLErrors("end of GlyphCloud::drawImplementation().");
}

void GlyphCloud::drawSelection(osg::State& state, bool usingVertexBufferObjects) const
{
    const osg::Program::PerContextProgram* program = state.getLastAppliedProgramObject();
    if (_selectionElements->empty() || !getEffectiveTechnique()->supportsCulling() || !program)
        return;
    static const unsigned int highlightID = osg::Uniform::getNameID("osgGlyphs_highlight");
    const GLint highlight = program->getUniformLocation(highlightID);
    if (highlight < 0)
        return;
    osg::GLExtensions* ext = state.get<osg::GLExtensions>();
    const osg::Depth* depth =
        dynamic_cast<const osg::Depth*>(state.getLastAppliedAttribute(osg::StateAttribute::DEPTH));
    ext->glUniform4f(highlight, _selectionColor.r(), _selectionColor.g(), _selectionColor.b(),
                     _selectionColor.a());
    glDepthFunc(GL_LEQUAL); // the same program draws the same depth again
    _selectionElements->draw(state, usingVertexBufferObjects);
    glDepthFunc(depth ? GLenum(depth->getFunction()) : GLenum(GL_LESS));
    ext->glUniform4f(highlight, 0.0f, 0.0f, 0.0f, 0.0f);
}

void GlyphCloud::resizeGLObjectBuffers(unsigned int maxSize)
{
    osg::Geometry::resizeGLObjectBuffers(maxSize);
    _selectionElements->resizeGLObjectBuffers(maxSize);
    _cullingStatistics.resize(maxSize);
    _chunkRecords.resize(maxSize);
    _variantStateSet->resizeGLObjectBuffers(maxSize);
    _cloudStateSet->resizeGLObjectBuffers(maxSize);
}

void GlyphCloud::releaseGLObjects(osg::State* state) const
{
    osg::Geometry::releaseGLObjects(state);
    _selectionElements->releaseGLObjects(state);
    _variantStateSet->releaseGLObjects(state);
    _cloudStateSet->releaseGLObjects(state);
}
