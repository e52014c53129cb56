"""Plot of the benchmark's CSV: filter time against cloud size, per fit mode
and thread count, with CGAL's jet fitting (extrapolated, 1 thread).

    python3 Benchmarks/plot_benchmark.py benchmark.csv Benchmarks/benchmark.png
"""

import csv
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main(source, picture):
    series = defaultdict(list)
    with open(source) as handle:
        for row in csv.DictReader(handle):
            if row["kind"] == "filter":
                series["%s, %s thread(s)" % (row["mode"], row["threads"])].append(
                    (int(row["points"]), float(row["seconds"])))
            elif row["kind"] == "peer":
                series["CGAL jet fitting, 1 thread"].append((int(row["points"]), float(row["seconds"])))
    figure, axes = plt.subplots(figsize=(7, 5))
    for label, points in sorted(series.items()):
        points.sort()
        style = "k--" if label.startswith("CGAL") else ("-" if "2 thread" in label else ":")
        axes.loglog([p[0] for p in points], [p[1] for p in points], style, marker="o", label=label)
    sizes = sorted({p[0] for points in series.values() for p in points})
    if sizes:
        axes.loglog(sizes, [1.5e-6 * n for n in sizes], color="grey", linewidth=0.8,
                    label="target: 1.5 s per 1M points")
    axes.set_xlabel("points (torus, about 375 neighbours each)")
    axes.set_ylabel("wall time of the filter (s, median)")
    axes.set_title("vtkPrincipalCurvatureEstimation, 2-core machine")
    axes.grid(True, which="both", alpha=0.3)
    axes.legend(fontsize=8)
    figure.tight_layout()
    figure.savefig(picture, dpi=110)
    print("wrote %s" % picture)


if __name__ == "__main__":
    main(*sys.argv[1:3])
