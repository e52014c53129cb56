"""What the default (OrientedCircles with the automatic neighborhood) costs
against the paper's fit at its fixed scale (New01, the radius holding 375
neighbors, p = 0.1 s: the default until 2026-12-01), a program, not a test.

A torus (R 3, r 1) uniform in area, exact normals (the benchmark's cloud),
with position noise 0, 0.1 and 0.5 point spacings h = sqrt(area / N). Every
(noise, setting, threads) is run RUNS times, interleaved in one process so
that a slow phase of a shared machine does not fall on one of them; prints
the medians, the default's time over the paper fit's, the mean neighbor
count and the mean |k - exact| of each.

    pvpython Benchmarks/default_cost.py [--points 1000000] [--runs 3]
        [--threads 1,2] [--noise 0,0.1,0.5] [--estimate-normals]

Needs the wrapped Python package on PYTHONPATH (the build's
lib/python3.X/site-packages).
"""

import argparse
import math
import statistics

import numpy
from vtkmodules.util.numpy_support import vtk_to_numpy

from dense_patch import MAJOR, MINOR, cloud_of, torus_points, uniform_torus_angles
from dense_patch import run as timed_run

SETTINGS = ("paper: New01, 375", "default")


def torus(points, noise, seed=11):
    """The cloud with exact normals and curvatures (outward normals: the
    filter's sign, k = 1 around the tube)."""
    generator = numpy.random.default_rng(seed)
    xyz, normals, kmin, kmax = torus_points(*uniform_torus_angles(generator, points))
    spacing = math.sqrt(4.0 * math.pi ** 2 * MAJOR * MINOR / points)
    xyz += generator.normal(0.0, noise * spacing, xyz.shape)
    return cloud_of(xyz, normals), kmin, kmax


def run(data, setting, threads, estimate_normals):
    # The paper's fit: New01 at the radius holding 375 neighbors.
    return timed_run(data, threads, estimate_normals, None if setting == "default" else 1)


def quality(output, kmin, kmax):
    data = output.GetPointData()
    valid = vtk_to_numpy(data.GetArray("Curvature_Valid")).astype(bool)
    low = vtk_to_numpy(data.GetArray("Minimum_Curvature"))[valid]
    high = vtk_to_numpy(data.GetArray("Maximum_Curvature"))[valid]
    error = max(numpy.abs(low - kmin[valid]).mean(), numpy.abs(high - kmax[valid]).mean())
    neighbors = vtk_to_numpy(data.GetArray("Neighbor_Count"))[valid].mean()
    return error, neighbors, 1.0 - valid.mean()


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--points", type=int, default=1000000)
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--threads", default="1,2")
    parser.add_argument("--noise", default="0,0.1,0.5")
    parser.add_argument("--estimate-normals", action="store_true")
    arguments = parser.parse_args()
    threads = [int(t) for t in arguments.threads.split(",")]
    print("| noise | threads | paper: New01, 375 | default | default / paper | neighbors (paper, default) "
          "| mean abs error (paper, default) |")
    print("|---|---|---|---|---|---|---|")
    for noise in [float(n) for n in arguments.noise.split(",")]:
        data, kmin, kmax = torus(arguments.points, noise)
        times = {(s, t): [] for s in SETTINGS for t in threads}
        measured = {}
        for _ in range(arguments.runs):
            for t in threads:
                for setting in SETTINGS:
                    seconds, output = run(data, setting, t, arguments.estimate_normals)
                    times[(setting, t)].append(seconds)
                    if setting not in measured:
                        measured[setting] = quality(output, kmin, kmax)
        for t in threads:
            paper = statistics.median(times[(SETTINGS[0], t)])
            default = statistics.median(times[(SETTINGS[1], t)])
            print("| %g h | %d | %.2f s | %.2f s | %.2fx | %.0f, %.0f | %.4f, %.4f |" % (
                noise, t, paper, default, default / paper, measured[SETTINGS[0]][1],
                measured[SETTINGS[1]][1], measured[SETTINGS[0]][0], measured[SETTINGS[1]][0]), flush=True)


if __name__ == "__main__":
    main()
