"""Writes the HDF5 test files from the reference dump ../melt.lammpstrj (500 atoms x 6 frames,
steps 0 to 100 by 20, columns id type x y z vx vy vz, box 0 to 8.3979809569125372 cubic):

  melt.h5md          H5MD 1.1, /particles/all: position, velocity, species and id time-dependent
                     (float32, float32, int32, int32; step and time lists, time = 0.005 * step),
                     box/edges a fixed vector (float64).
  melt_gzip.h5md     the same but velocity, every dataset chunked and gzip-compressed (shuffled);
                     box/edges time-dependent
                     edge vectors (a 3 x 3 matrix a frame), step and time as fixed intervals
                     (scalars with an offset attribute).
  melt_fixed.h5md    species, id, mass and charge fixed in time (one value per atom), velocity
                     written every other frame only (steps 0, 40, 80: a frame takes the last
                     before its step).
  melt_groups.h5md   the atoms in two particle groups, "left" (ids 1-200) and "right" (201-500),
                     positions and ids only.
  snapshot.hdf5      a SWIFT-style snapshot: PartType0 (40 gas particles: Coordinates float64
                     near 1e4, Velocities, Masses, ParticleIDs, Densities) and PartType1 (60 dark
                     matter particles without Masses: Header MassTable gives 0.25), Header
                     BoxSize 20000 (three values) and Time 0.5. The values follow formulas that
                     the test computes too (snapshotValue in H5mdTest.cpp).
  custom.h5          datasets of custom names for FrameFileOptions::datasets: /data/points
                     (30 x 3 float64), /data/temperature (30), /data/spin (30 x 3 float32) and
                     /meta/history (5, not per point).
"""

import math
import os
import sys

import h5py
import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../.."))
from h5md_header import write_header  # noqa: E402

DUMP = "../melt.lammpstrj"
BOX = 8.3979809569125372
TIMESTEP = 0.005


def read_dump(path):
    frames = []
    with open(path) as lines:
        lines = iter(lines)
        for line in lines:
            if line.startswith("ITEM: TIMESTEP"):
                step = int(next(lines))
            elif line.startswith("ITEM: NUMBER OF ATOMS"):
                count = int(next(lines))
            elif line.startswith("ITEM: ATOMS"):
                rows = [next(lines).split() for _ in range(count)]
                table = np.array(rows, dtype=np.float64)
                frames.append((step, table))
    return frames


def write_box(group, edges, dtype=np.float64):
    box = group.create_group("box")
    box.attrs["dimension"] = np.int32(3)
    box.attrs["boundary"] = np.array([b"periodic"] * 3, dtype="S8")
    box.create_dataset("edges", data=np.array(edges, dtype=dtype))
    return box


def time_dependent(group, name, values, steps, times, **options):
    element = group.create_group(name)
    element.create_dataset("value", data=values, **options)
    element.create_dataset("step", data=np.array(steps, dtype=np.int64))
    element.create_dataset("time", data=np.array(times, dtype=np.float64))
    return element


def fixed_interval(element, name, interval, offset, dtype):
    series = element.create_dataset(name, data=np.array(interval, dtype=dtype))
    series.attrs["offset"] = np.array(offset, dtype=dtype)


def column_stack(frames, columns, dtype):
    return np.stack([frame[:, columns] for _, frame in frames]).astype(dtype)


