#include <osgGlyphsData/PointData>

#include "PointColumns.h"

#include <cmath>
#include <utility>

using namespace osgGlyphsData;
using namespace osgGlyphsData::detail;

PointData::PointData(std::size_t numPoints)
    : _numPoints(numPoints), _tilt(0.0, 0.0, 0.0), _hasBox(false), _timestep(0)
{
}

PointData::~PointData() {}

bool PointData::setNumPoints(std::size_t numPoints)
{
    if (!_columns.empty() && numPoints != _numPoints)
        return false;
    _numPoints = numPoints;
    return true;
}

int PointData::findColumn(const std::string& name) const
{
    for (std::size_t i = 0; i < _names.size(); ++i)
    {
        if (_names[i] == name)
            return static_cast<int>(i);
    }
    return -1;
}

const std::vector<float>* PointData::getColumn(const std::string& name) const
{
    const int index = findColumn(name);
    return index < 0 ? nullptr : &_columns[index];
}

std::vector<float>* PointData::getColumn(const std::string& name)
{
    const int index = findColumn(name);
    return index < 0 ? nullptr : &_columns[index];
}

const std::vector<float>* PointData::getColumn(std::size_t index) const
{
    return index < _columns.size() ? &_columns[index] : nullptr;
}

bool PointData::addColumn(const std::string& name, std::vector<float>&& values)
{
    std::string ignored;
    return addColumn(name, std::move(values), ignored);
}

bool PointData::addColumn(const std::string& name, std::vector<float>&& values, std::string& error)
{
    if (name.empty())
    {
        error = "a column needs a name";
        return false;
    }
    if (values.size() != _numPoints)
    {
        error = "column '" + name + "' has " + std::to_string(values.size()) + " values, the frame has " +
                std::to_string(_numPoints) + " points";
        return false;
    }
    if (hasColumn(name))
    {
        error = "duplicate column '" + name + "'";
        return false;
    }
    _names.push_back(name);
    _columns.push_back(std::move(values));
    _origins.push_back(0.0);
    _labels.emplace_back();
    return true;
}

double PointData::getColumnOrigin(const std::string& name) const
{
    const int index = findColumn(name);
    return index < 0 ? 0.0 : _origins[index];
}

bool PointData::setColumnOrigin(const std::string& name, double origin)
{
    const int index = findColumn(name);
    if (index < 0)
        return false;
    _origins[index] = origin;
    return true;
}

const std::vector<std::string>& PointData::getColumnLabels(const std::string& name) const
{
    static const std::vector<std::string> none;
    const int index = findColumn(name);
    return index < 0 ? none : _labels[index];
}

bool PointData::setColumnLabels(const std::string& name, std::vector<std::string> labels)
{
    const int index = findColumn(name);
    if (index < 0)
        return false;
    _labels[index] = std::move(labels);
    return true;
}

void PointData::setBox(const osg::BoundingBoxd& box, const osg::Vec3d& tilt)
{
    _box = box;
    _tilt = tilt;
    _hasBox = true;
}

void PointData::clearBox()
{
    _box.init();
    _tilt.set(0.0, 0.0, 0.0);
    _hasBox = false;
}

osg::Vec3d PointData::scaledToCartesian(const osg::Vec3d& s) const
{
    const osg::Vec3d length = _box._max - _box._min;
    return osg::Vec3d(_box._min.x() + s.x() * length.x() + s.y() * _tilt.x() + s.z() * _tilt.y(),
                      _box._min.y() + s.y() * length.y() + s.z() * _tilt.z(),
                      _box._min.z() + s.z() * length.z());
}

PointDataset::PointDataset() {}

PointDataset::~PointDataset() {}

bool osgGlyphsData::getPositions(const PointData& data, const std::vector<std::string>& columns,
                                 std::vector<osg::Vec3f>& out, osg::Vec3d& origin, std::string& error)
{
    std::vector<std::string> names = columns;
    bool scaled = false;
    if (columns.empty())
    {
        // Cartesian, unwrapped, then box-scaled (LAMMPS' names).
        static const std::vector<std::vector<std::string>> candidates = {
            {"x", "y", "z"}, {"xu", "yu", "zu"}, {"xs", "ys", "zs"}, {"xsu", "ysu", "zsu"}};
        const int index = findColumnTriple(data, candidates);
        if (index < 0)
        {
            error = "no position columns (x y z, xu yu zu, xs ys zs or xsu ysu zsu); " + listColumns(data);
            return false;
        }
        names = candidates[index];
        scaled = index >= 2;
        if (scaled && !data.hasBox())
        {
            error = "scaled coordinates need a simulation box, and the frame has none";
            return false;
        }
    }
    else if (columns.size() != 3)
    {
        error = "positions need exactly three columns, " + std::to_string(columns.size()) + " given";
        return false;
    }
    int index[3];
    for (int axis = 0; axis < 3; ++axis)
    {
        index[axis] = data.findColumn(names[axis]);
        if (index[axis] < 0)
        {
            error = "no column '" + names[axis] + "'; " + listColumns(data);
            return false;
        }
    }

    const std::size_t n = data.getNumPoints();
    out.resize(n);
    if (scaled)
    {
        const osg::Vec3d& corner = data.getBox()._min;
        origin.set(std::round(corner.x()), std::round(corner.y()), std::round(corner.z()));
        for (std::size_t i = 0; i < n; ++i)
        {
            const osg::Vec3d s(data.getValue(index[0], i), data.getValue(index[1], i),
                               data.getValue(index[2], i));
            const osg::Vec3d p = data.scaledToCartesian(s) - origin;
            out[i].set(static_cast<float>(p.x()), static_cast<float>(p.y()), static_cast<float>(p.z()));
        }
        return true;
    }
    // The columns' own origins: the offsets are the positions.
    origin.set(data.getColumnOrigin(index[0]), data.getColumnOrigin(index[1]),
               data.getColumnOrigin(index[2]));
    const std::vector<float>& x = *data.getColumn(index[0]);
    const std::vector<float>& y = *data.getColumn(index[1]);
    const std::vector<float>& z = *data.getColumn(index[2]);
    for (std::size_t i = 0; i < n; ++i)
        out[i].set(x[i], y[i], z[i]);
    return true;
}

bool osgGlyphsData::getPositions(const PointData& data, const std::vector<std::string>& columns,
                                 std::vector<osg::Vec3f>& out, std::string& error)
{
    osg::Vec3d origin;
    if (!getPositions(data, columns, out, origin, error))
        return false;
    if (origin != osg::Vec3d())
    {
        for (osg::Vec3f& p : out)
            p = osg::Vec3f(osg::Vec3d(p) + origin);
    }
    return true;
}
