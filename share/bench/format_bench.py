#!/usr/bin/python3
"""The binary formats benchmark: osgGlyphs' frame readers against the Python readers, same files.

Run with Debian's Python (python3-mdanalysis, python3-h5py, python3-gsd), from the source folder
after a build:
    /usr/bin/python3 share/bench/format_bench.py --data /tmp/traj --csv share/bench/format_results.csv

From DATA/melt256k.lammpstrj (256,000 atoms, 31 frames: share/bench/trajectory_bench.sh's dump) it
writes, once, the same frames as DCD, XTC and TRR (MDAnalysis), GSD (gsd) and H5MD (h5py), and a
LAS file of --las-points points with the same points as binary PLY. Then, round by round in turn:
- osgglyphtrajbench decode over every trajectory (FrameSource::readFrame in order and at random);
- MDAnalysis (DCD, XTC, TRR), gsd (GSD) and h5py (H5MD) reading the positions of every frame in
  order, and of --jumps frames at random;
- osgglyphtrajbench decode of the LAS file (points/s decoded);
then, after the rounds, osgglyphconvert converting the LAS and the PLY file (seconds each). Every
file is read through before it is timed, so that all readers find it in the page cache.
Results go to the CSV as date, machine, suite, case, metric, value, unit; ratios are taken within
each round, medians reported.
"""

import argparse
import csv
import datetime
import os
import random
import statistics
import struct
import subprocess
import sys
import tempfile
import time
import warnings

import numpy

FORMATS = ["dcd", "xtc", "trr", "gsd", "h5md"]


def write_trajectories(data, dump):
    """The dump's frames in each binary format, written by the format's own Python writer."""
    import MDAnalysis

    universe = None
    for extension in ["dcd", "xtc", "trr"]:
        path = os.path.join(data, "melt256k." + extension)
        if os.path.exists(path):
            continue
        universe = universe or MDAnalysis.Universe(dump, format="LAMMPSDUMP")
        print(f"format_bench: writing {path}", file=sys.stderr)
        with MDAnalysis.Writer(path, universe.atoms.n_atoms) as writer:
            for _ in universe.trajectory:
                writer.write(universe.atoms)
    gsd_path, h5md_path = os.path.join(data, "melt256k.gsd"), os.path.join(data, "melt256k.h5md")
    if os.path.exists(gsd_path) and os.path.exists(h5md_path):
        return
    universe = universe or MDAnalysis.Universe(dump, format="LAMMPSDUMP")
    positions = numpy.array([ts.positions.copy() for ts in universe.trajectory], dtype=numpy.float32)
    box = universe.trajectory[0].dimensions[:3]
    types = numpy.array(universe.atoms.types.astype(int) - 1, dtype=numpy.uint32)
    if not os.path.exists(gsd_path):
        import gsd.hoomd

        print(f"format_bench: writing {gsd_path}", file=sys.stderr)
        with gsd.hoomd.open(gsd_path, "wb") as trajectory:
            for index, frame_positions in enumerate(positions):
                snapshot = gsd.hoomd.Snapshot()
                snapshot.configuration.step = index
                snapshot.configuration.box = [box[0], box[1], box[2], 0, 0, 0]
                snapshot.particles.N = len(frame_positions)
                snapshot.particles.position = frame_positions - box / 2
                snapshot.particles.typeid = types
                snapshot.particles.types = ["1", "2"]
                trajectory.append(snapshot)
    if not os.path.exists(h5md_path):
        import h5py

        print(f"format_bench: writing {h5md_path}", file=sys.stderr)
        with h5py.File(h5md_path, "w") as out:
            out.create_group("h5md").attrs["version"] = numpy.array([1, 1], dtype=numpy.int32)
            group = out.create_group("particles/all")
            box_group = group.create_group("box")
            box_group.attrs["dimension"] = 3
            box_group.attrs["boundary"] = numpy.array([b"periodic"] * 3)
            box_group["edges"] = numpy.array(box, dtype=numpy.float64)
            position = group.create_group("position")
            position["value"] = positions
            position["step"] = numpy.arange(len(positions), dtype=numpy.int64)
            position["time"] = numpy.arange(len(positions), dtype=numpy.float64)
            group["species"] = types


