// HDF5 particle files of one frame:
//   SWIFT and Gadget snapshots: one group per particle type, /PartType0, /PartType1, ..., each with
//   Coordinates [particles x 3] and further per-particle datasets (Velocities, Masses,
//   ParticleIDs, ...), read as columns, the groups concatenated with the categorical column
//   particle_type; the attributes of /Header give the box (BoxSize, a length or three, the box
//   from 0), the time (Time) and the masses of types without a Masses dataset (MassTable).
//   Named datasets (FrameFileOptions::datasets): positions [particles x 2 or 3] first, then
//   columns [particles] or [particles x k], named after the datasets.
// Double-precision coordinates keep their decimals through the columns' origins.

#include "Hdf5Readers.h"

#include <algorithm>
#include <set>

using namespace osgGlyphsData;
using namespace osgGlyphsHdf5::detail;

namespace
{

const char* const Header = "/Header";

/** Datasets that snapshots name: one of another length than the coordinates is an error, where
 * another is taken for something not per particle and left out. */
bool isNamedDataset(const std::string& name)
{
    static const std::set<std::string> names = {"Velocities", "Masses", "ParticleIDs"};
    return names.count(name) > 0;
}

/** The N of a group named PartTypeN; -1 for any other name. */
int particleType(const std::string& name)
{
    const std::string prefix = "PartType";
    if (name.size() <= prefix.size() || name.size() > prefix.size() + 3 || name.rfind(prefix, 0) != 0)
        return -1;
    const std::string digits = name.substr(prefix.size());
    if (!std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; }))
        return -1;
    return std::stoi(digits);
}

class ParticleFile : public FrameFile
{
public:
    ParticleFile(Handle file, const std::string& path, const std::string& format)
        : FrameFile(path, format), _file(std::move(file))
    {
    }

    void openSnapshot()
    {
        const Place place{&_path};
        std::vector<std::pair<int, std::string>> types;
        for (const std::string& name : listMembers(_file.get(), "/", place))
        {
            const int type = particleType(name);
            if (type >= 0 && objectType(_file.get(), "/" + name) == H5O_TYPE_GROUP)
                types.emplace_back(type, name);
        }
        std::sort(types.begin(), types.end());
        const std::vector<double> masses = readHeader("MassTable", 64, place);
        for (const auto& [type, name] : types)
        {
            const std::string group = "/" + name;
            if (objectType(_file.get(), group + "/Coordinates") == H5O_TYPE_UNKNOWN)
            {
                if (!listMembers(_file.get(), group, place).empty())
                    _warnings.push_back(
                        place.describe(group + "/Coordinates", "missing: the group is left out"));
                continue;
            }
            readGroup(group, masses.size() > std::size_t(type) ? masses[std::size_t(type)] : 0.0, place);
        }
        if (_groups.empty())
            place.fail("/PartType<N>/Coordinates", "missing: not a snapshot");
        _columns = planColumns(_groups, GroupColumn, _path, _warnings);
        const std::vector<double> box = readHeader("BoxSize", 3, place);
        if (box.size() == 1 || box.size() == 3)
        {
            _hasBox = true;
            _box = osg::BoundingBoxd(osg::Vec3d(), box.size() == 1 ? osg::Vec3d(box[0], box[0], box[0])
                                                                   : osg::Vec3d(box[0], box[1], box[2]));
        }
        const std::vector<double> time = readHeader("Time", 1, place);
        _hasTime = time.size() == 1;
        _time = _hasTime ? time[0] : 0.0;
    }

    void openDatasets(const std::vector<std::string>& datasets)
    {
        const Place place{&_path};
        ParticleGroup group;
        group.name = baseName(parentPath(datasets.front()));
        group.position = describeElement(_file.get(), datasets.front(), ElementKind::Position, place);
        std::set<std::string> names = {"x", "y", "z"};
        for (std::size_t i = 1; i < datasets.size(); ++i)
        {
            try
            {
                Element element = describeElement(_file.get(), datasets[i], ElementKind::Numbers, place);
                for (const std::string& column : element.columns)
                {
                    if (!names.insert(column).second)
                        place.fail(datasets[i],
                                   "gives the column " + column + ", which an earlier dataset gives");
                }
                group.elements.push_back(std::move(element));
            }
            catch (const Hdf5Error& failure)
            {
                group.elements.push_back(brokenElement(baseName(datasets[i]), failure));
            }
        }
        _groups.push_back(std::move(group));
        _columns = planColumns(_groups, GroupColumn, _path, _warnings);
    }

