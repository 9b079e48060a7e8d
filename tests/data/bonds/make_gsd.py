#!/usr/bin/python3
"""Writes polymer.gsd with the gsd package (Debian's python3-gsd): the five frames of
polymer.lammpstrj (LAMMPS, sorted by id, so particle i is atom id i + 1) in HOOMD's box centred on
the origin, and the bonds of polymer.data in frame 0. gsd.hoomd writes a later frame's chunk only
where it differs from frame 0's: frames 1 to 4 hold no bonds chunks and take frame 0's.
Run from this folder: /usr/bin/python3 make_gsd.py"""
import os
import sys

import gsd.hoomd

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from lammps_text import data_bonds, dump_frames  # noqa: E402


bonds = data_bonds("polymer.data")
with gsd.hoomd.open("polymer.gsd", "wb") as trajectory:
    for step, bounds, _, rows in dump_frames("polymer.lammpstrj"):
        frame = gsd.hoomd.Snapshot()
        frame.configuration.step = step
        lengths = [hi - lo for lo, hi in bounds]
        frame.configuration.box = lengths + [0, 0, 0]
        centre = [(lo + hi) / 2 for lo, hi in bounds]
        frame.particles.N = len(rows)
        frame.particles.types = [str(t) for t in range(1, max(int(row[1]) for row in rows) + 1)]
        frame.particles.typeid = [int(row[1]) - 1 for row in rows]
        frame.particles.position = [[float(row[2 + a]) - centre[a] for a in range(3)] for row in rows]
        frame.bonds.N = len(bonds)
        frame.bonds.types = ["backbone"]
        frame.bonds.typeid = [0] * len(bonds)
        frame.bonds.group = bonds
        trajectory.append(frame)
