/* K processes sharing a dataset, played by K threads of one process: a ShareReduction whose
 * collective functions meet as MPI ranks do, for deterministic tests without MPI. */

#ifndef OSGGLYPHS_TESTS_THREADSHARES_H
#define OSGGLYPHS_TESTS_THREADSHARES_H 1

#include <osgGlyphsData/PointShare>

#include <osg/ref_ptr>

#include <algorithm>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace readertest
{

/** Where the threads of one run meet: each collective call waits for every thread's values. */
class ThreadMeeting
{
public:
    explicit ThreadMeeting(unsigned int count) : _count(count), _doubles(count), _strings(count) {}

    unsigned int getCount() const { return _count; }

    /** Every thread's values, in thread order. */
    template <typename T>
    std::vector<T> gather(unsigned int index, const std::vector<T>& values)
    {
        std::unique_lock<std::mutex> lock(_mutex);
        std::vector<std::vector<T>>& slots = this->slots<T>();
        slots[index] = values;
        arrive(lock);
        std::vector<T> all;
        for (const std::vector<T>& slot : slots)
            all.insert(all.end(), slot.begin(), slot.end());
        arrive(lock); // nobody refills the slots before everyone has read them
        return all;
    }

private:
    template <typename T>
    std::vector<std::vector<T>>& slots();

    void arrive(std::unique_lock<std::mutex>& lock)
    {
        const unsigned long generation = _generation;
        if (++_arrived == _count)
        {
            _arrived = 0;
            ++_generation;
            _changed.notify_all();
        }
        else
            _changed.wait(lock, [&] { return _generation != generation; });
    }

    unsigned int _count;
    std::mutex _mutex;
    std::condition_variable _changed;
    unsigned int _arrived = 0;
    unsigned long _generation = 0;
    std::vector<std::vector<double>> _doubles;
    std::vector<std::vector<std::string>> _strings;
};

template <>
inline std::vector<std::vector<double>>& ThreadMeeting::slots<double>()
{
    return _doubles;
}

template <>
inline std::vector<std::vector<std::string>>& ThreadMeeting::slots<std::string>()
{
    return _strings;
}

/** Share index of a ThreadMeeting's count shares. */
class ThreadShare : public osgGlyphsData::ShareReduction
{
public:
    ThreadShare(ThreadMeeting& meeting, unsigned int index) : _meeting(meeting), _index(index) {}

    void minimum(std::vector<double>& values) const override
    {
        combine(values, [](double a, double b) { return std::min(a, b); });
    }
    void maximum(std::vector<double>& values) const override
    {
        combine(values, [](double a, double b) { return std::max(a, b); });
    }
    void sum(std::vector<double>& values) const override
    {
        combine(values, [](double a, double b) { return a + b; });
    }
    void gather(std::vector<double>& values) const override { values = _meeting.gather(_index, values); }
    void gather(std::vector<std::string>& strings) const override
    {
        strings = _meeting.gather(_index, strings);
    }
    osgGlyphsData::PointShare getShare() const override
    {
        return osgGlyphsData::PointShare{_index, _meeting.getCount()};
    }

private:
    void combine(std::vector<double>& values, const std::function<double(double, double)>& operation) const
    {
        const std::vector<double> all = _meeting.gather(_index, values);
        for (std::size_t i = 0; i < values.size(); ++i)
        {
            values[i] = all[i];
            for (std::size_t at = i + values.size(); at < all.size(); at += values.size())
                values[i] = operation(values[i], all[at]);
        }
    }

    ThreadMeeting& _meeting;
    unsigned int _index;
};

/** Runs work(reduction, share index) in count threads at once, one per share; returns when all
 * are done. */
inline void runShares(unsigned int count,
                      const std::function<void(const osgGlyphsData::ShareReduction&, unsigned int)>& work)
{
    ThreadMeeting meeting(count);
    std::vector<osg::ref_ptr<ThreadShare>> shares;
    std::vector<std::thread> threads;
    for (unsigned int index = 0; index < count; ++index)
        shares.push_back(new ThreadShare(meeting, index));
    for (unsigned int index = 0; index < count; ++index)
        threads.emplace_back([&, index] { work(*shares[index], index); });
    for (std::thread& thread : threads)
        thread.join();
}

}

#endif
