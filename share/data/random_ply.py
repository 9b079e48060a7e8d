#!/usr/bin/env python3
"""Writes a large binary PLY of random points for measuring osgglyphconvert: x, y, z in the unit
cube and an intensity in [0, 1), each a little-endian float, from a fixed seed.
    python3 share/data/random_ply.py <points> <output.ply>
"""
import array
import random
import sys

BLOCK = 1 << 18


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    count, path = int(sys.argv[1]), sys.argv[2]
    rng = random.Random(1)
    with open(path, "wb") as out:
        out.write(("ply\nformat binary_little_endian 1.0\nelement vertex %d\n"
                   "property float x\nproperty float y\nproperty float z\nproperty float intensity\n"
                   "end_header\n" % count).encode("ascii"))
        for first in range(0, count, BLOCK):
            values = array.array("f", (rng.random() for _ in range(4 * min(BLOCK, count - first))))
            if sys.byteorder != "little":
                values.byteswap()
            values.tofile(out)


if __name__ == "__main__":
    main()
