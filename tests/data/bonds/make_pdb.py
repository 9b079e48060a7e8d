#!/usr/bin/python3
"""Writes polymer.pdb: the chains of polymer.data (LAMMPS write_data) written by MDAnalysis
(python3-mdanalysis) with a CONECT record for each bond, and polymer.lammpstrj: the chains moving
on for 2000 steps in Debian's LAMMPS (in.trajectory), a dump sorted by id whose topology
polymer.data is. Run from this folder: /usr/bin/python3 make_pdb.py"""
import subprocess
import warnings

import MDAnalysis as mda

warnings.simplefilter("ignore")  # MDAnalysis guesses elements and notes the missing ones
u = mda.Universe("polymer.data", atom_style="id resid type x y z")
u.add_TopologyAttr("names", ["B%s" % t for t in u.atoms.types])
u.atoms.write("polymer.pdb", bonds="all")
subprocess.run(["lmp", "-in", "in.trajectory", "-log", "none", "-screen", "none"], check=True)
