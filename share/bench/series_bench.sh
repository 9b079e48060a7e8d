#!/bin/sh
# The time-series benchmark: a moving trajectory (DCD, osgglyphseriesbench trajectory) converted
# into a series of tile archives (osgglyphconvert --frame-range 0: ... series.osgt: glyph-frames per
# second, bytes per glyph-frame, peak memory), then played against one of its frames standing
# still (osgglyphseriesbench play), flat out and at PLAY_FPS frames a second.
#
#   share/bench/series_bench.sh                   from the source folder, after a build
#
# Settings, from the environment: BUILD (the build folder, build/ by default), DATA (the work
# folder), PARTICLES, FRAMES, RADIUS (0.4: dense, 0.4 x the mean spacing of 1), ROUNDS, RENDERS,
# PLAY_FPS.
set -eu

BUILD=${BUILD:-build}
DATA=${DATA:-/tmp/seriesbench}
PARTICLES=${PARTICLES:-10000000}
FRAMES=${FRAMES:-20}
RADIUS=${RADIUS:-0.4}
ROUNDS=${ROUNDS:-3}
RENDERS=${RENDERS:-20}
PLAY_FPS=${PLAY_FPS:-2}
BENCH=$BUILD/applications/osgglyphseriesbench/osgglyphseriesbench
CONVERT=$BUILD/applications/osgglyphconvert/osgglyphconvert

mkdir -p "$DATA"
echo "series_bench.sh: osgGlyphs $(git rev-parse --short HEAD 2>/dev/null || echo '?'), $(nproc) cores, $(date)" >&2
DCD=$DATA/moving_${PARTICLES}x$FRAMES.dcd
[ -s "$DCD" ] || "$BENCH" trajectory "$DCD" --particles "$PARTICLES" --frames "$FRAMES"
ls -l "$DCD"
cat "$DCD" >/dev/null # from the page cache: the converter's time, not the disk's
rm -f "$DATA"/series*.osga "$DATA/series.osgt"
/usr/bin/time -f "osgglyphconvert: %e s, peak memory %M KB" \
    "$CONVERT" --frame-range 0: --radius "$RADIUS" "$DCD" "$DATA/series.osgt"
du -cb "$DATA"/series_*.osga | tail -1
"$BENCH" sizes "$DATA/series_000000.osga"
"$BENCH" play "$DATA/series.osgt" --rounds "$ROUNDS" --renders "$RENDERS"
"$BENCH" play "$DATA/series.osgt" --rounds "$ROUNDS" --renders "$RENDERS" --play-fps "$PLAY_FPS"
