"""Shape_Class and Curvature_Trusted on the shared accuracy suite.

The suite is generated as Study/suite_study.py says; then, with the build's
Python package on PYTHONPATH:

    /usr/bin/python3 Study/shape_class_suite.py SUITE [--sizes 20000,200000] [--noise 0,0.1,0.5]

For every cloud, with the suite's exact and PCA(30) normals and with the
filter's own normals, at the suite's evaluation points: the share of points
whose Shape_Class is the class of their exact curvatures, among the points
away from class boundaries (each exact curvature either zero, as along a
cylinder's axis, or at least a tenth of the shape's largest |k|), and the
share of valid points that are trusted (Curvature_Trusted), with how many
trusted points are off by more than a fifth of the shape's largest |k|,
and how many by more than what trust promises (a third of the point's
largest exact |k|, or a tenth of Trusted_Curvature_Scale if more), and
the share the earlier, absolute rule trusted (twice the standard error
within a tenth of Trusted_Curvature_Scale).

With --plane N instead of a suite: the false features on a noisy plane of
N points (uniform on a square, spacing h = 1, noise 0.1 and 0.5 h), with
exact normals and with the filter's own: the share of the estimated points
not Flat (the border's points without an estimate left out).
"""

import argparse
import json
import math
import os
import sys

import numpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from suite_study import LARGEST_CURVATURE, load, polydata  # noqa: E402

from vtkmodules.util.numpy_support import vtk_to_numpy  # noqa: E402
from principal_curvatures import vtkPrincipalCurvatureEstimation  # noqa: E402

FLAT, DOME, CUP, RIDGE, VALLEY, SADDLE = 1, 2, 3, 4, 5, 6
NAMES = {FLAT: "flat", DOME: "dome", CUP: "cup", RIDGE: "ridge", VALLEY: "valley", SADDLE: "saddle"}


def exact_classes(kmin, kmax, largest):
    """The class of the exact curvatures, and whether the point is away from
    a class boundary (-1 where it is not)."""
    zero = 1e-9 * largest
    near = 0.1 * largest
    far_min = (numpy.abs(kmin) <= zero) | (numpy.abs(kmin) >= near)
    far_max = (numpy.abs(kmax) <= zero) | (numpy.abs(kmax) >= near)
    up_max, down_min = kmax > zero, kmin < -zero
    classes = numpy.full(kmin.shape, FLAT)
    classes[up_max & ~down_min] = RIDGE
    classes[down_min & ~up_max] = VALLEY
    classes[up_max & down_min] = SADDLE
    classes[kmin > zero] = DOME
    classes[kmax < -zero] = CUP
    classes[~(far_min & far_max)] = -1
    return classes


def run(data, with_normals):
    curvatures = vtkPrincipalCurvatureEstimation()
    curvatures.GlobalWarningDisplayOff()
    curvatures.SetInputData(polydata(data, with_normals))
    if not with_normals:
        curvatures.SetNormalsSourceToEstimated()
    curvatures.Update()
    output = curvatures.GetOutput()
    pd = output.GetPointData()
    get = lambda name: vtk_to_numpy(pd.GetArray(name))  # noqa: E731
    arrays = {name: get(name) for name in ("Shape_Class", "Curvature_Trusted", "Curvature_Valid",
                                           "Minimum_Curvature", "Maximum_Curvature",
                                           "Curvature_Standard_Error")}
    arrays["scale"] = output.GetFieldData().GetArray("Trusted_Curvature_Scale").GetValue(0)
    return arrays


def plane(count):
    side = math.sqrt(count)
    generator = numpy.random.default_rng(11)
    clean = numpy.column_stack([generator.uniform(0.0, side, (count, 2)), numpy.zeros(count)])
    normals = numpy.tile([0.0, 0.0, 1.0], (count, 1))
    print("| points | noise | normals | estimated, not flat | of which | trusted |")
    print("|---|---|---|---|---|---|")
    for noise in (0.1, 0.5):
        data = numpy.hstack([clean + generator.normal(0.0, noise, clean.shape), normals])
        for normals_kind in ("exact", "own"):
            out = run(data, normals_kind == "exact")
            shape = out["Shape_Class"][out["Curvature_Valid"] == 1]
            kinds = {NAMES[k]: int(numpy.sum(shape == k)) for k in NAMES if k != FLAT}
            print("| %d | %g h | %s | %.4f %% | %s | %.1f %% |" % (
                count, noise, normals_kind, 100.0 * numpy.mean(shape != FLAT),
                ", ".join("%s %d" % item for item in kinds.items() if item[1]) or "-",
                100.0 * numpy.mean(out["Curvature_Trusted"] == 1)), flush=True)


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("suite", nargs="?")
    parser.add_argument("--plane", type=int, help="a noisy plane of this many points instead")
    parser.add_argument("--sizes", default="20000,200000")
    parser.add_argument("--noise", default="0,0.1,0.5")
    parser.add_argument("--normals", default="exact,PCA,own")
    arguments = parser.parse_args(argv)
    if arguments.plane:
        plane(arguments.plane)
        return
    meta = json.load(open(os.path.join(arguments.suite, "meta.json")))
    sizes = [int(s) for s in arguments.sizes.split(",")]
    noises = [float(v) for v in arguments.noise.split(",")]
    print("| shape | points | noise | normals | expected | right (away from boundaries) | evaluated "
          "| trusted | trusted off > 20 % of largest | trusted beyond their promise | trusted, absolute rule |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for cloud in meta["clouds"]:
        if cloud["N"] not in sizes or cloud["noise"] not in noises or cloud["name"].endswith("_pca30"):
            continue
        largest = LARGEST_CURVATURE[cloud["shape"]]
        for normals in arguments.normals.split(","):
            data, evaluation = load(arguments.suite, cloud, "PCA" if normals == "PCA" else "exact")
            out = run(data, normals != "own")
            kmin, kmax = data[evaluation, 6], data[evaluation, 7]
            expected = exact_classes(kmin, kmax, largest)
            got = out["Shape_Class"][evaluation]
            away = expected >= 0
            right = numpy.mean(got[away] == expected[away]) if away.any() else float("nan")
            valid = out["Curvature_Valid"][evaluation] == 1
            trusted = out["Curvature_Trusted"][evaluation] == 1
            error = numpy.maximum(numpy.abs(out["Minimum_Curvature"][evaluation] - kmin),
                                  numpy.abs(out["Maximum_Curvature"][evaluation] - kmax))
            far_trusted = int(numpy.sum(trusted & (error > 0.2 * largest)))
            bound = numpy.maximum(numpy.maximum(numpy.abs(kmin), numpy.abs(kmax)) / 3.0, 0.1 * out["scale"])
            beyond = int(numpy.sum(trusted & (error > bound)))
            absolute = valid & (2.0 * out["Curvature_Standard_Error"][evaluation] <= 0.1 * out["scale"])
            kinds = sorted(set(expected[away].tolist()))
            print("| %s | %d | %g h | %s | %s | %.1f %% | %d | %.1f %% | %d | %d | %.1f %% |" % (
                cloud["shape"], cloud["N"], cloud["noise"], normals, "/".join(NAMES[k] for k in kinds),
                100 * right, int(away.sum()), 100 * trusted[valid].mean() if valid.any() else 0.0,
                far_trusted, beyond, 100 * absolute[valid].mean() if valid.any() else 0.0), flush=True)


if __name__ == "__main__":
    main(sys.argv[1:])
