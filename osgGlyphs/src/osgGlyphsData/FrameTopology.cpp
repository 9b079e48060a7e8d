#include "FrameTopology.h"

#include <osgGlyphsData/PointReader>

#include <algorithm>

using namespace osgGlyphsData;

namespace
{

/** Columns that belong to a frame, not to its atoms: a topology does not give them. */
bool isPerFrame(const std::string& name)
{
    static const char* const perFrame[] = {"x",  "y",  "z",   "xu",  "yu",  "zu", "xs",
                                           "ys", "zs", "xsu", "ysu", "zsu", "ix", "iy",
                                           "iz", "vx", "vy",  "vz",  "fx",  "fy", "fz"};
    return std::find(std::begin(perFrame), std::end(perFrame), name) != std::end(perFrame);
}

/** The bonds between the atoms of a range, indexed from its first atom; the list itself (shared)
 * for a range that starts at the first atom and holds every bond. */
std::shared_ptr<const PointData::BondList>
bondsOfRange(const std::shared_ptr<const PointData::BondList>& bonds, const PointRange& range)
{
    auto inRange = [&](uint32_t atom) { return atom >= range.begin && atom < range.end; };
    const bool all =
        std::all_of(bonds->begin(), bonds->end(),
                    [&](const Bond& bond) { return inRange(bond.first) && inRange(bond.second); });
    if (all && range.begin == 0)
        return bonds;
    auto part = std::make_shared<PointData::BondList>();
    for (Bond bond : *bonds)
    {
        if (!inRange(bond.first) || !inRange(bond.second))
            continue;
        bond.first -= static_cast<uint32_t>(range.begin);
        bond.second -= static_cast<uint32_t>(range.begin);
        part->push_back(bond);
    }
    return part;
}

}

FrameTopology::FrameTopology(const std::string& path, PointData* atoms) : _path(path), _atoms(atoms)
{
    for (const std::string& name : atoms->getColumnNames())
    {
        if (!isPerFrame(name))
            _columns.push_back(name);
    }
}

std::unique_ptr<FrameTopology> FrameTopology::read(const std::string& path, const std::string& format,
                                                   const std::function<void(const std::string&)>& warning,
                                                   std::string& error)
{
    PointReadOptions options;
    options.format = format;
    options.maxFrames = 1;
    options.warning = warning;
    osg::ref_ptr<PointDataset> dataset = readPointFile(path, options, error);
    if (!dataset)
        return nullptr;
    if (dataset->getNumFrames() == 0)
    {
        error = path + ": the topology holds no atoms";
        return nullptr;
    }
    return std::unique_ptr<FrameTopology>(new FrameTopology(path, dataset->getFrame(0)));
}

bool FrameTopology::apply(PointData& frame, const PointShare& share, const std::string& trajectory,
                          std::size_t frameIndex, std::string& error) const
{
    const uint64_t atoms = frame.getFilePointCount() > 0 ? frame.getFilePointCount() : frame.getNumPoints();
    const std::string where = trajectory + ": frame " + std::to_string(frameIndex);
    if (atoms != _atoms->getNumPoints())
    {
        error = where + " has " + std::to_string(atoms) + " atoms, its topology " + _path + " " +
                std::to_string(_atoms->getNumPoints());
        return false;
    }
    const PointRange range = getShareRange(share, atoms);
    const std::size_t count = static_cast<std::size_t>(range.end - range.begin);
    if (count != frame.getNumPoints())
    {
        error = where + ": its share holds " + std::to_string(frame.getNumPoints()) + " atoms, not the " +
                std::to_string(count) + " from atom " + std::to_string(range.begin) +
                " that the same share of the topology " + _path +
                " holds: the format shares its atoms otherwise";
        return false;
    }
    for (const std::string& name : _columns)
    {
        if (frame.hasColumn(name))
            continue;
        const std::vector<float>& values = *_atoms->getColumn(name);
        const auto begin = values.begin() + static_cast<std::ptrdiff_t>(range.begin);
        std::vector<float> part(begin, begin + static_cast<std::ptrdiff_t>(count));
        frame.addColumn(name, std::move(part));
        frame.setColumnOrigin(name, _atoms->getColumnOrigin(name));
        const std::vector<std::string>& labels = _atoms->getColumnLabels(name);
        if (!labels.empty())
            frame.setColumnLabels(name, labels);
    }
    if (_atoms->getBonds() && !frame.getBonds())
        frame.setBonds(bondsOfRange(_atoms->getBonds(), range));
    return true;
}
