/* osgGlyphs - private: reading the root tiles of a TileSeries' frames on a thread. Not
 * installed. */

#ifndef OSGGLYPHS_TILEFRAMELOADER_H
#define OSGGLYPHS_TILEFRAMELOADER_H 1

#include <osgGlyphsTiles/TileRoot>

#include <condition_variable>
#include <cstddef>
#include <deque>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace osgGlyphsTiles
{
namespace detail
{

/** Reads frames' archives (their root tiles, checked against their checksums) one at a time on
 * a worker thread started at the first request and joined on destruction. */
class TileFrameLoader : public osg::Referenced
{
public:
    struct Result
    {
        std::size_t frame = 0;
        osg::ref_ptr<TileRoot> root; // nullptr: error says why
        std::string error;
    };

    TileFrameLoader() = default;

    /** Queues frame's archive at path unless it is queued or being read. */
    void request(std::size_t frame, const std::string& path);
    /** Drops the queued requests of frames other than these (being read: finished anyway). */
    void keepOnly(const std::vector<std::size_t>& frames);
    /** The frames read since the last call. */
    std::vector<Result> takeResults();
    /** Whether frame is queued or being read. */
    bool isBusyWith(std::size_t frame) const;

    /** Reads the archive at path on this thread: its TileRoot (one made above an older
     * archive's root), or nullptr with a one-line error naming path. */
    static Result load(std::size_t frame, const std::string& path);

protected:
    ~TileFrameLoader() override;

    void run();

    struct Request
    {
        std::size_t frame;
        std::string path;
    };
    mutable std::mutex _mutex;
    std::condition_variable _wake;
    std::deque<Request> _queue;
    std::size_t _reading = SIZE_MAX;
    std::vector<Result> _results;
    bool _stopping = false;
    std::thread _thread;
};

}
}

#endif
