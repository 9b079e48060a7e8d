#!/bin/sh
# The trajectory benchmark: osgglyphtrajbench's suites and MDAnalysis on a LAMMPS dump of 256,000
# atoms (31 frames; the same written gzip and zstd; the 31 frames five times over; frame 0 alone),
# appended to one CSV. Ratios are taken within each suite's run (its cases alternate, round by
# round); memory is measured one process a file, alternating the files.
#
#   share/bench/trajectory_bench.sh                   from the source folder, after a build
#
# Settings, from the environment: BENCH (the program; build-dev's by default), DATA (the folder of
# melt256k.lammpstrj[.gz|.zst]), CSV, ROUNDS, MACHINE (words for the CSV; the GL renderer is
# added), SUITES (a subset of: open last decode play memory mdanalysis), SNAPSHOT (a folder: the
# program and the build's osgGlyphs libraries are copied there first, so that a rebuild while the
# benchmark runs neither breaks nor changes it).
set -eu

BENCH=${BENCH:-build-dev/applications/osgglyphtrajbench/osgglyphtrajbench}
DATA=${DATA:-/tmp/traj}
CSV=${CSV:-share/bench/trajectory_results.csv}
ROUNDS=${ROUNDS:-3}
MACHINE=${MACHINE:-"$(nproc)-core VM"}
SUITES=${SUITES:-"open last decode play memory mdanalysis"}
INDEX=${INDEX:-/tmp/osgglyphtrajbench-index}

if [ -n "${SNAPSHOT:-}" ]; then
    mkdir -p "$SNAPSHOT"
    cp -L $(ldd "$BENCH" | awk '/libosgGlyphs/ { print $3 }') "$SNAPSHOT"
    cp "$BENCH" "$SNAPSHOT"
    BENCH=$SNAPSHOT/$(basename "$BENCH")
    LD_LIBRARY_PATH=$SNAPSHOT${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}
    export LD_LIBRARY_PATH
fi
echo "trajectory_bench.sh: $BENCH, osgGlyphs $(git rev-parse --short HEAD 2>/dev/null || echo '?'), $(date)" >&2

DUMP=$DATA/melt256k.lammpstrj
ONE=$DATA/melt256k_f0.lammpstrj
FIVE=$DATA/melt256k_x5.lammpstrj

# Frame 0 alone, and the dump five times over (155 frames, 2.35 GB).
[ -s "$ONE" ] || awk 'NR > 1 && /^ITEM: TIMESTEP/ { exit } { print }' "$DUMP" >"$ONE"
[ -s "$FIVE" ] || cat "$DUMP" "$DUMP" "$DUMP" "$DUMP" "$DUMP" >"$FIVE"
# Every reading is from the page cache: the times are the parser's, not the disk's.
cat "$DUMP" "$DUMP.gz" "$DUMP.zst" "$ONE" "$FIVE" >/dev/null

run() {
    echo "+ $*" >&2
    "$@"
}
common="--rounds $ROUNDS --csv $CSV --index-folder $INDEX"

for suite in $SUITES; do
    case $suite in
    open) run "$BENCH" open $common --machine "$MACHINE" "$ONE" "$DUMP" "$FIVE" ;;
    last) run "$BENCH" last $common --machine "$MACHINE" "$DUMP" "$FIVE" "$DUMP.gz" "$DUMP.zst" ;;
    decode) run "$BENCH" decode $common --machine "$MACHINE" "$ONE" "$DUMP" "$DUMP.gz" "$DUMP.zst" ;;
    play) run "$BENCH" play $common --machine "$MACHINE" "$DUMP" "$DUMP.gz" ;;
    memory)
        # One process a file, alternating; /usr/bin/time's maximum resident size besides VmHWM.
        for round in 1 2; do
            for file in "$ONE" "$DUMP" "$FIVE"; do
                rss=$(mktemp)
                run /usr/bin/time -f %M -o "$rss" "$BENCH" memory $common --machine "$MACHINE" "$file"
                echo "$(date +%F),\"$MACHINE (/usr/bin/time)\",memory,\"play every frame: $(basename "$file")\",max_rss_time_MB,$(awk '{ print $1 * 1024 / 1e6 }' "$rss"),MB" >>"$CSV"
                rm -f "$rss"
            done
        done
        ;;
    mdanalysis)
        run /usr/bin/python3 share/bench/mdanalysis_bench.py --rounds 2 --csv "$CSV" --machine "$MACHINE" \
            --osgglyph-bench "$BENCH" --one-frame "$ONE" "$DUMP"
        ;;
    *)
        echo "trajectory_bench.sh: no suite $suite" >&2
        exit 1
        ;;
    esac
done
