#include <osgGlyphsData/GlyphMapping>

#include "NeighbourDistance.h"
#include "PointColumns.h"
#include "SymmetricTensor.h"

#include <osgGlyphsData/Elements>

#include <osg/BoundingBox>
#include <osgDB/FileUtils>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <set>
#include <sstream>

using namespace osgGlyphs;
using namespace osgGlyphsData;
using namespace osgGlyphsData::detail;

namespace
{

/** The categorical palette of types and species (Tableau 10). */
const osg::Vec4 CATEGORY_PALETTE[] = {{0.122f, 0.467f, 0.706f, 1.0f}, {1.000f, 0.498f, 0.055f, 1.0f},
                                      {0.173f, 0.627f, 0.173f, 1.0f}, {0.839f, 0.153f, 0.157f, 1.0f},
                                      {0.580f, 0.404f, 0.741f, 1.0f}, {0.549f, 0.337f, 0.294f, 1.0f},
                                      {0.890f, 0.467f, 0.761f, 1.0f}, {0.498f, 0.498f, 0.498f, 1.0f},
                                      {0.737f, 0.741f, 0.133f, 1.0f}, {0.090f, 0.745f, 0.812f, 1.0f}};
const int NUM_CATEGORY_COLORS = sizeof(CATEGORY_PALETTE) / sizeof(CATEGORY_PALETTE[0]);

/** Glyphs of data without any colour information. */
const osg::Vec4 UNIFORM_COLOR(0.35f, 0.55f, 0.80f, 1.0f);

/** The most categories a colour key lists. */
const std::size_t MAX_KEY_CATEGORIES = 12;

/** Velocity columns tried, in order, when --vector is not given. */
const std::vector<std::vector<std::string>> VECTOR_CANDIDATES = {
    {"vx", "vy", "vz"}, {"velo_x", "velo_y", "velo_z"}, {"velocity_x", "velocity_y", "velocity_z"}};

/** Ellipsoids' shape columns tried, in order: LAMMPS's diameters, OVITO's semi-axes. */
const std::vector<std::vector<std::string>> SHAPE_CANDIDATES = {
    {"shapex", "shapey", "shapez"}, {"Aspherical Shape.X", "Aspherical Shape.Y", "Aspherical Shape.Z"}};
const float SHAPE_FACTORS[] = {0.5f, 1.0f};

/** Quaternion columns, as x, y, z, w: LAMMPS's and GSD's, OVITO's. */
const std::vector<std::vector<std::string>> ROTATION_CANDIDATES = {
    {"quati", "quatj", "quatk", "quatw"},
    {"Orientation.X", "Orientation.Y", "Orientation.Z", "Orientation.W"}};

/** Superquadrics' exponents: OVITO's Superquadric Roundness (Phi, along the body z axis; Theta,
 * around it: Barr's e1 and e2), by its component names or as X and Y. */
const std::vector<std::vector<std::string>> ROUNDNESS_CANDIDATES = {
    {"Superquadric Roundness.Phi", "Superquadric Roundness.Theta"},
    {"Superquadric Roundness.X", "Superquadric Roundness.Y"}};

/** OVITO's roundness 0 is a box: the sharpest exponent the glyphs draw. */
const float SHARPEST_ROUNDNESS = 0.1f;

/** What --color-by names of a tensor, in the order of TensorQuantity. */
const char* const TENSOR_QUANTITIES[] = {"trace", "anisotropy", "eigenvalue1", "eigenvalue2", "eigenvalue3"};

/** The smallest semi-axis of a tensor's glyph, as a fraction of the default radius. */
const float TENSOR_FLOOR = 0.05f;

/** Colour columns, as PLY files name them. */
const std::vector<std::string> RGB_COLUMNS = {"red", "green", "blue"};

/** "a,b,c" */
std::string joinColumns(const std::vector<std::string>& names, const char* separator = ",")
{
    std::string list;
    for (const std::string& name : names)
        list += (list.empty() ? "" : separator) + name;
    return list;
}

/** 4 significant digits. */
std::string formatNumber(float value)
{
    char text[32];
    std::snprintf(text, sizeof(text), "%.4g", value);
    return text;
}

osg::Vec4ub toVec4ub(const osg::Vec4& color)
{
    auto channel = [](float c)
    { return static_cast<unsigned char>(std::lround(std::clamp(c, 0.0f, 1.0f) * 255.0f)); };
    return osg::Vec4ub(channel(color.r()), channel(color.g()), channel(color.b()), channel(color.a()));
}

const Element& elementOf(float value)
{
    if (!std::isfinite(value) || value < 0.0f || value > 1000.0f)
        return getUnknownElement();
    return getElement(static_cast<unsigned int>(std::lround(value)));
}

}

void osgGlyphsData::applyGlyphStyle(GlyphCloud& cloud, const GlyphMappingOptions& options)
{
    cloud.setShape(options.shape);
    cloud.setTechnique(createTechnique(options.technique).get());
    cloud.setLit(options.lit);
    if (options.colorMap.valid())
        cloud.setColorMap(options.colorMap.get());
    if (options.hasRange)
        cloud.setScalarRange(options.rangeMin, options.rangeMax);
}

std::string GlyphMapper::frameName(const PointData& data) const
{
    return _multiFrame ? data.getSource() + " timestep " + std::to_string(data.getTimestep())
                       : data.getSource();
}

std::string GlyphMapper::missingColumn(const std::string& option, const std::string& column,
                                       const PointData& data) const
{
    return option + ": no column '" + column + "' in " + frameName(data) + "; " + listColumns(data);
}

