#!/usr/bin/env python3
"""Runs osgglyphbench with --repeat 3 and checks that each case's CSV row holds the median of the
medians its three passes printed (to their three printed digits), the least minimum and the
greatest maximum, with one row a case.
    check_repeat.py <osgglyphbench> <csv>"""
import csv
import re
import subprocess
import sys

bench, csv_path = sys.argv[1], sys.argv[2]
run = subprocess.run([bench, "--quick", "--n", "100,1000", "--techniques", "default", "--repeat", "3",
                      "--csv", csv_path], capture_output=True, text=True)
if run.returncode != 0:
    sys.exit(f"osgglyphbench failed ({run.returncode}):\n{run.stdout}{run.stderr}")

progress = re.compile(r"^\[\d+/\d+\] (\S+) (\S+) n=(\d+) .*: median ([0-9.]+) ms \(min ([0-9.]+), max ([0-9.]+)\)")
passes = {}
for line in run.stdout.splitlines():
    match = progress.match(line)
    if match:
        technique, shape, n, median, low, high = match.groups()
        passes.setdefault((technique, shape, n), []).append((float(median), float(low), float(high)))

rows = list(csv.DictReader(open(csv_path)))
keys = [(row["technique"], row["shape"], row["n"]) for row in rows]
if sorted(keys) != sorted(passes) or len(keys) != len(set(keys)):
    sys.exit(f"CSV cases {keys}, printed cases {sorted(passes)}")


def close(value, printed):
    """Whether value, printed to three significant digits, reads as printed."""
    return abs(value - printed) <= 0.005 * printed + 1e-9


for row, key in zip(rows, keys):
    measured = passes[key]
    if len(measured) != 3:
        sys.exit(f"{key}: {len(measured)} passes printed, not 3")
    middle = sorted(m[0] for m in measured)[1]
    checks = [("ms_median", middle), ("ms_min", min(m[1] for m in measured)),
              ("ms_max", max(m[2] for m in measured))]
    for column, expected in checks:
        if not close(float(row[column]), expected):
            sys.exit(f"{key}: {column} {row[column]}, expected {expected} from the passes {measured}")
print(f"{len(rows)} cases, each the median of 3 passes")
