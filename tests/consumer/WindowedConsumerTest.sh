#!/usr/bin/env bash
# A windowed application against the installed osgGlyphs (ctest -L package):
#   WindowedConsumerTest.sh <cmake> <build dir> <consumer source dir> <work dir> <c++ compiler> [c++ flags]
# Installs the build into <work dir>/prefix and builds windowed_consumer.cpp against it twice,
# with find_package(osgGlyphs) (the consumer's CMakeLists.txt) and with pkg-config, each linking
# glvnd's -lGL before everything else, and of osgGlyphs only the core library, beside osgViewer.
# Checks that libGL precedes every OSG library among each program's DT_NEEDED entries, that
# neither loads libOSMesa nor libosgGlyphsHeadless, and runs each in a window under Xvfb, where
# the program checks its pixels against the analytic scene.
# Exits 77 (ctest SKIP_RETURN_CODE) when Xvfb is missing.
set -u
cmake=$1 build=$2 source=$3 work=$4 cxx=$5 cxxflags=${6:-}

source "$(dirname "${BASH_SOURCE[0]}")/../harness/WindowSession.sh" || exit 1
display_session_begin "$work" pkg-config readelf ldd
# The installed package only: no shader, plugin or library paths of the build tree.
unset OSG_FILE_PATH OSG_LIBRARY_PATH LD_LIBRARY_PATH

# step <command...>: runs a build step, fails with its output.
step()
{
    "$@" >step.log 2>&1 || { cat step.log; fail "failed: $*"; }
}

prefix=$work/prefix
step "$cmake" --install "$build" --prefix "$prefix"
pkgconfig=$(find "$prefix" -maxdepth 3 -type d -name pkgconfig -path "$prefix/lib*" | head -n 1)
[[ -n $pkgconfig ]] || fail "no pkgconfig folder under $prefix"
libdir=$(dirname "$pkgconfig")

step "$cmake" -S "$source" -B "$work/cmake-build" -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_CXX_COMPILER="$cxx" \
    "-DCMAKE_CXX_FLAGS=$cxxflags"
step "$cmake" --build "$work/cmake-build" --target windowed_consumer

flags=$(PKG_CONFIG_PATH=$pkgconfig pkg-config --cflags --libs osgGlyphs openscenegraph-osgViewer) ||
    fail "pkg-config does not find osgGlyphs in $pkgconfig"
# shellcheck disable=SC2086 # the flags are words
step "$cxx" -std=c++17 $cxxflags -Wl,--no-as-needed -lGL -Wl,--as-needed "$source/windowed_consumer.cpp" $flags \
    -o "$work/windowed_consumer-pkgconfig"

# check_links <program>: libGL before OSG, the core osgGlyphs from the prefix, nothing headless.
check_links()
{
    local program=$1 needed list loaded gl osg glyphs
    needed=$(readelf -d "$program" | sed -n 's/.*(NEEDED).*\[\(.*\)\]/\1/p')
    list=$(tr '\n' ' ' <<<"$needed")
    gl=$(grep -n '^libGL\.so' <<<"$needed" | head -n 1 | cut -d: -f1)
    osg=$(grep -n '^libosg\|^libOpenThreads' <<<"$needed" | head -n 1 | cut -d: -f1)
    [[ -n $gl && -n $osg && $gl -lt $osg ]] ||
        fail "$program: libGL is not needed before the OSG libraries: $list"
    grep -q '^libosgGlyphs\.so' <<<"$needed" || fail "$program does not need libosgGlyphs: $list"
    grep -q '^libosgGlyphs[A-Z]\|^libOSMesa' <<<"$needed" &&
        fail "$program needs more than the core osgGlyphs: $list"
    loaded=$(LD_LIBRARY_PATH=$libdir ldd "$program") || fail "ldd $program failed"
    grep -q 'libOSMesa\|libosgGlyphsHeadless' <<<"$loaded" && fail "$program loads OSMesa or osgGlyphsHeadless: $loaded"
    glyphs=$(sed -n 's/.*libosgGlyphs\.so[^ ]* => \([^ ]*\).*/\1/p' <<<"$loaded")
    [[ -n $glyphs && $(realpath "$glyphs") == "$(realpath "$prefix")"/* ]] ||
        fail "$program loads libosgGlyphs from '$glyphs', not from $prefix"
    echo "ok: $program needs $list"
}

# run_in_window <program> <image>: the program opens its window on Xvfb's display and checks it.
run_in_window()
{
    LD_LIBRARY_PATH=$libdir "$1" "$2" >viewer.log 2>&1
    local status=$?
    cat viewer.log
    [[ $status == 0 ]] || fail "$1 exited with $status"
}

for program in "$work/cmake-build/windowed_consumer" "$work/windowed_consumer-pkgconfig"; do
    check_links "$program"
    run_in_window "$program" "$(basename "$program").png"
done
echo "ok: the core osgGlyphs drew in a window, linked after glvnd's libGL"
