#!/usr/bin/python3
"""Writes docs/results.md, the current benchmark figures, from the committed benchmark CSVs.

    /usr/bin/python3 share/bench/results-page.py            write docs/results.md
    /usr/bin/python3 share/bench/results-page.py --check    exit 1 when docs/results.md is stale
    /usr/bin/python3 share/bench/results-page.py --output FILE

Standard library only. It reads, from share/bench/:
- results.csv, dense.csv, shapes.csv and shapes_round.csv, written by osgglyphbench --csv
  (applications/osgglyphbench, BenchReport.cpp: one row per case; no date or machine column);
- format_results.csv, written by share/bench/format_bench.py, and trajectory_results.csv, written
  by osgglyphtrajbench and share/bench/trajectory_bench.sh (rows of date, machine, suite, case,
  metric, value, unit).

The page names the machine and the date where a CSV carries them. Where it does not, it says which
column is missing, and gives what the commit that added the CSV says, for the CSV as committed then
(recognised by its git blob id); a CSV measured again without them is said to have none.
"""

import argparse
import csv
import hashlib
import os
import re
import sys

BENCH = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(BENCH))
PAGE = os.path.join(ROOT, "docs", "results.md")

# What is known of the osgglyphbench CSVs, which carry no date or machine: keyed by the git blob id
# of the file as committed (git hash-object), from the commit that added it (git log).
OSGGLYPHBENCH_SOURCES = {
    "315801a769431f8d7fa075225818073004234511": {
        "commit": "f6e20b5",
        "date": "2026-11-26",
        "machine": "llvmpipe, 2 cores",
        "said": 'the README section it was committed with was headed "Results (llvmpipe, 2 cores, 800x600)"',
        "command": "osgglyphbench --techniques geometry-shader,instanced,point-sprite,paper-quad,polygons,"
        "texture-blend,texture-multi,points-floor --shapes sphere,cone,arrow,cylinder --max-ms 2500",
    },
    "e24ac073d0e31429834871e0211b7121266fcab8": {
        "commit": "cfee057",
        "date": "2026-11-26",
        "machine": None,
        "said": 'the README it was committed with says "one run on a quiet machine" and names no machine',
        "command": "osgglyphbench --techniques default,points-floor --culling off,occlusion --radius-spacing 0.4 "
        "--n 10000,31623,100000,316228,1000000 --frames 5 --plot dense.png",
    },
    "fd9c8df7fca948c947137c0fe106bc53d119e094": {
        "commit": "a2fe8be",
        "date": "2026-11-29",
        "machine": "llvmpipe, 2 cores",
        "said": "its commit message names the machine and the date",
        "command": "osgglyphbench --techniques geometry-shader --shapes sphere,ellipsoid,superquadric "
        "--culling off,occlusion --n 30000,300000 --radius-spacing 0.4 --frames 10 --repeat 3 --smallest-axis 1",
    },
    "2fadcfa5da0cffc65030721833dc04da10ed0b8e": {
        "commit": "ca16cf1",
        "date": "2026-11-29",
        "machine": "llvmpipe, 2 cores",
        "said": "its commit message names the machine and the date",
        "command": "osgglyphbench --techniques geometry-shader --shapes sphere,ellipsoid,superquadric "
        "--culling off,occlusion --n 30000,300000 --radius-spacing 0.4 --frames 10 --repeat 3",
    },
}

SHAPES = ["sphere", "cone", "arrow", "cylinder"]


def blob_id(path):
    """The git blob id of a file's bytes, as git hash-object computes it."""
    with open(path, "rb") as stream:
        data = stream.read()
    return hashlib.sha1(b"blob %d\0" % len(data) + data).hexdigest()


def read_rows(name):
    with open(os.path.join(BENCH, name), newline="") as stream:
        return list(csv.DictReader(stream))


def number(text):
    try:
        return float(text)
    except (TypeError, ValueError):
        return None


def fmt(value):
    """A figure as a reader takes it in: three significant digits, no exponent."""
    if value is None:
        return "-"
    if value == int(value) and abs(value) < 1e15:
        return f"{int(value):,}" if abs(value) >= 1000 else str(int(value))
    magnitude = abs(value)
    if magnitude >= 1000:
        return f"{value:,.0f}"
    if magnitude >= 100:
        return f"{value:.0f}"
    if magnitude >= 10:
        return f"{value:.1f}"
    if magnitude >= 1:
        return f"{value:.2f}"
    if magnitude == 0:
        return "0"
    return f"{value:.3g}"


