#include <osgGlyphsTiles/TileSeries>

#include "TileFrameLoader.h"

#include <osg/PagedLOD>
#include <osgDB/FileNameUtils>
#include <osgDB/Registry>
#include <osgUtil/CullVisitor>

using namespace osgGlyphsTiles;

namespace
{

/** Priority of the prefetched frame's tile requests: below any of the shown frame's (a PagedLOD
 * in pixel-size mode asks at about 0). */
const float PREFETCH_PRIORITY = -1.0f;

/** Requests the tiles under node that a cull at lodScale would page in and are not in yet. */
void requestTilesInView(osg::Node& node, osgUtil::CullVisitor& cv, float lodScale)
{
    if (cv.isCulled(node))
        return;
    osg::PagedLOD* lod = dynamic_cast<osg::PagedLOD*>(&node);
    if (!lod)
    {
        if (osg::Group* group = node.asGroup())
            for (unsigned int i = 0; i < group->getNumChildren(); ++i)
                requestTilesInView(*group->getChild(i), cv, lodScale);
        return;
    }
    if (lod->getNumRanges() < 2 || lod->getNumChildren() == 0 ||
        cv.clampedPixelSize(lod->getBound()) / lodScale < lod->getMinRange(1))
        return;
    const osg::FrameStamp* stamp = cv.getFrameStamp();
    if (lod->getNumChildren() > 1)
    {
        // Kept from expiring until it is shown, as a traversal of the PagedLOD would.
        if (stamp)
        {
            lod->setTimeStamp(1, stamp->getReferenceTime());
            lod->setFrameNumber(1, stamp->getFrameNumber());
        }
        requestTilesInView(*lod->getChild(1), cv, lodScale);
        return;
    }
    osg::NodeVisitor::DatabaseRequestHandler* pager = cv.getDatabaseRequestHandler();
    if (!pager || lod->getFileName(1).empty())
        return;
    osg::NodePath path(1, lod);
    pager->requestNodeFile(lod->getDatabasePath() + lod->getFileName(1), path, PREFETCH_PRIORITY, stamp,
                           lod->getDatabaseRequest(1), lod->getDatabaseOptions());
}

/** Closes a frame's archive, which osgDB keeps open in its archive cache after reading it. */
void closeArchive(const std::string& path)
{
    osgDB::Registry::instance()->removeFromArchiveCache(path);
}

}

TileSeries::TileSeries() : _loader(new detail::TileFrameLoader), _prefetchBudget(new TileBudget)
{
    setNumChildrenRequiringUpdateTraversal(getNumChildrenRequiringUpdateTraversal() + 1);
}

TileSeries::TileSeries(const TileSeries& other, const osg::CopyOp& copyop)
    : osg::Group(other, copyop), _frames(other._frames), _databasePath(other._databasePath),
      _glyphBudget(other._glyphBudget), _loader(new detail::TileFrameLoader), _prefetchBudget(new TileBudget)
{
    // The copy reads and shows its frames itself.
    removeChildren(0, getNumChildren());
    setNumChildrenRequiringUpdateTraversal(getNumChildrenRequiringUpdateTraversal() + 1);
}

TileSeries::~TileSeries()
{
    _loader = nullptr; // joins its thread before the frames go
    for (const auto& loaded : _loaded)
        closeArchive(getFramePath(loaded.first));
}

void TileSeries::addFrame(const std::string& file, double timestep)
{
    _frames.push_back({file, timestep});
}

void TileSeries::setFrames(const std::vector<Frame>& frames)
{
    _frames = frames;
}

void TileSeries::setDatabasePath(const std::string& path)
{
    _databasePath = path;
    if (!_databasePath.empty() && _databasePath.back() != '/' && _databasePath.back() != '\\')
        _databasePath += '/';
}

std::string TileSeries::getFramePath(std::size_t frame) const
{
    if (frame >= _frames.size())
        return std::string();
    const std::string& file = _frames[frame].file;
    return osgDB::isAbsolutePath(file) ? file : _databasePath + file;
}

void TileSeries::setGlyphBudget(std::size_t maxGlyphs)
{
    _glyphBudget = maxGlyphs;
    for (const auto& loaded : _loaded)
        if (maxGlyphs)
            loaded.second->setGlyphBudget(maxGlyphs);
}

TileRoot* TileSeries::getShownRoot() const
{
    const auto shown = _loaded.find(_shown);
    return shown == _loaded.end() ? nullptr : shown->second.get();
}

bool TileSeries::getFrameError(std::size_t frame, std::string& error) const
{
    const auto failed = _failed.find(frame);
    if (failed == _failed.end())
        return false;
    error = failed->second;
    return true;
}

