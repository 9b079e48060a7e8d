// H5MD (nongnu.org/h5md, version 1.x): molecular data in HDF5.
//   /particles/<group>/position   the positions: a time-dependent element (a group holding value
//                                  [time x particles x dimension], step and time, each step and
//                                  time a list or a fixed interval with an offset attribute) or a
//                                  fixed dataset [particles x dimension];
//   /particles/<group>/<element>  species, id, velocity, force, charge, mass, image and any other
//                                  per-particle element, each time-dependent or fixed;
//   /particles/<group>/box        attributes dimension and boundary, and edges (a vector: an
//                                  orthogonal box, or a matrix of edge vectors, time-dependent or
//                                  fixed) with an optional offset (its lower corner).
// One frame per step of the first group's positions; every element (and the other groups)
// gives its value at that step or the last before it. Several groups are concatenated in name
// order with a categorical column "group". The boundary attribute is not read: PointData's box
// has no periodicity.
//   /connectivity/<name>          pairs of particles (ids where the group has an id element, else
//                                  its rows; a fill value marks unused pairs), fixed or
//                                  time-dependent: the frame's bonds (H5mdConnectivity).

#include "H5mdConnectivity.h"
#include "Hdf5Readers.h"

#include "formats/CellBox.h"

#include <mutex>
#include <set>

using namespace osgGlyphsData;
using namespace osgGlyphsHdf5::detail;

namespace
{

/** Elements that H5MD names: one of another length than the positions is an error, where an
 * element of another name is taken for something not per particle and left out. */
bool isNamedElement(const std::string& name)
{
    static const std::set<std::string> names = {"species", "id",   "velocity", "force",
                                                "charge",  "mass", "image"};
    return names.count(name) > 0;
}

ElementKind kindOf(const std::string& name)
{
    return name == "species" ? ElementKind::Species : ElementKind::Numbers;
}

class H5mdFile : public FrameFile
{
public:
    H5mdFile(Handle file, const std::string& path, const std::string& format)
        : FrameFile(path, format), _file(std::move(file))
    {
    }

    void open(const std::vector<std::string>& datasets)
    {
        const Place place{&_path};
        if (datasets.empty())
            findGroups(place);
        else
            namedGroup(datasets, place);
        _columns = planColumns(_groups, "group", _path, _warnings);
        describeBox(place);
        _connectivity = describeConnectivity(_file.get(), _groups, _warnings, place);
        _fixedConnectivity = isFixedConnectivity(_connectivity, _groups);
        if (_groups.size() > 1)
            _warnings.push_back(_path + ": " + std::to_string(_groups.size()) +
                                " particle groups, read together with the column \"group\"");
    }

    std::size_t getNumFrames() const override
    {
        const Element& position = _groups.front().position;
        return position.timed ? position.steps.size() : 1;
    }

    FrameInfo getFrameInfo(std::size_t frame) const override
    {
        FrameInfo info;
        if (frame >= getNumFrames())
            return info;
        const Element& position = _groups.front().position;
        info.timestep = position.timed ? position.steps[frame] : 0;
        info.hasTime = position.hasTimes;
        info.time = position.hasTimes ? position.times[frame] : 0.0;
        for (const ParticleGroup& group : _groups)
            info.points += group.count();
        info.fileFrame = frame;
        return info;
    }