bool GlyphMapper::prepare(const PointDataset& dataset, std::size_t startFrame, std::string& error)
{
    _multiFrame = _namesTimesteps || dataset.getNumFrames() > 1;
    const PointData* data = dataset.getFrame(startFrame);
    if (!data)
    {
        error = dataset.getSource() + ": no frame " + std::to_string(startFrame);
        return false;
    }
    std::vector<osg::Vec3f> positions;
    osg::Vec3d origin;
    if (!getPositions(*data, _options.positionColumns, positions, origin, error))
    {
        error = (_options.positionColumns.empty() ? frameName(*data) : option("position")) + ": " + error;
        return false;
    }
    if (!resolveEllipsoids(*data, error))
        return false;
    const bool vectorShape = osgGlyphs::isVectorShape(_options.shape);
    if (!resolveVectors(*data, vectorShape, error) || !resolveColor(*data, error))
        return false;
    if (!_options.radiusColumn.empty() && !data->hasColumn(_options.radiusColumn))
    {
        error = missingColumn(option("radius-by"), _options.radiusColumn, *data);
        return false;
    }
    computeBounds(positions);
    _positionOrigin = origin;
    computeSizes(*data, positions);
    if (!computeTensorScale(*data, error))
        return false;

    _key = ColorKey();
    if (usesScalars())
    {
        _key.kind = ColorKey::Scalar;
        _key.title = _colorSource == ColorSource::Speed ? "speed" : _colorColumn;
        _key.colorMap = _options.colorMap.valid() ? _options.colorMap.get() : ColorMap::getBuiltin("viridis");
        if (!computeRange(dataset, error))
            return false;
    }
    else if (_colorSource == ColorSource::Element || _colorSource == ColorSource::Category)
        buildCategoryKey(*data);
    return true;
}

bool GlyphMapper::resolveEllipsoids(const PointData& data, std::string& error)
{
    _semiAxisColumns.clear();
    _rotationColumns.clear();
    _exponentColumns.clear();
    if (!_options.tensorColumns.empty())
    {
        for (const std::string& column : _options.tensorColumns)
            if (!data.hasColumn(column))
            {
                error = missingColumn(option("tensor"), column, data);
                return false;
            }
        if (_options.shapeGiven && !isAxesShape(_options.shape))
        {
            error = option("tensor") + " draws ellipsoids or superquadrics, not " + option("glyph") + " " +
                    getShapeName(_options.shape);
            return false;
        }
        if (!_options.shapeGiven)
            _options.shape = GlyphShape::Ellipsoid;
        return true;
    }
    const int shape = findColumnTriple(data, SHAPE_CANDIDATES);
    const auto roundness = std::find_if(ROUNDNESS_CANDIDATES.begin(), ROUNDNESS_CANDIDATES.end(),
                                        [&](const std::vector<std::string>& names)
                                        { return data.hasColumn(names[0]) && data.hasColumn(names[1]); });
    if (_options.shape == GlyphShape::Superquadric && (shape < 0 || roundness == ROUNDNESS_CANDIDATES.end()))
    {
        error = option("glyph") + " superquadric draws tensors (" + option("tensor") +
                ", Kindlmann's glyphs) or shapes with a roundness (OVITO's Aspherical Shape and Superquadric "
                "Roundness); " +
                frameName(data) + " has none";
        return false;
    }
    if (shape >= 0 && !_options.shapeGiven)
        _options.shape =
            roundness != ROUNDNESS_CANDIDATES.end() ? GlyphShape::Superquadric : GlyphShape::Ellipsoid;
    if (!isAxesShape(_options.shape))
        return true;
    if (_options.shape == GlyphShape::Superquadric)
        _exponentColumns = *roundness;
    if (shape < 0)
    {
        error = option("glyph") + " ellipsoid needs semi-axes: no shapex,shapey,shapez in " +
                frameName(data) + "; " + listColumns(data);
        return false;
    }
    _semiAxisColumns = SHAPE_CANDIDATES[shape];
    _semiAxisFactor = SHAPE_FACTORS[shape];
    for (const std::vector<std::string>& names : ROTATION_CANDIDATES)
        if (std::all_of(names.begin(), names.end(),
                        [&](const std::string& name) { return data.hasColumn(name); }))
        {
            _rotationColumns = names;
            break;
        }
    return true;
}

bool GlyphMapper::resolveVectors(const PointData& data, bool required, std::string& error)
{
    _vectorColumns.clear();
    if (!_options.vectorColumns.empty())
    {
        for (const std::string& column : _options.vectorColumns)
        {
            if (!data.hasColumn(column))
            {
                error = missingColumn(option("vector"), column, data);
                return false;
            }
        }
        _vectorColumns = _options.vectorColumns;
        return true;
    }
    const int found = findColumnTriple(data, VECTOR_CANDIDATES);
    if (found >= 0)
    {
        _vectorColumns = VECTOR_CANDIDATES[found];
        return true;
    }
    if (required)
    {
        error = option("glyph") + " " + getShapeName(_options.shape) + " needs vectors: no vx,vy,vz in " +
                frameName(data) + " (name the columns with " + option("vector") + "); " + listColumns(data);
        return false;
    }
    return true;
}

