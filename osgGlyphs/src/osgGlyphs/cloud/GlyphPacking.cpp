// GlyphCloud's packing: each job re-packs what depends on the arrays that changed.
#include <osgGlyphs/GlyphCloud>

#include "HalfFloat.h"
#include "PositionGrid.h"

#include <osg/Notify>
#include <osg/Quat>
#include <osg/ValueObject>

#include <algorithm>
#include <cmath>
#include <limits>

using namespace osgGlyphs;

namespace
{

/** Why a glyph is not drawn. */
enum SkipReason : uint8_t
{
    SKIP_POSITION = 1,
    SKIP_RADIUS = 2,
    SKIP_SCALAR = 4,
    SKIP_VECTOR = 8,
    SKIP_ZERO_VECTOR = 16,
    SKIP_SEMI_AXES = 32,
    SKIP_ORIENTATION = 64,
    SKIP_EXPONENTS = 128
};

const int NUM_SKIP_REASONS = 8;

const float MIN_EXPONENT = 0.1f, MAX_EXPONENT = 2.0f;
const osg::Vec2 ELLIPSOID_EXPONENTS(1.0f, 1.0f);

const uint16_t HALF_ONE = 0x3c00;
const osg::Vec4 IDENTITY_ROTATION(0.0f, 0.0f, 0.0f, 1.0f);

bool isFinite(const osg::Vec3& v)
{
    return std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z());
}

bool areValidSemiAxes(const osg::Vec3& a)
{
    return isFinite(a) && a.x() > 0.0f && a.y() > 0.0f && a.z() > 0.0f;
}

bool areValidExponents(const osg::Vec2& e)
{
    return std::isfinite(e.x()) && std::isfinite(e.y()) && e.x() > 0.0f && e.y() > 0.0f;
}

/** An exponent in a byte, e = byte / 127, within [MIN_EXPONENT, MAX_EXPONENT]. */
unsigned int toExponentByte(float exponent)
{
    return static_cast<unsigned int>(std::lround(std::clamp(exponent, MIN_EXPONENT, MAX_EXPONENT) * 127.0f));
}

/** A scale of the semi-axes whose ellipsoid holds the superquadric, the radius it is packed against:
 * 2^((1 - e)/2) per exponent below 1, at most sqrt(3). superquadric.glsl bounds the glyph on screen
 * by the ellipsoid that touches it, up to 7% smaller; this one stays, since a dataset's largest
 * radius (sqrt(3) times its largest semi-axis, where any exponents are small) is then its tiles'
 * too, and a tile's glyphs decode as the whole cloud's. */
float superquadricBoundScale(const osg::Vec2& exponents)
{
    const float excess = std::max(1.0f - exponents.x(), 0.0f) + std::max(1.0f - exponents.y(), 0.0f);
    return std::min(std::exp2(0.5f * excess), 1.7320508f);
}

/** The L^p norm of (a, b), p >= 1, or the largest for p of 1e9 and more. */
double normOfPair(double a, double b, double p)
{
    a = std::abs(a);
    b = std::abs(b);
    const double largest = std::max(a, b);
    if (!(largest > 0.0) || p >= 1e9)
        return largest;
    return largest * std::pow(std::pow(a / largest, p) + std::pow(b / largest, p), 1.0 / p);
}

/** The extent along w of the unit-frame superquadric of exponents (e1, e2), max w . p over it: the
 * dual of its norm (superquadric.glsl), an L^s* norm of an L^q* norm with 1/q + 1/q* = 1. */
double superquadricSupport(const osg::Vec3d& w, const osg::Vec2& exponents)
{
    auto dual = [](double p) { return p > 1.0 + 1e-9 ? p / (p - 1.0) : 1e9; };
    const double q = 2.0 / exponents.y(), s = 2.0 / exponents.x();
    return normOfPair(normOfPair(w.x(), w.y(), dual(q)), w.z(), dual(s));
}

bool isValidRotation(const osg::Vec4& q)
{
    const float length = q.length();
    return std::isfinite(length) && length > 0.0f;
}

