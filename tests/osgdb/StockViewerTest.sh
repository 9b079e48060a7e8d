#!/usr/bin/env bash
# Stock osgviewer opens a point file through osgdb_glyphs (ctest -L osgdb), in a window under
# Xvfb: StockViewerTest.sh <image check> <point file> <work dir> [osgviewer options...]
# Takes a screenshot with osgviewer's key c, checks that it shows glyphs, closes the window
# with Escape and checks the exit code. Exits 77 (ctest SKIP_RETURN_CODE) when osgviewer,
# Xvfb or xdotool is missing.
set -u
check=$1 file=$2 work=$3
shift 3

for tool in osgviewer Xvfb xdotool; do
    if ! command -v "$tool" >/dev/null; then
        echo "SKIP: $tool is not installed (Debian packages openscenegraph, xvfb, xdotool)"
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
    echo "--- osgviewer output:"
    cat viewer.log 2>/dev/null
    exit 1
}

Xvfb -displayfd 3 -screen 0 1024x768x24 -nolisten tcp 3>display.txt 2>xvfb.log &
xvfb_pid=$!
for _ in $(seq 100); do
    [[ -s display.txt ]] && break
    sleep 0.1
done
[[ -s display.txt ]] || fail "Xvfb did not start: $(cat xvfb.log)"
export DISPLAY=:$(head -n 1 display.txt)
# Mesa's GLX driver leaks and is unloaded before LeakSanitizer reports (see InteractiveViewerTest.sh).
export ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0"

osgviewer --window 0 0 400 300 "$file" "$@" >viewer.log 2>&1 &
viewer_pid=$!
# OSG's window has neither a name nor _NET_WM_PID; it is the only window of this display.
window=$(timeout 30 xdotool search --sync --onlyvisible --class '.' | head -n 1)
[[ -n $window ]] || fail "no osgviewer window appeared"
xdotool windowfocus --sync "$window" || fail "cannot focus the window"
sleep 1

xdotool key c
for _ in $(seq 100); do
    shot=$(ls screen_shot_*.jpg 2>/dev/null | head -n 1)
    [[ -n $shot ]] && break
    sleep 0.1
done
[[ -n $shot ]] || fail "no screenshot after key c"
sleep 0.5
"$check" coverage "$shot" 0.05 || fail "$shot shows no glyphs"

xdotool key Escape
for _ in $(seq 100); do
    kill -0 "$viewer_pid" 2>/dev/null || break
    sleep 0.1
done
kill -0 "$viewer_pid" 2>/dev/null && fail "osgviewer did not close on Escape"
wait "$viewer_pid"
status=$?
viewer_pid=
[[ $status -eq 0 ]] || fail "osgviewer exited with $status"
grep -qi "error\|could not find plugin" viewer.log && fail "osgviewer reported an error"
echo "ok: osgviewer drew $file through osgdb_glyphs ($shot)"