bool GlyphMapper::resolveColor(const PointData& data, std::string& error)
{
    const std::string& by = _options.colorBy;
    ColumnValues rgb[3];
    _colorColumn.clear();
    const auto quantity = std::find(std::begin(TENSOR_QUANTITIES), std::end(TENSOR_QUANTITIES), by);
    if (!_options.tensorColumns.empty() && (by.empty() || quantity != std::end(TENSOR_QUANTITIES)))
    {
        _colorSource = ColorSource::Tensor;
        _tensorQuantity =
            by.empty() ? TensorQuantity::Trace : TensorQuantity(quantity - std::begin(TENSOR_QUANTITIES));
        _colorColumn = TENSOR_QUANTITIES[int(_tensorQuantity)];
    }
    else if (by == "speed" && !data.hasColumn(by))
    {
        if (_vectorColumns.empty())
        {
            error = option("color-by") + " speed needs velocities: no vx,vy,vz in " + frameName(data) +
                    " (name the columns with " + option("vector") + "); " + listColumns(data);
            return false;
        }
        _colorSource = ColorSource::Speed;
    }
    else if (!by.empty())
    {
        if (!data.hasColumn(by))
        {
            error = missingColumn(option("color-by"), by, data);
            return false;
        }
        _colorSource = ColorSource::Column;
        _colorColumn = by;
    }
    else if (data.hasColumn("element"))
        _colorSource = ColorSource::Element;
    else if (getColumnTriple(data, RGB_COLUMNS, rgb))
    {
        _colorSource = ColorSource::RGB;
        float largest = 0.0f;
        for (const ColumnValues& column : rgb)
            for (float value : *column)
                largest = std::isfinite(value) ? std::max(largest, value) : largest;
        // 0..1, 8 bits (PLY, CSV) or 16 bits (LAS), by the largest value.
        _rgbScale = largest > 255.0f ? 1.0f / 65535.0f : largest > 1.0f ? 1.0f / 255.0f : 1.0f;
    }
    else if (!_vectorColumns.empty())
        _colorSource = ColorSource::Speed;
    else if (data.hasColumn("type") || data.hasColumn("species"))
    {
        _colorSource = ColorSource::Category;
        _colorColumn = data.hasColumn("type") ? "type" : "species";
    }
    else
        _colorSource = ColorSource::Uniform;
    return true;
}

bool GlyphMapper::readTensors(const PointData& data, std::vector<double>& components,
                              std::string& error) const
{
    const std::size_t width = _options.tensorColumns.size(), n = data.getNumPoints();
    components.assign(n * 6, 0.0);
    for (std::size_t k = 0; k < width; ++k)
    {
        const int index = data.findColumn(_options.tensorColumns[k]);
        if (index < 0)
        {
            error = missingColumn(option("tensor"), _options.tensorColumns[k], data);
            return false;
        }
        // Row by row into xx yy zz xy xz yz, the off-diagonal pairs averaged.
        static const int SLOT_OF_ROWS[9] = {0, 3, 4, 3, 1, 5, 4, 5, 2};
        const bool diagonal = width == 6 || k == 0 || k == 4 || k == 8;
        const std::size_t slot = width == 6 ? k : std::size_t(SLOT_OF_ROWS[k]);
        for (std::size_t i = 0; i < n; ++i)
            components[6 * i + slot] += (diagonal ? 1.0 : 0.5) * data.getValue(std::size_t(index), i);
    }
    return true;
}

namespace
{

osgGlyphsData::detail::SymmetricTensor tensorAt(const std::vector<double>& components, std::size_t i)
{
    const double* c = &components[6 * i];
    osgGlyphsData::detail::SymmetricTensor tensor;
    tensor.xx = c[0];
    tensor.yy = c[1];
    tensor.zz = c[2];
    tensor.xy = c[3];
    tensor.xz = c[4];
    tensor.yz = c[5];
    return tensor;
}

}

bool GlyphMapper::computeTensorScale(const PointData& data, std::string& error)
{
    if (_options.tensorColumns.empty())
        return true;
    if (_options.tensorScale > 0.0f)
    {
        _tensorScale = _options.tensorScale;
        return true;
    }
    std::vector<double> components;
    if (!readTensors(data, components, error))
        return false;
    std::vector<double> largest;
    for (std::size_t i = 0; i < data.getNumPoints(); ++i)
    {
        const detail::SymmetricTensor tensor = tensorAt(components, i);
        if (!tensor.isFinite())
            continue;
        const osg::Vec3d values = detail::decompose(tensor).values;
        const double magnitude = std::max(std::abs(values.x()), std::abs(values.z()));
        if (magnitude > 0.0)
            largest.push_back(magnitude);
    }
    _tensorScale = 1.0f;
    if (!largest.empty())
    {
        std::nth_element(largest.begin(), largest.begin() + largest.size() / 2, largest.end());
        _tensorScale = static_cast<float>(_radius / largest[largest.size() / 2]);
    }
    return true;
}

bool GlyphMapper::computeScalars(const PointData& data, std::vector<float>& scalars, std::string& error) const
{
    if (_colorSource == ColorSource::Tensor)
    {
        std::vector<double> components;
        if (!readTensors(data, components, error))
            return false;
        scalars.resize(data.getNumPoints());
        for (std::size_t i = 0; i < scalars.size(); ++i)
        {
            const detail::SymmetricTensor tensor = tensorAt(components, i);
            const osg::Vec3d values = tensor.isFinite() ? detail::decompose(tensor).values : osg::Vec3d();
            double value = tensor.trace();
            if (_tensorQuantity == TensorQuantity::Anisotropy)
                value = detail::fractionalAnisotropy(values);
            else if (_tensorQuantity != TensorQuantity::Trace)
                value = values[int(_tensorQuantity) - int(TensorQuantity::Eigenvalue1)];
            scalars[i] = static_cast<float>(value);
        }
        return true;
    }
    if (_colorSource == ColorSource::Column)
    {
        ColumnValues column;
        if (!column.assign(data, _colorColumn))
        {
            error = missingColumn(option("color-by"), _colorColumn, data);
            return false;
        }
        scalars = *column;
        return true;
    }
    ColumnValues v[3];
    if (!getColumnTriple(data, _vectorColumns, v))
    {
        error = frameName(data) + ": speed needs the columns " + joinColumns(_vectorColumns) + "; " +
                listColumns(data);
        return false;
    }
    scalars.resize(data.getNumPoints());
    for (std::size_t i = 0; i < scalars.size(); ++i)
        scalars[i] = osg::Vec3f((*v[0])[i], (*v[1])[i], (*v[2])[i]).length();
    return true;
}