def write_las(path, points, rng):
    """A LAS 1.2 file of point format 3 (coordinates, intensity, returns, class, GPS time, RGB),
    written from the specification, and returns the points' coordinates for the PLY."""
    scale, offset = 0.001, (500000.0, 4000000.0, 100.0)
    xyz = rng.integers(0, 2_000_000, size=(points, 3), dtype=numpy.int32)
    record = numpy.zeros(points, dtype=numpy.dtype([
        ("xyz", "<i4", 3), ("intensity", "<u2"), ("flags", "u1"), ("classification", "u1"),
        ("scan_angle", "i1"), ("user", "u1"), ("source", "<u2"), ("gps", "<f8"), ("rgb", "<u2", 3)]))
    record["xyz"] = xyz
    record["intensity"] = rng.integers(0, 65535, size=points)
    record["flags"] = 0b00001001
    record["classification"] = rng.integers(1, 10, size=points)
    record["gps"] = 1.0e8 + numpy.arange(points) * 1e-5
    record["rgb"] = rng.integers(0, 65535, size=(points, 3))
    header = bytearray(227)
    header[0:4] = b"LASF"
    struct.pack_into("<BB", header, 24, 1, 2)
    struct.pack_into("<HIIBHI", header, 94, 227, 227, 0, 3, record.dtype.itemsize, points)
    struct.pack_into("<3d3d", header, 131, scale, scale, scale, *offset)
    low, high = xyz.min(axis=0) * scale + offset, xyz.max(axis=0) * scale + offset
    struct.pack_into("<6d", header, 179, high[0], low[0], high[1], low[1], high[2], low[2])
    with open(path, "wb") as out:
        out.write(header)
        record.tofile(out)
    return xyz * scale + numpy.array(offset)


def write_ply(path, coordinates):
    """The same points as binary PLY (double coordinates, like the LAS' precision)."""
    with open(path, "wb") as out:
        out.write((f"ply\nformat binary_little_endian 1.0\nelement vertex {len(coordinates)}\n"
                   "property double x\nproperty double y\nproperty double z\nend_header\n").encode())
        coordinates.astype("<f8").tofile(out)


def timed(function):
    start = time.perf_counter()
    function()
    return time.perf_counter() - start


def read_each(read, frames):
    for frame in frames:
        read(frame)


def python_reader(fmt, path):
    """Opens path with the format's Python reader: returns (frames, read_frame(i))."""
    if fmt in ("dcd", "xtc", "trr"):
        import MDAnalysis

        reader = MDAnalysis.coordinates.core.reader(path)
        return len(reader), lambda i: reader[i].positions
    if fmt == "gsd":
        import gsd.fl

        handle = gsd.fl.open(path, "rb")
        return handle.nframes, lambda i: handle.read_chunk(i, "particles/position")
    import h5py

    handle = h5py.File(path, "r")
    value = handle["particles/all/position/value"]
    return value.shape[0], lambda i: value[i]


# glibc gives a freed frame's memory back to the system, so that every new frame is fresh pages,
# whose first touch is slow on a VM: the same readings with the memory kept, through glibc's own
# settings, show what the decoding costs without that (the Python readers reuse their arrays).
KEEP_FREED_MEMORY = "glibc.malloc.mmap_threshold=268435456:glibc.malloc.trim_threshold=1073741824"


