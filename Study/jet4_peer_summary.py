"""Tables for REPORT.md's "Peer: jet fitting of degree 4 (CGAL), at its best k".

    /usr/bin/python3 Study/jet4_peer_summary.py Study/jet4_peer.csv ../shared/accuracy/peers.csv \
        [--default SUITE_STUDY.csv]

Reads JetPeerStudy's rows (method cgal_jet4), the suite's peers.csv (its
cgal_jet2 rows; jet fitting uses positions only, so its "exact" rows stand
for both kinds of normals) and, optionally, Study/suite_study.py's --csv
output for the default (setting "default"). A method's best per cloud is its
lowest max(rel_err_kmin, rel_err_kmax) over its k; medians are over the six
shapes (the middle two averaged; angles over the shapes that have one: the
sphere has no maximum direction). Prints the group table and, per cloud,
jet4's best against jet2's and against the default.
"""

import argparse
import csv
import math
import statistics


def best_per_cloud(path, method):
    """(shape, N, noise, normals) -> (error, angle, k, seconds per 1M per core)."""
    best = {}
    with open(path) as handle:
        for row in csv.DictReader(handle):
            if row["method"] != method:
                continue
            key = (row["shape"], int(row["N"]), float(row["noise_x_h"]), row["normals"])
            error = max(float(row["rel_err_kmin"]), float(row["rel_err_kmax"]))
            if key not in best or error < best[key][0]:
                best[key] = (error, float(row["median_angle_kmax_deg"]), int(row["k"]),
                             float(row["t_total_s_per_1M"]))
    return best


def default_per_cloud(path):
    result = {}
    with open(path) as handle:
        for row in csv.DictReader(handle):
            if row["setting"] != "default":
                continue
            key = (row["shape"], int(row["N"]), float(row["noise"]), row["normals"])
            result[key] = (float(row["error"]), float(row["angle"]))
    return result


def median(values):
    values = [v for v in values if not math.isnan(v)]
    return statistics.median(values) if values else math.nan


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("jet4")
    parser.add_argument("peers")
    parser.add_argument("--default", help="suite_study.py --csv output with the default setting")
    arguments = parser.parse_args()
    jet4 = best_per_cloud(arguments.jet4, "cgal_jet4")
    jet2 = best_per_cloud(arguments.peers, "cgal_jet2")
    default = default_per_cloud(arguments.default) if arguments.default else {}

    groups = sorted({(n, noise, normals) for (_, n, noise, normals) in jet4},
                    key=lambda g: (g[0], g[1], g[2] != "PCA"))
    print("| points | noise | normals | jet4 best | jet4 angle | jet4 k (range) | jet2 best | jet2 angle "
          "| default | default angle | jet4 s per 1M |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for n, noise, normals in groups:
        shapes = sorted(s for (s, n2, x, m) in jet4 if (n2, x, m) == (n, noise, normals))
        j4 = [jet4[(s, n, noise, normals)] for s in shapes]
        j2 = [jet2[(s, n, noise, "exact")] for s in shapes if (s, n, noise, "exact") in jet2]
        d = [default[(s, n, noise, normals)] for s in shapes if (s, n, noise, normals) in default]
        ks = [b[2] for b in j4]
        row = ["%dk" % (n // 1000), "0" if noise == 0 else "%g h" % noise, normals,
               "%.3g" % median([b[0] for b in j4]), "%.3f" % median([b[1] for b in j4]),
               "%d-%d" % (min(ks), max(ks)),
               "%.3g" % median([b[0] for b in j2]) if j2 else "", "%.3f" % median([b[1] for b in j2]) if j2 else "",
               "%.3g" % median([b[0] for b in d]) if d else "", "%.3f" % median([b[1] for b in d]) if d else "",
               "%.0f" % median([b[3] for b in j4])]
        print("| " + " | ".join(row) + " |")

    print("\nper cloud: shape, N, noise, normals, jet4 best (k), jet2 best, jet4/jet2, default, default/jet4")
    for key in sorted(jet4, key=lambda k: (k[1], k[2], k[3], k[0])):
        shape, n, noise, normals = key
        e4, a4, k4, _ = jet4[key]
        e2 = jet2.get((shape, n, noise, "exact"), (math.nan,))[0]
        ed = default.get(key, (math.nan,))[0]
        mark = "  <- jet4 beats the default" if ed > e4 else ""
        print("%-10s %6d %3g %-5s %.3g (%4d) %.3g %5.2f %.3g %6.2f%s"
              % (shape, n, noise, normals, e4, k4, e2, e4 / e2, ed, ed / e4, mark))


if __name__ == "__main__":
    main()
