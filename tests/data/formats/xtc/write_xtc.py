"""Writes the melt (../melt.lammpstrj) and two made-up sets of points with MDAnalysis's XTC and TRR
writers, for make_xtc.sh. MDAnalysis takes Angstrom, ps and kJ/(mol Angstrom) and writes GROMACS's
nm, ps and kJ/(mol nm): the dump's LJ lengths are given as Angstrom, so the files hold 0.1 times them.

melt.xtc, melt.trr     the dump's 500 atoms x 6 frames: x = 0.1 * dump x (LJ sigma read as Angstrom,
                       so nm), v = 0.1 * dump v, f = -(dump vx, vy, vz) (the dump has no forces),
                       box 0.1 * 8.3979809569125372 cubic, step = the dump's timestep (TRR; MDAnalysis
                       writes the frame index as the XTC's step), time = frame * 0.1 ps.
melt9.xtc, melt9.trr   the same for the first 9 atoms: XTC stores up to 9 atoms uncompressed.
scatter.xtc            3000 atoms, 2 frames, of molecules of three atoms (water-like: O, H1, H2 close
                       together) at points spread through 20 nm, every 400th molecule 20000 nm away,
                       so that the integers are large (over 24 bits) and some steps are big jumps.
                       Position of atom i in frame f (all in double, then float32):
                         molecule m = i // 3, part k = i % 3
                         h(m, axis) = ((m * 2654435761 + axis * 40503 + f * 97) % 1000003) / 1000003
                         centre = h * 20000 if m % 400 == 7 else h * 20
                         offset = (0, 0, 0), (0.0957, 0, 0), (-0.024, 0.0927, 0) for k = 0, 1, 2
                       box 20 nm cubic; step f, time 2.5 * f ps.
"""
import warnings

import numpy as np

import MDAnalysis as mda
from MDAnalysis.coordinates.memory import MemoryReader

warnings.simplefilter("ignore")


def read_dump(path):
    steps, frames = [], []
    with open(path) as dump:
        lines = dump.read().split("\n")
    at = 0
    while at < len(lines) and lines[at].startswith("ITEM: TIMESTEP"):
        steps.append(int(lines[at + 1]))
        atoms = int(lines[at + 3])
        columns = lines[at + 8].split()[2:]
        rows = np.array([[float(v) for v in line.split()] for line in lines[at + 9:at + 9 + atoms]])
        rows = rows[np.argsort(rows[:, columns.index("id")])]
        frames.append(rows[:, [columns.index(c) for c in ("x", "y", "z", "vx", "vy", "vz")]])
        at += 9 + atoms
    return steps, np.array(frames)


def universe(positions, velocities=None, forces=None, box=None, dt=1.0):
    u = mda.Universe.empty(positions.shape[1], trajectory=False)
    u.add_TopologyAttr("name", ["A"] * positions.shape[1])
    u.add_TopologyAttr("resname", ["MLT"])
    u.load_new(positions.astype(np.float32), format=MemoryReader, dt=dt,
               velocities=None if velocities is None else velocities.astype(np.float32),
               forces=None if forces is None else forces.astype(np.float32),
               dimensions=np.array([box, box, box, 90, 90, 90], dtype=np.float32))
    return u


def write(u, path, steps=None):
    with mda.Writer(path, u.atoms.n_atoms) as writer:
        for ts in u.trajectory:
            if steps is not None:
                ts.data["step"] = steps[ts.frame]
            writer.write(u.atoms)


def scatter(frame, atoms=3000):
    i = np.arange(atoms, dtype=np.int64)
    m, k = i // 3, i % 3
    h = np.stack([((m * 2654435761 + axis * 40503 + frame * 97) % 1000003) / 1000003.0
                  for axis in range(3)], axis=1)
    centre = np.where((m % 400 == 7)[:, None], h * 20000.0, h * 20.0)
    offsets = np.array([[0.0, 0.0, 0.0], [0.0957, 0.0, 0.0], [-0.024, 0.0927, 0.0]])
    return centre + offsets[k]


steps, dump = read_dump("../melt.lammpstrj")
box = 8.3979809569125372
x, v, f = dump[:, :, 0:3], dump[:, :, 3:6], -0.1 * dump[:, :, 3:6]
melt = universe(x, v, f, box, dt=0.1)
write(melt, "melt.xtc")
write(melt, "melt.trr", steps)
melt9 = universe(x[:, :9], v[:, :9], f[:, :9], box, dt=0.1)
write(melt9, "melt9.xtc")
write(melt9, "melt9.trr", steps)

write(universe(10.0 * np.array([scatter(0), scatter(1)]), box=200.0, dt=2.5), "scatter.xtc")
