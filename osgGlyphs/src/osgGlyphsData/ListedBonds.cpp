#include "ListedBonds.h"

#include <algorithm>

using namespace osgGlyphsData;

std::shared_ptr<const PointData::BondList>
osgGlyphsData::makeListedBonds(const std::vector<std::pair<uint32_t, uint32_t>>& rows,
                               const std::vector<uint32_t>& frameIndexOfRow)
{
    auto bonds = std::make_shared<PointData::BondList>();
    bonds->reserve(rows.size());
    for (const auto& [rowA, rowB] : rows)
    {
        const uint32_t a = frameIndexOfRow[rowA], b = frameIndexOfRow[rowB];
        if (a == NOT_IN_FRAME || b == NOT_IN_FRAME)
            continue;
        Bond bond = {std::min(a, b), std::max(a, b), {0, 0, 0}};
        bonds->push_back(bond);
    }
    auto byAtoms = [](const Bond& x, const Bond& y)
    { return x.first != y.first ? x.first < y.first : x.second < y.second; };
    auto sameAtoms = [](const Bond& x, const Bond& y) { return x.first == y.first && x.second == y.second; };
    std::sort(bonds->begin(), bonds->end(), byAtoms);
    bonds->erase(std::unique(bonds->begin(), bonds->end(), sameAtoms), bonds->end());
    bonds->shrink_to_fit();
    return bonds;
}