def ratio(value):
    return "-" if value is None else fmt(value) + "x"


def table(header, rows):
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    for row in rows:
        lines.append("| " + " | ".join(cell.replace("|", "\\|") for cell in row) + " |")
    return lines


def count_name(n):
    n = int(n)
    if n >= 1000000 and n % 1000000 == 0:
        return f"{n // 1000000}M"
    if n >= 1000 and n % 1000 == 0:
        return f"{n // 1000}k"
    return str(n)


def osgglyphbench_provenance(name, rows):
    """Lines saying where an osgglyphbench CSV's figures come from."""
    source = OSGGLYPHBENCH_SOURCES.get(blob_id(os.path.join(BENCH, name)))
    sizes = sorted({f"{row['width']}x{row['height']}" for row in rows})
    frames = sorted({row["frames"] for row in rows}, key=int)
    passes = re.search(r"--repeat (\d+)", source["command"]) if source else None
    per_case = f"the median of {' or '.join(frames)} orbiting frames per case"
    if passes:
        per_case = (f"the median over {passes.group(1)} passes of each case's median of "
                    f"{' or '.join(frames)} orbiting frames")
    lines = [f"Source: `share/bench/{name}`, {len(rows)} cases, {', '.join(sizes)} pixels, {per_case}."]
    if source:
        machine = source["machine"] or "not recorded"
        lines.append(f"Machine: {machine}. Date: {source['date']}, the commit that added the CSV "
                     f"({source['commit']}). The CSV has no `date` or `machine` column: {source['said']}.")
        lines.append(f"Command: `{source['command']}`.")
    else:
        lines.append("Machine and date: not recorded. The CSV has no `date` or `machine` column; note them in "
                     "the commit that adds it, and in this script (OSGGLYPHBENCH_SOURCES).")
    return [" ".join(lines)]


def paper_comparison():
    rows = read_rows("results.csv")
    out = ["## The paper's comparison", ""]
    out += osgglyphbench_provenance("results.csv", rows)
    out += ["", "![frames per second against N](../share/bench/results.png)", ""]
    out.append("Random glyphs in the unit cube, of radius 0.5/sqrt(N) (the paper's datasets). `/ floor`: the "
               "frame time over `points-floor`'s, the cost of drawing each glyph as one pixel. `polygons / this`: "
               "how many times faster than 8x4 polygons. `B/glyph`: GPU bytes per glyph (at 100k). The exact techniques "
               "(`geometry-shader`, the default, and `point-sprite`) were measured with occlusion culling, the "
               "others without (the CSV's `culling` column).")
    out.append("")
    by_case = {(row["technique"], row["shape"], int(row["n"])): row for row in rows}
    counts = sorted({int(row["n"]) for row in rows})
    focus = [n for n in (100000, 1000000) if n in counts]
    techniques = []
    for row in rows:
        if row["technique"] not in techniques:
            techniques.append(row["technique"])

    def ms(technique, shape, n):
        row = by_case.get((technique, shape, n))
        return number(row["ms_median"]) if row else None

    header = ["shape", "technique", "B/glyph"]
    for n in focus:
        header += [f"{count_name(n)}: ms", "/ floor", "polygons / this"]
    lines = []
    for shape in SHAPES:
        for technique in techniques:
            cases = [by_case.get((technique, shape, n)) for n in counts]
            if not any(cases):
                continue
            bytes_case = next((by_case[(technique, shape, n)] for n in focus + counts
                               if (technique, shape, n) in by_case))
            name = f"**{technique}**" if technique == "geometry-shader" else technique
            line = [shape, name, fmt(number(bytes_case["gpu_bytes_per_glyph"]))]
            for n in focus:
                this, floor, polygons = ms(technique, shape, n), ms("points-floor", shape, n), ms("polygons", shape, n)
                line += [fmt(this), ratio(this / floor if this and floor else None),
                         "-" if technique == "polygons" else ratio(polygons / this if this and polygons else None)]
            lines.append(line)
    out += table(header, lines)
    out += ["", "Every N, median ms per frame:", ""]
    header = ["shape", "technique"] + [count_name(n) for n in counts]
    lines = []
    for shape in SHAPES:
        for technique in techniques:
            if not any((technique, shape, n) in by_case for n in counts):
                continue
            lines.append([shape, technique] + [fmt(ms(technique, shape, n)) for n in counts])
    out += table(header, lines)
    return out