def write_melt(frames):
    steps = [step for step, _ in frames]
    times = [TIMESTEP * step for step in steps]
    positions = column_stack(frames, [2, 3, 4], np.float32)
    velocities = column_stack(frames, [5, 6, 7], np.float32)
    species = column_stack(frames, 1, np.int32)
    ids = column_stack(frames, 0, np.int32)

    with h5py.File("melt.h5md", "w") as f:
        write_header(f)
        group = f.create_group("particles/all")
        write_box(group, [BOX, BOX, BOX])
        time_dependent(group, "position", positions, steps, times)
        time_dependent(group, "velocity", velocities, steps, times)
        time_dependent(group, "species", species, steps, times)
        time_dependent(group, "id", ids, steps, times)

    gzip = dict(compression="gzip", compression_opts=6, shuffle=True)
    with h5py.File("melt_gzip.h5md", "w") as f:
        write_header(f)
        group = f.create_group("particles/all")
        box = group.create_group("box")
        box.attrs["dimension"] = np.int32(3)
        box.attrs["boundary"] = np.array([b"periodic"] * 3, dtype="S8")
        edges = box.create_group("edges")
        edges.create_dataset("value", data=np.tile(np.eye(3) * BOX, (len(steps), 1, 1)),
                             chunks=(1, 3, 3), **gzip)
        fixed_interval(edges, "step", 20, 0, np.int64)
        fixed_interval(edges, "time", 20 * TIMESTEP, 0.0, np.float64)
        for name, values in (("position", positions), ("species", species), ("id", ids)):
            chunks = (1, 128) + values.shape[2:]
            element = group.create_group(name)
            element.create_dataset("value", data=values, chunks=chunks, **gzip)
            element.create_dataset("step", data=np.array(steps, dtype=np.int64), chunks=(2,), **gzip)
            element.create_dataset("time", data=np.array(times), chunks=(2,), **gzip)

    with h5py.File("melt_fixed.h5md", "w") as f:
        write_header(f)
        group = f.create_group("particles/all")
        write_box(group, [BOX, BOX, BOX])
        time_dependent(group, "position", positions, steps, times)
        every_other = slice(0, None, 2)
        time_dependent(group, "velocity", velocities[every_other], steps[every_other],
                       times[every_other])
        group.create_dataset("species", data=species[0])
        group.create_dataset("id", data=ids[0])
        group.create_dataset("mass", data=np.full(len(ids[0]), 1.0))
        group.create_dataset("charge", data=np.where(species[0] == 2, -0.5, 0.25))

    with h5py.File("melt_groups.h5md", "w") as f:
        write_header(f)
        for name, part in (("left", slice(0, 200)), ("right", slice(200, None))):
            group = f.create_group("particles/" + name)
            write_box(group, [BOX, BOX, BOX])
            time_dependent(group, "position", positions[:, part], steps, times)
            time_dependent(group, "id", ids[:, part], steps, times)


def snapshot_value(kind, particle_type, i):
    """The formulas of snapshotValue in H5mdTest.cpp."""
    if kind == "x":
        return 10000.0 + 0.123456789 * i + particle_type
    if kind == "y":
        return 12000.0 + 0.0987654321 * i
    if kind == "z":
        return 9000.0 + math.sqrt(i + 1.0)
    if kind == "v":
        return [float(i), -float(i), 0.5 * i]
    if kind == "id":
        return particle_type * 1000 + i + 1
    if kind == "mass":
        return 0.01 * (i + 1)
    raise KeyError(kind)


def write_snapshot():
    counts = {0: 40, 1: 60}
    with h5py.File("snapshot.hdf5", "w") as f:
        header = f.create_group("Header")
        header.attrs["BoxSize"] = np.array([20000.0, 20000.0, 20000.0])
        header.attrs["Time"] = 0.5
        header.attrs["MassTable"] = np.array([0.0, 0.25, 0, 0, 0, 0, 0])
        header.attrs["NumPart_ThisFile"] = np.array([40, 60, 0, 0, 0, 0, 0], dtype=np.uint32)
        for particle_type, count in counts.items():
            group = f.create_group("PartType%d" % particle_type)
            rows = range(count)
            group.create_dataset("Coordinates", data=np.array(
                [[snapshot_value(axis, particle_type, i) for axis in "xyz"] for i in rows]))
            group.create_dataset("Velocities", data=np.array(
                [snapshot_value("v", particle_type, i) for i in rows], dtype=np.float32))
            group.create_dataset("ParticleIDs", data=np.array(
                [snapshot_value("id", particle_type, i) for i in rows], dtype=np.uint64))
            if particle_type == 0:
                group.create_dataset("Masses", data=np.array(
                    [snapshot_value("mass", particle_type, i) for i in rows]))
                group.create_dataset("Densities", data=np.arange(count, dtype=np.float32) + 1.0)


def write_custom():
    count = 30
    i = np.arange(count, dtype=np.float64)
    with h5py.File("custom.h5", "w") as f:
        f.create_dataset("data/points", data=np.stack([i, 2.0 * i, -i], axis=1))
        f.create_dataset("data/temperature", data=300.0 + i)
        f.create_dataset("data/spin", data=np.stack([i, i, i], axis=1).astype(np.float32) * 0.5)
        f.create_dataset("meta/history", data=np.arange(5.0))


write_melt(read_dump(DUMP))
write_snapshot()
write_custom()
