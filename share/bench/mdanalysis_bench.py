#!/usr/bin/python3
"""MDAnalysis reading a LAMMPS text dump, against osgGlyphs' FrameSource in the same run.

Run with Debian's python3-mdanalysis (2.4): /usr/bin/python3 share/bench/mdanalysis_bench.py DUMP.
Each round reads every frame in order, then jumps to --jumps frames in a random order; with
--osgglyph-bench, the round then runs `osgglyphtrajbench decode --rounds 1 ONE_FRAME DUMP` so
that the ratio of the two readers is taken within the same minutes of a shared machine.

MDAnalysis 2.4 opens a dump as Universe(dump, format="LAMMPSDUMP"): the topology (ids, types)
comes from the first frame's ITEM: ATOMS columns, and the reader takes x y z (or xs, xu, xsu)
and vx vy vz from the same header. atom_style="id type x y z" is the option of LAMMPS *data*
files (format="DATA"); given with a dump, 2.4 ignores it, so it is not passed here.
"""

import argparse
import csv
import datetime
import os
import random
import statistics
import subprocess
import sys
import tempfile
import time
import warnings


def timed(function):
    """Wall and CPU seconds of a call (the CPU time of this process: MDAnalysis reads on one thread)."""
    wall, cpu = time.perf_counter(), time.process_time()
    function()
    return time.perf_counter() - wall, time.process_time() - cpu


def run_osgglyphs(bench, one_frame, dump):
    """One round of osgglyphtrajbench decode: its readFrame in order, frames/s (wall and thread CPU)."""
    with tempfile.NamedTemporaryFile(suffix=".csv") as out:
        subprocess.run([bench, "decode", "--rounds", "1", "--csv", out.name, one_frame, dump],
                       check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        rows = list(csv.DictReader(open(out.name)))
    case = "readFrame in order: " + os.path.basename(dump)
    value = {r["metric"]: float(r["value"]) for r in rows if r["case"] == case}
    return value["per_s"], value["ms_each"] / 1000.0, value["thread_cpu_s"]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("dump")
    parser.add_argument("--rounds", type=int, default=2)
    parser.add_argument("--jumps", type=int, default=8, help="random jumps per round")
    parser.add_argument("--csv", help="append the results to this CSV")
    parser.add_argument("--machine", default="unnamed machine")
    parser.add_argument("--osgglyph-bench", help="osgglyphtrajbench, run in every round")
    parser.add_argument("--one-frame", help="the one-frame file osgglyphtrajbench decode compares with")
    args = parser.parse_args()
    warnings.simplefilter("ignore")
    import MDAnalysis

    rows = []

    def report(case, metric, value, unit):
        print(f"  {case:44} {metric:22} {value:10.4g} {unit}")
        rows.append([datetime.date.today().isoformat(), args.machine, "mdanalysis", case, metric,
                     f"{value:.6g}", unit])

    name = os.path.basename(args.dump)
    print(f"mdanalysis_bench: MDAnalysis {MDAnalysis.__version__}, {name}, {args.rounds} rounds")
    opened, ordered, jumped, ours = [], [], [], []
    for round in range(args.rounds):
        # Opening parses the first frame twice (topology, reader); len() scans the file for offsets.
        universe = None

        def open_universe():
            nonlocal universe
            universe = MDAnalysis.Universe(args.dump, format="LAMMPSDUMP")
            len(universe.trajectory)

        opened.append(timed(open_universe))
        trajectory = universe.trajectory
        frames = len(trajectory)
        # Not "for ts in trajectory": that reads frame 0 again at the end (it rewinds).
        ordered.append(timed(lambda: [trajectory[0]] + [trajectory.next() for _ in range(frames - 1)]))
        order = list(range(frames))
        random.Random(round).shuffle(order)
        order = order[:args.jumps]
        jumped.append(timed(lambda: [trajectory[k] for k in order]))
        assert trajectory.ts.has_velocities and trajectory.n_atoms == universe.atoms.n_atoms
        if args.osgglyph_bench:
            ours.append(run_osgglyphs(args.osgglyph_bench, args.one_frame, args.dump))
        print(f"mdanalysis_bench: round {round + 1} of {args.rounds}", file=sys.stderr)

    median = statistics.median
    bytes_per_frame = os.path.getsize(args.dump) / frames
    case = "MDAnalysis: " + name
    report(case, "frames", frames, "")
    report(case, "open_s", median(w for w, _ in opened), "s")
    report(case + " in order", "per_s", frames / median(w for w, _ in ordered), "1/s")
    report(case + " in order", "per_cpu_s", frames / median(c for _, c in ordered), "1/s")
    report(case + " in order", "MB_per_s", bytes_per_frame * frames / 1e6 / median(w for w, _ in ordered), "MB/s")
    report(case + " at random", "ms_each", 1000.0 * median(w for w, _ in jumped) / len(order), "ms")
    if ours:
        # Per round: our frames/s over theirs, by wall time and by CPU time.
        wall = [o[0] / (frames / w) for o, (w, _) in zip(ours, ordered)]
        cpu = [(1.0 / o[2] * frames) / (frames / c) for o, (_, c) in zip(ours, ordered)]
        report("osgGlyphs readFrame: " + name + " in order", "per_s", median(o[0] for o in ours), "1/s")
        report("osgGlyphs readFrame: " + name + " in order", "speedup_to_mdanalysis", median(wall), "x")
        report("osgGlyphs readFrame: " + name + " in order", "cpu_speedup_to_mdanalysis", median(cpu), "x")
    if args.csv:
        fresh = not os.path.exists(args.csv) or os.path.getsize(args.csv) == 0
        with open(args.csv, "a", newline="") as out:
            writer = csv.writer(out)
            if fresh:
                writer.writerow(["date", "machine", "suite", "case", "metric", "value", "unit"])
            writer.writerows(rows)


if __name__ == "__main__":
    main()