void GlyphMapper::combineMean(double& sum, std::size_t& count) const
{
    if (!_reduction.valid())
        return;
    std::vector<double> totals{sum, static_cast<double>(count)};
    _reduction->sum(totals);
    sum = totals[0];
    count = static_cast<std::size_t>(totals[1]);
}

bool GlyphMapper::computeRange(const PointDataset& dataset, std::string& error)
{
    if (_options.hasRange)
    {
        _key.min = _options.rangeMin;
        _key.max = _options.rangeMax;
        return true;
    }
    // The range of every frame, so that one colour means one value throughout a file.
    float low = std::numeric_limits<float>::infinity();
    float high = -low;
    std::vector<float> scalars;
    for (const osg::ref_ptr<PointData>& frame : dataset.getFrames())
    {
        std::string frameError;
        if (!computeScalars(*frame, scalars, frameError))
            continue;
        for (float value : scalars)
        {
            if (std::isfinite(value))
            {
                low = std::min(low, value);
                high = std::max(high, value);
            }
        }
    }
    if (_reduction.valid())
    {
        std::vector<double> lows{low}, highs{high};
        _reduction->minimum(lows);
        _reduction->maximum(highs);
        low = static_cast<float>(lows[0]);
        high = static_cast<float>(highs[0]);
    }
    if (!(low <= high))
    {
        error = option("color-by") + " " + _key.title + ": the data has no finite values to colour by";
        return false;
    }
    if (_colorSource == ColorSource::Tensor && _tensorQuantity != TensorQuantity::Anisotropy)
    {
        // Signed: a range even about zero, where a diverging map's middle shows the sign change.
        high = std::max(std::abs(low), std::abs(high));
        low = -high;
    }
    _key.min = low;
    _key.max = high;
    return true;
}

void GlyphMapper::computeBounds(const std::vector<osg::Vec3f>& positions)
{
    // In double: the extent of float positions may exceed the range of a float.
    osg::BoundingBoxd box;
    for (const osg::Vec3f& p : positions)
    {
        if (std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z()))
            box.expandBy(osg::Vec3d(p));
    }
    _positionBounds = box;
}

void GlyphMapper::computeSizes(const PointData& data, const std::vector<osg::Vec3f>& positions)
{
    const bool vectorShape = osgGlyphs::isVectorShape(_options.shape);
    const std::size_t n = data.getNumPoints();
    _radiusColumn = _options.radiusColumn;
    float factor = _options.radius > 0.0f ? _options.radius : 1.0f; // the factor of --radius-by
    if (_radiusColumn.empty() && _options.radius <= 0.0f)
    {
        // Without --radius-by or --radius: a column of radii or diameters (LAMMPS granular dumps).
        if (data.hasColumn("radius"))
            _radiusColumn = "radius";
        else if (data.hasColumn("diameter"))
        {
            _radiusColumn = "diameter";
            factor = 0.5f;
        }
    }
    _elementRadii = _radiusColumn.empty() && _options.radius <= 0.0f && data.hasColumn("element");
    // A typical radius: the unit of the default length scale.
    float typical = 1.0f;
    if (!_radiusColumn.empty() || _elementRadii)
    {
        const double angstroms = data.getAngstromsPerUnit();
        _radius = _elementRadii ? (angstroms > 0.0 ? float(1.0 / angstroms) : 1.0f) : factor;
        double sum = 0.0;
        std::size_t count = 0;
        ColumnValues column;
        column.assign(data, _elementRadii ? "element" : _radiusColumn);
        for (float value : *column)
        {
            const float radius = (_elementRadii ? elementOf(value).covalentRadius : value) * _radius;
            if (std::isfinite(radius) && radius > 0.0f)
            {
                sum += radius;
                ++count;
            }
        }
        combineMean(sum, count);
        typical = count ? static_cast<float>(sum / count) : 1.0f;
    }
    else if (_options.radius > 0.0f)
        typical = _radius = _options.radius;
    else
    {
        osg::BoundingBoxd box = _positionBounds;
        if (_reduction.valid())
        {
            std::vector<double> low(box._min.ptr(), box._min.ptr() + 3),
                high(box._max.ptr(), box._max.ptr() + 3);
            _reduction->minimum(low);
            _reduction->maximum(high);
            box.set(low[0], low[1], low[2], high[0], high[1], high[2]);
        }
        const double diagonal = box.valid() ? (box._max - box._min).length() : 0.0;
        const double spacing = _reduction.valid() ? detail::estimateNeighbourDistance(positions, *_reduction)
                                                  : detail::estimateNeighbourDistance(positions);
        const double radius =
            std::max(spacing * (vectorShape ? 0.2 : 0.4), diagonal / (vectorShape ? 500.0 : 250.0));
        typical = _radius =
            radius > 0.0 ? static_cast<float>(std::min(radius, double(std::numeric_limits<float>::max())))
                         : 0.5f;
    }

    _lengthScale = _options.lengthScale > 0.0f ? _options.lengthScale : 1.0f;
    ColumnValues v[3];
    if (vectorShape && _options.lengthScale <= 0.0f && getColumnTriple(data, _vectorColumns, v))
    {
        double sum = 0.0;
        std::size_t count = 0;
        for (std::size_t i = 0; i < n; ++i)
        {
            const float length = osg::Vec3f((*v[0])[i], (*v[1])[i], (*v[2])[i]).length();
            if (std::isfinite(length) && length > 0.0f)
            {
                sum += length;
                ++count;
            }
        }
        combineMean(sum, count);
        if (count)
            _lengthScale = static_cast<float>(4.0 * typical / (sum / count));
    }
}

