#!/bin/bash
# osgglyphviewer --follow on a LAMMPS dump that another process is still writing:
#   FollowViewerTest.sh <osgglyphviewer> <work dir>
# The dump starts with a complete frame and half of the next. The viewer shows frame 0; the
# writer completes frame 1, waits until the viewer reports it, then writes frame 2; the viewer
# renders one picture per frame and exits 0. A malformed frame appended later is one error line
# naming the file and line, and exit code 1.
set -u
viewer=$1
work=$2
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1

# frame <timestep> <x>: two atoms, at (x, 0, 0) and (0, x, 0).
frame() {
    printf 'ITEM: TIMESTEP\n%d\nITEM: NUMBER OF ATOMS\n2\nITEM: BOX BOUNDS pp pp pp\n-2 2\n-2 2\n-2 2\n' "$1"
    printf 'ITEM: ATOMS id x y z\n1 %s 0 0\n2 0 %s 0\n' "$2" "$2"
}

fail() {
    echo "FAIL: $*"
    echo "--- stdout"; cat out.txt
    echo "--- stderr"; cat err.txt
    exit 1
}

# Waits up to 30 s for a line matching pattern in out.txt.
wait_for_line() {
    for _ in $(seq 300); do
        grep -q "$1" out.txt && return 0
        sleep 0.1
    done
    fail "no line '$1'"
}

frame 0 0.5 >dump.lammpstrj
frame 100 1.0 | head -c 70 >>dump.lammpstrj
"$viewer" dump.lammpstrj --follow --follow-timeout 30 --offscreen --frames 3 --size 80 60 --radius 0.3 \
    --output follow.png >out.txt 2>err.txt &
pid=$!
wait_for_line "wrote follow.png"
frame 100 1.0 | tail -c +71 >>dump.lammpstrj
wait_for_line "frame 1 completed"
frame 200 1.5 >>dump.lammpstrj
wait $pid
rc=$?
[ $rc -eq 0 ] || fail "exit code $rc"
grep -q "frame 2 completed" out.txt || fail "frame 2 was not shown"
[ "$(grep -c 'wrote follow.png' out.txt)" -eq 3 ] || fail "expected 3 pictures"
[ -s err.txt ] && fail "unexpected stderr"

# A malformed frame: one line naming the file and line, exit code 1.
"$viewer" dump.lammpstrj --follow --follow-timeout 30 --offscreen --frames 2 --size 80 60 --radius 0.3 \
    --output follow.png >out.txt 2>err.txt &
pid=$!
wait_for_line "wrote follow.png"
frame 300 2.0 | sed 's/^2 0 2.0 0$/2 0 two 0/' >>dump.lammpstrj
wait $pid
rc=$?
[ $rc -eq 1 ] || fail "malformed frame: exit code $rc, expected 1"
[ "$(wc -l <err.txt)" -eq 1 ] || fail "malformed frame: expected one line on stderr"
grep -q "^osgglyphviewer: dump.lammpstrj:44: .*'two'" err.txt || fail "malformed frame: the line does not name dump.lammpstrj:44 and 'two'"
echo "PASS"
