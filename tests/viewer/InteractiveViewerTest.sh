#!/usr/bin/env bash
# The osgglyphviewer window under Xvfb, driven by xdotool (ctest -L viewer):
#   InteractiveViewerTest.sh <osgglyphviewer> <osgglyphviewer_image_check> <data dir> <work dir>
# Opens the viewer on spheres.lammpstrj (WriteViewerTestData.cmake) and takes screenshots with
# its ScreenCaptureHandler key c: as it opens, after l (unlit), after n (next frame) and after a
# mouse drag (trackball). Checks that each shows glyphs and that each step changed the picture,
# then closes the window with Escape and checks the exit code.
# Exits 77 (ctest SKIP_RETURN_CODE) when Xvfb or xdotool is missing.
set -u
viewer=$1 check=$2 data=$3 work=$4

for tool in Xvfb xdotool; do
    if ! command -v "$tool" >/dev/null; then
        echo "SKIP: $tool is not installed (Debian packages xvfb, xdotool)"
        exit 77
    fi
done

rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
xvfb_pid= viewer_pid=
cleanup()
{
    [[ -n $viewer_pid ]] && kill "$viewer_pid" 2>/dev/null
    [[ -n $xvfb_pid ]] && kill "$xvfb_pid" 2>/dev/null
}
trap cleanup EXIT
fail()
{
    echo "FAIL: $*"
    echo "--- viewer output:"
    cat viewer.log 2>/dev/null
    exit 1
}

# A display of its own: Xvfb picks a free number and writes it to fd 3.
Xvfb -displayfd 3 -screen 0 1024x768x24 -nolisten tcp 3>display.txt 2>xvfb.log &
xvfb_pid=$!
for _ in $(seq 100); do
    [[ -s display.txt ]] && break
    sleep 0.1
done
[[ -s display.txt ]] || fail "Xvfb did not start: $(cat xvfb.log)"
export DISPLAY=:$(head -n 1 display.txt)

# Sanitizer builds: Mesa's GLX driver leaks 112 bytes and is unloaded (dlclose) before LeakSanitizer
# reports, so the report cannot name the library and tests/sanitizer/lsan.supp cannot match it
# (with dlclose disabled the report names the driver and lsan.supp suppresses it). The headless
# tests keep checking the viewer for leaks; this one does not.
export ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0"
"$viewer" "$data/spheres.lammpstrj" --size 400 300 --radius 0.5 >viewer.log 2>&1 &
viewer_pid=$!
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
xdotool mousemove --window "$window" 200 150 mousedown 1 \
    mousemove --window "$window" 240 170 sleep 0.2 mousemove --window "$window" 280 190 sleep 0.2 mouseup 1
sleep 0.5
dragged=$(screenshot 3) || fail "no screenshot after dragging"

for shot in "$lit" "$unlit" "$next" "$dragged"; do
    "$check" coverage "$shot" 0.03 || fail "$shot shows no glyphs"
done
"$check" differ "$lit" "$unlit" 0.01 || fail "l did not change the picture (lit to unlit)"
"$check" differ "$unlit" "$next" 0.01 || fail "n did not change the picture (next frame)"
"$check" differ "$next" "$dragged" 0.01 || fail "dragging did not turn the view"
grep -q "glyphs unlit" viewer.log || fail "l did not report unlit glyphs"
grep -q "frame 1 of 0..1" viewer.log || fail "n did not report frame 1"

xdotool key Escape
for _ in $(seq 100); do
    kill -0 "$viewer_pid" 2>/dev/null || break
    sleep 0.1
done
kill -0 "$viewer_pid" 2>/dev/null && fail "Escape did not close the viewer"
wait "$viewer_pid"
status=$?
viewer_pid=
[[ $status == 0 ]] || fail "the viewer exited with $status"
echo "PASS: screenshots in $work"
