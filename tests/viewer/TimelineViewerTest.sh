#!/usr/bin/env bash
# The trajectory timeline of the osgglyphviewer window under Xvfb, driven by xdotool (ctest -L viewer):
#   TimelineViewerTest.sh <osgglyphviewer> <osgglyphviewer_image_check> <trajectory data dir> <work dir>
# Opens melt500.lammpstrj (11 frames, tests/data/trajectory) in a 640x480 window. Space plays
# ("playing" printed) and pauses ("paused"); a click on the timeline bar at 70 % of its length
# seeks to frame 7 (not 3/4: 7.5 lies between frames 7 and 8), which n then steps from
# ("frame 8 of 0..10"); a drag along the bar scrubs (to frame 2); a click above the bar picks
# instead of seeking; resized to 800x600, the bar follows. Screenshots (key c) show the
# glyphs and the bar, filled up to the frame shown. The bar's pixels follow Timeline::layoutBar:
# size = clamp(round(h / 36), 11, 20), x from size to w - 4 size, y from 0.8 size to 1.3 size
# above the bottom. Exits 77 (ctest SKIP_RETURN_CODE) when Xvfb or xdotool is missing.
set -u
viewer=$1 check=$2 data=$3 work=$4

source "$(dirname "${BASH_SOURCE[0]}")/../harness/WindowSession.sh"
window_session_begin "$work"
# A copy: opening a file writes its frame index beside it.
cp "$data/melt500.lammpstrj" . || fail "no $data/melt500.lammpstrj"
width=640 height=480
launch "$viewer" melt500.lammpstrj --size $width $height --range 0 3
window=$(timeout 30 xdotool search --sync --name '^osgglyphviewer' | head -n 1)
[[ -n $window ]] || fail "no osgglyphviewer window appeared"
xdotool windowfocus --sync "$window" || fail "cannot focus the window"
sleep 1

# The bar in window pixels from the top left, for the window's width and height: bar_x
# <fraction> and bar_y (its middle row); layout sets size and bar_y.
layout()
{
    size=$(( (height + 18) / 36 )) # round(h / 36)
    (( size < 11 )) && size=11
    (( size > 20 )) && size=20
    bar_y=$(awk -v s="$size" -v h="$height" 'BEGIN { printf "%d", h - 1.05 * s }')
}
bar_x()
{
    awk -v s="$size" -v w="$width" -v f="$1" 'BEGIN { x0 = s; x1 = w - 4 * s; printf "%d", x0 + f * (x1 - x0) + 0.5 }'
}
layout

# screenshot <n>: key c, then wait for osgglyphviewer-screenshot_<context>_<n>.png.
screenshot()
{
    xdotool key c
    for _ in $(seq 100); do
        shot=$(ls osgglyphviewer-screenshot_*_"$1".png 2>/dev/null | head -n 1)
        [[ -n $shot ]] && sleep 0.3 && echo "$shot" && return 0
        sleep 0.1
    done
    return 1
}

# wait_for_line <extended regex>: the viewer prints a line matching it within 5 s.
wait_for_line()
{
    for _ in $(seq 50); do
        grep -qE "$1" viewer.log && return 0
        sleep 0.1
    done
    return 1
}

# pixel <png> <x> <y>: the colour at (x, y) from the top left, as ImageMagick writes it.
pixel()
{
    convert "$1" -format "%[pixel:p{$2,$3}]" info: 2>/dev/null
}

first=$(screenshot 0) || fail "no screenshot after opening"
"$check" coverage "$first" 0.05 || fail "$first shows no glyphs"

xdotool key space
wait_for_line "^osgglyphviewer: frame [0-9.]+ of 0\.\.10  timestep [0-9]+  playing at 10/s$" ||
    fail "space printed no 'frame .. of 0..10  timestep ..  playing at 10/s' line"
