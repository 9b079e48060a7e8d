#!/usr/bin/env bash
# Writes the PDB, GRO and LAMMPS data test files from the melt (../melt.lammpstrj) with their
# formats' own writers: MDAnalysis (python3-mdanalysis: melt.pdb, models = dump frames 0, 2, 4;
# melt.gro, the same frames with velocities), GROMACS (gmx editconf: melt_gmx.pdb, the first frame
# of melt.gro) and LAMMPS (lmp write_data: melt.data, the melt at step 0, atoms in LAMMPS's own
# order). The outputs are committed, so that the tests need none of these programs.
set -euo pipefail
cd "$(dirname "$0")"
python=/usr/bin/python3
"$python" make_pdb.py 0,2,4
rm -f frame.gro
GMX_MAXBACKUP=-1 gmx -quiet editconf -f melt.gro -o melt_gmx.pdb
lmp -in in.data -log none -screen none
ls -l melt.pdb melt.gro melt_gmx.pdb melt.data
