#!/usr/bin/env bash
# Writes the trajectory tests' data with LAMMPS (Debian's lammps package: apt-get install lammps).
# The outputs are committed, so that the tests need no LAMMPS; run this to make them again.
set -euo pipefail
cd "$(dirname "$0")"
lmp -in in.melt500 -log none -screen none
lmp -in in.evaporate -log none -screen none
ls -l melt500.* evaporate.lammpstrj
