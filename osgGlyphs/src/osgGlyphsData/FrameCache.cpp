#include <osgGlyphsData/FrameCache>

#include <chrono>
#include <condition_variable>
#include <deque>
#include <map>
#include <mutex>
#include <set>
#include <thread>

using namespace osgGlyphsData;

const uint64_t FrameCache::DEFAULT_BUDGET_BYTES = uint64_t(256) << 20;

namespace
{

/** Frames decoded ahead of playback at most, whatever the budget. */
const std::size_t MAX_LOOKAHEAD = 64;
/** The frames a cache holds whatever their size: a pair to interpolate between. */
const std::size_t MIN_FRAMES = 2;

/** Reads a frame from the source, timing it. */
osg::ref_ptr<PointData> decode(const FrameSource& source, std::size_t frame, std::string& error,
                               double& seconds)
{
    const auto start = std::chrono::steady_clock::now();
    osg::ref_ptr<PointData> data = source.readFrame(frame, error);
    seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return data;
}

struct Entry
{
    osg::ref_ptr<PointData> data;
    std::string error;
    uint64_t bytes = 0;
};

}

struct FrameCache::Impl
{
    std::mutex mutex;
    std::condition_variable wake;    // the worker: a request, a new position, or stop
    std::condition_variable decoded; // getFrame(): a frame in flight is done
    std::map<std::size_t, Entry> frames;
    std::set<std::size_t> inFlight;
    std::deque<std::size_t> requests; // most recent first
    std::size_t position = 0;
    int step = 1;
    bool loop = false;
    std::size_t first = 0;
    std::size_t last = SIZE_MAX;
    bool stop = false;
    FrameCacheStatistics statistics;
    uint64_t typicalBytes = 0; // of the last frame decoded
    std::thread worker;

    /** The k-th frame from the position in the playback direction; false past the range's end. */
    bool ahead(std::size_t k, std::size_t numFrames, std::size_t& frame) const
    {
        if (numFrames == 0)
            return false;
        const int64_t lo = static_cast<int64_t>(first);
        const int64_t hi = static_cast<int64_t>(std::min(last, numFrames - 1));
        if (lo > hi)
            return false;
        int64_t f = static_cast<int64_t>(position) + static_cast<int64_t>(k) * step;
        if (f < lo || f > hi)
        {
            if (!loop)
                return false;
            const int64_t span = hi - lo + 1;
            f = lo + (((f - lo) % span) + span) % span;
        }
        frame = static_cast<std::size_t>(f);
        return true;
    }

    /** How far a frame lies ahead of the position in playback order; frames behind are farthest. */
    std::size_t distance(std::size_t frame, std::size_t numFrames) const
    {
        for (std::size_t k = 0; k <= MAX_LOOKAHEAD; ++k)
        {
            std::size_t f = 0;
            if (!ahead(k, numFrames, f))
                break;
            if (f == frame)
                return k;
        }
        const std::size_t behind = frame > position ? frame - position : position - frame;
        return MAX_LOOKAHEAD + 1 + behind;
    }

    bool fits(uint64_t budget) const
    {
        return frames.size() < MIN_FRAMES || statistics.bytes + typicalBytes <= budget;
    }

    /** The next frame the worker decodes, if any: a request, else the next frame ahead. */
    bool chooseNext(std::size_t numFrames, uint64_t budget, std::size_t& next)
    {
        while (!requests.empty())
        {
            next = requests.front();
            requests.pop_front();
            if (!frames.count(next) && !inFlight.count(next) && next < numFrames)
                return true;
        }
        for (std::size_t k = 0; k < MAX_LOOKAHEAD; ++k)
        {
            if (!ahead(k, numFrames, next))
                return false;
            if (frames.count(next) || inFlight.count(next))
                continue;
            return makeRoom(budget, numFrames, k);
        }
        return false;
    }

    /** The frame if it is held (its error for one that failed), counted as a hit or a miss. */
    bool lookUp(std::size_t frame, osg::ref_ptr<const PointData>& data, std::string& error)
    {
        auto found = frames.find(frame);
        ++(found != frames.end() ? statistics.hits : statistics.misses);
        if (found == frames.end())
            return false;
        error = found->second.error;
        data = found->second.data;
        return true;
    }

    /** Drops frames farther than k ahead until another frame fits; false when it cannot. */
    bool makeRoom(uint64_t budget, std::size_t numFrames, std::size_t k)
    {
        while (!fits(budget))
        {
            auto farthest = findFarthest(numFrames, SIZE_MAX);
            if (farthest == frames.end() || distance(farthest->first, numFrames) <= k)
                return false;
            statistics.bytes -= farthest->second.bytes;
            frames.erase(farthest);
        }
        return true;
    }

