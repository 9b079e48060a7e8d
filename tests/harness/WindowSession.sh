# Sourced by the tests that drive a real window under Xvfb with xdotool.
#   window_session_begin <work dir> <tools...>   skips (exit 77) without Xvfb, xdotool or a tool,
#                                                 starts a display of its own, cd's into work dir
#   display_session_begin <work dir> <tools...>  the same for programs that need no input: no xdotool
#   launch <command...>                           starts the program (output in viewer.log)
#   close_with_escape                             presses Escape, fails unless the program exits 0
#   fail <message>                                prints the message and the program's output
viewer_pid= xvfb_pid=

fail()
{
    echo "FAIL: $*"
    echo "--- program output:"
    cat viewer.log 2>/dev/null
    exit 1
}

window_session_end()
{
    [[ -n $viewer_pid ]] && kill "$viewer_pid" 2>/dev/null
    if [[ -n $xvfb_pid ]]; then
        kill "$xvfb_pid" 2>/dev/null
        # Until it is gone: a server still on its way out removes the socket and lock file of the
        # next test's server of its display number (tests run side by side), whose clients then
        # cannot connect ("Unable to open display").
        wait "$xvfb_pid" 2>/dev/null
    fi
    return 0
}

window_session_begin()
{
    local work=$1
    shift
    display_session_begin "$work" xdotool "$@"
}

display_session_begin()
{
    local work=$1 tool
    shift
    for tool in Xvfb "$@"; do
        if ! command -v "$tool" >/dev/null; then
            echo "SKIP: $tool is not installed"
            exit 77
        fi
    done
    rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
    trap window_session_end EXIT
    # A display of its own: Xvfb picks a free number and writes it to fd 3.
    # -noreset: a server that resets when its last client leaves refuses the next one for a moment,
    # and OSG opens the display, closes it and opens it again at once.
    Xvfb -displayfd 3 -screen 0 1024x768x24 -nolisten tcp -noreset 3>display.txt 2>xvfb.log &
    xvfb_pid=$!
    for _ in $(seq 100); do
        [[ -s display.txt ]] && break
        sleep 0.1
    done
    [[ -s display.txt ]] || fail "Xvfb did not start: $(cat xvfb.log)"
    export DISPLAY=:$(head -n 1 display.txt)
    # Sanitizer builds: Mesa's GLX driver leaks 112 bytes and is unloaded (dlclose) before
    # LeakSanitizer reports, so the report cannot name the library and tests/sanitizer/lsan.supp
    # cannot match it. The headless tests keep checking for leaks; the windowed ones do not.
    export ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0"
}

launch()
{
    "$@" >viewer.log 2>&1 &
    viewer_pid=$!
}

close_with_escape()
{
    xdotool key Escape
    for _ in $(seq 100); do
        kill -0 "$viewer_pid" 2>/dev/null || break
        sleep 0.1
    done
    kill -0 "$viewer_pid" 2>/dev/null && fail "Escape did not close the window"
    wait "$viewer_pid"
    local status=$?
    viewer_pid=
    [[ $status == 0 ]] || fail "the program exited with $status"
}
