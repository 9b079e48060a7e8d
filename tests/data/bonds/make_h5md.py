#!/usr/bin/python3
"""Writes the H5MD files of the bond tests with h5py (Debian's python3-h5py, HDF5 1.10): the five
frames of polymer.lammpstrj (LAMMPS, sorted by id) and the bonds of polymer.data as H5MD 1.1
connectivity (/connectivity, tuples of particles with a particles_group object reference):

  polymer.h5md          the particles in a shuffled order (row r holds the atom of id ids[r]), with
                        their id element: /connectivity/bonds holds the data file's bonds as ids,
                        fixed in time; /connectivity/angles, triples of ids along the chains (not
                        bonds: a reader leaves them out).
  polymer_indices.h5md  the particles in id order without an id element: bonds as 0-based indices
                        into the group, time-dependent (value, step), two more tuples a frame
                        holding the dataset's fill value -1, which a reader ignores.

Run from this folder: /usr/bin/python3 make_h5md.py"""
import os
import random
import sys

import h5py
import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from h5md_header import write_header  # noqa: E402
from lammps_text import data_bonds, dump_frames  # noqa: E402

TIMESTEP = 0.005


def write_particles(f, frames, order, with_ids):
    group = f.create_group("particles/all")
    steps = np.array([step for step, _, _, _ in frames], dtype=np.int64)
    position = group.create_group("position")
    position["value"] = np.array(
        [[[float(v) for v in rows[i][2:5]] for i in order] for _, _, _, rows in frames], dtype=np.float32)
    position["step"] = steps
    position["time"] = steps * TIMESTEP
    rows0 = frames[0][3]
    group["species"] = np.array([int(rows0[i][1]) for i in order], dtype=np.int32)
    if with_ids:
        group["id"] = np.array([int(rows0[i][0]) for i in order], dtype=np.int32)
    box = group.create_group("box")
    box.attrs["dimension"] = 3
    box.attrs["boundary"] = np.array([b"periodic"] * 3, dtype="S8")
    bounds = frames[0][1]
    box["edges"] = np.array([hi - lo for lo, hi in bounds])
    box["offset"] = np.array([lo for lo, _ in bounds])
    return group


frames = list(dump_frames("polymer.lammpstrj"))
bonds = data_bonds("polymer.data")  # 0-based: atom id - 1
atoms = len(frames[0][3])

# Shuffled rows, ids as the tuples' values.
order = list(range(atoms))
random.Random(7).shuffle(order)
with h5py.File("polymer.h5md", "w") as f:
    write_header(f)
    group = write_particles(f, frames, order, True)
    connectivity = f.create_group("connectivity")
    pairs = connectivity.create_dataset("bonds", data=np.array([(a + 1, b + 1) for a, b in bonds], dtype=np.int32))
    pairs.attrs["particles_group"] = group.ref
    after = {}
    for a, b in bonds:
        after.setdefault(a, []).append(b)
    angles = [(a + 1, b + 1, c + 1) for a, b in bonds for c in after.get(b, [])]
    triples = connectivity.create_dataset("angles", data=np.array(angles, dtype=np.int32))
    triples.attrs["particles_group"] = group.ref

# Id order, indices as the tuples' values, time-dependent with filler tuples.
with h5py.File("polymer_indices.h5md", "w") as f:
    write_header(f)
    group = write_particles(f, frames, list(range(atoms)), False)
    value = np.array([list(bonds) + [(-1, -1), (5, -1)] for _ in frames], dtype=np.int32)
    element = f.create_group("connectivity/bonds")
    element.create_dataset("value", data=value, fillvalue=-1)
    element["step"] = np.array([step for step, _, _, _ in frames], dtype=np.int64)
    element.attrs["particles_group"] = group.ref
