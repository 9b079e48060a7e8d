#!/usr/bin/env bash
# The keys of osgglyphviewer's effects, in a window under Xvfb driven by xdotool (ctest -L viewer):
#   EffectKeysViewerTest.sh <osgglyphviewer> <osgglyphviewer_image_check> <data dir> <work dir>
# On spheres.lammpstrj: e (outlines) and a (screen-space occlusion) each change the picture and
# say so; x (transparency) with them on keeps the glyphs, transparent; each toggled off again gives
# the picture before it back; o (per-glyph occlusion) changes the picture. Exits 77 (ctest SKIP_RETURN_CODE) when Xvfb or xdotool is missing.
set -u
viewer=$1 check=$2 data=$3 work=$4

source "$(dirname "${BASH_SOURCE[0]}")/../harness/WindowSession.sh"
window_session_begin "$work"
launch "$viewer" "$data/spheres.lammpstrj" --size 400 300 --radius 0.5
window=$(timeout 30 xdotool search --sync --name '^osgglyphviewer' | head -n 1)
[[ -n $window ]] || fail "no osgglyphviewer window appeared"
xdotool windowfocus --sync "$window" || fail "cannot focus the window"
sleep 1

# press <key> <line>: the key, then the line it must print; echoes the screenshot after it.
press()
{
    xdotool key "$1"
    for _ in $(seq 200); do
        grep -qF "osgglyphviewer: $2" viewer.log && break
        sleep 0.1
    done
    grep -qF "osgglyphviewer: $2" viewer.log || fail "key $1 did not print '$2'"
    sleep 0.5
    screenshot || fail "no screenshot after key $1"
}
# screenshot: key c, then echoes the next osgglyphviewer-screenshot_<context>_<n>.png.
screenshot()
{
    local n shot
    n=$(ls osgglyphviewer-screenshot_*.png 2>/dev/null | wc -l)
    xdotool key c
    for _ in $(seq 100); do
        shot=$(ls osgglyphviewer-screenshot_*_"$n".png 2>/dev/null | head -n 1)
        [[ -n $shot ]] && sleep 0.3 && echo "$shot" && return 0
        sleep 0.1
    done
    return 1
}
# same <a> <b>: at most 0.2% of the pixels differ (an effect left on changes more than 1%).
same() { ! "$check" differ "$1" "$2" 0.002 >/dev/null; }

plain=$(screenshot) || fail "no screenshot after opening"
"$check" coverage "$plain" 0.03 || fail "$plain shows no glyphs"

outlined=$(press e "outlines on")
"$check" differ "$plain" "$outlined" 0.01 || fail "e did not draw outlines"
occluded=$(press a "screen-space ambient occlusion on")
"$check" differ "$outlined" "$occluded" 0.01 || fail "a did not darken the picture"
transparent=$(press x "transparency at opacity")
"$check" differ "$occluded" "$transparent" 0.01 || fail "x did not make the outlined glyphs transparent"
"$check" coverage "$transparent" 0.03 || fail "the transparent glyphs vanished under the effects"
opaque=$(press x "transparency off")
same "$occluded" "$opaque" || fail "x twice did not give the effects' picture back"
press e "outlines off" >/dev/null
back=$(press a "screen-space ambient occlusion off")
same "$plain" "$back" || fail "with both effects off again, the picture is not the first one"

occlusion=$(press o "ambient occlusion on")
"$check" differ "$plain" "$occlusion" 0.01 || fail "o did not darken the glyphs"
close_with_escape
echo "PASS: screenshots in $work"
