#include <osgGlyphsData/TrajectoryPlayer>

#include <osg/NodeVisitor>
#include <osg/Notify>

#include <algorithm>
#include <cmath>

using namespace osgGlyphsData;

TrajectoryPlayer::TrajectoryPlayer(FrameCache* cache, const GlyphMapper& mapper, osgGlyphs::GlyphCloud* cloud)
    : _cache(cache), _mapper(mapper), _cloud(cloud)
{
    // Its arrays change between frames while a viewer may draw it.
    _cloud->setDataVariance(osg::Object::DYNAMIC);
    const FrameInfo first = _cache->getSource()->getFrameInfo(0);
    _shownPosition = 0.0;
    _shownTimestep = static_cast<double>(first.timestep);
    tellCache();
}

void TrajectoryPlayer::setPlaying(bool playing)
{
    _playing = playing;
    _due = 0.0;
}

void TrajectoryPlayer::setFramesPerSecond(double framesPerSecond)
{
    _framesPerSecond = std::max(framesPerSecond, 1e-3);
}

void TrajectoryPlayer::setStep(int step)
{
    _step = step == 0 ? 1 : step;
    tellCache();
}

void TrajectoryPlayer::setRange(std::size_t first, std::size_t last)
{
    _first = first;
    _last = std::max(first, last);
    tellCache();
}

void TrajectoryPlayer::setSubframes(unsigned int subframes)
{
    _subframes = subframes;
}

std::size_t TrajectoryPlayer::getNumFrames() const
{
    return _cache->getSource()->getNumFrames();
}

void TrajectoryPlayer::seek(double position)
{
    const double last = static_cast<double>(std::min(_last, std::max<std::size_t>(getNumFrames(), 1) - 1));
    _position = std::clamp(position, static_cast<double>(_first), last);
    _lateCounted = false;
    tellCache();
}

TrajectoryPlayer::Place TrajectoryPlayer::locate(double position) const
{
    const std::size_t stride = static_cast<std::size_t>(std::abs(_step));
    const std::size_t last = std::min(_last, std::max<std::size_t>(getNumFrames(), 1) - 1);
    const double steps = std::floor((position - static_cast<double>(_first)) / stride + 1e-9);
    Place place;
    place.a = std::min(_first + static_cast<std::size_t>(std::max(steps, 0.0)) * stride, last);
    place.b = std::min(place.a + stride, last);
    place.t =
        place.b == place.a ? 0.0 : std::clamp((position - static_cast<double>(place.a)) / stride, 0.0, 1.0);
    if (place.t < 1e-9)
        place.b = place.a;
    return place;
}

bool TrajectoryPlayer::nextPosition(double& position) const
{
    const double stride = std::abs(_step);
    const double pictures = (_subframes + 1) / stride; // pictures per stored frame
    const double first = static_cast<double>(_first);
    const double last = static_cast<double>(std::min(_last, std::max<std::size_t>(getNumFrames(), 1) - 1));
    // Counted in pictures from the first frame, so that steps never drift off the grid.
    const double lastPicture = std::floor((last - first) * pictures + 1e-9);
    double picture = std::round((position - first) * pictures) + (_step > 0 ? 1.0 : -1.0);
    if (picture > lastPicture || picture < 0.0)
    {
        if (!_loop || lastPicture <= 0.0)
            return false;
        picture = picture < 0.0 ? lastPicture : 0.0;
    }
    position = first + picture / pictures;
    return true;
}

void TrajectoryPlayer::update(double time)
{
    const double elapsed = _hasTime ? std::max(time - _lastTime, 0.0) : 0.0;
    _hasTime = true;
    _lastTime = time;
    if (_shownPosition != _position)
    {
        // A late (or sought) picture: once shown, it stays a whole interval, the next one is not
        // shown over it in this update.
        if (show(_position, false))
            _due = 0.0;
        else if (!_lateCounted)
        {
            ++_statistics.late;
            _lateCounted = true;
        }
        return;
    }
    if (!_playing)
        return;
    _due += elapsed * _framesPerSecond;
    if (_due < 1.0)
        return;
    _due = std::min(_due - 1.0, 1.0); // no bursts to catch up
    double next = _position;
    if (!nextPosition(next))
    {
        _playing = false;
        return;
    }
    _position = next;
    _lateCounted = false;
    if (!_loop && !nextPosition(next))
        _playing = false; // the last picture: it is shown, and playback ends there
    tellCache();
    if (!show(_position, false))
    {
        ++_statistics.late;
        _lateCounted = true;
    }
}

