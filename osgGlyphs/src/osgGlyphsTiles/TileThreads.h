/* osgGlyphs - private: the threads that cut a dataset's subtrees into tiles side by side. Not
 * installed. */

#ifndef OSGGLYPHS_TILETHREADS_H
#define OSGGLYPHS_TILETHREADS_H 1

#include <atomic>
#include <cstddef>
#include <functional>
#include <thread>

namespace osgGlyphsTiles
{
namespace detail
{

/** Fork and join with a given number of threads at work: start() runs a task on a new thread
 * while fewer are at work, else at once on the caller's. A thread waiting in join() lends its
 * place, so the task it waits for may start threads of its own (and one more may be at work for
 * a while after the wait). */
class TileThreads
{
public:
    /** threads: the most at work at once, the caller's included (0: the machine's cores). */
    explicit TileThreads(unsigned int threads);

    unsigned int getNumThreads() const { return _threads; }

    /** Runs task on a thread of its own (returned, to join) or, when none is free, now on this one
     * (an empty thread returned). */
    std::thread start(const std::function<void()>& task);

    /** Waits for a thread start() returned, if any. */
    void join(std::thread& thread);

    /** Runs first on another thread (when one is free) and second on this one, and waits for
     * both. */
    void runBoth(const std::function<void()>& first, const std::function<void()>& second);

    /** Calls visit(half, first, last) for the two halves (0, 1) of [0, count) through runBoth();
     * returns where the second half starts. */
    std::size_t
    runHalves(std::size_t count,
              const std::function<void(unsigned int half, std::size_t first, std::size_t last)>& visit);

private:
    unsigned int _threads;
    std::atomic<int> _free; // threads that may still start
};

}
}

#endif