def dense_series():
    rows = read_rows("dense.csv")
    out = ["## Dense data", ""]
    out += osgglyphbench_provenance("dense.csv", rows)
    out += ["", "![frames per second against N, dense spheres](../share/bench/dense.png)", ""]
    out.append("Spheres in the unit cube at 0.4 times their mean spacing: the cube fills the same part of the "
               "view at every N, so the visible area is constant and N grows behind it. `/ floor`: over "
               "`points-floor`'s frame. Fragments: fragment shader invocations per covered pixel (the CSV's "
               "`overdraw`; llvmpipe counts whole 4x4 blocks). Submitted: the share of the glyphs culling sent "
               "to the GPU. See [culling](design/culling.md).")
    out.append("")
    by_case = {(row["technique"], row["culling"], int(row["n"])): row for row in rows}
    counts = sorted({int(row["n"]) for row in rows})
    glyphs = "geometry-shader"
    cullings = []
    for row in rows:
        if row["technique"] == glyphs and row["culling"] not in cullings:
            cullings.append(row["culling"])
    header = ["N", "covered"]
    for culling in cullings:
        header += [f"culling {culling}: ms", "/ floor", "fragments", "submitted"]
    lines = []
    for n in counts:
        floor_row = by_case.get(("points-floor", "off", n))
        floor = number(floor_row["ms_median"]) if floor_row else None
        any_row = next((by_case[(glyphs, c, n)] for c in cullings if (glyphs, c, n) in by_case), None)
        line = [count_name(n), fmt(number(any_row["coverage"])) if any_row else "-"]
        for culling in cullings:
            row = by_case.get((glyphs, culling, n))
            this = number(row["ms_median"]) if row else None
            line += [fmt(this), ratio(this / floor if this and floor else None),
                     fmt(number(row["overdraw"])) if row else "-", fmt(number(row["submitted"])) if row else "-"]
        lines.append(line)
    out += table(header, lines)
    return out


def shapes_table(rows):
    """Each shape's frame at each N and culling, over the spheres' of the same N and culling."""
    rows = [row for row in rows if row["technique"] == "geometry-shader"]
    by_case = {(row["shape"], row["culling"], int(row["n"])): row for row in rows}
    shapes = []
    cullings = []
    for row in rows:
        if row["shape"] not in shapes:
            shapes.append(row["shape"])
        if row["culling"] not in cullings:
            cullings.append(row["culling"])
    counts = sorted({int(row["n"]) for row in rows})
    header = ["shape", "N"]
    for culling in cullings:
        header += [f"culling {culling}: ms", "/ sphere", "fragments", "submitted"]
    lines = []
    for shape in shapes:
        for n in counts:
            line = [shape, count_name(n)]
            for culling in cullings:
                row = by_case.get((shape, culling, n))
                sphere = by_case.get(("sphere", culling, n))
                this = number(row["ms_median"]) if row else None
                base = number(sphere["ms_median"]) if sphere else None
                line += [fmt(this), ratio(this / base if this and base else None),
                         fmt(number(row["overdraw"])) if row else "-",
                         fmt(number(row["submitted"])) if row else "-"]
            lines.append(line)
    return table(header, lines)


def dense_shapes():
    rows = read_rows("shapes.csv")
    out = ["## Ellipsoids and superquadrics, dense", ""]
    out += osgglyphbench_provenance("shapes.csv", rows)
    out.append("")
    out.append("Spheres of radius r = 0.4 times the mean spacing in the unit cube, and ellipsoids and "
               "superquadrics of semi-axes r and r times two numbers uniform in [0.25, 1], in uniformly "
               "random turns (the largest semi-axis is the spheres' radius); superquadrics' two exponents "
               "uniform in [0.1, 1], from rounded boxes to ellipsoids. With culling off every glyph is drawn: "
               "the cost of a glyph drawn. With occlusion culling (the default) the frame draws what can be "
               "seen, and the other shapes, thinner than the spheres, hide less of the cloud behind them. "
               "`/ sphere`: over the spheres' frame of the same N and culling. Fragments and submitted as "
               "above.")
    out.append("")
    out += shapes_table(rows)
    rows = read_rows("shapes_round.csv")
    out += ["", "### Every semi-axis the spheres' radius", ""]
    out += osgglyphbench_provenance("shapes_round.csv", rows)
    out.append("")
    out.append("The same with `--smallest-axis 1`: the ellipsoids are spheres of radius r, drawn as "
               "ellipsoids, and hide as much of the cloud as the spheres do (the same fragments and glyphs "
               "submitted), so their ratio is the cost of the shape itself. The superquadrics are rounded "
               "cubes of half-side r, larger than the spheres: more fragments.")
    out.append("")
    out += shapes_table(rows)
    return out


