#!/usr/bin/env python3
"""Plot the CSV of PrincipalCurvatureBenchmark (--csv FILE) as a PNG.

Left: wall time of the whole filter against the number of points, log-log,
one line per fit mode and thread count, with CGAL's jet fitting (one core,
extrapolated from its query points) and the target (1M points in 1.5 s).
Right: where one thread's time goes, per fit mode, at the largest size with
phase timings.

    python3 Benchmarks/plot_benchmark.py benchmark.csv Benchmarks/benchmark.png

Needs matplotlib (Debian: apt-get install python3-matplotlib).
"""

import argparse
import csv
import math
import sys
from collections import defaultdict

try:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError:  # pragma: no cover - depends on the machine
    sys.exit("matplotlib is needed: apt-get install python3-matplotlib, and run Debian's "
             "/usr/bin/python3")

MODES = ["Previous", "New01", "New02"]
COLORS = {"Previous": "tab:red", "New01": "tab:blue", "New02": "tab:green"}
PHASES = [
    ("grid_build_seconds", "grid build"),
    ("search_seconds", "neighbor search"),
    ("binning_sums_seconds", "half planes + sums"),
    ("fits_seconds", "circle fits"),
    ("sine_seconds", "sine fit"),
    ("rest_seconds", "rest (arrays, radius, output)"),
]


def read(path):
    rows = []
    with open(path, newline="") as handle:
        for row in csv.DictReader(handle):
            try:
                row["value"] = float(row["value"])
                row["points"] = int(row["points"])
                row["threads"] = int(row["threads"])
            except ValueError:
                continue
            if math.isfinite(row["value"]):
                rows.append(row)
    return rows


def plot_times(axes, rows):
    series = defaultdict(list)
    for row in rows:
        if row["section"] == "filter" and row["metric"] == "seconds":
            series[(row["mode"], row["threads"])].append((row["points"], row["value"]))
    threads = sorted({key[1] for key in series})
    styles = ["-", "--", ":", "-."]
    for (mode, count), points in sorted(series.items(), key=lambda kv: (MODES.index(kv[0][0])
                                                                       if kv[0][0] in MODES else 9,
                                                                       kv[0][1])):
        points.sort()
        axes.loglog([p[0] for p in points], [p[1] for p in points],
                    linestyle=styles[threads.index(count) % len(styles)], marker="o",
                    color=COLORS.get(mode, "gray"),
                    label="%s, %d thread%s" % (mode, count, "" if count == 1 else "s"))
    peer = sorted((row["points"], row["value"]) for row in rows
                  if row["section"] == "peer" and row["mode"] == "CGAL"
                  and row["metric"] == "seconds")
    if peer:
        axes.loglog([p[0] for p in peer], [p[1] for p in peer], "k-.", marker="s",
                    label="CGAL jet fitting, 1 core (extrapolated)")
    sizes = sorted({p[0] for points in series.values() for p in points})
    if sizes:
        axes.loglog(sizes, [1.5e-6 * n for n in sizes], color="gray", linewidth=0.8,
                    label="target: 1.5 s per 1M points (linear)")
        axes.plot([1e6], [1.5], marker="*", markersize=14, color="gold",
                  markeredgecolor="black", linestyle="none", label="target: 1M New01, 2 threads")
    axes.set_xlabel("points (%s)" % (rows[0]["surface"] if rows else "cloud"))
    axes.set_ylabel("wall time of Update() (s, median)")
    axes.set_title("Whole filter against cloud size")
    axes.grid(True, which="both", alpha=0.3)
    axes.legend(fontsize=7, loc="upper left")


def plot_phases(axes, rows):
    phases = defaultdict(dict)
    for row in rows:
        if row["section"] == "phase":
            phases[row["points"]].setdefault(row["mode"], {})[row["metric"]] = row["value"]
    if not phases:
        axes.set_axis_off()
        axes.text(0.5, 0.5, "no phase timings in the CSV", ha="center", va="center")
        return
    size = max(phases)
    modes = [mode for mode in MODES if mode in phases[size]]
    left = [0.0] * len(modes)
    colors = plt.get_cmap("tab10")
    for index, (metric, label) in enumerate(PHASES):
        values = [max(0.0, phases[size][mode].get(metric, 0.0)) for mode in modes]
        axes.barh(modes, values, left=left, color=colors(index), label=label)
        left = [a + b for a, b in zip(left, values)]
    axes.invert_yaxis()
    axes.set_xlabel("seconds, one thread, %s points" % format(size, ","))
    axes.set_title("Where the time goes (core on the filter's neighborhoods)")
    axes.grid(True, axis="x", alpha=0.3)
    axes.legend(fontsize=7, loc="lower right")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("csv", help="the benchmark's CSV (--csv FILE)")
    parser.add_argument("png", help="the picture to write")
    arguments = parser.parse_args()
    rows = read(arguments.csv)
    if not rows:
        sys.exit("no measurements in %s" % arguments.csv)
    figure, (times, phases) = plt.subplots(1, 2, figsize=(13, 5.5),
                                           gridspec_kw={"width_ratios": [1.15, 1]})
    plot_times(times, rows)
    plot_phases(phases, rows)
    figure.suptitle("vtkPrincipalCurvatureEstimation benchmark (medians)", fontsize=11)
    figure.tight_layout()
    figure.savefig(arguments.png, dpi=100)
    print("wrote %s" % arguments.png)


if __name__ == "__main__":
    main()