/** A fraction in (0, 1] in 16 bits, at least one step, so that no semi-axis is drawn flat. */
uint16_t toUnorm16(float fraction)
{
    return static_cast<uint16_t>(std::lround(std::clamp(fraction * 65535.0f, 1.0f, 65535.0f)));
}

int16_t toSnorm16(float value)
{
    return static_cast<int16_t>(std::lround(std::clamp(value, -1.0f, 1.0f) * 32767.0f));
}

}

bool GlyphCloud::PackedSource::changedFrom(const osg::Array* current) const
{
    return !packed || current != array || (current && current->getModifiedCount() != modifiedCount);
}

void GlyphCloud::PackedSource::set(const osg::Array* current)
{
    packed = true;
    array = current;
    modifiedCount = current ? current->getModifiedCount() : 0;
}

unsigned int GlyphCloud::countGlyphs(bool report) const
{
    const size_t numPositions = _positions.valid() ? _positions->size() : 0;
    size_t count = numPositions;
    auto limit = [&](const osg::Array* array, const char* what)
    {
        if (!array || array->getNumElements() == numPositions)
            return;
        if (report && numPositions > 0) // a cloud being filled, positions last
            OSG_WARN << "osgGlyphs::GlyphCloud \"" << getName() << "\": the " << what << " array has "
                     << array->getNumElements() << " values for " << numPositions
                     << " positions; only the first " << std::min<size_t>(count, array->getNumElements())
                     << " glyphs are drawn" << std::endl;
        count = std::min<size_t>(count, array->getNumElements());
    };
    limit(_radii.get(), "radius");
    limit(_colors.get(), "colour");
    limit(_scalars.get(), "scalar");
    if (hasVectorShape())
    {
        if (!_vectors.valid() && numPositions && report)
            OSG_INFO << "osgGlyphs::GlyphCloud \"" << getName()
                     << "\": vector glyphs without vectors; nothing is drawn" << std::endl;
        count = _vectors.valid() ? count : 0;
        limit(_vectors.get(), "vector");
    }
    if (hasEllipsoidShape())
    {
        if (!_semiAxes.valid() && numPositions && report)
            OSG_INFO << "osgGlyphs::GlyphCloud \"" << getName()
                     << "\": ellipsoids without semi-axes; nothing is drawn" << std::endl;
        count = _semiAxes.valid() ? count : 0;
        limit(_semiAxes.get(), "semi-axis");
        limit(_orientations.get(), "orientation");
        if (hasSuperquadricShape())
            limit(_exponents.get(), "exponent");
    }
    return static_cast<unsigned int>(count);
}

void GlyphCloud::updateGlyphs(bool report)
{
    const unsigned int count = countGlyphs(report);
    const bool resized = count != _numGlyphs || _skipped.size() != count;
    const osg::Array* vectors = hasVectorShape() ? _vectors.get() : nullptr;
    const osg::Array* semiAxes = hasEllipsoidShape() ? _semiAxes.get() : nullptr;
    const osg::Array* orientations = hasEllipsoidShape() ? _orientations.get() : nullptr;
    const osg::Array* exponents = hasSuperquadricShape() ? _exponents.get() : nullptr;
    const bool ellipsoids = resized || _packedSemiAxes.changedFrom(semiAxes) ||
                            _packedOrientations.changedFrom(orientations) ||
                            _packedExponents.changedFrom(exponents);
    _packedSemiAxes.set(semiAxes);
    _packedOrientations.set(orientations);
    _packedExponents.set(exponents);
    if (resized)
        _numGlyphs = count;
    if (ellipsoids)
        packEllipsoids(); // before the radii: the largest semi-axes are the ellipsoids' radii
    const bool positions = resized || _packedPositions.changedFrom(_positions.get());
    const bool radii = resized || _packedRadii.changedFrom(getPackedRadiusSource());
    const bool scalars = resized || _packedScalars.changedFrom(_scalars.get());
    const bool vectorsChanged = resized || _packedVectors.changedFrom(vectors);
    _packedPositions.set(_positions.get());
    _packedRadii.set(getPackedRadiusSource());
    _packedScalars.set(_scalars.get());
    _packedVectors.set(vectors);

    if (resized)
    {
        _skipped.assign(count, 0);
        _packed->assign(count, 0u);
        _unpacked->assign(_compressedAttributes ? 0 : count, osg::Vec2());
        updateSelectionElements(); // the selection's pass reads only glyphs the arrays hold
    }
    if (scalars)
        updateDataRange();
    if (radii)
        updateRadiusScale();
    const std::vector<unsigned int> flipped =
        updateSkipped(positions, radii, scalars, vectorsChanged, ellipsoids);
    if (radii)
        packRadii();
    else if (!flipped.empty())
    {
        for (unsigned int i : flipped)
            packRadius(i);
        _packed->dirty();
        _unpacked->dirty();
    }
    if (scalars)
        packScalars();
    if (positions)
        packPositions();
    if (report && (positions || radii || scalars || vectorsChanged || ellipsoids))
        reportSkipped();
    updateScalarMapping();
    if (positions || radii || vectorsChanged || ellipsoids || !flipped.empty())
        updateChunks();
    buildPrimitives();
}

