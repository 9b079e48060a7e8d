#include "PointColumns.h"

std::string osgGlyphsData::detail::listColumns(const PointData& data)
{
    if (data.getNumColumns() == 0)
        return "the frame has no columns";
    std::string list = "available columns:";
    for (const std::string& name : data.getColumnNames())
        list += " " + name;
    return list;
}

bool osgGlyphsData::detail::getColumnTriple(const PointData& data, const std::vector<std::string>& names,
                                            const std::vector<float>* columns[3])
{
    for (int axis = 0; axis < 3; ++axis)
    {
        columns[axis] = names.size() == 3 ? data.getColumn(names[axis]) : nullptr;
        if (!columns[axis])
            return false;
    }
    return true;
}

int osgGlyphsData::detail::findColumnTriple(const PointData& data,
                                            const std::vector<std::vector<std::string>>& candidates,
                                            const std::vector<float>* columns[3])
{
    for (std::size_t index = 0; index < candidates.size(); ++index)
    {
        if (getColumnTriple(data, candidates[index], columns))
            return static_cast<int>(index);
    }
    return -1;
}
