#!/usr/bin/env python3
"""Writes polymer.data: 12 bead-spring chains of 16 beads (bead types 1 and 2 alternating in blocks
of 4) that LAMMPS (Debian's lmp) relaxed in a periodic box and wrote with write_data, Bonds
included. The chains start straight along x on a 3 x 4 grid (polymer.start.data, written here and
read by read_data); LAMMPS moves them for 3000 steps of Langevin dynamics, so that they coil and
cross the periodic faces (write_data wraps the atoms into the box, with image flags). Run from this
folder: python3 make_polymer.py"""
import subprocess

chains, beads, box = 12, 16, 18.0
atoms, bonds = [], []
for c in range(chains):
    y, z = 2.25 + 4.5 * (c % 4), 3.0 + 6.0 * (c // 4)
    for i in range(beads):
        atoms.append((len(atoms) + 1, c + 1, 1 + (i // 4) % 2, 1.5 + 0.97 * i, y, z))
        if i > 0:
            bonds.append((len(bonds) + 1, 1, len(atoms) - 1, len(atoms)))
with open("polymer.start.data", "w") as f:
    f.write("12 straight chains (make_polymer.py)\n\n%d atoms\n%d bonds\n2 atom types\n1 bond types\n"
            "2 extra bond per atom\n4 extra special per atom\n\n" % (len(atoms), len(bonds)))
    f.write("0 %g xlo xhi\n0 %g ylo yhi\n0 %g zlo zhi\n\nMasses\n\n1 1.0\n2 1.0\n\nAtoms # bond\n\n" % (box, box, box))
    f.writelines("%d %d %d %.4f %.4f %.4f\n" % a for a in atoms)
    f.write("\nBonds\n\n")
    f.writelines("%d %d %d %d\n" % b for b in bonds)

with open("in.polymer", "w") as f:
    f.write("""# bead-spring chains in a periodic box, written by write_data (make_polymer.py)
units lj
atom_style bond
boundary p p p
read_data polymer.start.data
pair_style lj/cut 1.12246
pair_modify shift yes
pair_coeff * * 1.0 1.0
bond_style harmonic
bond_coeff 1 100.0 0.97
special_bonds lj 0 1 1
velocity all create 1.0 9127
fix 1 all nve
fix 2 all langevin 1.0 1.0 1.0 3317
thermo 1000
run 3000
write_data polymer.data
""")
subprocess.run(["lmp", "-in", "in.polymer", "-log", "none", "-screen", "none"], check=True)
