"""The LAMMPS text files the test data scripts read: dumps (dump custom) and the Bonds of data
files (write_data). Imported by bonds/make_gsd.py, bonds/make_h5md.py and
formats/gsd/write_ellipsoids.py."""


def dump_frames(path):
    """Each frame of a dump: its step, its box bounds (three (lo, hi) pairs), its column names and
    its rows (lists of the words of each atom line, in file order)."""
    with open(path) as text:
        lines = iter(text.read().splitlines())
    for line in lines:
        if line != "ITEM: TIMESTEP":
            continue
        step = int(next(lines))
        next(lines)
        count = int(next(lines))
        next(lines)
        bounds = [tuple(map(float, next(lines).split()[:2])) for _ in range(3)]
        columns = next(lines).split()[2:]
        rows = [next(lines).split() for _ in range(count)]
        yield step, bounds, columns, rows


def data_bonds(path):
    """The Bonds section of a data file: (atom id - 1, atom id - 1) pairs, in file order."""
    with open(path) as text:
        lines = text.read().splitlines()
    start = lines.index("Bonds") + 2
    bonds = []
    for line in lines[start:]:
        fields = line.split()
        if len(fields) != 4:
            break
        bonds.append((int(fields[2]) - 1, int(fields[3]) - 1))
    return bonds