bool TrajectoryPlayer::showNow(double position, std::string& error)
{
    seek(position);
    const uint64_t failed = _statistics.failed;
    _reportErrors = false; // the caller reports them
    show(_position, true);
    _reportErrors = true;
    if (_statistics.failed != failed)
    {
        error = _statistics.lastError;
        return false;
    }
    return true;
}

void TrajectoryPlayer::operator()(osg::Node* node, osg::NodeVisitor* nv)
{
    if (nv->getFrameStamp())
        update(nv->getFrameStamp()->getSimulationTime());
    traverse(node, nv);
}

osg::ref_ptr<const PointData> TrajectoryPlayer::fetch(std::size_t frame, bool blocking, bool& failed)
{
    std::string error;
    osg::ref_ptr<const PointData> data =
        blocking ? _cache->getFrame(frame, error) : _cache->tryGetFrame(frame, error);
    if (!data && !error.empty())
    {
        failed = true;
        fail(error);
    }
    return data;
}

void TrajectoryPlayer::fail(const std::string& error)
{
    ++_statistics.failed;
    _statistics.lastError = error;
    if (!_reportErrors)
        return;
    if (_onError)
        _onError(error);
    else
        OSG_WARN << error << std::endl;
}

bool TrajectoryPlayer::show(double position, bool blocking)
{
    const Place place = locate(position);
    bool failed = false;
    osg::ref_ptr<const PointData> a = fetch(place.a, blocking, failed);
    osg::ref_ptr<const PointData> b = place.b == place.a || failed ? a : fetch(place.b, blocking, failed);
    if (failed)
    {
        _shownPosition = position; // skipped: the last picture stays, playback goes on
        return true;
    }
    if (!a || !b)
        return false;
    osg::ref_ptr<const PointData> picture = a;
    if (b != a)
    {
        if (_pair.a != place.a || _pair.b != place.b)
        {
            const bool smooth = _interpolation.method == FrameInterpolationOptions::Method::Smooth;
            const std::size_t stride = static_cast<std::size_t>(std::abs(_step));
            // The frames around for a smooth curve: waited for only where the picture is (offscreen).
            const auto neighbour = [this, blocking](std::size_t frame)
            {
                std::string ignored;
                return frame < getNumFrames() ? (blocking ? _cache->getFrame(frame, ignored)
                                                          : _cache->tryGetFrame(frame, ignored))
                                              : osg::ref_ptr<const PointData>();
            };
            osg::ref_ptr<const PointData> before =
                smooth && place.a >= _first + stride ? neighbour(place.a - stride) : nullptr;
            osg::ref_ptr<const PointData> after = smooth ? neighbour(place.b + stride) : nullptr;
            _pair = {place.a, place.b,
                     new FrameInterpolator(before.get(), *a, *b, after.get(), _interpolation)};
            if (!_pair.interpolator->isValid())
                fail(_pair.interpolator->getError());
        }
        if (_pair.interpolator->isValid())
        {
            picture = _pair.interpolator->interpolate(place.t);
            ++_statistics.interpolated;
        }
        else if (place.t >= 0.5)
            picture = b;
    }
    std::string error;
    if (!_mapper.updateCloud(*_cloud, *picture, error))
        fail(error);
    _shownPosition = position;
    _shownTimestep = a->getTimestep() + place.t * double(b->getTimestep() - a->getTimestep());
    ++_statistics.shown;
    return true;
}

void TrajectoryPlayer::tellCache()
{
    _cache->setPlayback(locate(_position).a, _step, _loop, _first, _last);
}

osg::ref_ptr<PointDataset> osgGlyphsData::sampleFrames(const FrameSource& source, std::size_t count,
                                                       std::size_t first)
{
    osg::ref_ptr<PointDataset> dataset = new PointDataset;
    dataset->setSource(source.getSource());
    dataset->setFormat(source.getFormat());
    std::vector<std::size_t> frames{first};
    const std::size_t known = source.getNumFrames();
    for (std::size_t i = 0; count > 1 && known > 1 && i < count - 1; ++i)
    {
        const std::size_t frame = (i * (known - 1) + (count - 2) / 2) / std::max<std::size_t>(count - 2, 1);
        if (std::find(frames.begin(), frames.end(), std::min(frame, known - 1)) == frames.end())
            frames.push_back(std::min(frame, known - 1));
    }
    for (std::size_t frame : frames)
    {
        std::string error;
        osg::ref_ptr<PointData> data = source.getFirstFrame();
        if (frame != 0)
            data = source.readFrame(frame, error);
        if (data.valid())
            dataset->addFrame(data.get());
        else if (frame == first)
            break;
    }
    return dataset;
}
