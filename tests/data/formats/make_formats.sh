#!/usr/bin/env bash
# Writes the format tests' data with the formats' own writers: LAMMPS (lammps) for the reference
# dump, MDAnalysis (python3-mdanalysis) for DCD. The outputs are committed, so that the tests need
# none of these programs; run this to make them again.
set -euo pipefail
cd "$(dirname "$0")"
python=/usr/bin/python3
lmp -in in.melt -log none -screen none
"$python" write_mdanalysis.py
ls -l melt.*
