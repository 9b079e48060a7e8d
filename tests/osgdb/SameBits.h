// What the osgDB tests compare arrays by: the bytes they hold, so that a float reads back bit for bit.

#ifndef OSGGLYPHS_TESTS_SAMEBITS_H
#define OSGGLYPHS_TESTS_SAMEBITS_H

#include <cstring>

/** Whether two arrays hold the same elements, byte for byte; two null arrays do. */
template <class ArrayType>
bool sameBits(const ArrayType* a, const ArrayType* b)
{
    if (!a || !b)
        return a == b;
    return a->size() == b->size() &&
           std::memcmp(a->getDataPointer(), b->getDataPointer(), a->getTotalDataSize()) == 0;
}

#endif
