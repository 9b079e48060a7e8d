#!/usr/bin/env bash
# Writes the XTC and TRR test files with their real writers: MDAnalysis (python3-mdanalysis, see
# write_xtc.py) and GROMACS's own trjconv (package gromacs: gmx, and gmx_d for double precision).
#   melt.xtc melt.trr melt9.xtc melt9.trr scatter.xtc   MDAnalysis (write_xtc.py says what they hold)
#   melt_gmx.xtc     gmx trjconv of melt.trr: the same frames, with the TRR's steps
#   melt_gmx_d.trr   gmx_d trjconv of melt.trr: the first 100 atoms with x, v and f, double precision
# The outputs are committed, so that the tests need none of these programs.
set -euo pipefail
cd "$(dirname "$0")"
export GMX_MAXBACKUP=-1
/usr/bin/python3 -W ignore write_xtc.py
gmx -quiet trjconv -f melt.trr -o melt_gmx.xtc >/dev/null 2>&1
index=$(mktemp --suffix=.ndx)
printf '[ first100 ]\n%s\n' "$(seq -s ' ' 1 100)" >"$index"
echo 0 | gmx_d -quiet trjconv -f melt.trr -n "$index" -o melt_gmx_d.trr -force >/dev/null 2>&1
rm -f "$index" melt.gro
ls -l ./*.xtc ./*.trr
