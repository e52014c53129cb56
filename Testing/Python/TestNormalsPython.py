"""Clouds without normals through the plugin, as a new user has them:

    pvpython TestNormalsPython.py PLUGIN.so

* a sphere of radius 2 with points only: PrincipalCurvatures(Input=...) with
  defaults estimates the normals (output array Normals, outward), and gives
  k = +1/2 at every point; paraview.simple.Show shows it as points colored
  by Mean_Curvature_Clipped;
* the same sphere with colors (unsigned char RGB, a 3-component array):
  the Normals property neither offers nor picks it; chosen by hand, it is
  not used, the normals are estimated; with Normals Source 'Input Array' the
  filter fails and says how to estimate normals instead;
* Point Cloud Normals on the sphere: unit, outward, within a degree of the
  exact normals (median); towards a viewpoint inside: all inward;
* a sphere whose normals are all zero: an error of its own.

Every check prints one line; the exit code is 0 when all pass, 1 otherwise.
"""

import math
import sys

import numpy
from paraview import servermanager, simple
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkPolyData

from test_checks import check, failures  # noqa: E402 (the tests' folder is on sys.path)


def sphere(count=20000, radius=2.0):
    """Fibonacci sphere: points and their exact outward normals."""
    i = numpy.arange(count)
    z = 1.0 - 2.0 * (i + 0.5) / count
    r = numpy.sqrt(1.0 - z * z)
    angle = math.pi * (3.0 - math.sqrt(5.0)) * i
    normals = numpy.column_stack([r * numpy.cos(angle), r * numpy.sin(angle), z])
    return radius * normals, normals


def cloud(points, arrays=()):
    data = vtkPolyData()
    vtk_points = vtkPoints()
    vtk_points.SetData(numpy_to_vtk(numpy.ascontiguousarray(points), deep=True))
    data.SetPoints(vtk_points)
    for name, values in arrays:
        array = numpy_to_vtk(numpy.ascontiguousarray(values), deep=True)
        array.SetName(name)
        data.GetPointData().AddArray(array)
    source = simple.TrivialProducer()
    source.GetClientSideObject().SetOutput(data)
    source.UpdatePipeline()
    return source


def fetch(proxy):
    proxy.UpdatePipeline()
    return servermanager.Fetch(proxy)


def array(output, name):
    found = output.GetPointData().GetArray(name)
    return vtk_to_numpy(found) if found is not None else None


simple.LoadPlugin(sys.argv[1], remote=False, ns=globals())
points, exact = sphere()

# Points only.
bare = cloud(points)
shown = PrincipalCurvatures(Input=bare)  # noqa: F821 (from LoadPlugin)
result = fetch(shown)
# paraview.simple.Show as a first Apply: points, colored by the display array.
display = simple.Show(shown)
check(display.Representation == "Points" and list(display.ColorArrayName)[-1] == "Mean_Curvature_Clipped",
      "Show: Points, colored by Mean_Curvature_Clipped (%s, %s)"
      % (display.Representation, list(display.ColorArrayName)))
simple.Hide(shown)
normals = array(result, "Normals")
check(normals is not None and normals.shape == (20000, 3), "points only: Normals estimated and output")
if normals is not None:
    dots = numpy.sum(normals * exact, axis=1)
    check(numpy.all(dots > 0.0), "points only: every estimated normal outward")
kmin, kmax = array(result, "Minimum_Curvature"), array(result, "Maximum_Curvature")
check(kmin is not None and numpy.all(numpy.isfinite(kmin)), "points only: every point estimated")
check(kmin is not None and abs(numpy.mean(kmin) - 0.5) < 0.01 and abs(numpy.mean(kmax) - 0.5) < 0.01,
      "points only: k_min = k_max = +1/2 (%.4f, %.4f)" % (numpy.mean(kmin), numpy.mean(kmax)))

# Colors only.
rgb = ((points - points.min(axis=0)) / numpy.ptp(points, axis=0) * 255).astype(numpy.uint8)
colored = cloud(points, [("RGB", rgb)])
curvatures = PrincipalCurvatures(Input=colored)  # noqa: F821
# The panel's entry for no array comes first, so ParaView no longer picks
# the first 3-component array (RGB) by default; chosen by hand, RGB is
# still not taken for normals.
check(list(curvatures.Normals)[-1] == "None (automatic)",
      "colors: the Normals property defaults to 'None (automatic)', not RGB (%s)" % list(curvatures.Normals))
# Only floating-point arrays are offered: 8-bit colors never are.
domain = curvatures.GetProperty("Normals").SMProperty.GetDomain("array_list")
offered = [domain.GetString(i) for i in range(domain.GetNumberOfStrings())]
check("RGB" not in offered, "colors: RGB is not offered as normals (offered: %s)" % offered)
curvatures.Normals = ["POINTS", "RGB"]
result = fetch(curvatures)
kmean = array(result, "Mean_Curvature")
check(kmean is not None and abs(numpy.nanmean(kmean) - 0.5) < 0.01 and numpy.all(numpy.isfinite(kmean)),
      "colors: not used as normals; normals estimated, k = +1/2 everywhere")
strict = PrincipalCurvatures(Input=colored, NormalsSource="Input Array")  # noqa: F821
strict.Normals = ["POINTS", "RGB"]
result = fetch(strict)
check(result.GetNumberOfPoints() == 0, "colors as 'Input Array': the filter fails (empty output)")

# The normals filter alone.
normals_filter = PointCloudNormals(Input=bare)  # noqa: F821
result = fetch(normals_filter)
normals = array(result, "Normals")
lengths = numpy.linalg.norm(normals, axis=1)
dots = numpy.sum(normals * exact, axis=1)
angles = numpy.degrees(numpy.arccos(numpy.clip(numpy.abs(dots), 0.0, 1.0)))
check(numpy.allclose(lengths, 1.0), "Point Cloud Normals: unit normals")
check(numpy.all(dots > 0.0), "Point Cloud Normals: outward")
check(numpy.median(angles) < 1.0, "Point Cloud Normals: median angle %.3f degrees < 1" % numpy.median(angles))
inward = fetch(PointCloudNormals(Input=bare, Orientation="Towards Viewpoint", Viewpoint=[0.0, 0.0, 0.0]))  # noqa: F821
check(numpy.all(numpy.sum(array(inward, "Normals") * exact, axis=1) < 0.0),
      "Point Cloud Normals towards the center: all inward")

# All-zero normals.
zero = cloud(points, [("Normals", numpy.zeros_like(points))])
result = fetch(PrincipalCurvatures(Input=zero, Normals=["POINTS", "Normals"]))  # noqa: F821
check(result.GetNumberOfPoints() == 0, "all-zero normals: the filter fails (its own error message)")

print("%d failed" % len(failures))
sys.exit(1 if failures else 0)