std::vector<unsigned int> GlyphCloud::updateSkipped(bool positions, bool radii, bool scalars, bool vectors,
                                                    bool ellipsoids)
{
    std::vector<unsigned int> flipped;
    // Sets or clears one reason for every glyph; notes the glyphs that became drawn or skipped.
    auto update = [&](uint8_t reason, auto applies)
    {
        for (unsigned int i = 0; i < _numGlyphs; ++i)
        {
            uint8_t& flags = _skipped[i];
            const uint8_t updated = applies(i) ? uint8_t(flags | reason) : uint8_t(flags & ~reason);
            if ((updated == 0) != (flags == 0))
                flipped.push_back(i);
            flags = updated;
        }
    };
    if (positions)
        update(SKIP_POSITION, [&](unsigned int i) { return !isFinite((*_positions)[i]); });
    // An ellipsoid's radius is its largest semi-axis, which SKIP_SEMI_AXES checks.
    if (radii && _radii.valid() && !hasEllipsoidShape())
        update(SKIP_RADIUS,
               [&](unsigned int i) { return !(std::isfinite((*_radii)[i]) && (*_radii)[i] > 0.0f); });
    else if (radii)
        update(SKIP_RADIUS, [](unsigned int) { return false; });
    if (scalars)
        update(SKIP_SCALAR,
               [&](unsigned int i) { return _scalars.valid() && !std::isfinite((*_scalars)[i]); });
    if (vectors && hasVectorShape())
    {
        update(SKIP_VECTOR, [&](unsigned int i) { return !isFinite((*_vectors)[i]); });
        update(SKIP_ZERO_VECTOR, [&](unsigned int i) { return (*_vectors)[i].length2() == 0.0f; });
    }
    else if (vectors)
        update(SKIP_VECTOR | SKIP_ZERO_VECTOR, [](unsigned int) { return false; });
    if (ellipsoids && hasEllipsoidShape())
    {
        update(SKIP_SEMI_AXES, [&](unsigned int i) { return !areValidSemiAxes((*_semiAxes)[i]); });
        update(SKIP_ORIENTATION, [&](unsigned int i)
               { return _orientations.valid() && !isValidRotation((*_orientations)[i]); });
        update(
            SKIP_EXPONENTS, [&](unsigned int i)
            { return hasSuperquadricShape() && _exponents.valid() && !areValidExponents((*_exponents)[i]); });
    }
    else if (ellipsoids)
        update(SKIP_SEMI_AXES | SKIP_ORIENTATION | SKIP_EXPONENTS, [](unsigned int) { return false; });
    _numSkipped =
        static_cast<unsigned int>(_numGlyphs - std::count(_skipped.begin(), _skipped.end(), uint8_t(0)));
    return flipped;
}