class Suites:
    """The rows of a CSV of date, machine, suite, case, metric, value, unit."""

    def __init__(self, name):
        self.name = name
        self.rows = read_rows(name)

    def suites(self):
        names = []
        for row in self.rows:
            if row["suite"] not in names:
                names.append(row["suite"])
        return names

    def provenance(self, suite):
        rows = [row for row in self.rows if row["suite"] == suite]
        dates = sorted({row["date"] for row in rows})
        machines = []
        for row in rows:
            if row["machine"] not in machines:
                machines.append(row["machine"])
        loads = [row["value"] for row in rows if row["metric"] == "loadavg_1min_before"]
        text = f"Measured {', '.join(dates)} on {'; '.join(machines)}"
        if loads:
            text += f" (load average before the run: {', '.join(loads)})"
        return text + f"; `share/bench/{self.name}`, suite `{suite}`."

    def pivot(self, suite, label=lambda metric: metric, skip=lambda metric: False):
        """Cases in order, and for each a dict of column label -> list of (value, unit)."""
        cases, cells, columns = [], {}, []
        for row in self.rows:
            if row["suite"] != suite or row["case"] == "(machine)" or skip(row["metric"]):
                continue
            column = label(row["metric"])
            if column is None:
                continue
            if row["case"] not in cells:
                cases.append(row["case"])
                cells[row["case"]] = {}
            if column not in columns:
                columns.append(column)
            cells[row["case"]].setdefault(column, []).append((number(row["value"]), row["unit"]))
        return cases, columns, cells

    def ratios(self, suite):
        """(case, reference, ratios) of the metrics named ...ratio_to:<reference>."""
        found = []
        for row in self.rows:
            if row["suite"] == suite and "ratio_to:" in row["metric"]:
                prefix, reference = row["metric"].split("ratio_to:", 1)
                what = prefix.rstrip("_").replace("_", " ") or "time"
                found.append((row["case"], f"{what} against {reference}", fmt(number(row["value"])) + "x"))
        return found


# Column headings of the metrics of format_bench.py and osgglyphtrajbench (the CSV's own names
# otherwise, with their unit).
LABELS = {
    "frames_per_s": "frames/s",
    "random_over_in_order": "random jump / frame in order",
    "random_ms_each": "random jump, ms",
    "points_per_s": "points/s",
    "s": "seconds",
    "time_ratio_to_ply": "time / PLY's",
    "median_ms": "median, ms",
    "open_ms": "open, ms",
    "map_ms": "map, ms",
    "draw_ms": "draw, ms",
    "index_ms": "index, ms",
    "decode_ms": "decode, ms",
    "jump_minus_first_ms": "jump beyond decoding, ms",
    "scan_MB_per_s": "index scan, MB/s of text",
    "scan_file_MB_per_s": "index scan, MB/s of file",
    "ms_each": "ms each",
    "per_s": "per second",
    "per_cpu_s": "per CPU second",
    "MB_per_s": "MB/s",
    "MB_per_thread_cpu_s": "MB per thread CPU second",
    "late": "late",
    "draws": "pictures drawn",
    "cores_busy": "cores busy",
    "rate_to_min": "rate / the slower of drawing and decoding",
    "rate_to_serial": "rate / drawing then decoding",
    "pictures": "pictures",
    "data_MB": "frames' data, MB",
    "cache_budget_MB": "cache budget, MB",
    "peak_rss_opened_MB": "peak RSS after opening, MB",
    "peak_rss_MB": "peak RSS, MB",
    "max_rss_time_MB": "peak RSS by /usr/bin/time, MB",
    "pictures_per_s": "pictures/s",
    "open_s": "open, s",
    "speedup_to_mdanalysis": "speed / MDAnalysis's",
    "cpu_speedup_to_mdanalysis": "speed per CPU second / MDAnalysis's",
}


