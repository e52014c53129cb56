"""The cost of a locally very dense cloud (a program, not a test): a
100,000-point torus (R 3, r 1), alone and with 20,000 more points on a
0.16 x 0.04 piece of it (about 3,700 times denser, as a terrestrial scan is
near its scanner), exact normals, the filter's defaults. Prints the median
time of each over RUNS runs, measured alternately in one process, their
ratio (the target is at most 2), and the mean curvature error on the patch.

    pvpython Benchmarks/dense_patch.py [RUNS] [THREADS] [--estimate-normals]

With --estimate-normals the normals are estimated (a scan without normals)
instead of given exactly.

Needs the wrapped Python package on PYTHONPATH (the build's
lib/python3.X/site-packages).
"""

import statistics
import sys
import time

import numpy
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkPolyData

from principal_curvatures import vtkPrincipalCurvatureEstimation

MAJOR, MINOR = 3.0, 1.0


def uniform_torus_angles(generator, count):
    """The angles u, v of `count` points uniform in the torus' area: v by
    rejection on the ring's length."""
    u = numpy.empty(0)
    v = numpy.empty(0)
    while len(u) < count:
        uu = generator.uniform(0.0, 2.0 * numpy.pi, count)
        vv = generator.uniform(0.0, 2.0 * numpy.pi, count)
        keep = generator.uniform(0.0, MAJOR + MINOR, count) < MAJOR + MINOR * numpy.cos(vv)
        u, v = numpy.concatenate([u, uu[keep]]), numpy.concatenate([v, vv[keep]])
    return u[:count], v[:count]


def torus_points(u, v):
    ring = MAJOR + MINOR * numpy.cos(v)
    points = numpy.column_stack([ring * numpy.cos(u), ring * numpy.sin(u), MINOR * numpy.sin(v)])
    normals = numpy.column_stack([numpy.cos(v) * numpy.cos(u), numpy.cos(v) * numpy.sin(u), numpy.sin(v)])
    # Exact principal curvatures with outward normals (vtkCurvatures' sign).
    tube = numpy.full(len(u), 1.0 / MINOR)
    around = numpy.cos(v) / ring
    return points, normals, numpy.minimum(tube, around), numpy.maximum(tube, around)


def cloud_of(points, normals):
    """A vtkPolyData of the points, with the normals as its Normals."""
    data = vtkPolyData()
    vtk_points = vtkPoints()
    vtk_points.SetData(numpy_to_vtk(points, deep=True))
    data.SetPoints(vtk_points)
    array = numpy_to_vtk(normals, deep=True)
    array.SetName("Normals")
    data.GetPointData().SetNormals(array)
    return data


def cloud(with_patch, seed=7):
    generator = numpy.random.default_rng(seed)
    # Uniform in area: v by rejection on the ring's length.
    u = generator.uniform(0.0, 2.0 * numpy.pi, 400000)
    v = generator.uniform(0.0, 2.0 * numpy.pi, 400000)
    keep = generator.uniform(0.0, MAJOR + MINOR, 400000) < MAJOR + MINOR * numpy.cos(v)
    u, v = u[keep][:100000], v[keep][:100000]
    patch = numpy.zeros(len(u), dtype=bool)
    if with_patch:
        # 0.16 x 0.04 (arc lengths) on the outer equator, where the ring is R + r.
        pu = generator.uniform(0.0, 0.16 / (MAJOR + MINOR), 20000)
        pv = generator.uniform(0.0, 0.04 / MINOR, 20000)
        u, v = numpy.concatenate([u, pu]), numpy.concatenate([v, pv])
        patch = numpy.concatenate([patch, numpy.ones(20000, dtype=bool)])
    points, normals, kmin, kmax = torus_points(u, v)
    return cloud_of(points, normals), patch, kmin, kmax


def run(data, threads, estimate, fit_mode=None):
    """Seconds of one Update (the defaults, or `fit_mode`), and the output."""
    curvatures = vtkPrincipalCurvatureEstimation()
    curvatures.SetInputData(data)
    curvatures.SetNumberOfThreads(threads)
    if fit_mode is not None:
        curvatures.SetFitMode(fit_mode)
    if estimate:
        curvatures.SetNormalsSourceToEstimated()
    start = time.perf_counter()
    curvatures.Update()
    return time.perf_counter() - start, curvatures.GetOutput()


def main(runs, threads, estimate):
    alone, _, _, _ = cloud(False)
    patched, patch, kmin, kmax = cloud(True)
    times = {"alone": [], "with patch": []}
    for _ in range(runs):
        times["alone"].append(run(alone, threads, estimate)[0])
        seconds, output = run(patched, threads, estimate)
        times["with patch"].append(seconds)
    for name, values in times.items():
        print("%-12s median %.3f s (%s)" % (name, statistics.median(values), " ".join("%.3f" % t for t in values)))
    ratio = statistics.median(times["with patch"]) / statistics.median(times["alone"])
    print("ratio        %.2f (target: at most 2)" % ratio)
    data = output.GetPointData()
    valid = vtk_to_numpy(data.GetArray("Curvature_Valid")).astype(bool)
    low = vtk_to_numpy(data.GetArray("Minimum_Curvature"))
    high = vtk_to_numpy(data.GetArray("Maximum_Curvature"))
    for name, where in (("patch", patch), ("elsewhere", ~patch)):
        ok = where & valid
        error = max(numpy.abs(low[ok] - kmin[ok]).mean(), numpy.abs(high[ok] - kmax[ok]).mean())
        print("%-12s %d of %d estimated, mean |k - exact| %.4f (1/length; k_max = 1)" % (
            name, ok.sum(), where.sum(), error))


if __name__ == "__main__":
    numbers = [int(a) for a in sys.argv[1:] if not a.startswith("--")]
    main(numbers[0] if numbers else 3, numbers[1] if len(numbers) > 1 else 0, "--estimate-normals" in sys.argv)
