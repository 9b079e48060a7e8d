#include <osgGlyphsTiles/TileSeriesPlayer>

using namespace osgGlyphsTiles;

TileSeriesPlayer::TileSeriesPlayer(TileSeries* series) : _series(series)
{
    _shownPosition = -1.0; // nothing shown: the first update shows frame 0
}

bool TileSeriesPlayer::show(double position, bool blocking)
{
    const Place place = locate(position);
    const std::size_t frame = place.t >= 0.5 ? place.b : place.a;
    std::string error;
    const TileSeries::FrameState state =
        blocking ? _series->showFrameNow(frame, error) : _series->showFrame(frame, error);
    if (state == TileSeries::FRAME_PENDING)
        return false;
    if (state == TileSeries::FRAME_FAILED)
    {
        if (_reported.insert(frame).second || !_reportErrors)
            fail(error);
        _shownPosition = position; // skipped: the last picture stays, playback goes on
        return true;
    }
    shown(position, _series->getFrames()[frame].timestep, false);
    double next = position;
    if (nextPosition(next))
    {
        const Place ahead = locate(next);
        _series->setPrefetchFrame(ahead.t >= 0.5 ? ahead.b : ahead.a);
    }
    return true;
}
