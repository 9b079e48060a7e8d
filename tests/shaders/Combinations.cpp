#include "ProgramVariants.h"

#include <set>
#include <tuple>

using namespace shadervariants;

namespace
{

using Row = std::vector<std::size_t>;
/** Factor i's value a together with factor j's value b, i < j. */
using Pair = std::tuple<std::size_t, std::size_t, std::size_t, std::size_t>;

DefineMap toDefines(const std::vector<Factor>& factors, const Row& row)
{
    DefineMap defines;
    for (std::size_t i = 0; i < factors.size(); ++i)
        defines.insert(factors[i].values[row[i]].begin(), factors[i].values[row[i]].end());
    return defines;
}

std::set<Pair> getAllPairs(const std::vector<Factor>& factors)
{
    std::set<Pair> pairs;
    for (std::size_t i = 0; i < factors.size(); ++i)
        for (std::size_t j = i + 1; j < factors.size(); ++j)
            for (std::size_t a = 0; a < factors[i].values.size(); ++a)
                for (std::size_t b = 0; b < factors[j].values.size(); ++b)
                    pairs.insert({i, a, j, b});
    return pairs;
}

/** How many uncovered pairs factor k at value v makes with the factors chosen so far (fixed). */
std::size_t countNewPairs(const std::set<Pair>& uncovered, const Row& row, const std::vector<bool>& fixed,
                          std::size_t k, std::size_t v)
{
    std::size_t count = 0;
    for (std::size_t i = 0; i < row.size(); ++i)
        if (fixed[i] && i != k)
            count += uncovered.count(i < k ? Pair{i, row[i], k, v} : Pair{k, v, i, row[i]});
    return count;
}

/** A row that covers the first uncovered pair, and greedily as many others as it can. */
Row nextRow(const std::vector<Factor>& factors, const std::set<Pair>& uncovered)
{
    Row row(factors.size(), 0);
    std::vector<bool> fixed(factors.size(), false);
    const Pair& first = *uncovered.begin();
    row[std::get<0>(first)] = std::get<1>(first);
    row[std::get<2>(first)] = std::get<3>(first);
    fixed[std::get<0>(first)] = fixed[std::get<2>(first)] = true;
    for (std::size_t k = 0; k < factors.size(); ++k)
    {
        if (fixed[k])
            continue;
        std::size_t best = 0, bestCount = 0;
        for (std::size_t v = 0; v < factors[k].values.size(); ++v)
        {
            const std::size_t count = countNewPairs(uncovered, row, fixed, k, v);
            if (count > bestCount)
                best = v, bestCount = count;
        }
        row[k] = best;
        fixed[k] = true;
    }
    return row;
}

}

std::vector<DefineMap> shadervariants::crossProduct(const std::vector<Factor>& factors)
{
    std::vector<DefineMap> combinations;
    Row row(factors.size(), 0);
    for (;;)
    {
        combinations.push_back(toDefines(factors, row));
        std::size_t i = 0;
        while (i < factors.size() && ++row[i] == factors[i].values.size())
            row[i++] = 0;
        if (i == factors.size())
            return combinations;
    }
}

std::vector<DefineMap> shadervariants::allPairs(const std::vector<Factor>& factors)
{
    if (factors.size() < 2)
        return crossProduct(factors);
    std::vector<DefineMap> combinations;
    std::set<Pair> uncovered = getAllPairs(factors);
    while (!uncovered.empty())
    {
        const Row row = nextRow(factors, uncovered);
        for (std::size_t i = 0; i < row.size(); ++i)
            for (std::size_t j = i + 1; j < row.size(); ++j)
                uncovered.erase({i, row[i], j, row[j]});
        combinations.push_back(toDefines(factors, row));
    }
    return combinations;
}
