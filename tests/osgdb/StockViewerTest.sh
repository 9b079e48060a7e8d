#!/usr/bin/env bash
# Stock osgviewer opens a point file through osgdb_glyphs (ctest -L osgdb), in a window under
# Xvfb: StockViewerTest.sh <image check> <point file> <work dir> [osgviewer options...]
# Takes a screenshot with osgviewer's key c, checks that it shows glyphs, closes the window
# with Escape and checks the exit code. Exits 77 (ctest SKIP_RETURN_CODE) when osgviewer,
# Xvfb or xdotool is missing. With LOG_MUST_MATCH set, osgviewer's output must match that
# extended regular expression.
set -u
check=$1 file=$2 work=$3
shift 3

source "$(dirname "${BASH_SOURCE[0]}")/../harness/WindowSession.sh"
window_session_begin "$work" osgviewer

# Sanitizer builds: the stock program needs the ASan runtime before our plugin.
launch env ${OSGGLYPHS_STOCK_TOOL_PRELOAD:+LD_PRELOAD=$OSGGLYPHS_STOCK_TOOL_PRELOAD} \
    osgviewer --window 0 0 400 300 "$file" "$@"
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
# Glyphs, and background around them: the dataset framed, not one glyph filling the window.
"$check" coverage "$shot" 0.05 0.9 || fail "$shot shows no glyphs, or no background around them"

close_with_escape
grep -qi "error\|could not find plugin" viewer.log && fail "osgviewer reported an error"
[[ -z ${LOG_MUST_MATCH:-} ]] || grep -qE "$LOG_MUST_MATCH" viewer.log || fail "osgviewer did not print /$LOG_MUST_MATCH/"
echo "ok: osgviewer drew $file through osgdb_glyphs ($shot)"
