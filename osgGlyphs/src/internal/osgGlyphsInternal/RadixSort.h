/* osgGlyphsInternal - private: a least-significant-digit radix sort by unsigned integer keys,
 * shared by the culling chunks and the tile builder's octree (a template: nothing to link).
 * Not installed. */

#ifndef OSGGLYPHS_RADIXSORT_H
#define OSGGLYPHS_RADIXSORT_H 1

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace osgGlyphs
{
namespace detail
{

/** Sorts the items [begin, end) by keyOf(item), a key of keyBits bits, stably, 11 bits at a
 * time; a digit that every item shares costs one counting pass and no move. Takes a second array
 * as large. */
template <typename Item, typename KeyOf>
void radixSort(Item* begin, Item* end, unsigned int keyBits, KeyOf keyOf)
{
    const unsigned int DIGIT_BITS = 11;
    const std::size_t DIGITS = std::size_t(1) << DIGIT_BITS;
    const std::size_t count = static_cast<std::size_t>(end - begin);
    std::vector<Item> scratch;
    std::vector<std::size_t> offsets(DIGITS + 1);
    Item* from = begin;
    for (unsigned int shift = 0; shift < keyBits; shift += DIGIT_BITS)
    {
        const auto digitOf = [&](const Item& item)
        { return static_cast<std::size_t>((uint64_t(keyOf(item)) >> shift) & (DIGITS - 1)); };
        std::fill(offsets.begin(), offsets.end(), 0);
        for (const Item* item = from; item != from + count; ++item)
            ++offsets[digitOf(*item) + 1];
        bool shared = false;
        for (std::size_t digit = 1; digit <= DIGITS && !shared; ++digit)
            shared = offsets[digit] == count;
        if (shared)
            continue;
        for (std::size_t digit = 1; digit <= DIGITS; ++digit)
            offsets[digit] += offsets[digit - 1];
        if (scratch.empty())
            scratch.resize(count);
        Item* to = from == begin ? scratch.data() : begin;
        for (const Item* item = from; item != from + count; ++item)
            to[offsets[digitOf(*item)]++] = *item;
        from = to;
    }
    if (from != begin)
        std::copy(from, from + count, begin);
}

/** Sorts a whole vector so. */
template <typename Item, typename KeyOf>
void radixSort(std::vector<Item>& items, unsigned int keyBits, KeyOf keyOf)
{
    radixSort(items.data(), items.data() + items.size(), keyBits, keyOf);
}

}
}

#endif
