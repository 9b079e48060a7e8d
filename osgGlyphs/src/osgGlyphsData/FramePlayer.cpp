#include <osgGlyphsData/FramePlayer>

#include <osg/NodeVisitor>
#include <osg/Notify>

#include <algorithm>
#include <cmath>

using namespace osgGlyphsData;

void FramePlayer::setPlaying(bool playing)
{
    _playing = playing;
    _due = 0.0;
}

void FramePlayer::setFramesPerSecond(double framesPerSecond)
{
    _framesPerSecond = std::max(framesPerSecond, 1e-3);
}

void FramePlayer::setStep(int step)
{
    _step = step == 0 ? 1 : step;
    positionChanged();
}

void FramePlayer::setRange(std::size_t first, std::size_t last)
{
    _first = first;
    _last = std::max(first, last);
    positionChanged();
}

void FramePlayer::seek(double position)
{
    const double last = static_cast<double>(std::min(_last, std::max<std::size_t>(getNumFrames(), 1) - 1));
    _position = std::clamp(position, static_cast<double>(_first), last);
    _lateCounted = false;
    positionChanged();
}

FramePlayer::Place FramePlayer::locate(double position) const
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

bool FramePlayer::nextPosition(double& position) const
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

void FramePlayer::update(double time)
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
    positionChanged();
    if (!show(_position, false))
    {
        ++_statistics.late;
        _lateCounted = true;
    }
}

bool FramePlayer::showNow(double position, std::string& error)
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

void FramePlayer::operator()(osg::Node* node, osg::NodeVisitor* nv)
{
    if (nv->getFrameStamp())
        update(nv->getFrameStamp()->getSimulationTime());
    traverse(node, nv);
}

void FramePlayer::shown(double position, double timestep, bool interpolated)
{
    _shownPosition = position;
    _shownTimestep = timestep;
    ++_statistics.shown;
    if (interpolated)
        ++_statistics.interpolated;
}

void FramePlayer::fail(const std::string& error)
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
