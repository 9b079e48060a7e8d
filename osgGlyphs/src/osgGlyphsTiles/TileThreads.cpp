#include "TileThreads.h"

#include <algorithm>

using namespace osgGlyphsTiles::detail;

TileThreads::TileThreads(unsigned int threads)
    : _threads(threads ? threads : std::max(1u, std::thread::hardware_concurrency()))
{
}

TileThreads::~TileThreads()
{
    {
        std::lock_guard<std::mutex> lock(_mutex);
        _stopping = true;
    }
    _changed.notify_all();
    for (std::thread& thread : _pool)
        thread.join();
}

TileThreads::TaskHandle TileThreads::start(const std::function<void()>& task)
{
    if (_threads < 2)
    {
        task();
        return nullptr;
    }
    TaskHandle handle = std::make_shared<Task>();
    handle->run = task;
    {
        std::lock_guard<std::mutex> lock(_mutex);
        if (_pool.empty())
            for (unsigned int i = 1; i < _threads; ++i)
                _pool.emplace_back(&TileThreads::work, this);
        _queue.push_back(handle);
    }
    _changed.notify_one();
    return handle;
}

void TileThreads::runQueued(std::unique_lock<std::mutex>& lock, const TaskHandle& task)
{
    _queue.erase(std::find(_queue.begin(), _queue.end(), task));
    task->taken = true;
    lock.unlock();
    task->run();
    lock.lock();
    task->done = true;
    _changed.notify_all();
}

void TileThreads::join(TaskHandle& task)
{
    if (!task)
        return;
    std::unique_lock<std::mutex> lock(_mutex);
    while (!task->done)
    {
        if (!task->taken)
            runQueued(lock, task);
        else if (!_queue.empty())
            runQueued(lock, TaskHandle(_queue.front()));
        else
            _changed.wait(lock);
    }
    task.reset();
}

void TileThreads::work()
{
    std::unique_lock<std::mutex> lock(_mutex);
    while (true)
    {
        _changed.wait(lock, [this] { return _stopping || !_queue.empty(); });
        if (_queue.empty())
            return;
        runQueued(lock, TaskHandle(_queue.front()));
    }
}

void TileThreads::runBoth(const std::function<void()>& first, const std::function<void()>& second)
{
    TaskHandle task = start(first);
    second();
    join(task);
}

std::size_t TileThreads::runHalves(
    std::size_t count,
    const std::function<void(unsigned int half, std::size_t first, std::size_t last)>& visit)
{
    const std::size_t middle = count / 2;
    runBoth([&] { visit(0, 0, middle); }, [&] { visit(1, middle, count); });
    return middle;
}
