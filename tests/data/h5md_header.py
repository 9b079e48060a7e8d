"""The /h5md group of the H5MD test files (version 1.1, author, creator), imported by
formats/h5md/make_h5md.py and bonds/make_h5md.py."""

import h5py
import numpy as np


def write_header(f):
    h5md = f.create_group("h5md")
    h5md.attrs["version"] = np.array([1, 1], dtype=np.int32)
    h5md.create_group("author").attrs["name"] = "osgGlyphs tests"
    creator = h5md.create_group("creator")
    creator.attrs["name"] = "make_h5md.py (h5py)"
    creator.attrs["version"] = h5py.version.version
