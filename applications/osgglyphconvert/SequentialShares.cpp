#include "SequentialShares.h"

#include <algorithm>

void SequentialShares::beginShare(unsigned int index)
{
    _index = index;
    _next = 0;
}

bool SequentialShares::endPass()
{
    const bool converged = _settled && _recording.size() == _previous.size();
    _previous.swap(_recording);
    _recording.clear();
    _settled = true;
    return converged;
}

const SequentialShares::Call* SequentialShares::record(Kind kind, const std::vector<double>* values,
                                                       const std::vector<std::string>* strings) const
{
    const std::size_t call = _next++;
    if (_recording.size() <= call)
        _recording.resize(call + 1, Call{kind, {}, {}});
    Call& recorded = _recording[call];
    recorded.kind = kind;
    recorded.values.resize(_shares);
    recorded.strings.resize(_shares);
    if (values)
        recorded.values[_index] = *values;
    if (strings)
        recorded.strings[_index] = *strings;
    const Call* previous = call < _previous.size() ? &_previous[call] : nullptr;
    if (!previous || previous->kind != kind)
    {
        _settled = false;
        return nullptr;
    }
    if (previous->values[_index] != recorded.values[_index] ||
        previous->strings[_index] != recorded.strings[_index])
        _settled = false;
    if (kind != Kind::GatherValues && kind != Kind::GatherStrings)
        for (const std::vector<double>& share : previous->values)
            if (share.size() != recorded.values[_index].size())
            {
                _settled = false;
                return nullptr;
            }
    return previous;
}

void SequentialShares::combine(Kind kind, std::vector<double>& values) const
{
    const Call* previous = record(kind, &values, nullptr);
    if (!previous)
        return;
    // In share order, from the first share's values.
    values = previous->values.front();
    for (std::size_t share = 1; share < previous->values.size(); ++share)
        for (std::size_t i = 0; i < values.size(); ++i)
        {
            const double value = previous->values[share][i];
            values[i] = kind == Kind::Sum       ? values[i] + value
                        : kind == Kind::Minimum ? std::min(values[i], value)
                                                : std::max(values[i], value);
        }
}

void SequentialShares::minimum(std::vector<double>& values) const
{
    combine(Kind::Minimum, values);
}

void SequentialShares::maximum(std::vector<double>& values) const
{
    combine(Kind::Maximum, values);
}

void SequentialShares::sum(std::vector<double>& values) const
{
    combine(Kind::Sum, values);
}

namespace
{

/** The concatenation of every share's values; before any are known, this share's for each share,
 * so that what the caller parses out of it is well formed. */
template <typename T>
void concatenate(const std::vector<std::vector<T>>* shares, unsigned int count, std::vector<T>& values)
{
    const std::vector<T> own = values;
    values.clear();
    for (unsigned int share = 0; share < count; ++share)
    {
        const std::vector<T>& part = shares ? (*shares)[share] : own;
        values.insert(values.end(), part.begin(), part.end());
    }
}

}

void SequentialShares::gather(std::vector<double>& values) const
{
    const Call* previous = record(Kind::GatherValues, &values, nullptr);
    concatenate(previous ? &previous->values : nullptr, _shares, values);
}

void SequentialShares::gather(std::vector<std::string>& strings) const
{
    const Call* previous = record(Kind::GatherStrings, nullptr, &strings);
    concatenate(previous ? &previous->strings : nullptr, _shares, strings);
}

osgGlyphsData::PointShare SequentialShares::getShare() const
{
    osgGlyphsData::PointShare share;
    share.index = _index;
    share.count = _shares;
    return share;
}
