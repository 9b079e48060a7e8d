#!/bin/sh
# Writes dump.ellipsoids with Debian's LAMMPS (package lammps, 20220106), then renames the columns of
# compute property/atom to the keywords newer LAMMPS dumps write (shapex ... quatk): this version's
# dump custom has no such keywords. The values are LAMMPS's own.
set -e
cd "$(dirname "$0")"
lmp -in in.ellipsoids -log none -screen none
sed -i -e 's/c_shape\[1\]/shapex/; s/c_shape\[2\]/shapey/; s/c_shape\[3\]/shapez/' \
    -e 's/c_shape\[4\]/quatw/; s/c_shape\[5\]/quati/; s/c_shape\[6\]/quatj/; s/c_shape\[7\]/quatk/' dump.ellipsoids
