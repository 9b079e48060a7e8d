#!/usr/bin/env bash
# Sort-last rendering over MPI against one process: the colour (PNG) and eye-space depth (PFM)
# that `mpirun -np K osgglyphviewer ... --offscreen` writes must equal, byte for byte, what one
# plain process writes, for K = 1..4. Usage:
#   composite.sh VIEWER WORKDIR CASE
# CASE: random-sphere, random-cone (--random, split across ranks), dump-sphere, dump-cone (a
# generated LAMMPS dump, each rank reading its share; colour by a column, default radius),
# dump-species (labels met in another order by later ranks), dump-far (coordinates 1e6 from zero),
# dump-frames (the second of two frames, each rank seeking to its part of each and past the rest),
# csv-sphere (a generated CSV split by its bytes; default radius from every 3rd point),
# dcd-frames (a DCD's fourth frame, each rank reading its records' part: tests/data/formats),
# empty-share (fewer atoms than ranks), bad-share (a malformed atom in the last rank's share:
# every rank ends with that one error), devices (each rank reports the EGL device it chose).
set -euo pipefail
viewer=$1 work=$2 case=$3
formats=$(cd "$(dirname "$0")/../data/formats" && pwd)
mkdir -p "$work" && cd "$work"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
mpi() { local k=$1; shift; mpirun --oversubscribe -np "$k" "$viewer" "$@"; }

# A LAMMPS dump of n atoms at pseudo-random places (a fixed linear congruential sequence), with
# velocities and a column c; the atom at line bad_line (if any) gets a malformed x. Optional:
# offset (added to x, y and z, and to the box) and species (1: an element column whose later
# atoms meet the elements in another order than the first ones).
dump() {
    awk -v n="$1" -v bad="${2:-0}" -v offset="${4:-0}" -v species="${5:-0}" 'BEGIN {
        s = 12345; m = 2147483648
        printf "ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n%d\nITEM: BOX BOUNDS pp pp pp\n", n
        for (k = 0; k < 3; k++) printf "%d %d\n", offset, offset + 20
        printf "ITEM: ATOMS id type%s x y z vx vy vz c\n", species ? " element" : ""
        split("Ni Al Cu", later, " ")
        for (i = 1; i <= n; i++) {
            for (k = 0; k < 7; k++) { s = (1103515245 * s + 12345) % m; v[k] = s / m }
            x = (i == bad) ? "1.5.5" : sprintf("%.4f", offset + 20 * v[0])
            element = species ? " " (3 * i <= n ? "Cu" : later[1 + i % 3]) : ""
            printf "%d %d%s %s %.4f %.4f %.4f %.4f %.4f %.4f\n", i, 1 + (i % 3), element, x, \
                offset + 20 * v[1], offset + 20 * v[2], v[3] - 0.5, v[4] - 0.5, v[5] - 0.5, 100 * v[6]
        }
    }' > "$3"
}

# A CSV of n points on a grid of unit spacing, 20 x 20 wide, each moved by up to 0.05 at random
# (a fixed linear congruential sequence), with a column c, a comment every 700 rows: the
# default radius (0.4 of the median neighbour distance) keeps spheres apart, so that no two
# glyphs meet at equal depths, where compositing and one process may choose differently.
csv() {
    awk -v n="$1" 'BEGIN {
        s = 12345; m = 2147483648
        print "x,y,z,c"
        for (i = 0; i < n; i++) {
            for (k = 0; k < 4; k++) { s = (1103515245 * s + 12345) % m; v[k] = s / m }
            printf "%.4f,%.4f,%.4f,%.4f\n", i % 20 + 0.1 * (v[0] - 0.5), int(i / 20) % 20 + 0.1 * (v[1] - 0.5), \
                int(i / 400) + 0.1 * (v[2] - 0.5), 100 * v[3]
            if (i % 700 == 699) print "# a comment"
        }
    }' > "$2"
}

compare() {
    local name=$1; shift
    "$viewer" "$@" --offscreen --output single.png --depth-output single.pfm > single.log
    for k in 1 2 3 4; do
        mpi "$k" "$@" --offscreen --output "np$k.png" --depth-output "np$k.pfm" > "np$k.log"
        cmp single.png "np$k.png" || { echo "$name: colour differs with $k processes"; exit 1; }
        cmp single.pfm "np$k.pfm" || { echo "$name: depth differs with $k processes"; exit 1; }
    done
    echo "$name: colour and depth of 1 to 4 processes equal the single process's"
}

case $case in
random-sphere) compare "$case" --random 3000 --glyph sphere ;;
random-cone) compare "$case" --random 3000 --glyph cone ;;
dump-sphere) dump 2500 0 atoms.lammpstrj; compare "$case" atoms.lammpstrj --glyph sphere --color-by c ;;
dump-cone) dump 2500 0 atoms.lammpstrj; compare "$case" atoms.lammpstrj --glyph cone --color-by speed ;;
dump-species) dump 2500 0 atoms.lammpstrj 0 1; compare "$case" atoms.lammpstrj --color-by species ;;
csv-sphere) csv 6000 points.csv; compare "$case" points.csv --color-by c ;;
dump-far) dump 2500 0 atoms.lammpstrj 1000000; compare "$case" atoms.lammpstrj --glyph cone --color-by c ;;
dump-frames)
    dump 3000 0 first.lammpstrj; dump 2500 0 second.lammpstrj 0 1; cat first.lammpstrj second.lammpstrj > frames.lammpstrj
    compare "$case" frames.lammpstrj --frame 1 --color-by species ;;
dcd-frames) compare "$case" "$formats/melt.dcd" --frame 3 ;;
empty-share)
    dump 2 0 two.lammpstrj
    "$viewer" two.lammpstrj --offscreen --output single.png > single.log
    mpi 3 two.lammpstrj --offscreen --output np3.png > np3.log
    cmp single.png np3.png && echo "empty-share: a rank without atoms changes nothing" ;;
bad-share)
    dump 40 35 bad.lammpstrj # line 44: in the last of 2 ranks' shares
    if mpi 2 bad.lammpstrj --offscreen --output bad.png > bad.log 2> bad.err; then
        echo "bad-share: succeeded"; exit 1
    fi
    cat bad.err
    [ "$(grep -c 'osgglyphviewer: bad.lammpstrj:44: ' bad.err)" = 1 ] || { echo "bad-share: not one error line"; exit 1; }
    [ ! -e bad.png ] || { echo "bad-share: wrote an image"; exit 1; }
    echo "bad-share: every rank ended with the one error of the rank that could not read its share" ;;
devices)
    mpi 3 --random 300 --offscreen --output devices.png > devices.log
    for rank in 0 1 2; do
        grep -q "^osgglyphviewer (rank $rank of 3): OpenGL through EGL device 0: .*OMPI_COMM_WORLD_LOCAL_RANK=$rank of 1 EGL device: " devices.log ||
            { cat devices.log; echo "devices: rank $rank does not report the device it chose"; exit 1; }
    done
    OSGGLYPHS_EGL_DEVICE=4 mpi 3 --random 300 --offscreen --output none.png > none.log 2> none.err && exit 1
    [ "$(grep -c '^osgglyphviewer: OSGGLYPHS_EGL_DEVICE=4 is not a device: there is 1 EGL device$' none.err)" = 1 ] ||
        { cat none.err; echo "devices: not one error naming the device"; exit 1; }
    echo "devices: each of 3 ranks reports the EGL device its local rank chose; a missing device is one error" ;;
*) echo "composite.sh: unknown case $case"; exit 2 ;;
esac
