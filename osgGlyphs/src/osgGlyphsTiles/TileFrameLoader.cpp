#include "TileFrameLoader.h"

#include <osgGlyphsTiles/TileBuilder>
#include <osgGlyphsTiles/TileChecksum>

#include <osgDB/FileUtils>
#include <osgDB/Registry>

#include <algorithm>

using namespace osgGlyphsTiles;
using namespace osgGlyphsTiles::detail;

TileFrameLoader::~TileFrameLoader()
{
    {
        std::lock_guard<std::mutex> lock(_mutex);
        _stopping = true;
        _queue.clear();
    }
    _wake.notify_all();
    if (_thread.joinable())
        _thread.join();
}

void TileFrameLoader::request(std::size_t frame, const std::string& path)
{
    {
        std::lock_guard<std::mutex> lock(_mutex);
        if (_reading == frame ||
            std::any_of(_queue.begin(), _queue.end(), [frame](const Request& r) { return r.frame == frame; }))
            return;
        _queue.push_back({frame, path});
        if (!_thread.joinable())
            _thread = std::thread(&TileFrameLoader::run, this);
    }
    _wake.notify_one();
}

void TileFrameLoader::keepOnly(const std::vector<std::size_t>& frames)
{
    std::lock_guard<std::mutex> lock(_mutex);
    _queue.erase(std::remove_if(_queue.begin(), _queue.end(),
                                [&frames](const Request& r)
                                { return std::find(frames.begin(), frames.end(), r.frame) == frames.end(); }),
                 _queue.end());
}

std::vector<TileFrameLoader::Result> TileFrameLoader::takeResults()
{
    std::lock_guard<std::mutex> lock(_mutex);
    std::vector<Result> results;
    results.swap(_results);
    return results;
}

bool TileFrameLoader::isBusyWith(std::size_t frame) const
{
    std::lock_guard<std::mutex> lock(_mutex);
    return _reading == frame ||
           std::any_of(_queue.begin(), _queue.end(), [frame](const Request& r) { return r.frame == frame; });
}

void TileFrameLoader::run()
{
    std::unique_lock<std::mutex> lock(_mutex);
    for (;;)
    {
        _wake.wait(lock, [this] { return _stopping || !_queue.empty(); });
        if (_stopping)
            return;
        const Request request = _queue.front();
        _queue.pop_front();
        _reading = request.frame;
        lock.unlock();
        Result result = load(request.frame, request.path);
        lock.lock();
        _reading = SIZE_MAX;
        _results.push_back(std::move(result));
    }
}

TileFrameLoader::Result TileFrameLoader::load(std::size_t frame, const std::string& path)
{
    Result result;
    result.frame = frame;
    if (!osgDB::fileExists(path))
    {
        result.error = path + ": no such file";
        return result;
    }
    if (!findTileSerializers(result.error))
        return result;
    // Through the Registry, which returns what went wrong instead of printing it.
    osgDB::Registry* registry = osgDB::Registry::instance();
    osgDB::ReaderWriter::ReadResult read = registry->readNode(path, registry->getOptions());
    osg::ref_ptr<osg::Node> node = read.getNode();
    if (!node)
    {
        result.error = path + ": not an OSG archive of glyph tiles (osgDB cannot read it" +
                       (read.message().empty() ? std::string() : ": " + read.message()) + ")";
        return result;
    }
    std::string error;
    if (!checkTileChecksum(*node, error))
    {
        result.error = path + ": root tile: " + error;
        return result;
    }
    result.root = dynamic_cast<TileRoot*>(node.get());
    if (!result.root)
    {
        result.root = new TileRoot;
        result.root->addChild(node.get());
    }
    return result;
}