def heading(column, cells):
    if column in LABELS:
        return LABELS[column]
    unit = unit_of(cells, column)
    return f"{column} ({unit})" if unit else column


def cell(values):
    return ", ".join(fmt(value) for value, _ in values) if values else "-"


def unit_of(cells, column):
    for case in cells.values():
        for value, unit in case.get(column, []):
            if unit and unit != "x":
                return unit
    return ""


def suite_table(suites, suite, columns_wanted=None, label=lambda metric: metric):
    cases, columns, cells = suites.pivot(suite, label, skip=lambda metric: "ratio_to:" in metric or
                                         metric == "loadavg_1min_before")
    if columns_wanted:
        columns = [column for column in columns_wanted if column in columns]
    cases = [case for case in cases if any(column in cells[case] for column in columns)]
    filled = sum(1 for case in cases for column in columns if column in cells[case])
    if filled >= 0.6 * len(cases) * len(columns):
        header = ["case"] + [heading(column, cells) for column in columns]
        out = table(header, [[f"`{case}`"] + [cell(cells[case].get(column)) for column in columns]
                             for case in cases])
    else:  # mostly empty as a grid: a row per figure
        lines = []
        for case in cases:
            for index, column in enumerate(c for c in columns if c in cells[case]):
                lines.append([f"`{case}`" if index == 0 else "", heading(column, cells),
                              cell(cells[case][column])])
        out = table(["case", "figure", "value"], lines)
    found = suites.ratios(suite)
    if found:
        out += ["", "Ratios within the run:", ""]
        out += table(["case", "ratio", "value"], [[f"`{case}`", what, value] for case, what, value in found])
    return out


def formats():
    suites = Suites("format_results.csv")
    out = ["## Binary formats", ""]
    out.append("The binary readers (`FrameSource::readFrame`, through `osgglyphtrajbench decode`) against the "
               "Python readers on the same files: 256,000 atoms, 31 frames, files in the page cache, one reader "
               "thread each; medians over the rounds (`share/bench/format_bench.py`). `freed memory kept`: the "
               "reader run with the memory of freed frames kept by the allocator. See "
               "[formats.md](formats.md#speed).")
    for suite in suites.suites():
        out += ["", suites.provenance(suite), ""]
        cases, _, cells = suites.pivot(suite)

        def first(case, prefix):
            values = [value for metric, values in cells.get(case, {}).items() if metric.startswith(prefix)
                      for value in values]
            return values[0][0] if values else None

        files = []
        for case in cases:
            if ": " in case and case.split(": ", 1)[1] not in files:
                files.append(case.split(": ", 1)[1])
        lines, rest = [], []
        for name in files:
            ours, kept = f"osgGlyphs readFrame: {name}", f"osgGlyphs readFrame, freed memory kept: {name}"
            theirs = [case for case in cases if case.endswith(": " + name) and not case.startswith("osgGlyphs")
                      and "frames_per_s" in cells[case]]
            if theirs and ours in cells:
                reader = theirs[0].split(": ", 1)[0]
                lines.append([f"`{name}`", fmt(first(ours, "frames_per_s")), fmt(first(kept, "frames_per_s")),
                              ratio(first(ours, "random_over_in_order")), reader,
                              fmt(first(theirs[0], "frames_per_s")), fmt(first(theirs[0], "random_ms_each")),
                              ratio(first(ours, "speedup_to_"))])
            else:
                rest += [case for case in cases if case.endswith(": " + name)]
        out += table(["file", "osgGlyphs frames/s", "freed memory kept", "random jump / in order",
                      "Python reader", "its frames/s", "its random jump, ms", "osgGlyphs / Python"], lines)
        if rest:
            out += ["", "LAS: decoding a 20-million-point file, and `osgglyphconvert` converting it and the same "
                        "points as binary PLY:", ""]
            rows = []
            for case in rest:
                for metric, values in cells[case].items():
                    rows.append([f"`{case}`", LABELS.get(metric, metric), cell(values)])
            out += table(["case", "figure", "value"], rows)
    return out


