/* Counts the bytes that operator new hands out in the test program, and refuses more than a cap:
 * what a reader holds and at most held, measured without timing anything or reading RSS. */

#ifndef OSGGLYPHS_TESTS_ALLOCATIONMETER_H
#define OSGGLYPHS_TESTS_ALLOCATIONMETER_H 1

#include <cstddef>

namespace hostiletest
{

constexpr std::size_t MiB = std::size_t(1) << 20;

/** While one exists, operator new throws std::bad_alloc rather than let the bytes in use exceed
 * the cap, and the meter records the most bytes in use at once. One at a time. */
class AllocationMeter
{
public:
    explicit AllocationMeter(std::size_t capBytes);
    ~AllocationMeter();

    AllocationMeter(const AllocationMeter&) = delete;
    AllocationMeter& operator=(const AllocationMeter&) = delete;

    /** Bytes allocated since the meter was made and not freed yet. */
    std::ptrdiff_t getBytesInUse() const;

    /** The most getBytesInUse() has been. */
    std::ptrdiff_t getPeakBytes() const;

    /** True when an allocation was refused. */
    bool wasCapReached() const;
};

}

#endif