    std::size_t getNumFrames() const override { return 1; }

    FrameInfo getFrameInfo(std::size_t frame) const override
    {
        FrameInfo info;
        if (frame != 0)
            return info;
        for (const ParticleGroup& group : _groups)
            info.points += group.count();
        info.hasTime = _hasTime;
        info.time = _time;
        return info;
    }

    osg::ref_ptr<PointData> readFrame(std::size_t frame, const PointShare& share,
                                      std::string& error) const override
    {
        Hdf5Lock lock;
        try
        {
            const Place place{&_path, frame};
            if (frame != 0)
                place.fail(_groups.front().position.value.path, "no such frame (the file holds one)");
            osg::ref_ptr<PointData> data = readParticles(_groups, _columns, GroupColumn, 0, share, place);
            if (_hasBox)
                data->setBox(_box);
            return data;
        }
        catch (const Hdf5Error& failure)
        {
            error = failure.message;
        }
        return nullptr;
    }

protected:
    ~ParticleFile() override
    {
        Hdf5Lock lock;
        _groups.clear();
        _file.reset();
    }

private:
    static constexpr const char* GroupColumn = "particle_type";

    /** A numeric attribute of /Header (at most limit values); none when there is no such. */
    std::vector<double> readHeader(const std::string& name, std::size_t limit, const Place& place)
    {
        if (!hasAttribute(_file.get(), Header, name))
            return {};
        try
        {
            return readAttributeNumbers(_file.get(), Header, name, limit, place);
        }
        catch (const Hdf5Error& failure)
        {
            _warnings.push_back(failure.message + ": left out");
        }
        return {};
    }

    void readGroup(const std::string& path, double mass, const Place& place)
    {
        ParticleGroup group;
        group.name = baseName(path);
        group.position = describeElement(_file.get(), path + "/Coordinates", ElementKind::Position, place);
        for (const std::string& name : listMembers(_file.get(), path, place))
        {
            if (name == "Coordinates")
                continue;
            const std::string dataset = path + "/" + name;
            if (objectType(_file.get(), dataset) != H5O_TYPE_DATASET)
            {
                _warnings.push_back(place.describe(dataset, "is not a dataset: left out"));
                continue;
            }
            try
            {
                Element element = describeElement(_file.get(), dataset, ElementKind::Numbers, place);
                if (!isNamedDataset(name) && element.rows() != group.count())
                {
                    _warnings.push_back(place.describe(dataset, "holds " + std::to_string(element.rows()) +
                                                                    " rows, not one a particle: left out"));
                    continue;
                }
                group.elements.push_back(std::move(element));
            }
            catch (const Hdf5Error& failure)
            {
                if (!isNamedDataset(name))
                    _warnings.push_back(failure.message + ": left out");
                else
                    group.elements.push_back(brokenElement(name, failure));
            }
        }
        if (mass != 0.0)
            group.defaults["mass"] = mass;
        _groups.push_back(std::move(group));
    }

    Handle _file;
    std::vector<ParticleGroup> _groups;
    std::vector<std::string> _columns;
    bool _hasBox = false;
    osg::BoundingBoxd _box;
    bool _hasTime = false;
    double _time = 0.0;
};

}

bool osgGlyphsHdf5::detail::looksLikeSnapshot(hid_t file)
{
    for (int type = 0; type < 8; ++type)
    {
        if (objectType(file, "/PartType" + std::to_string(type) + "/Coordinates") == H5O_TYPE_DATASET)
            return true;
    }
    return false;
}

osg::ref_ptr<FrameFile> osgGlyphsHdf5::detail::openSnapshot(Handle file, const std::string& path,
                                                            const std::string& format)
{
    osg::ref_ptr<ParticleFile> frames = new ParticleFile(std::move(file), path, format);
    frames->openSnapshot();
    return frames;
}

osg::ref_ptr<FrameFile> osgGlyphsHdf5::detail::openDatasets(Handle file, const std::string& path,
                                                            const std::string& format,
                                                            const std::vector<std::string>& datasets)
{
    osg::ref_ptr<ParticleFile> frames = new ParticleFile(std::move(file), path, format);
    frames->openDatasets(datasets);
    return frames;
}