GlyphCloud::PackingScales GlyphCloud::getOwnPackingScales() const
{
    PackingScales scales;
    scales.scalarMin = std::numeric_limits<float>::max();
    scales.scalarMax = std::numeric_limits<float>::lowest();
    for (unsigned int i = 0; _scalars.valid() && i < _numGlyphs; ++i)
    {
        const float s = (*_scalars)[i];
        if (std::isfinite(s))
        {
            scales.scalarMin = std::min(scales.scalarMin, s);
            scales.scalarMax = std::max(scales.scalarMax, s);
        }
    }
    const osg::FloatArray* radii = getPackedRadiusSource();
    for (unsigned int i = 0; radii && i < _numGlyphs; ++i)
        if (std::isfinite((*radii)[i]))
            scales.largestRadius = std::max(scales.largestRadius, (*radii)[i]);
    return scales;
}

void GlyphCloud::setSharedPackingScales(const PackingScales& scales)
{
    _hasSharedScales = true;
    _sharedScales = scales;
    updateDataRange();
    updateRadiusScale();
    packRadii();
    packScalars();
    updateScalarMapping();
    updateChunks(); // the chunk boxes hold the radii as the GPU decodes them
    buildPrimitives();
    dirtyBound();
}

void GlyphCloud::updateDataRange()
{
    _dataMin = std::numeric_limits<float>::max();
    _dataMax = std::numeric_limits<float>::lowest();
    for (unsigned int i = 0; _scalars.valid() && i < _numGlyphs; ++i)
    {
        const float s = (*_scalars)[i];
        if (std::isfinite(s))
        {
            _dataMin = std::min(_dataMin, s);
            _dataMax = std::max(_dataMax, s);
        }
    }
    if (_hasSharedScales)
    {
        _dataMin = _sharedScales.scalarMin;
        _dataMax = _sharedScales.scalarMax;
    }
    if (_dataMin > _dataMax)
        _dataMin = _dataMax = 0.0f;
    if (_autoRange)
    {
        _rangeMin = _dataMin;
        _rangeMax = _dataMax;
    }
    updateQuantisationRange();
}

void GlyphCloud::updateRadiusScale()
{
    // Radii are stored relative to the largest, which keeps half floats precise at any scale.
    _radiusScale = _radius;
    if (const osg::FloatArray* radii = getPackedRadiusSource())
    {
        _radiusScale = 0.0f;
        for (unsigned int i = 0; i < _numGlyphs; ++i)
            if (std::isfinite((*radii)[i]))
                _radiusScale = std::max(_radiusScale, (*radii)[i]);
        if (_hasSharedScales)
            _radiusScale = _sharedScales.largestRadius;
    }
    _radiusScaleUniform->set(_radiusScale);
}

bool GlyphCloud::updateQuantisationRange()
{
    // The colour range: values beyond it clamp to the same colours anyway, 16 bits over it are
    // finer than any colour map, and clouds of one range (the tiles of a dataset) quantise
    // alike. The data's range where the colour range is empty or not finite.
    float lo = std::min(_rangeMin, _rangeMax), hi = std::max(_rangeMin, _rangeMax);
    if (!std::isfinite(lo) || !std::isfinite(hi) || !(lo < hi))
    {
        lo = _dataMin;
        hi = _dataMax;
    }
    const bool changed = lo != _quantisedMin || hi != _quantisedMax;
    _quantisedMin = lo;
    _quantisedMax = hi;
    return changed;
}

void GlyphCloud::packRadius(unsigned int i)
{
    const bool radiusValid = _radiusScale > 0.0f && _radiusScale <= std::numeric_limits<float>::max();
    const osg::FloatArray* radii = getPackedRadiusSource();
    const float relative = radii ? (*radii)[i] / _radiusScale : 1.0f;
    const bool drawn = radiusValid && _skipped[i] == 0;
    const uint16_t half = !drawn ? 0 : radii ? detail::toHalf(relative) : HALF_ONE;
    uint32_t& word = (*_packed)[i];
    word = (word & 0xffff0000u) | half;
    if (!_compressedAttributes)
        (*_unpacked)[i].x() = drawn ? relative : 0.0f;
}