osg::Vec4 GlyphMapper::getCategoryColor(float value) const
{
    if (_colorSource == ColorSource::Element)
        return elementOf(value).getColor();
    if (!std::isfinite(value) || std::fabs(value) > 1e6f)
        return CATEGORY_PALETTE[7];
    // LAMMPS types count from 1, categorical columns from 0.
    const long index = std::lround(value) - (_colorColumn == "type" ? 1 : 0);
    return CATEGORY_PALETTE[((index % NUM_CATEGORY_COLORS) + NUM_CATEGORY_COLORS) % NUM_CATEGORY_COLORS];
}

void GlyphMapper::buildCategoryKey(const PointData& data)
{
    const bool elements = _colorSource == ColorSource::Element;
    const std::string column = elements ? "element" : _colorColumn;
    _key.kind = ColorKey::Categories;
    _key.title = elements ? "element" : column;
    std::set<long> values;
    ColumnValues categories;
    categories.assign(data, column);
    for (float value : *categories)
    {
        if (std::isfinite(value) && std::fabs(value) <= 1e6f)
            values.insert(std::lround(value));
        if (values.size() > MAX_KEY_CATEGORIES)
            break;
    }
    if (_reduction.valid())
    {
        std::vector<double> all(values.begin(), values.end());
        _reduction->gather(all);
        values.clear();
        for (double value : all)
            values.insert(static_cast<long>(value));
    }
    const std::vector<std::string>& labels = data.getColumnLabels(column);
    for (long value : values)
    {
        if (_key.categories.size() == MAX_KEY_CATEGORIES)
        {
            _key.categories.emplace_back("...", osg::Vec4(0.0f, 0.0f, 0.0f, 0.0f));
            break;
        }
        std::string label = std::to_string(value);
        if (elements)
            label = elementOf(static_cast<float>(value)).symbol;
        else if (value >= 0 && static_cast<std::size_t>(value) < labels.size())
            label = labels[value];
        _key.categories.emplace_back(label, getCategoryColor(static_cast<float>(value)));
    }
}

osg::ref_ptr<GlyphCloud> GlyphMapper::createCloud(const PointData& data, std::string& error) const
{
    osg::ref_ptr<osg::Vec3Array> positions = new osg::Vec3Array;
    osg::Vec3d origin;
    if (!getPositions(data, _options.positionColumns, positions->asVector(), origin, error))
    {
        error = frameName(data) + ": " + error;
        return nullptr;
    }
    FrameArrays arrays;
    if (!computeArrays(data, arrays, error))
        return nullptr;
    osg::ref_ptr<GlyphCloud> cloud = new GlyphCloud;
    cloud->setName(data.getSource() + " timestep " + std::to_string(data.getTimestep()));
    applyGlyphStyle(*cloud, _options);
    cloud->setCulling(_culling);
    cloud->setOrigin(origin);
    // The positions last: the setters before them work on an empty cloud, and the culling chunks
    // are built once.
    if (arrays.radii.valid())
        cloud->setRadii(arrays.radii.get());
    else
        cloud->setRadius(_radius);
    if (arrays.vectors.valid())
    {
        cloud->setVectors(arrays.vectors.get());
        cloud->setLengthScale(_lengthScale);
    }
    cloud->setSemiAxes(arrays.semiAxes.get());
    cloud->setOrientations(arrays.orientations.get());
    cloud->setExponents(arrays.exponents.get());
    if (arrays.scalars.valid())
    {
        cloud->setScalarRange(_key.min, _key.max); // before the scalars: they are packed once, for it
        cloud->setScalars(arrays.scalars.get());
    }
    else if (arrays.colors.valid())
        cloud->setColors(arrays.colors.get());
    else
        cloud->setColor(UNIFORM_COLOR);
    cloud->setPositions(positions.get());
    return cloud;
}

namespace
{

/** Gives target the contents of source where they differ; true when they did. */
template <class Array>
bool replaceContents(Array* target, Array* source)
{
    if (!target || !source || target->asVector() == source->asVector())
        return false;
    target->asVector().swap(source->asVector());
    target->dirty();
    return true;
}

}

bool GlyphMapper::updateCloud(GlyphCloud& cloud, const PointData& data, std::string& error) const
{
    osg::ref_ptr<osg::Vec3Array> positions = new osg::Vec3Array;
    osg::Vec3d origin;
    if (!getPositions(data, _options.positionColumns, positions->asVector(), origin, error))
    {
        error = frameName(data) + ": " + error;
        return false;
    }
    FrameArrays arrays;
    if (!computeArrays(data, arrays, error))
        return false;
    const bool sameKinds = arrays.radii.valid() == (cloud.getRadii() != nullptr) &&
                           arrays.vectors.valid() == (cloud.getVectors() != nullptr) &&
                           arrays.scalars.valid() == (cloud.getScalars() != nullptr) &&
                           arrays.colors.valid() == (cloud.getColors() != nullptr) &&
                           arrays.semiAxes.valid() == (cloud.getSemiAxes() != nullptr) &&
                           arrays.orientations.valid() == (cloud.getOrientations() != nullptr) &&
                           arrays.exponents.valid() == (cloud.getExponents() != nullptr) &&
                           cloud.getPositions();
    if (!sameKinds)
    {
        error = frameName(data) + ": the cloud was not made by this mapping";
        return false;
    }
    // Positions stay relative to the cloud's origin, which a frame's own may differ from.
    const osg::Vec3d shift = origin - cloud.getOrigin();
    if (shift != osg::Vec3d())
    {
        for (osg::Vec3f& p : positions->asVector())
            p = osg::Vec3f(osg::Vec3d(p) + shift);
    }
    bool changed = replaceContents(cloud.getPositions(), positions.get());
    changed = replaceContents(cloud.getRadii(), arrays.radii.get()) || changed;
    changed = replaceContents(cloud.getVectors(), arrays.vectors.get()) || changed;
    changed = replaceContents(cloud.getScalars(), arrays.scalars.get()) || changed;
    changed = replaceContents(cloud.getColors(), arrays.colors.get()) || changed;
    changed = replaceContents(cloud.getSemiAxes(), arrays.semiAxes.get()) || changed;
    changed = replaceContents(cloud.getOrientations(), arrays.orientations.get()) || changed;
    changed = replaceContents(cloud.getExponents(), arrays.exponents.get()) || changed;
    if (changed)
        cloud.dirtyGlyphs();
    return true;
}

