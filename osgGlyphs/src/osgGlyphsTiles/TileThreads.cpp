#include "TileThreads.h"

#include <algorithm>

using namespace osgGlyphsTiles::detail;

TileThreads::TileThreads(unsigned int threads)
    : _threads(threads ? threads : std::max(1u, std::thread::hardware_concurrency())),
      _free(static_cast<int>(_threads) - 1)
{
}

std::thread TileThreads::start(const std::function<void()>& task)
{
    int free = _free.load();
    while (free > 0)
        if (_free.compare_exchange_weak(free, free - 1))
            return std::thread(
                [this, task]
                {
                    task();
                    ++_free;
                });
    task();
    return std::thread();
}

void TileThreads::join(std::thread& thread)
{
    if (!thread.joinable())
        return;
    ++_free;
    thread.join();
    --_free;
}

void TileThreads::runBoth(const std::function<void()>& first, const std::function<void()>& second)
{
    std::thread thread = start(first);
    second();
    join(thread);
}

std::size_t TileThreads::runHalves(
    std::size_t count,
    const std::function<void(unsigned int half, std::size_t first, std::size_t last)>& visit)
{
    const std::size_t middle = count / 2;
    runBoth([&] { visit(0, 0, middle); }, [&] { visit(1, middle, count); });
    return middle;
}