void TileSeries::collectLoaded()
{
    for (detail::TileFrameLoader::Result& result : _loader->takeResults())
    {
        if (!result.root)
        {
            _failed[result.frame] = result.error;
            continue;
        }
        if (_loaded.count(result.frame))
            continue; // read meanwhile on the caller's thread (showFrameNow())
        if (result.frame != _wanted && result.frame != _prefetch && result.frame != _shown)
        {
            closeArchive(getFramePath(result.frame)); // no longer wanted
            continue;
        }
        if (_glyphBudget)
            result.root->setGlyphBudget(_glyphBudget);
        _loaded[result.frame] = result.root;
    }
}

void TileSeries::keepOnly(std::size_t a, std::size_t b, std::size_t c)
{
    for (auto loaded = _loaded.begin(); loaded != _loaded.end();)
    {
        if (loaded->first == a || loaded->first == b || loaded->first == c)
        {
            ++loaded;
            continue;
        }
        closeArchive(getFramePath(loaded->first));
        loaded = _loaded.erase(loaded);
    }
    _loader->keepOnly({a, b, c});
}

bool TileSeries::display(std::size_t frame)
{
    const auto loaded = _loaded.find(frame);
    if (loaded == _loaded.end())
        return false;
    if (_shown != frame)
    {
        removeChildren(0, getNumChildren());
        addChild(loaded->second.get());
        _shown = frame;
    }
    keepOnly(_shown, _wanted, _prefetch);
    return true;
}

TileSeries::FrameState TileSeries::findFrame(std::size_t frame, std::string& error)
{
    if (frame >= _frames.size())
    {
        error = "no frame " + std::to_string(frame) + " in the series (" + std::to_string(_frames.size()) +
                " frames)";
        return FRAME_FAILED;
    }
    collectLoaded();
    if (getFrameError(frame, error))
        return FRAME_FAILED;
    _wanted = frame;
    return display(frame) ? FRAME_SHOWN : FRAME_PENDING;
}

TileSeries::FrameState TileSeries::showFrame(std::size_t frame, std::string& error)
{
    const FrameState state = findFrame(frame, error);
    if (state == FRAME_PENDING)
        _loader->request(frame, getFramePath(frame));
    return state;
}

TileSeries::FrameState TileSeries::showFrameNow(std::size_t frame, std::string& error)
{
    const FrameState state = findFrame(frame, error);
    if (state != FRAME_PENDING)
        return state;
    detail::TileFrameLoader::Result result = detail::TileFrameLoader::load(frame, getFramePath(frame));
    if (!result.root)
    {
        _failed[frame] = error = result.error;
        return FRAME_FAILED;
    }
    if (_glyphBudget)
        result.root->setGlyphBudget(_glyphBudget);
    _loaded[frame] = result.root;
    display(frame);
    return FRAME_SHOWN;
}

void TileSeries::setPrefetchFrame(std::size_t frame)
{
    _prefetch = frame < _frames.size() ? frame : SIZE_MAX;
    if (_prefetch == SIZE_MAX || _loaded.count(_prefetch) || _failed.count(_prefetch))
        return;
    _loader->request(_prefetch, getFramePath(_prefetch));
}

void TileSeries::traverse(osg::NodeVisitor& nv)
{
    if (nv.getVisitorType() == osg::NodeVisitor::UPDATE_VISITOR)
    {
        std::string error;
        if (_shown == SIZE_MAX && _wanted == SIZE_MAX && !_frames.empty())
            showFrame(0, error);
        else if (_wanted != SIZE_MAX && _wanted != _shown)
            showFrame(_wanted, error);
        else
            collectLoaded();
        // The prefetched frame's tiles merged by the pager: bounds brought up to date as the
        // shown frame's TileRoot does it.
        const auto prefetched = _loaded.find(_prefetch);
        if (prefetched != _loaded.end() && _prefetch != _shown)
            prefetched->second->accept(nv);
    }
    else if (osgUtil::CullVisitor* cv = nv.asCullVisitor())
        prefetchTiles(*cv);
    osg::Group::traverse(nv);
    // A frame shown in place of another dirties the bound: computed here, before cull threads
    // would compute it together.
    if (nv.getVisitorType() == osg::NodeVisitor::UPDATE_VISITOR)
        getBound();
}

void TileSeries::prefetchTiles(osgUtil::CullVisitor& cv)
{
    const auto prefetched = _loaded.find(_prefetch);
    if (prefetched == _loaded.end() || _prefetch == _shown)
        return;
    TileRoot& root = *prefetched->second;
    // The cull threads of several views take turns: the budget and the PagedLODs' stamps are shared.
    std::lock_guard<std::mutex> lock(_prefetchMutex);
    float lodScale = cv.getLODScale();
    if (root.getGlyphBudget())
    {
        _prefetchBudget->setMaxGlyphs(root.getGlyphBudget());
        lodScale = static_cast<float>(lodScale * _prefetchBudget->computeLODScale(root, cv));
    }
    requestTilesInView(root, cv, lodScale);
}

void TileSeries::releaseGLObjects(osg::State* state) const
{
    osg::Group::releaseGLObjects(state);
    for (const auto& loaded : _loaded)
        if (loaded.first != _shown)
            loaded.second->releaseGLObjects(state);
}
