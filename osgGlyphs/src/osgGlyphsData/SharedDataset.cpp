#include <osgGlyphsData/SharedDataset>

#include "readers/ColumnTable.h"

#include <map>

using namespace osgGlyphsData;

namespace
{

/** Every process's columns at plain values where their origins differ between processes. */
void unifyOrigins(PointData& frame, const ShareReduction& reduction)
{
    const std::size_t count = frame.getNumColumns();
    std::vector<double> origins(count);
    for (std::size_t column = 0; column < count; ++column)
        origins[column] = frame.getColumnOrigin(column);
    std::vector<double> all = origins;
    reduction.gather(all);
    for (std::size_t column = 0; column < count; ++column)
    {
        bool same = true;
        for (std::size_t value = column; value < all.size(); value += count)
            same = same && all[value] == origins[column];
        if (same || origins[column] == 0.0)
            continue;
        const std::string& name = frame.getColumnNames()[column];
        for (float& stored : *frame.getColumn(name))
            stored = static_cast<float>(origins[column] + stored);
        frame.setColumnOrigin(name, 0.0);
    }
}

/** Every column's labels, each list led by its length: what one process adds to the gathering. */
std::vector<std::string> listLabels(const PointData& frame)
{
    std::vector<std::string> list;
    for (const std::string& name : frame.getColumnNames())
    {
        const std::vector<std::string>& labels = frame.getColumnLabels(name);
        list.push_back(std::to_string(labels.size()));
        list.insert(list.end(), labels.begin(), labels.end());
    }
    return list;
}

bool unifyLabels(PointData& frame, const ShareReduction& reduction, std::string& error)
{
    std::vector<std::string> gathered = listLabels(frame);
    reduction.gather(gathered);
    const std::size_t columns = frame.getNumColumns();
    const unsigned int index = reduction.getShare().index;
    // Per column: the labels of the whole file in order of first appearance (the shares are
    // ranges in share order), and where this process's labels went among them.
    std::vector<std::vector<std::string>> merged(columns);
    std::vector<std::vector<float>> renumbering(columns);
    std::vector<std::map<std::string, float>> numbers(columns);
    std::size_t next = 0;
    for (unsigned int share = 0; next < gathered.size(); ++share)
    {
        for (std::size_t column = 0; column < columns; ++column)
        {
            const std::size_t count = std::stoul(gathered[next++]);
            for (std::size_t i = 0; i < count; ++i, ++next)
            {
                const std::string& label = gathered[next];
                auto found = numbers[column].find(label);
                if (found == numbers[column].end())
                {
                    if (merged[column].size() == readers::ColumnTable::MaxLabels)
                    {
                        error = "column '" + frame.getColumnNames()[column] + "': more than " +
                                std::to_string(readers::ColumnTable::MaxLabels) +
                                " distinct labels in the shares together";
                        return false;
                    }
                    found = numbers[column].emplace(label, float(merged[column].size())).first;
                    merged[column].push_back(label);
                }
                if (share == index)
                    renumbering[column].push_back(found->second);
            }
        }
    }
    for (std::size_t column = 0; column < columns; ++column)
    {
        if (merged[column].empty())
            continue;
        const std::string& name = frame.getColumnNames()[column];
        for (float& value : *frame.getColumn(name))
            value = renumbering[column][static_cast<std::size_t>(value)];
        frame.setColumnLabels(name, std::move(merged[column]));
    }
    return true;
}

/** Whether the shares of a frame whose file states its points hold them all, once. */
bool checkPointCount(const PointData& frame, std::size_t index, const ShareReduction& reduction,
                     std::string& error)
{
    std::vector<double> counts = {static_cast<double>(frame.getNumPoints()),
                                  static_cast<double>(frame.getFilePointCount())};
    reduction.sum(counts);
    const double shares = static_cast<double>(reduction.getShare().count);
    if (frame.getFilePointCount() == 0 ||
        counts[1] != shares * static_cast<double>(frame.getFilePointCount()) ||
        counts[0] == counts[1] / shares)
        return true;
    error = frame.getSource() + ": frame " + std::to_string(index + 1) + " (timestep " +
            std::to_string(frame.getTimestep()) + "): the file counts " +
            std::to_string(frame.getFilePointCount()) + " points, its " +
            std::to_string(reduction.getShare().count) + " shares read " +
            std::to_string(static_cast<uint64_t>(counts[0])) + " together";
    return false;
}

}

bool osgGlyphsData::unifyShares(PointDataset& dataset, const ShareReduction& reduction, std::string& error)
{
    // A last frame that the file cuts short is left out only by the shares that meet the cut:
    // every share keeps the frames that all of them kept.
    std::vector<double> frames = {static_cast<double>(dataset.getNumFrames())};
    reduction.minimum(frames);
    dataset.getFrames().resize(static_cast<std::size_t>(frames[0]));
    for (std::size_t index = 0; index < dataset.getFrames().size(); ++index)
    {
        const osg::ref_ptr<PointData>& frame = dataset.getFrames()[index];
        if (!checkPointCount(*frame, index, reduction, error))
            return false;
        unifyOrigins(*frame, reduction);
        if (!unifyLabels(*frame, reduction, error))
            return false;
    }
    return true;
}
