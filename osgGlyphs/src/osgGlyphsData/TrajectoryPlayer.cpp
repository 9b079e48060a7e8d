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
    positionChanged();
}

std::size_t TrajectoryPlayer::getNumFrames() const
{
    return _cache->getSource()->getNumFrames();
}

bool TrajectoryPlayer::isIndexComplete() const
{
    return _cache->getSource()->isIndexComplete();
}

void TrajectoryPlayer::waitForIndex()
{
    _cache->getSource()->waitForIndex();
}

std::string TrajectoryPlayer::getSourceName() const
{
    return _cache->getSource()->getSource();
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
    bool interpolated = false;
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
            interpolated = true;
        }
        else if (place.t >= 0.5)
            picture = b;
    }
    std::string error;
    if (!_mapper.updateCloud(*_cloud, *picture, error))
        fail(error);
    shown(position, a->getTimestep() + place.t * double(b->getTimestep() - a->getTimestep()), interpolated);
    return true;
}

void TrajectoryPlayer::positionChanged()
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
