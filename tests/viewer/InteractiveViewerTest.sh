#!/usr/bin/env bash
# The osgglyphviewer window under Xvfb, driven by xdotool (ctest -L viewer):
#   InteractiveViewerTest.sh <osgglyphviewer> <osgglyphviewer_image_check> <data dir> <work dir>
# Opens the viewer on spheres.lammpstrj (WriteViewerTestData.cmake) and takes screenshots with
# its ScreenCaptureHandler key c: as it opens, after l (unlit), after n (next frame) and after a
# mouse drag (trackball); a click picks. Checks that each shows glyphs and that each step changed the picture.
# Then a shader on OSG's data path that does not compile: after r, the viewer prints one line and
# stays open, after its removal and r it draws again; Escape closes it with exit code 0. Last, the
# viewer started with that shader prints the line and exits by itself with exit code 1.
# Exits 77 (ctest SKIP_RETURN_CODE) when Xvfb or xdotool is missing.
set -u
viewer=$1 check=$2 data=$3 work=$4

source "$(dirname "${BASH_SOURCE[0]}")/../harness/WindowSession.sh"
window_session_begin "$work"
mkdir -p shaders/osgGlyphs
export OSG_FILE_PATH=$PWD/shaders
launch "$viewer" "$data/spheres.lammpstrj" --size 400 300 --radius 0.5
window=$(timeout 30 xdotool search --sync --name '^osgglyphviewer' | head -n 1)
[[ -n $window ]] || fail "no osgglyphviewer window appeared"
xdotool windowfocus --sync "$window" || fail "cannot focus the window"
sleep 1

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

lit=$(screenshot 0) || fail "no screenshot after opening"
xdotool key l && sleep 0.5
unlit=$(screenshot 1) || fail "no screenshot after l"
xdotool key n && sleep 0.5
next=$(screenshot 2) || fail "no screenshot after n"
# A click picks: a pick line, and a picked glyph drawn tinted and its values in the HUD.
xdotool mousemove --window "$window" 200 150 click 1 && sleep 0.5
pick_line=$(grep -E "^osgglyphviewer: pick (glyph=[0-9]+ x=[^ ]+ y=[^ ]+ z=[^ ]+|none)$" viewer.log | tail -n 1)
[[ -n $pick_line ]] || fail "a click printed no pick line"
picked=$(screenshot 3) || fail "no screenshot after the click"
if [[ $pick_line != *none ]]; then
    "$check" differ "$next" "$picked" 0.001 || fail "the picked glyph is not highlighted"
fi
xdotool mousemove --window "$window" 200 150 mousedown 1 \
    mousemove --window "$window" 240 170 sleep 0.2 mousemove --window "$window" 280 190 sleep 0.2 mouseup 1
sleep 0.5
dragged=$(screenshot 4) || fail "no screenshot after dragging"

for shot in "$lit" "$unlit" "$next" "$dragged"; do
    "$check" coverage "$shot" 0.03 || fail "$shot shows no glyphs"
done
"$check" differ "$lit" "$unlit" 0.01 || fail "l did not change the picture (lit to unlit)"
"$check" differ "$unlit" "$next" 0.01 || fail "n did not change the picture (next frame)"
"$check" differ "$next" "$dragged" 0.01 || fail "dragging did not turn the view"
grep -q "glyphs unlit" viewer.log || fail "l did not report unlit glyphs"
grep -q "frame 1 of 0..1" viewer.log || fail "n did not report frame 1"

broken_line="osgglyphviewer: glyph program 'osgGlyphs geometry-shader' does not compile: $PWD/shaders/osgGlyphs/sphere.glsl:3: error: "
printf '// broken\n\nthis is not GLSL;\n' >shaders/osgGlyphs/sphere.glsl
xdotool key r && sleep 1
grep -qF "$broken_line" viewer.log || fail "r with a broken shader did not print '$broken_line'"
kill -0 "$viewer_pid" 2>/dev/null || fail "the viewer exited after r with a broken shader"
rm shaders/osgGlyphs/sphere.glsl
xdotool key r && sleep 0.5
repaired=$(screenshot 5) || fail "no screenshot after repairing the shader"
"$check" coverage "$repaired" 0.03 || fail "$repaired shows no glyphs after the repaired shader"
close_with_escape

# Started with the broken shader: one line on stderr, exit code 1, without a key pressed.
printf '// broken\n\nthis is not GLSL;\n' >shaders/osgGlyphs/sphere.glsl
"$viewer" "$data/spheres.lammpstrj" --size 400 300 >broken.out 2>broken.err
status=$?
[[ $status == 1 ]] || fail "started with a broken shader, the viewer exited with $status"
[[ $(wc -l <broken.err) == 1 ]] && grep -qF "$broken_line" broken.err ||
    fail "started with a broken shader, stderr is not the one line: $(cat broken.err)"
echo "PASS: screenshots in $work"