sleep 0.5
xdotool key space
wait_for_line "^osgglyphviewer: frame [0-9.]+ of 0\.\.10  timestep [0-9]+  paused$" ||
    fail "space again printed no '..  paused' line"

# Seek: a click at 70 % of the bar is frame round(0.7 * 10) = 7; n steps to 8.
xdotool mousemove --window "$window" "$(bar_x 0.7)" "$bar_y" click 1
sleep 0.5
grep -q "pick" viewer.log && fail "the click on the timeline picked a glyph"
seeked=$(screenshot 1) || fail "no screenshot after the click on the timeline"
xdotool key n
wait_for_line "^osgglyphviewer: frame 8 of 0\.\.10$" ||
    fail "after a click on the timeline at frame 7, n did not print 'frame 8 of 0..10'"
stepped=$(screenshot 2) || fail "no screenshot after n"

# Scrub: press on the bar at 90 %, drag through 50 % to 20 % (frame 2), the last stretch off the
# bar (a drag keeps scrubbing), release; p steps back to 1.
xdotool mousemove --window "$window" "$(bar_x 0.9)" "$bar_y" mousedown 1 \
    mousemove --window "$window" "$(bar_x 0.5)" "$bar_y" sleep 0.2 \
    mousemove --window "$window" "$(bar_x 0.2)" "$((bar_y - 40))" sleep 0.2 mouseup 1
sleep 0.5
xdotool key p
wait_for_line "^osgglyphviewer: frame 1 of 0\.\.10$" ||
    fail "after a drag along the timeline to frame 2, p did not print 'frame 1 of 0..10'"

# A click above the bar (and its margin) is no seek: a pick, and the frame stays 1.
xdotool mousemove --window "$window" "$(bar_x 0.7)" "$((bar_y - 3 * size))" click 1
wait_for_line "^osgglyphviewer: pick " || fail "a click above the timeline did not pick"
xdotool key n
wait_for_line "^osgglyphviewer: frame 2 of 0\.\.10$" ||
    fail "a click above the timeline moved the frame: n did not print 'frame 2 of 0..10'"

for shot in "$seeked" "$stepped"; do
    "$check" coverage "$shot" 0.05 || fail "$shot shows no glyphs"
done
"$check" differ "$first" "$seeked" 0.02 || fail "the click on the timeline did not change the picture"
"$check" differ "$seeked" "$stepped" 0.02 || fail "n did not change the picture"

# The bar, filled up to frame 7 (blue, 0.26 0.52 0.85) and empty after it; ImageMagick probes it.
if command -v convert >/dev/null; then
    played=$(pixel "$seeked" "$(bar_x 0.5)" "$bar_y")
    rest=$(pixel "$seeked" "$(bar_x 0.85)" "$bar_y")
    echo "timeline at 50 %: $played, at 85 %: $rest"
    [[ $played == "srgb(66,133,217)" || $played == "srgba(66,133,217,1)" ]] ||
        fail "the timeline is not filled at 50 % after seeking to frame 7: $played"
    [[ $played != "$rest" ]] || fail "the timeline is filled past frame 7 at 85 %"
else
    echo "SKIPPED the timeline's pixels: ImageMagick's convert is not installed"
fi

# The bar follows the window's size: at 800x600, 30 % of it is frame 3; n steps to 4.
width=800 height=600
xdotool windowsize --sync "$window" $width $height || fail "cannot resize the window"
sleep 0.5
layout
xdotool mousemove --window "$window" "$(bar_x 0.3)" "$bar_y" click 1
sleep 0.3
xdotool key n
wait_for_line "^osgglyphviewer: frame 4 of 0\.\.10$" ||
    fail "in the window resized to 800x600, a click at 30 % of the timeline and n did not print 'frame 4 of 0..10'"

# And a picture of the whole screen for the eye, as X shows it.
command -v import >/dev/null && import -window root screen.png 2>/dev/null

close_with_escape
echo "PASS: screenshots in $work"
