/* osgGlyphs - private: the threads that cut a dataset's subtrees into tiles side by side. Not
 * installed. */

#ifndef OSGGLYPHS_TILETHREADS_H
#define OSGGLYPHS_TILETHREADS_H 1

#include <condition_variable>
#include <cstddef>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

namespace osgGlyphsTiles
{
namespace detail
{

/** Fork and join on a given number of threads: start() queues a task for the pool's threads,
 * and join() waits for one, running it on the caller's thread when no other has taken it yet,
 * and other queued tasks while it waits. So every thread stays at work while there is any,
 * whichever task forks the next ones. */
class TileThreads
{
public:
    /** A task start() queued. */
    struct Task
    {
        std::function<void()> run;
        bool taken = false;
        bool done = false;
    };
    typedef std::shared_ptr<Task> TaskHandle;

    /** threads: the most at work at once, the caller's included (0: the machine's cores). */
    explicit TileThreads(unsigned int threads);
    ~TileThreads();
    TileThreads(const TileThreads&) = delete;
    TileThreads& operator=(const TileThreads&) = delete;

    unsigned int getNumThreads() const { return _threads; }

    /** Queues task for the pool (returned, to join); with one thread, runs it now (null returned). */
    TaskHandle start(const std::function<void()>& task);

    /** Returns when a task start() returned, if any, is done. */
    void join(TaskHandle& task);

    /** Runs first on another thread (when one is free) and second on this one, and waits for
     * both. */
    void runBoth(const std::function<void()>& first, const std::function<void()>& second);

    /** Calls visit(half, first, last) for the two halves (0, 1) of [0, count) through runBoth();
     * returns where the second half starts. */
    std::size_t
    runHalves(std::size_t count,
              const std::function<void(unsigned int half, std::size_t first, std::size_t last)>& visit);

private:
    /** Takes the first queued task and runs it; the lock is held before and after. */
    void runQueued(std::unique_lock<std::mutex>& lock, const TaskHandle& task);
    void work();

    unsigned int _threads;
    std::vector<std::thread> _pool; // started with the first task
    std::mutex _mutex;              // the members below and every task's flags
    std::condition_variable _changed;
    std::deque<TaskHandle> _queue;
    bool _stopping = false;
};

}
}

#endif
