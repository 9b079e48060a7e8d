#!/usr/bin/env python3
"""Writes the small sample point files of share/data, one per format osgGlyphs reads.

Deterministic (fixed seeds): run it again and the files come out byte-identical.
    python3 share/data/generate_samples.py [output folder]
"""
import math
import os
import random
import struct
import sys


def lammps_dump(path):
    """An fcc Lennard-Jones crystal, 5x5x5 cells (500 atoms, 2 types), three timesteps."""
    rng = random.Random(1)
    cells, a = 5, 1.6796
    basis = [(0, 0, 0), (0.5, 0.5, 0), (0.5, 0, 0.5), (0, 0.5, 0.5)]
    sites = [((i + bx) * a, (j + by) * a, (k + bz) * a)
             for i in range(cells) for j in range(cells) for k in range(cells) for bx, by, bz in basis]
    length = cells * a
    velocities = [[rng.gauss(0.0, 1.2) for _ in range(3)] for _ in sites]
    with open(path, "w") as out:
        for frame, step in enumerate((0, 100, 200)):
            out.write("ITEM: TIMESTEP\n%d\nITEM: NUMBER OF ATOMS\n%d\n" % (step, len(sites)))
            out.write("ITEM: BOX BOUNDS pp pp pp\n")
            for _ in range(3):
                out.write("0.0000000000000000e+00 %.16e\n" % length)
            out.write("ITEM: ATOMS id type x y z vx vy vz\n")
            for index, (site, velocity) in enumerate(zip(sites, velocities)):
                spread = 0.05 * frame
                position = [(c + rng.gauss(0.0, spread)) % length for c in site]
                velocity[:] = [v + rng.gauss(0.0, 0.3) for v in velocity]
                kind = 1 if index % 4 else 2
                out.write("%d %d %g %g %g %g %g %g\n" % ((index + 1, kind) + tuple(position) + tuple(velocity)))


def extended_xyz(path):
    """64 water molecules in a 12.4 Å box, two frames with velocities."""
    rng = random.Random(2)
    box = 12.4
    molecules = []
    for i in range(4):
        for j in range(4):
            for k in range(4):
                oxygen = [(n + 0.5) * box / 4 + rng.uniform(-0.3, 0.3) for n in (i, j, k)]
                theta = rng.uniform(0, 2 * math.pi)
                h1 = [oxygen[0] + 0.9572 * math.cos(theta), oxygen[1] + 0.9572 * math.sin(theta), oxygen[2]]
                h2 = [oxygen[0] + 0.9572 * math.cos(theta + 1.824), oxygen[1] + 0.9572 * math.sin(theta + 1.824),
                      oxygen[2]]
                molecules.append((oxygen, h1, h2))
    with open(path, "w") as out:
        for frame in range(2):
            out.write("%d\n" % (3 * len(molecules)))
            out.write('Lattice="%.1f 0.0 0.0 0.0 %.1f 0.0 0.0 0.0 %.1f" Properties=species:S:1:pos:R:3:velo:R:3 '
                      'step=%d pbc="T T T"\n' % (box, box, box, 500 * frame))
            for molecule in molecules:
                for atom, species in zip(molecule, ("O", "H", "H")):
                    position = [c + frame * rng.gauss(0.0, 0.05) for c in atom]
                    velocity = [rng.gauss(0.0, 0.01) for _ in range(3)]
                    out.write("%-2s %12.6f %12.6f %12.6f %10.6f %10.6f %10.6f\n"
                              % ((species,) + tuple(position) + tuple(velocity)))


def csv_samples(path):
    """1000 probe samples on a spiral through a temperature and density field."""
    with open(path, "w") as out:
        out.write("# probe samples of a heated channel (synthetic)\n")
        out.write("x,y,z,temperature,density\n")
        for i in range(1000):
            t = i / 999.0
            x, y, z = math.cos(20 * t) * (1 - 0.5 * t), math.sin(20 * t) * (1 - 0.5 * t), 2 * t - 1
            temperature = 300 + 80 * math.exp(-4 * (x * x + y * y)) + 10 * z
            density = 1.2 - 0.3 * temperature / 400
            out.write("%.5f,%.5f,%.5f,%.3f,%.5f\n" % (x, y, z, temperature, density))


def ply_cloud(path):
    """A torus point cloud: 2000 vertices with normals and colours, binary little endian."""
    rng = random.Random(3)
    vertices = []
    for _ in range(2000):
        u, v = rng.uniform(0, 2 * math.pi), rng.uniform(0, 2 * math.pi)
        normal = (math.cos(u) * math.cos(v), math.sin(u) * math.cos(v), math.sin(v))
        position = ((1 + 0.35 * math.cos(v)) * math.cos(u), (1 + 0.35 * math.cos(v)) * math.sin(u), 0.35 * math.sin(v))
        colour = (int(127.5 + 127.5 * normal[0]), int(127.5 + 127.5 * normal[1]), int(127.5 + 127.5 * normal[2]))
        vertices.append(position + normal + colour)
    header = ("ply\nformat binary_little_endian 1.0\ncomment synthetic torus point cloud\n"
              "element vertex %d\nproperty float x\nproperty float y\nproperty float z\n"
              "property float nx\nproperty float ny\nproperty float nz\n"
              "property uchar red\nproperty uchar green\nproperty uchar blue\n"
              "element face 0\nproperty list uchar int vertex_indices\nend_header\n" % len(vertices))
    with open(path, "wb") as out:
        out.write(header.encode("ascii"))
        for vertex in vertices:
            out.write(struct.pack("<6f3B", *vertex))


def vtk_galaxy(path):
    """A two-armed spiral of 400 stars as POLYDATA with masses and velocities."""
    rng = random.Random(4)
    stars = []
    for i in range(400):
        arm = i % 2
        r = 0.2 + 4.8 * rng.random() ** 0.7
        phi = 1.3 * math.log(r + 1e-3) + arm * math.pi + rng.gauss(0, 0.15)
        position = (r * math.cos(phi), r * math.sin(phi), rng.gauss(0, 0.1))
        speed = 1.0 / math.sqrt(r + 0.3)
        velocity = (-speed * math.sin(phi), speed * math.cos(phi), 0.0)
        stars.append((position, velocity, 0.5 + 2.0 * rng.random()))
    with open(path, "w") as out:
        out.write("# vtk DataFile Version 3.0\nsynthetic spiral galaxy\nASCII\nDATASET POLYDATA\n")
        out.write("POINTS %d float\n" % len(stars))
        for position, _, _ in stars:
            out.write("%.5f %.5f %.5f\n" % position)
        out.write("VERTICES %d %d\n" % (len(stars), 2 * len(stars)))
        for i in range(len(stars)):
            out.write("1 %d\n" % i)
        out.write("POINT_DATA %d\nSCALARS mass float 1\nLOOKUP_TABLE default\n" % len(stars))
        for _, _, mass in stars:
            out.write("%.4f\n" % mass)
        out.write("VECTORS velocity float\n")
        for _, velocity, _ in stars:
            out.write("%.5f %.5f %.5f\n" % velocity)


def main():
    folder = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.abspath(__file__))
    lammps_dump(os.path.join(folder, "melt500.lammpstrj"))
    extended_xyz(os.path.join(folder, "water64.xyz"))
    csv_samples(os.path.join(folder, "probes.csv"))
    ply_cloud(os.path.join(folder, "torus.ply"))
    vtk_galaxy(os.path.join(folder, "galaxy.vtk"))


if __name__ == "__main__":
    main()
