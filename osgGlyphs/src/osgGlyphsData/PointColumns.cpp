#include "PointColumns.h"

namespace
{

// A column name as a message shows it: bytes that would not show (control characters, a byte
// order mark) as \xNN, and then the name in quotes.
std::string visibleName(const std::string& name)
{
    static const char hex[] = "0123456789abcdef";
    std::string shown;
    bool escaped = false;
    for (std::size_t i = 0; i < name.size(); ++i)
    {
        const unsigned char c = static_cast<unsigned char>(name[i]);
        const bool byteOrderMark = name.compare(i, 3, "\xEF\xBB\xBF") == 0;
        if (c >= 0x20 && c != 0x7F && !byteOrderMark)
        {
            shown += name[i];
            continue;
        }
        const std::size_t count = byteOrderMark ? 3 : 1;
        for (std::size_t k = 0; k < count; ++k)
        {
            const unsigned char b = static_cast<unsigned char>(name[i + k]);
            shown += std::string("\\x") + hex[b >> 4] + hex[b & 0xF];
        }
        i += count - 1;
        escaped = true;
    }
    return escaped ? "'" + shown + "'" : shown;
}

} // namespace

std::string osgGlyphsData::detail::listColumns(const PointData& data)
{
    if (data.getNumColumns() == 0)
        return "the frame has no columns";
    std::string list = "available columns:";
    for (const std::string& name : data.getColumnNames())
        list += " " + visibleName(name);
    return list;
}

bool osgGlyphsData::detail::ColumnValues::assign(const PointData& data, const std::string& name)
{
    const int index = data.findColumn(name);
    _values = index < 0 ? nullptr : data.getColumn(static_cast<std::size_t>(index));
    _shifted.clear();
    if (!_values || data.getColumnOrigin(static_cast<std::size_t>(index)) == 0.0)
        return _values != nullptr;
    _shifted.resize(_values->size());
    for (std::size_t i = 0; i < _shifted.size(); ++i)
        _shifted[i] = static_cast<float>(data.getValue(static_cast<std::size_t>(index), i));
    _values = &_shifted;
    return true;
}

bool osgGlyphsData::detail::getColumnTriple(const PointData& data, const std::vector<std::string>& names,
                                            ColumnValues columns[3])
{
    for (int axis = 0; axis < 3; ++axis)
    {
        if (names.size() != 3 || !columns[axis].assign(data, names[axis]))
            return false;
    }
    return true;
}

int osgGlyphsData::detail::findColumnTriple(const PointData& data,
                                            const std::vector<std::vector<std::string>>& candidates)
{
    for (std::size_t index = 0; index < candidates.size(); ++index)
    {
        const std::vector<std::string>& names = candidates[index];
        if (data.hasColumn(names[0]) && data.hasColumn(names[1]) && data.hasColumn(names[2]))
            return static_cast<int>(index);
    }
    return -1;
}