    osg::ref_ptr<PointData> readFrame(std::size_t frame, const PointShare& share,
                                      std::string& error) const override
    {
        Hdf5Lock lock;
        try
        {
            const Place place{&_path, frame};
            if (frame >= getNumFrames())
                place.fail(_groups.front().position.value.path, "no such frame");
            const int64_t step = getFrameInfo(frame).timestep;
            osg::ref_ptr<PointData> data = readParticles(_groups, _columns, "group", step, share, place);
            setBox(*data, step, place);
            if (!_connectivity.empty())
                data->setBonds(bondsAt(step, getShareRange(share, getFrameInfo(frame).points), place));
            return data;
        }
        catch (const Hdf5Error& failure)
        {
            error = failure.message;
        }
        return nullptr;
    }

protected:
    ~H5mdFile() override
    {
        Hdf5Lock lock;
        _groups.clear();
        _connectivity.clear();
        _fixedBonds.reset();
        _edges = Element();
        _offset = Element();
        _file.reset();
    }

private:
    /** The bonds of the frame at step: read at each step, or once where they cannot change
     * (isFixedConnectivity()), so that every frame holds the one list. Under the HDF5 lock. */
    std::shared_ptr<const PointData::BondList> bondsAt(int64_t step, const PointRange& range,
                                                       const Place& place) const
    {
        if (!_fixedConnectivity)
            return readConnectivity(_connectivity, _groups, step, range, place);
        if (!_fixedBonds || _fixedBondsRange.begin != range.begin || _fixedBondsRange.end != range.end)
        {
            _fixedBonds = readConnectivity(_connectivity, _groups, step, range, place);
            _fixedBondsRange = range;
        }
        return _fixedBonds;
    }

    void findGroups(const Place& place)
    {
        if (objectType(_file.get(), "/particles") != H5O_TYPE_GROUP)
            place.fail("/particles", "missing: not an H5MD file");
        std::string firstGroup;
        for (const std::string& name : listMembers(_file.get(), "/particles", place))
        {
            const std::string group = "/particles/" + name;
            if (objectType(_file.get(), group) != H5O_TYPE_GROUP)
                continue;
            if (firstGroup.empty())
                firstGroup = group;
            if (objectType(_file.get(), group + "/position") == H5O_TYPE_UNKNOWN)
            {
                _warnings.push_back(place.describe(group + "/position", "missing: the group is left out"));
                continue;
            }
            readGroup(group, listMembers(_file.get(), group, place), false, place);
        }
        if (_groups.empty())
            place.fail((firstGroup.empty() ? std::string("/particles/<group>") : firstGroup) + "/position",
                       "missing: no particle group has positions");
    }

    void namedGroup(const std::vector<std::string>& datasets, const Place& place)
    {
        const std::string group = parentPath(datasets.front());
        std::vector<std::string> names;
        for (const std::string& dataset : datasets)
        {
            if (parentPath(dataset) != group)
                place.fail(dataset, "is not an element of " + group + ", the group of the positions (" +
                                        datasets.front() + ")");
            names.push_back(baseName(dataset));
        }
        readGroup(group, names, true, place);
    }

    /** A particle group: its positions (the first name when named) and its other elements. */
    void readGroup(const std::string& path, const std::vector<std::string>& names, bool named,
                   const Place& place)
    {
        ParticleGroup group;
        group.name = baseName(path);
        const std::string positionPath = path + "/" + (named ? names.front() : std::string("position"));
        group.position = describeElement(_file.get(), positionPath, ElementKind::Position, place);
        for (std::size_t i = named ? 1 : 0; i < names.size(); ++i)
        {
            const std::string& name = names[i];
            if (!named && (name == "position" || name == "box"))
                continue;
            const bool required = named || isNamedElement(name);
            try
            {
                Element element = describeElement(_file.get(), path + "/" + name, kindOf(name), place);
                if (!required && element.rows() != group.count())
                {
                    _warnings.push_back(
                        place.describe(element.value.path, "holds " + std::to_string(element.rows()) +
                                                               " rows, not one a particle: left out"));
                    continue;
                }
                group.elements.push_back(std::move(element));
            }
            catch (const Hdf5Error& failure)
            {
                if (!required)
                    _warnings.push_back(failure.message + ": left out");
                else
                    group.elements.push_back(brokenElement(name, failure));
            }
        }
        _groups.push_back(std::move(group));
    }