def osgglyphs_decode(bench, one_frame, paths, keep_memory=False):
    """One round of osgglyphtrajbench decode: {(case, metric): value}."""
    env = dict(os.environ)
    if keep_memory:
        env["GLIBC_TUNABLES"] = KEEP_FREED_MEMORY
    with tempfile.NamedTemporaryFile(suffix=".csv") as out:
        subprocess.run([bench, "decode", "--rounds", "1", "--csv", out.name, one_frame] + paths,
                       check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=env)
        return {(r["case"], r["metric"]): float(r["value"]) for r in csv.DictReader(open(out.name))}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--data", default="/tmp/traj")
    parser.add_argument("--bench", default="build/applications/osgglyphtrajbench/osgglyphtrajbench")
    parser.add_argument("--convert", default="build/applications/osgglyphconvert/osgglyphconvert")
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--jumps", type=int, default=8)
    parser.add_argument("--convert-rounds", type=int, default=2)
    parser.add_argument("--las-points", type=int, default=20_000_000)
    parser.add_argument("--formats", default=",".join(FORMATS))
    parser.add_argument("--prepare-only", action="store_true", help="write the files, measure nothing")
    parser.add_argument("--csv")
    parser.add_argument("--machine", default=f"{os.cpu_count()}-core VM")
    args = parser.parse_args()
    warnings.simplefilter("ignore")
    formats = args.formats.split(",")

    dump = os.path.join(args.data, "melt256k.lammpstrj")
    one_frame = os.path.join(args.data, "melt256k_f0.lammpstrj")
    write_trajectories(args.data, dump)
    las, ply = os.path.join(args.data, "big.las"), os.path.join(args.data, "big.ply")
    if not os.path.exists(las) or not os.path.exists(ply):
        print(f"format_bench: writing {las} and {ply}", file=sys.stderr)
        write_ply(ply, write_las(las, args.las_points, numpy.random.default_rng(7)))
    paths = {fmt: os.path.join(args.data, "melt256k." + fmt) for fmt in formats}
    if args.prepare_only:
        return

    rows = []

    def report(case, metric, value, unit):
        print(f"  {case:44} {metric:26} {value:10.4g} {unit}")
        rows.append([datetime.date.today().isoformat(), args.machine, "formats", case, metric, f"{value:.6g}", unit])

    kept = []
    ours, theirs, jumps, converts = [], {fmt: [] for fmt in formats}, {fmt: [] for fmt in formats}, []

    def warm(paths_to_read):
        """Reads files through, so that every reader finds them in the page cache."""
        for path in paths_to_read:
            with open(path, "rb") as stream:
                while stream.read(1 << 24):
                    pass

    for round in range(args.rounds):
        warm([paths[f] for f in formats] + [las, one_frame])
        ours.append(osgglyphs_decode(args.bench, one_frame, [paths[f] for f in formats] + [las]))
        kept.append(osgglyphs_decode(args.bench, one_frame, [paths[f] for f in formats] + [las], True))
        for fmt in formats:
            warm([paths[fmt]])
            frames, read = python_reader(fmt, paths[fmt])
            # Each frame dropped before the next, as osgglyphtrajbench does.
            theirs[fmt].append(frames / timed(lambda: read_each(read, range(frames))))
            order = random.Random(round).sample(range(frames), min(args.jumps, frames))
            jumps[fmt].append(1000.0 * timed(lambda: read_each(read, order)) / len(order))
        print(f"format_bench: round {round + 1} of {args.rounds}", file=sys.stderr)
    # The conversions last: their memory pushes the trajectories out of the page cache.
    for round in range(args.convert_rounds):
        with tempfile.TemporaryDirectory() as scratch:
            converts.append([])
            for source in (las, ply):
                warm([source])
                converts[-1].append(timed(lambda: subprocess.run(
                    [args.convert, source, os.path.join(scratch, "out.osga")], check=True,
                    stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)))

    median = statistics.median
    for fmt in formats:
        name = os.path.basename(paths[fmt])
        order_rate = [o["readFrame in order: " + name, "per_s"] for o in ours]
        random_ms = [o["readFrame at random: " + name, "ms_each"] for o in ours]
        in_order_ms = [o["readFrame in order: " + name, "ms_each"] for o in ours]
        kept_rate = [o["readFrame in order: " + name, "per_s"] for o in kept]
        report("osgGlyphs readFrame: " + name, "frames_per_s", median(order_rate), "1/s")
        report("osgGlyphs readFrame, freed memory kept: " + name, "frames_per_s", median(kept_rate), "1/s")
        report("osgGlyphs readFrame: " + name, "random_over_in_order", median(
            r / i for r, i in zip(random_ms, in_order_ms)), "x")
        reader = "h5py" if fmt == "h5md" else "gsd" if fmt == "gsd" else "MDAnalysis"
        report(reader + ": " + name, "frames_per_s", median(theirs[fmt]), "1/s")
        report(reader + ": " + name, "random_ms_each", median(jumps[fmt]), "ms")
        report("osgGlyphs readFrame: " + name, "speedup_to_" + reader, median(
            a / b for a, b in zip(order_rate, theirs[fmt])), "x")
        report("osgGlyphs readFrame, freed memory kept: " + name, "speedup_to_" + reader, median(
            a / b for a, b in zip(kept_rate, theirs[fmt])), "x")
    las_name = os.path.basename(las)
    las_ms = median(o["readFrame 0: " + las_name, "ms_each"] for o in ours)
    report("osgGlyphs readFrame: " + las_name, "points_per_s", args.las_points / (las_ms / 1000.0), "1/s")
    las_kept_ms = median(o["readFrame 0: " + las_name, "ms_each"] for o in kept)
    report("osgGlyphs readFrame, freed memory kept: " + las_name, "points_per_s",
           args.las_points / (las_kept_ms / 1000.0), "1/s")
    report("osgglyphconvert: " + las_name, "s", median(c[0] for c in converts), "s")
    report("osgglyphconvert: " + os.path.basename(ply), "s", median(c[1] for c in converts), "s")
    report("osgglyphconvert: " + las_name, "time_ratio_to_ply", median(c[0] / c[1] for c in converts), "x")
    if args.csv:
        fresh = not os.path.exists(args.csv) or os.path.getsize(args.csv) == 0
        with open(args.csv, "a", newline="") as out:
            writer = csv.writer(out)
            if fresh:
                writer.writerow(["date", "machine", "suite", "case", "metric", "value", "unit"])
            writer.writerows(rows)


if __name__ == "__main__":
    main()