bool GlyphMapper::computeArrays(const PointData& data, FrameArrays& arrays, std::string& error) const
{
    return computeRadii(data, arrays.radii, error) && computeVectors(data, arrays.vectors, error) &&
           computeColors(data, arrays, error) && computeEllipsoids(data, arrays, error);
}

bool GlyphMapper::computeEllipsoids(const PointData& data, FrameArrays& arrays, std::string& error) const
{
    if (!_options.tensorColumns.empty())
    {
        std::vector<double> components;
        if (!readTensors(data, components, error))
            return false;
        const std::size_t n = data.getNumPoints();
        arrays.semiAxes = new osg::Vec3Array(n);
        arrays.orientations = new osg::Vec4Array(n);
        if (_options.shape == GlyphShape::Superquadric)
            arrays.exponents = new osg::Vec2Array(n);
        const float floor = TENSOR_FLOOR * _radius;
        for (std::size_t i = 0; i < n; ++i)
        {
            const detail::SymmetricTensor tensor = tensorAt(components, i);
            if (!tensor.isFinite())
            {
                const float nan = std::numeric_limits<float>::quiet_NaN();
                (*arrays.semiAxes)[i].set(nan, nan, nan); // skipped by the cloud, with a warning
                continue;
            }
            const detail::TensorEigen eigen = detail::decompose(tensor);
            if (arrays.exponents.valid())
            {
                const detail::TensorSuperquadric glyph = detail::kindlmannGlyph(eigen);
                for (int k = 0; k < 3; ++k)
                    (*arrays.semiAxes)[i][k] = std::max(float(glyph.semiAxes[k] * _tensorScale), floor);
                (*arrays.orientations)[i] = glyph.rotation.asVec4();
                (*arrays.exponents)[i] = osg::Vec2(glyph.exponents);
                continue;
            }
            for (int k = 0; k < 3; ++k)
                (*arrays.semiAxes)[i][k] = std::max(float(std::abs(eigen.values[k]) * _tensorScale), floor);
            (*arrays.orientations)[i] = eigen.rotation.asVec4();
        }
        return true;
    }
    if (_semiAxisColumns.empty())
        return true;
    ColumnValues axes[3];
    if (!getColumnTriple(data, _semiAxisColumns, axes))
    {
        error = missingColumn(option("glyph") + " ellipsoid", joinColumns(_semiAxisColumns), data);
        return false;
    }
    const std::size_t n = data.getNumPoints();
    arrays.semiAxes = new osg::Vec3Array(n);
    for (std::size_t i = 0; i < n; ++i)
    {
        osg::Vec3& a = (*arrays.semiAxes)[i];
        a.set((*axes[0])[i], (*axes[1])[i], (*axes[2])[i]);
        a *= _semiAxisFactor;
        if (a == osg::Vec3())
            a.set(_radius, _radius, _radius); // a point particle
    }
    if (_rotationColumns.empty())
        return computeExponents(data, arrays, error);
    ColumnValues q[4];
    for (int k = 0; k < 4; ++k)
        if (!q[k].assign(data, _rotationColumns[k]))
        {
            error = missingColumn(option("glyph") + " ellipsoid", _rotationColumns[k], data);
            return false;
        }
    arrays.orientations = new osg::Vec4Array(n);
    for (std::size_t i = 0; i < n; ++i)
        (*arrays.orientations)[i].set((*q[0])[i], (*q[1])[i], (*q[2])[i], (*q[3])[i]);
    return computeExponents(data, arrays, error);
}

bool GlyphMapper::computeExponents(const PointData& data, FrameArrays& arrays, std::string& error) const
{
    if (_exponentColumns.empty())
        return true;
    ColumnValues e[2];
    for (int k = 0; k < 2; ++k)
        if (!e[k].assign(data, _exponentColumns[k]))
        {
            error = missingColumn(option("glyph") + " superquadric", _exponentColumns[k], data);
            return false;
        }
    // Negative and non-finite exponents stay: the cloud skips their glyphs with a warning.
    const auto exponent = [](float roundness)
    { return roundness >= 0.0f ? std::max(roundness, SHARPEST_ROUNDNESS) : roundness; };
    arrays.exponents = new osg::Vec2Array(data.getNumPoints());
    for (std::size_t i = 0; i < data.getNumPoints(); ++i)
        (*arrays.exponents)[i].set(exponent((*e[0])[i]), exponent((*e[1])[i]));
    return true;
}

bool GlyphMapper::computeRadii(const PointData& data, osg::ref_ptr<osg::FloatArray>& radii,
                               std::string& error) const
{
    if (_radiusColumn.empty() && !_elementRadii)
        return true;
    ColumnValues column;
    if (!column.assign(data, _elementRadii ? "element" : _radiusColumn))
    {
        error = _elementRadii ? frameName(data) + ": no column 'element' for the radii of the elements; " +
                                    listColumns(data)
                              : missingColumn(option("radius-by"), _radiusColumn, data);
        return false;
    }
    radii = new osg::FloatArray(data.getNumPoints());
    for (std::size_t i = 0; i < radii->size(); ++i)
        (*radii)[i] = (_elementRadii ? elementOf((*column)[i]).covalentRadius : (*column)[i]) * _radius;
    return true;
}