    void describeBox(const Place& place)
    {
        const std::string box =
            parentPath(_groups.front().position.timed ? parentPath(_groups.front().position.value.path)
                                                      : _groups.front().position.value.path) +
            "/box";
        if (objectType(_file.get(), box + "/edges") == H5O_TYPE_UNKNOWN)
            return;
        try
        {
            _dimension = hasAttribute(_file.get(), box, "dimension")
                             ? readAttributeNumbers(_file.get(), box, "dimension", 1, place).at(0)
                             : 3.0;
            _edges = describeElement(_file.get(), box + "/edges", ElementKind::Numbers, place);
            const hsize_t dimension = _edges.rows();
            if (double(dimension) != _dimension || (_edges.width() != 1 && _edges.width() != dimension))
                place.fail(_edges.value.path,
                           "holds " + std::to_string(dimension) + " x " + std::to_string(_edges.width()) +
                               " values for a box of dimension " + std::to_string(_dimension));
            if (objectType(_file.get(), box + "/offset") != H5O_TYPE_UNKNOWN)
            {
                _offset = describeElement(_file.get(), box + "/offset", ElementKind::Numbers, place);
                if (_offset.rows() != dimension || _offset.width() != 1)
                    place.fail(_offset.value.path, "holds " + std::to_string(_offset.value.countFrom(0)) +
                                                       " values for a box of dimension " +
                                                       std::to_string(dimension));
            }
            if (dimension != 3)
                _warnings.push_back(
                    place.describe(box, "a box of dimension " + std::to_string(dimension) + " is not shown"));
        }
        catch (const Hdf5Error& failure)
        {
            _edges = brokenElement("edges", failure);
        }
    }

    std::vector<double> boxValues(const Element& element, int64_t step, const Place& place) const
    {
        std::vector<hsize_t> leading;
        if (element.timed)
            leading.push_back(indexAt(element, step, place));
        std::vector<double> values;
        readRows(element.value, leading, 0, element.rows(), place,
                 RowSink<double>([&values, &element](hsize_t, const double* block, hsize_t rows)
                                 { values.insert(values.end(), block, block + rows * element.width()); }));
        return values;
    }

    void setBox(PointData& data, int64_t step, const Place& place) const
    {
        if (!_edges.problem.empty())
            place.fail(_edges.problemDataset, _edges.problem);
        if (_edges.value.path.empty() || _edges.rows() != 3)
            return;
        const std::vector<double> edges = boxValues(_edges, step, place);
        osg::Vec3d offset;
        if (!_offset.value.path.empty())
        {
            const std::vector<double> corner = boxValues(_offset, step, place);
            offset.set(corner[0], corner[1], corner[2]);
        }
        if (_edges.width() == 1)
            osgGlyphsData::formats::setCellVectors(data, osg::Vec3d(edges[0], 0, 0),
                                                   osg::Vec3d(0, edges[1], 0), osg::Vec3d(0, 0, edges[2]),
                                                   offset);
        else
            osgGlyphsData::formats::setCellVectors(data, osg::Vec3d(edges[0], edges[1], edges[2]),
                                                   osg::Vec3d(edges[3], edges[4], edges[5]),
                                                   osg::Vec3d(edges[6], edges[7], edges[8]), offset);
    }

    Handle _file;
    std::vector<ParticleGroup> _groups;
    std::vector<PairList> _connectivity; // /connectivity's bonds
    bool _fixedConnectivity = false;
    mutable std::shared_ptr<const PointData::BondList> _fixedBonds; // of _fixedBondsRange
    mutable PointRange _fixedBondsRange;
    std::vector<std::string> _columns;
    double _dimension = 3.0;
    Element _edges;
    Element _offset;
};

}

bool osgGlyphsHdf5::detail::looksLikeH5md(hid_t file)
{
    return objectType(file, "/particles") == H5O_TYPE_GROUP || objectType(file, "/h5md") == H5O_TYPE_GROUP;
}

osg::ref_ptr<FrameFile> osgGlyphsHdf5::detail::openH5md(Handle file, const std::string& path,
                                                        const std::string& format,
                                                        const std::vector<std::string>& datasets)
{
    osg::ref_ptr<H5mdFile> frames = new H5mdFile(std::move(file), path, format);
    frames->open(datasets);
    return frames;
}
