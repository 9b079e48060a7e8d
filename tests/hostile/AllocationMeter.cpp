#include "AllocationMeter.h"

#include <atomic>
#include <cstdlib>
#include <malloc.h>
#include <new>

namespace
{

std::atomic<bool> g_metering{false};
std::atomic<std::ptrdiff_t> g_inUse{0};
std::atomic<std::ptrdiff_t> g_peak{0};
std::atomic<bool> g_capReached{false};
std::ptrdiff_t g_cap = 0;

void* allocate(std::size_t size)
{
    if (size == 0)
        size = 1;
    if (g_metering && g_inUse + static_cast<std::ptrdiff_t>(size) > g_cap)
    {
        g_capReached = true;
        throw std::bad_alloc();
    }
    void* memory = std::malloc(size);
    if (!memory)
        throw std::bad_alloc();
    // Counted by what free() will release, so that every block is counted the same both ways.
    const std::ptrdiff_t now = g_inUse += static_cast<std::ptrdiff_t>(malloc_usable_size(memory));
    std::ptrdiff_t peak = g_peak;
    while (now > peak && !g_peak.compare_exchange_weak(peak, now))
    {
    }
    return memory;
}

void release(void* memory) noexcept
{
    if (!memory)
        return;
    g_inUse -= static_cast<std::ptrdiff_t>(malloc_usable_size(memory));
    std::free(memory);
}

}

void* operator new(std::size_t size)
{
    return allocate(size);
}

void* operator new[](std::size_t size)
{
    return allocate(size);
}

void* operator new(std::size_t size, const std::nothrow_t&) noexcept
{
    try
    {
        return allocate(size);
    }
    catch (const std::bad_alloc&)
    {
        return nullptr;
    }
}

void* operator new[](std::size_t size, const std::nothrow_t& tag) noexcept
{
    return operator new(size, tag);
}

void operator delete(void* memory) noexcept
{
    release(memory);
}

void operator delete[](void* memory) noexcept
{
    release(memory);
}

void operator delete(void* memory, std::size_t) noexcept
{
    release(memory);
}

void operator delete[](void* memory, std::size_t) noexcept
{
    release(memory);
}

void operator delete(void* memory, const std::nothrow_t&) noexcept
{
    release(memory);
}

void operator delete[](void* memory, const std::nothrow_t&) noexcept
{
    release(memory);
}

namespace hostiletest
{

AllocationMeter::AllocationMeter(std::size_t capBytes)
{
    g_cap = static_cast<std::ptrdiff_t>(capBytes);
    g_capReached = false;
    g_inUse = 0;
    g_peak = 0;
    g_metering = true;
}

AllocationMeter::~AllocationMeter()
{
    g_metering = false;
}

std::ptrdiff_t AllocationMeter::getBytesInUse() const
{
    return g_inUse;
}

std::ptrdiff_t AllocationMeter::getPeakBytes() const
{
    return g_peak;
}

bool AllocationMeter::wasCapReached() const
{
    return g_capReached;
}

}
