#!/usr/bin/env bash
# Writes the HDF5 format tests' data with h5py (Debian's python3-h5py, HDF5 1.10): the reference
# dump ../melt.lammpstrj as H5MD in four variants, a SWIFT-style snapshot and a file of datasets
# of custom names (make_h5md.py says what each holds). The outputs are committed, so that the
# tests need neither; run this to make them again.
set -euo pipefail
cd "$(dirname "$0")"
/usr/bin/python3 make_h5md.py
ls -l *.h5md *.hdf5 *.h5