bool GlyphMapper::computeVectors(const PointData& data, osg::ref_ptr<osg::Vec3Array>& vectors,
                                 std::string& error) const
{
    if (!osgGlyphs::isVectorShape(_options.shape))
        return true;
    ColumnValues v[3];
    if (!getColumnTriple(data, _vectorColumns, v))
    {
        error = missingColumn(option("vector"), joinColumns(_vectorColumns), data);
        return false;
    }
    vectors = new osg::Vec3Array(data.getNumPoints());
    for (std::size_t i = 0; i < vectors->size(); ++i)
        (*vectors)[i].set((*v[0])[i], (*v[1])[i], (*v[2])[i]);
    return true;
}

bool GlyphMapper::computeColors(const PointData& data, FrameArrays& arrays, std::string& error) const
{
    const std::size_t n = data.getNumPoints();
    if (usesScalars())
    {
        arrays.scalars = new osg::FloatArray;
        return computeScalars(data, arrays.scalars->asVector(), error);
    }
    osg::ref_ptr<osg::Vec4ubArray> colors = new osg::Vec4ubArray(n);
    if (_colorSource == ColorSource::Element || _colorSource == ColorSource::Category)
    {
        const std::string name = _colorSource == ColorSource::Element ? "element" : _colorColumn;
        ColumnValues column;
        if (!column.assign(data, name))
        {
            error = frameName(data) + ": no column '" + name + "' to colour by; " + listColumns(data);
            return false;
        }
        for (std::size_t i = 0; i < n; ++i)
            (*colors)[i] = toVec4ub(getCategoryColor((*column)[i]));
    }
    else if (_colorSource == ColorSource::RGB)
    {
        ColumnValues rgb[3];
        if (!getColumnTriple(data, RGB_COLUMNS, rgb))
        {
            error = frameName(data) + ": no red, green, blue columns; " + listColumns(data);
            return false;
        }
        // An "alpha" column (PLY's name) is read on the scale of the colours.
        ColumnValues alpha;
        const bool hasAlpha = alpha.assign(data, "alpha");
        for (std::size_t i = 0; i < n; ++i)
            (*colors)[i] =
                toVec4ub(osg::Vec4((*rgb[0])[i] * _rgbScale, (*rgb[1])[i] * _rgbScale,
                                   (*rgb[2])[i] * _rgbScale, hasAlpha ? (*alpha)[i] * _rgbScale : 1.0f));
    }
    else
        return true; // one colour
    arrays.colors = colors;
    return true;
}

std::string GlyphMapper::describe() const
{
    std::string text = std::string(getShapeName(_options.shape)) + "s";
    switch (_colorSource)
    {
    case ColorSource::Column:
    case ColorSource::Speed:
    case ColorSource::Tensor:
        text += " coloured by " + _key.title +
                (_colorSource == ColorSource::Speed ? " |" + joinColumns(_vectorColumns) + "|" : "") + " (" +
                _key.colorMap->getName() + ", " + formatNumber(_key.min) + " .. " + formatNumber(_key.max) +
                ")";
        break;
    case ColorSource::Element:
        text += " coloured by element";
        break;
    case ColorSource::RGB:
        text += " in the colours of red,green,blue";
        break;
    case ColorSource::Category:
        text += " coloured by " + _colorColumn;
        break;
    default:
        text += " in one colour";
    }
    if (!_radiusColumn.empty())
        text += ", radius " + formatNumber(_radius) + " x " + _radiusColumn;
    else if (_elementRadii)
        text += ", covalent radii";
    else
        text += ", radius " + formatNumber(_radius);
    if (osgGlyphs::isVectorShape(_options.shape))
        text += ", vectors " + joinColumns(_vectorColumns) + " x " + formatNumber(_lengthScale);
    if (!_options.tensorColumns.empty())
        text += ", tensors " + joinColumns(_options.tensorColumns) +
                (_options.shape == GlyphShape::Superquadric ? " as Kindlmann's superquadrics, "
                                                            : " as ellipsoids, ") +
                formatNumber(_tensorScale) + " per unit of eigenvalue";
    if (!_semiAxisColumns.empty())
        text += (_exponentColumns.empty() ? ", ellipsoids" : ", superquadrics") +
                std::string(" of semi-axes ") + joinColumns(_semiAxisColumns) +
                (_semiAxisFactor != 1.0f ? " x " + formatNumber(_semiAxisFactor) : std::string()) +
                (_rotationColumns.empty() ? std::string() : " turned by " + joinColumns(_rotationColumns)) +
                (_exponentColumns.empty() ? std::string() : ", exponents " + joinColumns(_exponentColumns));
    return text;
}

std::string GlyphMapper::option(const char* name) const
{
    return _options.optionPrefix + name;
}

