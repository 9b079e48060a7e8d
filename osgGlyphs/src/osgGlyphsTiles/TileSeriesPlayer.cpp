#include <osgGlyphsTiles/TileSeriesPlayer>

using namespace osgGlyphsTiles;

TileSeriesPlayer::TileSeriesPlayer(TileSeries* series) : _series(series)
{
    _shownPosition = -1.0; // nothing shown: the first update shows frame 0
}

TileSeries* TileSeriesPlayer::getSeries() const
{
    osg::ref_ptr<TileSeries> series;
    return _series.lock(series) ? series.get() : nullptr;
}

std::size_t TileSeriesPlayer::getNumFrames() const
{
    const TileSeries* series = getSeries();
    return series ? series->getNumFrames() : 0;
}

std::string TileSeriesPlayer::getSourceName() const
{
    const TileSeries* series = getSeries();
    return series ? series->getDatabasePath() : std::string();
}

bool TileSeriesPlayer::show(double position, bool blocking)
{
    osg::ref_ptr<TileSeries> series;
    if (!_series.lock(series))
        return true; // nothing to show: not late
    const Place place = locate(position);
    const std::size_t frame = place.t >= 0.5 ? place.b : place.a;
    std::string error;
    const TileSeries::FrameState state =
        blocking ? series->showFrameNow(frame, error) : series->showFrame(frame, error);
    if (state == TileSeries::FRAME_PENDING)
        return false;
    if (state == TileSeries::FRAME_FAILED)
    {
        if (_reported.insert(frame).second || !_reportErrors)
            fail(error);
        _shownPosition = position; // skipped: the last picture stays, playback goes on
        return true;
    }
    shown(position, series->getFrames()[frame].timestep, false);
    double next = position;
    if (nextPosition(next))
    {
        const Place ahead = locate(next);
        series->setPrefetchFrame(ahead.t >= 0.5 ? ahead.b : ahead.a);
    }
    return true;
}