TRAJECTORY_COLUMNS = {
    "open": ["median_ms", "open_ms", "map_ms", "draw_ms"],
    "last": ["frames", "median_ms", "index_ms", "decode_ms", "jump_minus_first_ms", "scan_MB_per_s",
             "scan_file_MB_per_s"],
    "decode": ["ms_each", "per_s", "MB_per_s", "MB_per_thread_cpu_s"],
    "play": ["per_s", "ms_each", "MB_per_s", "late", "draws", "cores_busy", "rate_to_min", "rate_to_serial"],
    "memory": ["frames", "pictures", "data_MB", "cache_budget_MB", "peak_rss_opened_MB", "peak_rss_MB",
               "max_rss_time_MB", "pictures_per_s"],
    "mdanalysis": ["frames", "open_s", "per_s", "per_cpu_s", "MB_per_s", "ms_each", "speedup_to_mdanalysis",
                   "cpu_speedup_to_mdanalysis"],
}

TRAJECTORY_SUITES = {
    "open": "Time to the first picture of a file: no index, an index being built at a lower priority "
            "(`scan niced`), an index kept from before.",
    "last": "Time to the last frame, on the first opening and with the index kept; the index scan's speed.",
    "decode": "`readFrame` over every frame, in order and at random, against the one-frame reader "
              "(`readPointFile`).",
    "play": "Playback against drawing alone and decoding alone; pictures interpolated (`showNow(k+0.5)`) "
            "against stored ones (`showNow(k)`).",
    "memory": "Peak memory playing every frame once, one process a file, two rounds (each cell: round 1, "
              "round 2).",
    "mdanalysis": "The same dump read by MDAnalysis (`share/bench/mdanalysis_bench.py`).",
}


def trajectories():
    suites = Suites("trajectory_results.csv")
    out = ["## Trajectories", ""]
    out.append("A LAMMPS Lennard-Jones melt of 256,000 atoms, 31 frames (470 MB of text), plain, `.gz` and "
               "`.zst`; the same five times over (155 frames); and its frame 0 alone "
               "(`share/bench/trajectory_bench.sh`, `osgglyphtrajbench`). Cases alternate round by round: "
               "compare ratios within a run. See [trajectories.md](trajectories.md#measured).")
    for suite in suites.suites():
        out += ["", f"### {suite}", ""]
        if suite in TRAJECTORY_SUITES:
            out += [TRAJECTORY_SUITES[suite], ""]
        out += [suites.provenance(suite), ""]
        out += suite_table(suites, suite, TRAJECTORY_COLUMNS.get(suite))
    return out


def page():
    out = ["# Results", "",
           "<!-- Written by share/bench/results-page.py from the CSVs in share/bench/: edit those, and run it "
           "again. -->", "",
           "The current figures of the committed benchmark runs. No GPU has run the benchmarks yet: every "
           "figure so far is Mesa's llvmpipe software renderer's "
           "([headless-and-clusters.md](headless-and-clusters.md#gpu-figures)), and on a GPU the ratios differ "
           "([impostors](design/impostors.md#why-the-geometry-shader-is-the-default)). Frame times on a shared "
           "machine swing by 20-50% from run to run: compare figures within one table. How to run the "
           "benchmarks: [user guide](user-guide.md#benchmarks).", "",
           "Figures measured by hand and kept in no CSV (the tile converter, viewing paged archives, "
           "compositing over MPI, per-glyph ambient occlusion, screen effects, transparency) are not on this "
           "page; the last of them are in the README of commit 860f475 (`git show 860f475:README.md`).", ""]
    for section in (paper_comparison, dense_series, dense_shapes, formats, trajectories):
        out += section()
        out.append("")
    return "\n".join(out).rstrip("\n") + "\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--check", action="store_true", help="exit 1 when the page differs from the CSVs'")
    parser.add_argument("--output", default=PAGE, help="where to write the page (default docs/results.md)")
    arguments = parser.parse_args()
    text = page()
    if arguments.check:
        try:
            with open(arguments.output) as stream:
                current = stream.read()
        except OSError as error:
            print(f"results-page.py: {error}", file=sys.stderr)
            return 1
        if current != text:
            print(f"results-page.py: {os.path.relpath(arguments.output)} is not what the CSVs give: run "
                  "/usr/bin/python3 share/bench/results-page.py", file=sys.stderr)
            return 1
        return 0
    with open(arguments.output, "w") as stream:
        stream.write(text)
    print(f"results-page.py: wrote {os.path.relpath(arguments.output)}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
