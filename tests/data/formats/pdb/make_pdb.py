"""Writes frames of ../melt.lammpstrj with MDAnalysis's PDB and GRO writers, the atoms named by
their LAMMPS type (1: Ar, 2: Ne), each atom a residue of its own (LJ1 or LJ2) in chain A or B."""
import sys
import warnings

import MDAnalysis as mda
import numpy as np
from MDAnalysis.coordinates.memory import MemoryReader

warnings.simplefilter("ignore")
frames = [int(f) for f in sys.argv[1].split(",")]
dump = mda.Universe("../melt.lammpstrj", format="LAMMPSDUMP")
types = dump.atoms.types
positions = np.array([dump.trajectory[f].positions.copy() for f in frames])
velocities = np.array([dump.trajectory[f].velocities.copy() for f in frames])
box = dump.trajectory[0].dimensions.copy()

atoms = len(types)
universe = mda.Universe.empty(atoms, n_residues=atoms, atom_resindex=np.arange(atoms), trajectory=True)
first = types == "1"
universe.add_TopologyAttr("names", np.where(first, "Ar", "Ne"))
universe.add_TopologyAttr("elements", np.where(first, "Ar", "Ne"))
universe.add_TopologyAttr("types", np.where(first, "Ar", "Ne"))
universe.add_TopologyAttr("resnames", np.where(first, "LJ1", "LJ2"))
universe.add_TopologyAttr("resids", np.arange(1, atoms + 1))
universe.add_TopologyAttr("chainIDs", np.where(first, "A", "B"))
universe.add_TopologyAttr("ids", dump.atoms.ids)
universe.add_TopologyAttr("occupancies", np.ones(atoms))
universe.add_TopologyAttr("tempfactors", np.where(first, 1.5, 2.5))
universe.add_TopologyAttr("segids", ["MELT"])
universe.load_new(positions, format=MemoryReader, velocities=velocities,
                  dimensions=np.tile(box, (len(frames), 1)))

with mda.Writer("melt.pdb", atoms, multiframe=True) as writer:
    for _ in universe.trajectory:
        writer.write(universe.atoms)

# MDAnalysis's GRO writer writes one frame a file: the frames one after the other.
with open("melt.gro", "w") as out:
    for _ in universe.trajectory:
        universe.atoms.write("frame.gro")
        with open("frame.gro") as frame:
            out.write(frame.read())
