#!/usr/bin/env bash
# Writes the GSD test files with gsd.hoomd (Debian's python3-gsd, the GSD project's own writer):
# melt.gsd from the reference dump ../melt.lammpstrj, and two small files with known values. The
# outputs are committed, so that the tests need no Python; run this to make them again.
set -euo pipefail
cd "$(dirname "$0")"
/usr/bin/python3 write_gsd.py
/usr/bin/python3 write_ellipsoids.py
chmod 644 ./*.gsd
ls -l ./*.gsd