namespace
{

/** Splits "a,b,c" into exactly count non-empty parts. */
bool splitList(const std::string& text, std::size_t count, std::vector<std::string>& parts)
{
    parts.clear();
    std::istringstream stream(text);
    std::string part;
    while (std::getline(stream, part, ','))
        parts.push_back(part);
    if (!text.empty() && text.back() == ',')
        parts.push_back(std::string());
    return parts.size() == count &&
           std::none_of(parts.begin(), parts.end(), [](const std::string& p) { return p.empty(); });
}

bool parseNumber(const std::string& text, float& value)
{
    char* end = nullptr;
    value = std::strtof(text.c_str(), &end);
    return !text.empty() && end == text.c_str() + text.size() && std::isfinite(value);
}

bool parseSwitch(const std::string& text, bool& value)
{
    if (text == "on" || text == "true" || text == "1")
        value = true;
    else if (text == "off" || text == "false" || text == "0")
        value = false;
    else
        return false;
    return true;
}

bool resolveColorMap(const std::string& name, osg::ref_ptr<ColorMap>& colorMap, std::string& error)
{
    colorMap = ColorMap::getBuiltin(name);
    if (colorMap.valid())
        return true;
    if (!osgDB::fileExists(name))
    {
        error = "'" + name + "': neither a built-in colour map (" +
                joinColumns(ColorMap::getBuiltinNames(), ", ") + ") nor a file";
        return false;
    }
    colorMap = ColorMap::readFile(name, error);
    return colorMap.valid();
}

/** Sets the option; false with error saying what the value should be (without the option's name). */
/** Sets one option from its text; error says what is wrong with the value. */
using OptionSetter = void (*)(GlyphMappingOptions& options, const std::string& name, const std::string& value,
                              std::string& error);

void setColumns(GlyphMappingOptions& options, const std::string& name, const std::string& value,
                std::string& error)
{
    std::vector<std::string>& columns = name == "position" ? options.positionColumns : options.vectorColumns;
    if (!splitList(value, 3, columns))
        error = "'" + value + "': give 3 column names separated by commas";
}

void setPositiveNumber(GlyphMappingOptions& options, const std::string& name, const std::string& value,
                       std::string& error)
{
    float& number = name == "radius" ? options.radius : options.lengthScale;
    if (!parseNumber(value, number) || !(number > 0.0f))
        error = "'" + value + "': must be a positive number";
}

void setColumn(GlyphMappingOptions& options, const std::string& name, const std::string& value,
               std::string& error)
{
    (name == "radius-by" ? options.radiusColumn : options.colorBy) = value;
    if (value.empty())
        error = "needs a column name";
}

void setTensor(GlyphMappingOptions& options, const std::string&, const std::string& value, std::string& error)
{
    if (!splitList(value, 6, options.tensorColumns) && !splitList(value, 9, options.tensorColumns))
        error =
            "'" + value + "': give 6 column names (xx,yy,zz,xy,xz,yz) or 9 (row by row), separated by commas";
}

void setTensorScale(GlyphMappingOptions& options, const std::string&, const std::string& value,
                    std::string& error)
{
    if (!parseNumber(value, options.tensorScale) || !(options.tensorScale > 0.0f))
        error = "'" + value + "': must be a positive number";
}

void setColorMap(GlyphMappingOptions& options, const std::string&, const std::string& value,
                 std::string& error)
{
    resolveColorMap(value, options.colorMap, error);
}

void setRange(GlyphMappingOptions& options, const std::string&, const std::string& value, std::string& error)
{
    std::vector<std::string> bounds;
    options.hasRange = splitList(value, 2, bounds) && parseNumber(bounds[0], options.rangeMin) &&
                       parseNumber(bounds[1], options.rangeMax);
    if (!options.hasRange)
        error = "'" + value + "': give the minimum and the maximum";
    else if (!(options.rangeMin < options.rangeMax))
        error = "'" + value + "': the minimum must be less than the maximum";
}

void setShape(GlyphMappingOptions& options, const std::string&, const std::string& value, std::string& error)
{
    if (!parseShape(value, options.shape))
        error = "'" + value + "': unknown shape (sphere, cone, arrow, cylinder, ellipsoid)";
    else
        options.shapeGiven = true;
}

void setTechnique(GlyphMappingOptions& options, const std::string&, const std::string& value,
                  std::string& error)
{
    if (createTechnique(value).valid())
        options.technique = value;
    else
        error =
            "'" + value + "': unknown technique (default, " + joinColumns(getTechniqueNames(), ", ") + ")";
}

void setLit(GlyphMappingOptions& options, const std::string&, const std::string& value, std::string& error)
{
    if (!parseSwitch(value, options.lit))
        error = "'" + value + "': on or off";
}

void setUnlit(GlyphMappingOptions& options, const std::string&, const std::string& value, std::string& error)
{
    options.lit = false;
    if (!value.empty())
        error = "takes no value";
}

/** Every option, in the order the help lists them. */
const std::pair<const char*, OptionSetter> OPTIONS[] = {
    {"position", setColumns},  {"vector", setColumns},      {"radius", setPositiveNumber},
    {"radius-by", setColumn},  {"color-by", setColumn},     {"color", setColumn},
    {"colormap", setColorMap}, {"range", setRange},         {"length-scale", setPositiveNumber},
    {"glyph", setShape},       {"technique", setTechnique}, {"lit", setLit},
    {"unlit", setUnlit},       {"tensor", setTensor},       {"tensor-scale", setTensorScale}};

bool setOption(GlyphMappingOptions& options, const std::string& name, const std::string& value,
               std::string& error)
{
    for (const auto& option : OPTIONS)
    {
        if (name == option.first)
        {
            option.second(options, name, value, error);
            return error.empty();
        }
    }
    error = "unknown option (" + joinColumns(getGlyphMappingOptionNames(), ", ") + ")";
    return false;
}

}

const std::vector<std::string>& osgGlyphsData::getGlyphMappingOptionNames()
{
    static const std::vector<std::string> names = []
    {
        std::vector<std::string> all;
        for (const auto& option : OPTIONS)
            all.push_back(option.first);
        return all;
    }();
    return names;
}

bool osgGlyphsData::setGlyphMappingOption(GlyphMappingOptions& options, const std::string& name,
                                          const std::string& value, std::string& error)
{
    std::string what;
    if (setOption(options, name, value, what))
        return true;
    error = options.optionPrefix + name + (what[0] == '\'' ? " " : ": ") + what;
    return false;
}