void GlyphCloud::packRadii()
{
    catchUpWithResizedArrays();
    _unpacked->resize(_compressedAttributes ? 0 : _numGlyphs);
    for (unsigned int i = 0; i < _numGlyphs; ++i)
        packRadius(i);
    const bool radiusValid = std::isfinite(_radiusScale) && _radiusScale > 0.0f;
    if (!radiusValid)
        _numSkipped = _numGlyphs;
    _packed->dirty();
    _unpacked->dirty();
}

uint16_t GlyphCloud::quantiseScalar(float scalar, const osg::Vec2& range)
{
    const double span = double(range.y()) - double(range.x());
    if (!std::isfinite(scalar) || !(span > 0.0) || !std::isfinite(span))
        return 0;
    // std::lround on the clamped value, half away from zero, without a call: the conversion
    // truncates, and from 0 on the fraction left is exact.
    const double steps = std::clamp((double(scalar) - range.x()) * (65535.0 / span), 0.0, 65535.0);
    const uint16_t whole = static_cast<uint16_t>(steps);
    return static_cast<uint16_t>(whole + (steps - whole >= 0.5 ? 1 : 0));
}

float GlyphCloud::dequantiseScalar(uint16_t step, const osg::Vec2& range)
{
    return static_cast<float>(double(range.x()) + (double(range.y()) - double(range.x())) * (step / 65535.0));
}

void GlyphCloud::packScalars()
{
    catchUpWithResizedArrays();
    // The scalar over the quantisation range: 16 bits in the packed word, or a float in [0, 1]
    // (beyond it where the data is) when uncompressed.
    const double span = double(_quantisedMax) - double(_quantisedMin);
    const osg::Vec2 range = getScalarQuantisationRange();
    _unpacked->resize(_compressedAttributes ? 0 : _numGlyphs);
    for (unsigned int i = 0; i < _numGlyphs; ++i)
    {
        const float s = _scalars.valid() ? (*_scalars)[i] : 0.0f;
        const uint32_t steps = _scalars.valid() ? quantiseScalar(s, range) : 0u;
        uint32_t& word = (*_packed)[i];
        word = (word & 0xffffu) | (steps << 16);
        if (!_compressedAttributes)
            (*_unpacked)[i].y() = _scalars.valid() && span > 0.0 && _skipped[i] == 0
                                      ? static_cast<float>((s - double(_quantisedMin)) / span)
                                      : 0.0f;
    }
    _packed->dirty();
    _unpacked->dirty();
}

