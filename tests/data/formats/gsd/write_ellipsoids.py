"""Writes ellipsoids.gsd with gsd.hoomd (Debian's python3-gsd): the five frames of the Gay-Berne
liquid LAMMPS wrote (../../lammps/ellipsoids/dump.ellipsoids: 144 ellipsoids of diameters
shapex shapey shapez = 3 1 1, turned by quatw quati quatj quatk), in HOOMD's box centred at the
origin, with the type's shape as HOOMD's schema gives it in particles/type_shapes:
{"type": "Ellipsoid", "a": 1.5, "b": 0.5, "c": 0.5} (semi-axes), and the turns as
particles/orientation. Run from this folder: /usr/bin/python3 write_ellipsoids.py"""
import os
import sys

import gsd.hoomd
import numpy

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../.."))
from lammps_text import dump_frames  # noqa: E402

DUMP = "../../lammps/ellipsoids/dump.ellipsoids"


def frames(path):
    for step, bounds, columns, rows in dump_frames(path):
        yield step, bounds, [dict(zip(columns, row)) for row in rows]


with gsd.hoomd.open("ellipsoids.gsd", "wb") as trajectory:
    for step, bounds, rows in frames(DUMP):
        rows.sort(key=lambda row: int(row["id"]))
        frame = gsd.hoomd.Snapshot()
        frame.configuration.step = step
        frame.configuration.box = [hi - lo for lo, hi in bounds] + [0, 0, 0]
        centre = [(lo + hi) / 2 for lo, hi in bounds]
        frame.particles.N = len(rows)
        frame.particles.types = ["GB"]
        frame.particles.typeid = [0] * len(rows)
        shape = [float(rows[0][name]) / 2 for name in ("shapex", "shapey", "shapez")]
        frame.particles.type_shapes = [{"type": "Ellipsoid", "a": shape[0], "b": shape[1], "c": shape[2]}]
        frame.particles.position = numpy.array(
            [[float(row[axis]) - centre[k] for k, axis in enumerate("xyz")] for row in rows], dtype=numpy.float32)
        frame.particles.orientation = numpy.array(
            [[float(row[name]) for name in ("quatw", "quati", "quatj", "quatk")] for row in rows], dtype=numpy.float32)
        trajectory.append(frame)
