#!/usr/bin/env bash
# A newcomer who follows only the README (ctest -L package):
#   NewcomerTest.sh <README.md> <cmake> <build dir> <work dir> <c++ compiler>
# Installs the build into <work dir>/prefix as the README's "A first program" says, writes the
# README's first cmake and cpp blocks into a project folder, builds it against the prefix with the
# README's command, and runs it in a window under Xvfb: it must keep running and draw its glyphs
# (a screenshot of many colours). Then runs the README's viewer commands from the repository's
# root with the installed viewer: the windowed ones must open and keep running, the headless one
# must write its picture. Exits 77 (ctest SKIP_RETURN_CODE) when Xvfb or ImageMagick is missing.
set -u
readme=$(realpath "$1") cmake=$2 build=$3 work=$4 cxx=$5
root=$(dirname "$readme")

source "$(dirname "${BASH_SOURCE[0]}")/../harness/WindowSession.sh" || exit 1
display_session_begin "$work" import convert
unset OSG_FILE_PATH OSG_LIBRARY_PATH LD_LIBRARY_PATH

step()
{
    "$@" >step.log 2>&1 || { cat step.log; fail "failed: $*"; }
}

# block <language>: the README's first fenced block in that language.
block()
{
    awk -v fence="\`\`\`$1" '$0 == fence { inside = 1; next } inside && /^```/ { exit } inside { print }' "$readme"
}

# still_running <seconds> <what>: the launched program is alive after that long.
still_running()
{
    local waited=0
    while ((waited < $1 * 10)); do
        kill -0 "$viewer_pid" 2>/dev/null || { wait "$viewer_pid"; fail "$2 exited with $? after $((waited / 10)) s"; }
        sleep 0.1
        ((++waited))
    done
}

stop()
{
    kill "$viewer_pid" 2>/dev/null
    wait "$viewer_pid" 2>/dev/null
    viewer_pid=
}

prefix=$work/prefix
grep -q '^cmake --build build && cmake --install build --prefix /opt/osgGlyphs$' "$readme" ||
    fail "the README no longer installs with 'cmake --install build --prefix /opt/osgGlyphs': update this test"
step "$cmake" --install "$build" --prefix "$prefix"

mkdir -p first && block cmake >first/CMakeLists.txt && block cpp >first/main.cpp
grep -q find_package first/CMakeLists.txt || fail "no cmake block with find_package in the README"
grep -q 'int main' first/main.cpp || fail "no cpp block with main() in the README"
command=$(grep -m 1 '^cmake -S \. -B build -DCMAKE_PREFIX_PATH=/opt/osgGlyphs' "$readme") ||
    fail "the README's build command of the first program is gone: update this test"
# Its cmake steps (the run comes below, in a window), the prefix and the compiler of this build.
command=${command//\/opt\/osgGlyphs/$prefix}
command=${command%% && build/glyphs_first*}
command=${command/-DCMAKE_PREFIX_PATH=/-DCMAKE_CXX_COMPILER=$cxx -DCMAKE_PREFIX_PATH=}
(cd first && eval "$command") >first.log 2>&1 || { cat first.log; fail "the README's first program did not build"; }
[[ -x first/build/glyphs_first ]] || fail "the README's build command made no build/glyphs_first"
echo "ok: the README's first program built against $prefix"

launch first/build/glyphs_first
still_running 8 "the first program"
import -window root first.png || fail "no screenshot"
stop
colours=$(convert first.png -format %k info:)
echo "the first program's window: $colours colours"
((colours > 50)) || fail "the first program's window holds $colours colours: no shaded glyphs"

# The viewer in five commands, as the README writes them, from the repository's root with the
# installed viewer; pictures go to the work folder.
export PATH=$prefix/bin:$PATH
commands=$(awk '/^## The viewer in five commands/ { section = 1 } section && /^```sh/ { inside = 1; next }
                inside && /^```/ { exit } inside { print }' "$readme")
(($(grep -c '^osgglyphviewer ' <<<"$commands") == 5)) || fail "the README's viewer section lost its five commands"
while read -r line; do
    [[ $line == osgglyphviewer* ]] || continue
    echo "README: $line"
    read -ra words <<<"$line"
    output=
    for i in "${!words[@]}"; do
        [[ ${words[i]} == --output ]] && output=$work/${words[i + 1]} && words[i + 1]=$output
    done
    (cd "$root" && exec "${words[@]}") >"$work/viewer.log" 2>&1 &
    viewer_pid=$!
    if [[ -n $output ]]; then
        wait "$viewer_pid" || fail "'$line' failed"
        viewer_pid=
        [[ -s $output ]] || fail "'$line' wrote no picture"
    else
        still_running 5 "'$line'"
        stop
    fi
done <<<"$commands"
echo "ok: the README's viewer commands ran"