void GlyphCloud::reportSkipped() const
{
    unsigned int counts[NUM_SKIP_REASONS] = {};
    if (_numSkipped > 0)
        for (uint8_t flags : _skipped)
            for (int bit = 0; flags != 0 && bit < NUM_SKIP_REASONS; ++bit)
                counts[bit] += (flags >> bit) & 1u;
    const bool radiusValid = std::isfinite(_radiusScale) && _radiusScale > 0.0f;
    auto report = [&](unsigned int bad, const char* problem)
    {
        if (bad)
            OSG_WARN << "osgGlyphs::GlyphCloud \"" << getName() << "\": " << bad << " of " << _numGlyphs
                     << " glyphs " << problem << "; they are skipped" << std::endl;
    };
    report(counts[0], "have a non-finite position (NaN or inf)");
    report(radiusValid ? counts[1] : _numGlyphs, "have a radius that is not finite and > 0");
    report(counts[2], "have a non-finite scalar (NaN or inf)");
    report(counts[3], "have a non-finite vector (NaN or inf)");
    report(counts[5], "have semi-axes that are not all finite and > 0");
    report(counts[6], "have an orientation quaternion that is zero or not finite");
    report(counts[7], "have superquadric exponents that are not both finite and > 0");
    if (counts[4])
        OSG_INFO << "osgGlyphs::GlyphCloud \"" << getName() << "\": " << counts[4] << " of " << _numGlyphs
                 << " glyphs have a zero vector and no direction; they are not drawn" << std::endl;
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

float GlyphCloud::getAxesShapeRadius(const osg::Vec3& semiAxes, const osg::Vec2& exponents)
{
    if (!areValidSemiAxes(semiAxes) || !areValidExponents(exponents))
        return 0.0f;
    const osg::Vec2 stored(float(toExponentByte(exponents.x())) / 127.0f,
                           float(toExponentByte(exponents.y())) / 127.0f);
    return std::max(semiAxes.x(), std::max(semiAxes.y(), semiAxes.z())) * superquadricBoundScale(stored);
}

void GlyphCloud::packEllipsoids()
{
    const unsigned int count = hasEllipsoidShape() ? _numGlyphs : 0;
    _ellipsoidRadii->resize(count);
    _packedAxes->resize(count);
    _packedRotations->resize(count);
    for (unsigned int i = 0; i < count; ++i)
    {
        const osg::Vec3& a = (*_semiAxes)[i];
        const osg::Vec2 e =
            hasSuperquadricShape() && _exponents.valid() ? (*_exponents)[i] : ELLIPSOID_EXPONENTS;
        const bool valid = areValidSemiAxes(a) && areValidExponents(e);
        // A superquadric's radius bounds it: its semi-axes are fractions of that, and the 16 bits
        // left hold its exponents.
        const unsigned int exponentBytes =
            hasSuperquadricShape() && valid ? (toExponentByte(e.x()) << 8) | toExponentByte(e.y()) : 0u;
        const float largest = valid ? getAxesShapeRadius(a, e) : 0.0f;
        (*_ellipsoidRadii)[i] = largest;
        (*_packedAxes)[i] =
            valid ? osg::Vec4us(toUnorm16(a.x() / largest), toUnorm16(a.y() / largest),
                                toUnorm16(a.z() / largest), static_cast<uint16_t>(exponentBytes))
                  : osg::Vec4us();
        osg::Vec4 q = _orientations.valid() ? (*_orientations)[i] : IDENTITY_ROTATION;
        if (!isValidRotation(q))
        {
            (*_packedRotations)[i] = osg::Vec4s();
            continue;
        }
        q /= q.length();
        if (q.w() < 0.0f)
            q = -q; // the same rotation
        (*_packedRotations)[i] =
            osg::Vec4s(toSnorm16(q.x()), toSnorm16(q.y()), toSnorm16(q.z()), toSnorm16(q.w()));
    }
    _ellipsoidRadii->dirty();
    _packedAxes->dirty();
    _packedRotations->dirty();
}

void GlyphCloud::decodeEllipsoid(unsigned int i, osg::Vec3 semiAxes[3]) const
{
    // decode.glsl: normalised 16-bit values, the quaternion normalised again.
    const osg::Vec4us& a = (*_packedAxes)[i];
    const osg::Vec4s& r = (*_packedRotations)[i];
    osg::Quat q(std::max(r.x() / 32767.0, -1.0), std::max(r.y() / 32767.0, -1.0),
                std::max(r.z() / 32767.0, -1.0), std::max(r.w() / 32767.0, -1.0));
    q /= q.length();
    const float radius = decodeRadius(i);
    for (int k = 0; k < 3; ++k)
    {
        osg::Vec3 body;
        body[k] = radius * (a[k] / 65535.0f);
        semiAxes[k] = q * body;
    }
}

osg::Vec2 GlyphCloud::decodeExponents(unsigned int i) const
{
    if (!hasSuperquadricShape() || i >= _packedAxes->size())
        return ELLIPSOID_EXPONENTS;
    const unsigned int word = (*_packedAxes)[i].w();
    return osg::Vec2(float(word >> 8) / 127.0f, float(word & 255u) / 127.0f);
}

float GlyphCloud::decodeRadius(unsigned int i) const
{
    const uint16_t halfRadius = i < _numGlyphs ? static_cast<uint16_t>((*_packed)[i] & 0xffffu) : 0;
    if (halfRadius == 0)
        return 0.0f;
    const float relative = _compressedAttributes ? detail::fromHalf(halfRadius) : (*_unpacked)[i].x();
    return relative * _radiusScale;
}

void GlyphCloud::packPositions()
{
    catchUpWithResizedArrays();
    const unsigned int count = _compressedPositions && _positions.valid() ? _positions->size() : 0;
    const detail::PositionGrid grid =
        count ? detail::PositionGrid::fit(*_positions, count) : detail::PositionGrid();
    _positionGrid.set(grid.offset.x(), grid.offset.y(), grid.offset.z(), grid.step);
    _positionGridUniform->set(_positionGrid);
    if (_compressedPositions)
        _quantisedPositions->setUserValue(POSITION_GRID_USER_VALUE, _positionGrid);
    _quantisedPositions->resize(count);
    for (unsigned int i = 0; i < count; ++i)
        (*_quantisedPositions)[i] = grid.quantise((*_positions)[i]);
    _quantisedPositions->dirty();
}

osg::Vec3 GlyphCloud::drawnPosition(unsigned int i) const
{
    if (!_compressedPositions)
        return (*_positions)[i];
    detail::PositionGrid grid;
    grid.offset.set(_positionGrid.x(), _positionGrid.y(), _positionGrid.z());
    grid.step = _positionGrid.w();
    return grid.decode((*_quantisedPositions)[i]);
}

osg::BoundingBox GlyphCloud::computeGlyphBox(unsigned int i) const
{
    osg::BoundingBox box;
    const float decoded = decodeRadius(i);
    if (decoded == 0.0f)
        return box;
    const float widest = _shape == GlyphShape::Arrow ? std::max(_arrowParams.y(), 1.0f) : 1.0f;
    const float radius = decoded * widest;
    const osg::Vec3 pad(radius, radius, radius);
    const osg::Vec3 p = drawnPosition(i);
    if (hasEllipsoidShape())
    {
        // The extent along each of the cloud's axes: the support of the shape in the frame where its
        // semi-axes are unit, along that row of the semi-axes (for an ellipsoid, the row's length).
        osg::Vec3 semiAxes[3];
        decodeEllipsoid(i, semiAxes);
        const osg::Vec2 exponents = decodeExponents(i);
        osg::Vec3 extent;
        for (int row = 0; row < 3; ++row)
            extent[row] = static_cast<float>(superquadricSupport(
                osg::Vec3d(semiAxes[0][row], semiAxes[1][row], semiAxes[2][row]), exponents));
        box.expandBy(p - extent);
        box.expandBy(p + extent);
        return box;
    }
    if (!hasVectorShape())
    {
        box.expandBy(p - pad);
        box.expandBy(p + pad);
        return box;
    }
    // The glyph lies within its radius of the segment from tail to head.
    const osg::Vec3& v = (*_vectors)[i];
    const float magnitude = v.length();
    const osg::Vec3 axis = v / magnitude;
    const float length = _uniformLength ? _lengthScale : _lengthScale * magnitude;
    const osg::Vec3 tail = p - axis * (length * getAnchorFraction(_anchor));
    for (const osg::Vec3& end : {tail, tail + axis * length})
    {
        box.expandBy(end - pad);
        box.expandBy(end + pad);
    }
    return box;
}

osg::BoundingBox GlyphCloud::computeBoundingBox() const
{
    osg::BoundingBox local;
    for (unsigned int i = 0; i < _numGlyphs; ++i)
        local.expandBy(computeGlyphBox(i));
    _localBoundingBox = local;
    if (!local.valid())
        return local;
    // The nearest floats outside the exact box.
    const auto below = [](double value)
    {
        const float single = static_cast<float>(value);
        return single > value ? std::nextafter(single, -std::numeric_limits<float>::max()) : single;
    };
    const auto above = [](double value)
    {
        const float single = static_cast<float>(value);
        return single < value ? std::nextafter(single, std::numeric_limits<float>::max()) : single;
    };
    osg::BoundingBox box;
    for (int axis = 0; axis < 3; ++axis)
    {
        box._min[axis] = below(_origin[axis] + local._min[axis]);
        box._max[axis] = above(_origin[axis] + local._max[axis]);
    }
    return box;
}
