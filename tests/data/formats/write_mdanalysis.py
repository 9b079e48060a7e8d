"""Writes melt.lammpstrj's frames with MDAnalysis's writers (DCD)."""
import warnings

import MDAnalysis as mda

warnings.simplefilter("ignore")
universe = mda.Universe("melt.lammpstrj", format="LAMMPSDUMP")
with mda.Writer("melt.dcd", universe.atoms.n_atoms) as writer:
    for _ in universe.trajectory:
        writer.write(universe.atoms)
