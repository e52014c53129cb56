"""Normals and curvature signs on a classified airborne scan.

    pvpython Study/airborne_orientation.py PLUGIN.so SCAN [--class-array NAME] [--ground CODE]

SCAN is any cloud the plugin reads (.las, .ply, ...) with a per-point class:
`Classification` with ground 2 for LAS (the default), or e.g. `label` with
ground 0 for CGAL's b9_training.ply. The curvature filter runs with its
defaults (normals estimated). Printed, per class and for the points more than
2 and 5 length units above their nearest ground point (horizontally): the
share of normals pointing down, of positive mean curvature, and, among the
points whose Shape_Class is not Flat or Undetermined, of positive mean
curvature and of the convex classes (Dome, Ridge). On an airborne scan the
normals should point up, towards the sensor, and what stands above the ground
(crowns, roof crests) bend away from them.
"""

import argparse
import sys

import numpy
from paraview import servermanager, simple
from scipy.spatial import cKDTree
from vtkmodules.util.numpy_support import vtk_to_numpy

DOME, RIDGE = 2, 4  # pcurv::ShapeClass codes (Shape_Class_Names)


def arguments():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("plugin")
    parser.add_argument("scan")
    parser.add_argument("--class-array", default="Classification")
    parser.add_argument("--ground", type=int, default=2)
    return parser.parse_args()


def share(mask):
    return 100.0 * mask.mean() if mask.size else float("nan")


def main():
    args = arguments()
    simple.LoadPlugin(args.plugin, remote=False, ns=globals())
    source = simple.OpenDataFile(args.scan)
    source.UpdatePipeline()
    curvatures = PrincipalCurvatures(Input=source)  # noqa: F821 (from the plugin)
    curvatures.UpdatePipeline()
    output = servermanager.Fetch(curvatures)
    data = output.GetPointData()
    points = vtk_to_numpy(output.GetPoints().GetData())
    normals = vtk_to_numpy(data.GetArray("Normals"))
    mean = vtk_to_numpy(data.GetArray("Mean_Curvature"))
    shape = vtk_to_numpy(data.GetArray("Shape_Class"))
    classes = vtk_to_numpy(data.GetArray(args.class_array))
    down = normals[:, 2] < 0.0
    print("%d points; per class: points, down %%, H > 0 %%" % len(points))
    for code in numpy.unique(classes):
        m = classes == code
        print("  %s %4d: %7d  %5.1f  %5.1f" % (args.class_array, code, m.sum(), share(down[m]), share(mean[m] > 0)))
    ground = classes == args.ground
    if not ground.any():
        return 0
    nearest = cKDTree(points[ground, :2]).query(points[:, :2])[1]
    height = points[:, 2] - points[ground][nearest, 2]
    curved = shape >= DOME
    for above in (2.0, 5.0):
        m = (height > above) & ~ground
        c = m & curved
        print("more than %g above ground: %d points, down %.1f %%, H > 0 %.1f %%; "
              "%d curved: H > 0 %.1f %%, Dome or Ridge %.1f %%" % (
                  above, m.sum(), share(down[m]), share(mean[m] > 0), c.sum(),
                  share(mean[c] > 0), share(numpy.isin(shape[c], [DOME, RIDGE]))))
    return 0


if __name__ == "__main__":
    sys.exit(main())
