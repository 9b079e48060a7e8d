"""Writes the GSD test files with gsd.hoomd.

melt.gsd: the frames of ../melt.lammpstrj (500 atoms, 6 frames, types 1 and 2), positions moved
    into HOOMD's box centred at the origin (x - L/2), float32; types ['A', 'B'] and typeid = type - 1
    in frame 0 only (later frames omit them: they take frame 0's); velocities in every frame; the
    box only in frame 0 (the writer leaves out what equals frame 0).
triclinic.gsd: 8 particles at known fractional coordinates of a tilted box, placed as HOOMD's
    BoxDim::makeCoordinates places them: v = lo + f * L with lo = -L/2, then
    v.x += xy * v.y + xz * v.z and v.y += yz * v.z.
shapes.gsd: 6 particles with orientation, diameter, mass, charge, body, moment_inertia, image,
    angmom; frame 1 has 4 particles (so frame 0's per-particle values do not apply: defaults),
    frame 2 has 6 again and omits diameter and orientation (frame 0's apply).
shapes_v1.gsd: shapes.gsd rewritten in the GSD 1.0 file layer (64-byte names), checked by reading
    it back with gsd.
"""
import struct

import gsd.hoomd
import numpy

DUMP = "../melt.lammpstrj"


def read_dump(path):
    """The frames of a LAMMPS dump: (timestep, box bounds, rows of id type x y z vx vy vz)."""
    frames = []
    with open(path) as stream:
        lines = [line.strip() for line in stream]
    at = 0
    while at < len(lines) and lines[at]:
        assert lines[at] == "ITEM: TIMESTEP"
        step = int(lines[at + 1])
        count = int(lines[at + 3])
        bounds = [tuple(float(v) for v in lines[at + 5 + k].split()) for k in range(3)]
        assert lines[at + 8].split()[2:] == ["id", "type", "x", "y", "z", "vx", "vy", "vz"]
        rows = numpy.array([[float(v) for v in lines[at + 9 + i].split()] for i in range(count)])
        frames.append((step, bounds, rows))
        at += 9 + count
    return frames


def write_melt():
    frames = read_dump(DUMP)
    with gsd.hoomd.open("melt.gsd", "wb") as trajectory:
        for index, (step, bounds, rows) in enumerate(frames):
            lengths = numpy.array([hi - lo for lo, hi in bounds])
            centre = numpy.array([(lo + hi) / 2 for lo, hi in bounds])
            frame = gsd.hoomd.Snapshot()
            frame.configuration.step = step
            frame.configuration.box = [lengths[0], lengths[1], lengths[2], 0, 0, 0]
            frame.particles.N = len(rows)
            frame.particles.position = (rows[:, 2:5] - centre).astype(numpy.float32)
            frame.particles.velocity = rows[:, 5:8].astype(numpy.float32)
            if index == 0:
                frame.particles.types = ["A", "B"]
                frame.particles.typeid = (rows[:, 1] - 1).astype(numpy.uint32)
            trajectory.append(frame)


def make_coordinates(box, fractions):
    """HOOMD's BoxDim::makeCoordinates for the box [Lx, Ly, Lz, xy, xz, yz]."""
    lx, ly, lz, xy, xz, yz = box
    lengths = numpy.array([lx, ly, lz])
    v = -lengths / 2 + fractions * lengths
    x = v[:, 0] + xy * v[:, 1] + xz * v[:, 2]
    y = v[:, 1] + yz * v[:, 2]
    return numpy.stack([x, y, v[:, 2]], axis=1)


def write_triclinic():
    box = [4.0, 5.0, 6.0, 0.5, -0.25, 0.125]
    fractions = numpy.array([[(i & 1) * 0.5 + 0.25, ((i >> 1) & 1) * 0.5 + 0.25, ((i >> 2) & 1) * 0.5 + 0.125]
                             for i in range(8)])
    with gsd.hoomd.open("triclinic.gsd", "wb") as trajectory:
        frame = gsd.hoomd.Snapshot()
        frame.configuration.step = 12345678901
        frame.configuration.box = box
        frame.particles.N = 8
        frame.particles.types = ["solvent", "colloid"]
        frame.particles.typeid = [i % 2 for i in range(8)]
        frame.particles.position = make_coordinates(box, fractions).astype(numpy.float32)
        trajectory.append(frame)


def shapes_frame(count, step, with_shapes):
    i = numpy.arange(count)
    frame = gsd.hoomd.Snapshot()
    frame.configuration.step = step
    frame.configuration.box = [10, 10, 10, 0, 0, 0]
    frame.particles.N = count
    frame.particles.types = ["E1", "E2", "E3"]
    frame.particles.typeid = i % 3
    frame.particles.position = numpy.stack([i - 2.5, 0.5 * i, -0.25 * i], axis=1).astype(numpy.float32) + step
    frame.particles.mass = 1.0 + i
    frame.particles.charge = -1.0 + 0.5 * i
    frame.particles.body = numpy.where(i < 2, -1, i // 2)
    frame.particles.moment_inertia = numpy.stack([i, 2 * i, 3 * i], axis=1)
    frame.particles.image = numpy.stack([i - 3, -i, numpy.full(count, 7)], axis=1)
    frame.particles.angmom = numpy.stack([0.0 * i, i, 0.0 * i, -i], axis=1)
    if with_shapes:
        angle = 0.25 * i
        frame.particles.orientation = numpy.stack(
            [numpy.cos(angle / 2), 0.0 * i, 0.0 * i, numpy.sin(angle / 2)], axis=1)
        frame.particles.diameter = 0.5 + 0.25 * i
    return frame


def write_shapes():
    with gsd.hoomd.open("shapes.gsd", "wb") as trajectory:
        trajectory.append(shapes_frame(6, 0, True))
        trajectory.append(shapes_frame(4, 100, False))
        trajectory.append(shapes_frame(6, 200, False))


def rewrite_v1(source, target):
    """The same file in the GSD 1.0 layer: version 1.0, each name in a 64-byte segment."""
    data = bytearray(open(source, "rb").read())
    header = list(struct.unpack_from("QQQQQII64s64s80s", data, 0))
    names_at, names_segments = header[3], header[4]
    names = bytes(data[names_at:names_at + 64 * names_segments]).split(b"\0")
    names = [name for name in names[:names.index(b"")]]
    assert len(names) <= names_segments
    block = b"".join(name.ljust(64, b"\0") for name in names).ljust(64 * names_segments, b"\0")
    data[names_at:names_at + len(block)] = block
    header[4] = names_segments
    header[6] = 1 << 16
    struct.pack_into("QQQQQII64s64s80s", data, 0, *header)
    open(target, "wb").write(bytes(data))
    with gsd.hoomd.open(source, "rb") as a, gsd.hoomd.open(target, "rb") as b:
        assert b.file.gsd_version == (1, 0)
        assert len(a) == len(b)
        for fa, fb in zip(a, b):
            assert numpy.array_equal(fa.particles.position, fb.particles.position)
            assert fa.particles.types == fb.particles.types


write_melt()
write_triclinic()
write_shapes()
rewrite_v1("shapes.gsd", "shapes_v1.gsd")