    /** The held frame farthest from the position, but for the position, the next frame and keep. */
    std::map<std::size_t, Entry>::iterator findFarthest(std::size_t numFrames, std::size_t keep)
    {
        std::size_t next = position;
        ahead(1, numFrames, next);
        auto farthest = frames.end();
        std::size_t farthestDistance = 0;
        for (auto it = frames.begin(); it != frames.end(); ++it)
        {
            if (it->first == position || it->first == next || it->first == keep)
                continue;
            const std::size_t d = distance(it->first, numFrames);
            if (farthest == frames.end() || d > farthestDistance)
            {
                farthest = it;
                farthestDistance = d;
            }
        }
        return farthest;
    }

    void store(std::size_t frame, osg::ref_ptr<PointData> data, const std::string& error, double seconds,
               uint64_t budget, std::size_t numFrames)
    {
        Entry& entry = frames[frame];
        entry.data = data;
        entry.error = data.valid() ? std::string() : error;
        entry.bytes = data.valid() ? getFrameBytes(*data) : 0;
        ++(data.valid() ? statistics.decoded : statistics.failures);
        statistics.decodeSeconds += seconds;
        statistics.bytes += entry.bytes;
        if (data.valid())
            typicalBytes = entry.bytes;
        evict(budget, numFrames, frame);
        statistics.peakBytes = std::max(statistics.peakBytes, statistics.bytes);
        inFlight.erase(frame);
        decoded.notify_all();
    }

    /** Drops the farthest frames while the budget is exceeded, keeping at least MIN_FRAMES and keep. */
    void evict(uint64_t budget, std::size_t numFrames, std::size_t keep = SIZE_MAX)
    {
        while (statistics.bytes > budget && frames.size() > MIN_FRAMES)
        {
            auto farthest = findFarthest(numFrames, keep);
            if (farthest == frames.end())
                break;
            statistics.bytes -= farthest->second.bytes;
            frames.erase(farthest);
        }
    }
};

FrameCache::FrameCache(FrameSource* source, uint64_t budgetBytes)
    : _source(source), _budget(budgetBytes), _impl(new Impl)
{
    Impl& impl = *_impl;
    impl.worker = std::thread(
        [this, &impl]
        {
            std::unique_lock<std::mutex> lock(impl.mutex);
            while (!impl.stop)
            {
                std::size_t next = 0;
                if (!impl.chooseNext(_source->getNumFrames(), _budget, next))
                {
                    impl.wake.wait(lock);
                    continue;
                }
                impl.inFlight.insert(next);
                lock.unlock();
                std::string error;
                double seconds = 0.0;
                osg::ref_ptr<PointData> data = decode(*_source, next, error, seconds);
                lock.lock();
                impl.store(next, data, error, seconds, _budget, _source->getNumFrames());
            }
        });
}

FrameCache::~FrameCache()
{
    {
        std::lock_guard<std::mutex> lock(_impl->mutex);
        _impl->stop = true;
    }
    _impl->wake.notify_all();
    _impl->worker.join();
}

uint64_t FrameCache::getFrameBytes(const PointData& frame)
{
    return uint64_t(frame.getNumColumns()) * frame.getNumPoints() * sizeof(float) + sizeof(PointData);
}

osg::ref_ptr<const PointData> FrameCache::tryGetFrame(std::size_t frame, std::string& error)
{
    std::lock_guard<std::mutex> lock(_impl->mutex);
    osg::ref_ptr<const PointData> data;
    if (_impl->lookUp(frame, data, error))
        return data;
    if (!_impl->inFlight.count(frame))
    {
        _impl->requests.push_front(frame);
        _impl->wake.notify_all();
    }
    return nullptr;
}

osg::ref_ptr<const PointData> FrameCache::getFrame(std::size_t frame, std::string& error)
{
    std::unique_lock<std::mutex> lock(_impl->mutex);
    _impl->decoded.wait(lock, [&] { return !_impl->inFlight.count(frame); });
    osg::ref_ptr<const PointData> held;
    if (_impl->lookUp(frame, held, error))
        return held;
    _impl->inFlight.insert(frame);
    lock.unlock();
    double seconds = 0.0;
    osg::ref_ptr<PointData> data = decode(*_source, frame, error, seconds);
    lock.lock();
    _impl->store(frame, data, error, seconds, _budget, _source->getNumFrames());
    _impl->wake.notify_all();
    return data;
}

void FrameCache::setPlayback(std::size_t frame, int step, bool loop, std::size_t first, std::size_t last)
{
    {
        std::lock_guard<std::mutex> lock(_impl->mutex);
        _impl->position = frame;
        _impl->step = step == 0 ? 1 : step;
        _impl->loop = loop;
        _impl->first = first;
        _impl->last = last;
        _impl->evict(_budget, _source->getNumFrames());
    }
    _impl->wake.notify_all();
}

FrameCacheStatistics FrameCache::getStatistics() const
{
    std::lock_guard<std::mutex> lock(_impl->mutex);
    return _impl->statistics;
}
