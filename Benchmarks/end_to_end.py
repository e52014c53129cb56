"""End to end on a noisy scan without normals, a program, not a test:
binary .ply in, normals estimated, curvatures (the defaults), .vtp out in
single precision. Prints the seconds of each stage and the process's peak
resident size after it, in bytes per point (and above the peak before
reading: pvpython itself takes about 270 MB).

    pvpython Benchmarks/end_to_end.py make N scan.ply   # a noisy torus, x y z double
    pvpython Benchmarks/end_to_end.py run scan.ply out.vtp [--threads T] [--stages]

`run` reads with the plugin's PLY reader and runs one filter that estimates
the normals and the curvatures (what a user's run does); with --stages, the
normals filter and the curvature filter run one after the other, so that
each stage's time shows (their outputs both stay in memory: the peak is then
not the user's). Run each size in its own process: the peak is per process.

Needs the wrapped Python package on PYTHONPATH (the build's
lib/python3.X/site-packages).
"""

import argparse
import math
import resource
import sys
import time

import numpy

from dense_patch import MAJOR, MINOR, torus_points, uniform_torus_angles


def make(points, path, noise=0.1, seed=5):
    """A torus (R 3, r 1) uniform in area with Gaussian position noise of
    `noise` point spacings, written as binary little-endian PLY (double x y
    z, no normals), in blocks so that the generator's memory stays small."""
    generator = numpy.random.default_rng(seed)
    spacing = math.sqrt(4.0 * math.pi ** 2 * MAJOR * MINOR / points)
    with open(path, "wb") as handle:
        handle.write(("ply\nformat binary_little_endian 1.0\nelement vertex %d\n"
                      "property double x\nproperty double y\nproperty double z\nend_header\n"
                      % points).encode("ascii"))
        written = 0
        while written < points:
            block = min(1000000, points - written)
            xyz = torus_points(*uniform_torus_angles(generator, block))[0]
            xyz += generator.normal(0.0, noise * spacing, xyz.shape)
            handle.write(numpy.ascontiguousarray(xyz, dtype="<f8").tobytes())
            written += block


def peak_bytes():
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024.0


def run(path, output, threads, stages):
    from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter
    from principal_curvatures import (vtkPLYPointCloudReader, vtkPointCloudNormalEstimation,
                                      vtkPrincipalCurvatureEstimation)

    rows = []
    start_peak = peak_bytes()

    def stage(name, action):
        began = time.perf_counter()
        result = action()
        rows.append((name, time.perf_counter() - began, peak_bytes()))
        return result

    reader = vtkPLYPointCloudReader()
    reader.SetFileName(path)
    stage("read", reader.Update)
    points = reader.GetOutput().GetNumberOfPoints()
    source = reader
    curvatures = vtkPrincipalCurvatureEstimation()
    curvatures.SetNumberOfThreads(threads)
    curvatures.SetSinglePrecisionOutput(True)
    if stages:
        normals = vtkPointCloudNormalEstimation()
        normals.SetNumberOfThreads(threads)
        normals.SetInputConnection(reader.GetOutputPort())
        stage("normals", normals.Update)
        source = normals
    else:
        curvatures.SetNormalsSourceToEstimated()
    curvatures.SetInputConnection(source.GetOutputPort())
    stage("curvatures" if stages else "normals + curvatures", curvatures.Update)
    writer = vtkXMLPolyDataWriter()
    writer.SetInputConnection(curvatures.GetOutputPort())
    writer.SetFileName(output)
    writer.SetDataModeToBinary()  # inline: appended data is unreadable with Debian 12's libexpat
    writer.SetCompressorTypeToNone()
    stage("write", writer.Write)
    print("%d points, %s, %d threads; peak before reading %.0f MB" % (
        points, "separate stages" if stages else "one filter", threads, start_peak / 1e6))
    print("| stage | seconds | peak after it, bytes per point (above the start) |")
    print("|---|---|---|")
    for name, seconds, peak in rows:
        print("| %s | %.2f | %.0f (%.0f) |" % (name, seconds, peak / points, (peak - start_peak) / points))
    print("| total | %.2f | |" % sum(r[1] for r in rows))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    sub = parser.add_subparsers(dest="action", required=True)
    made = sub.add_parser("make")
    made.add_argument("points", type=int)
    made.add_argument("path")
    made.add_argument("--noise", type=float, default=0.1, help="in point spacings")
    ran = sub.add_parser("run")
    ran.add_argument("path")
    ran.add_argument("output")
    ran.add_argument("--threads", type=int, default=0)
    ran.add_argument("--stages", action="store_true")
    arguments = parser.parse_args()
    if arguments.action == "make":
        make(arguments.points, arguments.path, arguments.noise)
    else:
        run(arguments.path, arguments.output, arguments.threads, arguments.stages)
    return 0


if __name__ == "__main__":
    sys.exit(main())
