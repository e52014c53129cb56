"""pvpython test of the PrincipalCurvatures plugin through paraview.simple.

    pvpython TestPluginPython.py PLUGIN.so [CLOUD.vtp ...]
    pvpython TestPluginPython.py --autoload [CLOUD.vtp ...]

The first argument is the plugin to load with LoadPlugin, or --autoload: the
plugin must then already be loaded through PV_PLUGIN_CONFIG_FILE (pointing at
the build's PrincipalCurvatures.plugins.xml), and the test fails if
paraview.simple has no PrincipalCurvatures function.

The test builds its own clouds with exact normals, in memory:

* a sphere of radius 2 (20000 points on a Fibonacci spiral), estimated with
  each FitMode: every point estimated, mean |k - 1/2| below 0.01 for both
  principal curvatures, Maximum >= Minimum, principal directions of unit
  length, tangent (|dot with the normal| < 1e-6) and orthogonal to each
  other; with the normals turned inwards (a Calculator array chosen through
  the Normals property) the signs flip: mean curvature -1/2;
* an open cylinder of radius 1 and height 8 (20000 points), evaluated at
  least twice the surroundings-threshold away from its ends: k_max = 1 and
  k_min = 0 within 0.02, and the maximum direction around the axis (median
  |dot with the axis| below 0.035, about 2 degrees).

It also checks that FitMode is set by its names and that wrong property
values raise. Optional further arguments are .vtp clouds from
GenerateAnalyticCloud (with Exact_Minimum_Curvature, Exact_Maximum_Curvature
and Boundary_Distance arrays, as CTest passes them): they are read with
XMLPolyDataReader and compared with their exact curvatures, with fixed and
with dynamically adjusted thresholds.

Every check prints one line; the exit code is 0 when all pass, 1 otherwise.
"""

import math
import os
import sys

import numpy
from paraview import servermanager, simple
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkPolyData

FIT_MODES = ("Previous", "New01", "New02", "OrientedCircles")  # in the order of their values 0..3
POINT_COUNT = 20000
SPHERE_RADIUS = 2.0
CYLINDER_RADIUS = 1.0
CYLINDER_HEIGHT = 8.0
GOLDEN_ANGLE = math.pi * (3.0 - math.sqrt(5.0))

from test_checks import check, failures  # noqa: E402 (the tests' folder is on sys.path)


# ---------------------------------------------------------------------------
# Clouds


def fibonacci_sphere(count, radius):
    """Points evenly spread over a sphere around the origin (a Fibonacci
    spiral), with exact outward unit normals."""
    i = numpy.arange(count)
    z = 1.0 - 2.0 * (i + 0.5) / count
    r = numpy.sqrt(1.0 - z * z)
    normals = numpy.column_stack((r * numpy.cos(GOLDEN_ANGLE * i), r * numpy.sin(GOLDEN_ANGLE * i), z))
    return radius * normals, normals


def spiral_cylinder(count, radius, height):
    """Points evenly spread over the side of a cylinder around the z axis,
    from z = -height/2 to +height/2 (a spiral with the golden angle), with
    exact outward unit normals."""
    i = numpy.arange(count)
    angle = GOLDEN_ANGLE * i
    normals = numpy.column_stack((numpy.cos(angle), numpy.sin(angle), numpy.zeros(count)))
    points = radius * normals
    points[:, 2] = height * ((i + 0.5) / count - 0.5)
    return points, normals


def cloud_source(points, normals):
    """A pipeline source (TrivialProducer) holding a vtkPolyData with the
    given points and a point-data array 'Normals' (no cells)."""
    cloud = vtkPolyData()
    vtk_points = vtkPoints()
    vtk_points.SetData(numpy_to_vtk(numpy.ascontiguousarray(points, dtype=numpy.float64), deep=True))
    cloud.SetPoints(vtk_points)
    vtk_normals = numpy_to_vtk(numpy.ascontiguousarray(normals, dtype=numpy.float64), deep=True)
    vtk_normals.SetName("Normals")
    cloud.GetPointData().SetNormals(vtk_normals)
    source = simple.TrivialProducer()
    source.GetClientSideObject().SetOutput(cloud)
    source.UpdatePipeline()  # fills the array lists the filter's Normals domain reads
    return source


# ---------------------------------------------------------------------------
# Running the filter


def curvature_filter_factory():
    """The PrincipalCurvatures function: LoadPlugin(ns=globals()) defines it
    in this module; autoloading defines it in paraview.simple."""
    return globals().get("PrincipalCurvatures") or getattr(simple, "PrincipalCurvatures", None)


def fetch_arrays(proxy):
    """The point data of a pipeline object's output, as numpy arrays by name."""
    data = servermanager.Fetch(proxy)
    point_data = data.GetPointData()
    arrays = {point_data.GetArrayName(i): vtk_to_numpy(point_data.GetArray(i))
              for i in range(point_data.GetNumberOfArrays())}
    arrays["Points"] = vtk_to_numpy(data.GetPoints().GetData())
    return arrays


def estimate(source, fit_mode=None, **properties):
    """Runs the filter on source and returns its output arrays. fit_mode is
    assigned as a string after construction, and the value that reached the
    server-manager property is checked."""
    curvatures = curvature_filter_factory()(Input=source, **properties)
    if fit_mode is not None:
        curvatures.FitMode = fit_mode
        check(curvatures.FitMode == fit_mode
              and curvatures.GetProperty("FitMode").SMProperty.GetElement(0) == FIT_MODES.index(fit_mode),
              "FitMode = '%s' sets the value %d" % (fit_mode, FIT_MODES.index(fit_mode)))
    curvatures.UpdatePipeline()
    arrays = fetch_arrays(curvatures)
    simple.Delete(curvatures)
    return arrays


def valid_mask(arrays, label):
    """Curvature_Valid as booleans, checked to be 0/1 and consistent with the NaNs."""
    valid = arrays["Curvature_Valid"]
    check(set(numpy.unique(valid)) <= {0, 1}, "%s: Curvature_Valid holds only 0 and 1" % label)
    valid = valid.astype(bool)
    finite = numpy.isfinite(arrays["Minimum_Curvature"]) & numpy.isfinite(arrays["Maximum_Curvature"])
    check(numpy.array_equal(valid, finite), "%s: curvatures are finite exactly where Curvature_Valid is 1" % label)
    return valid


def check_directions(arrays, normals, valid, label):
    """Principal directions: unit length, tangent, orthogonal to each other.
    Tangent to the given normals with the paper's fits; with OrientedCircles
    to Fitted_Normal, the fitted surface's normal, which is within a few
    degrees of the given one and on its side."""
    minimum = arrays["Minimum_Curvature_Direction"][valid]
    maximum = arrays["Maximum_Curvature_Direction"][valid]
    normals = normals[valid] / numpy.linalg.norm(normals[valid], axis=1)[:, None]
    if "Fitted_Normal" in arrays:
        fitted = arrays["Fitted_Normal"][valid]
        length_error = numpy.abs(numpy.linalg.norm(fitted, axis=1) - 1.0).max()
        check(length_error < 1e-6, "%s: Fitted_Normal of unit length (max error %.2g)" % (label, length_error))
        turned = numpy.degrees(numpy.arccos(numpy.clip((fitted * normals).sum(axis=1), -1.0, 1.0))).max()
        check(turned < 5.0, "%s: Fitted_Normal within 5 degrees of the given normal (largest %.2f)" % (label, turned))
        normals = fitted
    for name, d in (("Minimum_Curvature_Direction", minimum), ("Maximum_Curvature_Direction", maximum)):
        length_error = numpy.abs(numpy.linalg.norm(d, axis=1) - 1.0).max()
        check(length_error < 1e-6, "%s: %s of unit length (max error %.2g)" % (label, name, length_error))
        tangency = numpy.abs((d * normals).sum(axis=1)).max()
        check(tangency < 1e-6, "%s: %s orthogonal to the normal (max |dot| %.2g)" % (label, name, tangency))
    crossing = numpy.abs((minimum * maximum).sum(axis=1)).max()
    check(crossing < 1e-6, "%s: minimum and maximum directions orthogonal (max |dot| %.2g)" % (label, crossing))


# ---------------------------------------------------------------------------
# The checks


def check_plugin_available(plugin):
    """Loads the plugin (or checks that it was autoloaded); False if unusable."""
    if plugin == "--autoload":
        return check(hasattr(simple, "PrincipalCurvatures"),
                     "plugin autoloaded through PV_PLUGIN_CONFIG_FILE (%s)"
                     % os.environ.get("PV_PLUGIN_CONFIG_FILE", "not set"))
    if not check(os.path.isfile(plugin), "plugin file exists: %s" % plugin):
        return False
    simple.LoadPlugin(plugin, remote=False, ns=globals())
    return check("PrincipalCurvatures" in globals(), "LoadPlugin(ns=globals()) defines PrincipalCurvatures")


def check_sphere():
    """Sphere of radius 2 with outward normals, every FitMode; then inward normals."""
    points, normals = fibonacci_sphere(POINT_COUNT, SPHERE_RADIUS)
    source = cloud_source(points, normals)
    expected = 1.0 / SPHERE_RADIUS
    for mode in FIT_MODES:
        label = "sphere R=%g, %s" % (SPHERE_RADIUS, mode)
        a = estimate(source, fit_mode=mode)
        valid = valid_mask(a, label)
        check(valid.all(), "%s: every point estimated (%d of %d)" % (label, valid.sum(), valid.size))
        k_min, k_max = a["Minimum_Curvature"][valid], a["Maximum_Curvature"][valid]
        error_min, error_max = numpy.abs(k_min - expected).mean(), numpy.abs(k_max - expected).mean()
        check(error_min < 0.02 * expected, "%s: mean |k_min - 0.5| = %.2g < 0.01" % (label, error_min))
        check(error_max < 0.02 * expected, "%s: mean |k_max - 0.5| = %.2g < 0.01" % (label, error_max))
        check((k_max >= k_min).all(), "%s: Maximum_Curvature >= Minimum_Curvature" % label)
        mean_error = numpy.abs(a["Mean_Curvature"][valid] - 0.5 * (k_min + k_max)).max()
        gauss_error = numpy.abs(a["Gauss_Curvature"][valid] - k_min * k_max).max()
        check(mean_error < 1e-12 and gauss_error < 1e-12, "%s: Mean = (min + max)/2, Gauss = min * max" % label)
        check_directions(a, normals, valid, label)

    # Inward normals, as a second array chosen through the Normals property.
    inward = simple.Calculator(Input=source, AttributeType="Point Data", ResultArrayName="Inward",
                               Function="-Normals")
    inward.UpdatePipeline()
    for mode in FIT_MODES:
        label = "sphere R=%g, inward normals, %s" % (SPHERE_RADIUS, mode)
        a = estimate(inward, fit_mode=mode, Normals=["POINTS", "Inward"])
        valid = valid_mask(a, label)
        check(valid.all(), "%s: every point estimated" % label)
        mean = a["Mean_Curvature"][valid]
        error = numpy.abs(mean + expected).mean()
        check(error < 0.02 * expected, "%s: mean curvature %.5f, mean |H + 0.5| = %.2g < 0.01"
              % (label, mean.mean(), error))
        check((a["Maximum_Curvature"][valid] >= a["Minimum_Curvature"][valid]).all(),
              "%s: Maximum_Curvature >= Minimum_Curvature" % label)
        check_directions(a, -normals, valid, label)
    simple.Delete(inward)
    simple.Delete(source)


def check_cylinder():
    """Open cylinder of radius 1, height 8, outward normals, every FitMode."""
    points, normals = spiral_cylinder(POINT_COUNT, CYLINDER_RADIUS, CYLINDER_HEIGHT)
    source = cloud_source(points, normals)
    for mode in FIT_MODES:
        label = "cylinder r=%g h=%g, %s" % (CYLINDER_RADIUS, CYLINDER_HEIGHT, mode)
        a = estimate(source, fit_mode=mode)
        valid = valid_mask(a, label)
        end_distance = 0.5 * CYLINDER_HEIGHT - numpy.abs(a["Points"][:, 2])
        inside = valid & (end_distance >= 2.0 * a["Surroundings_Threshold"])
        if not check(inside.sum() > 0.5 * POINT_COUNT,
                     "%s: %d points estimated at least 2 s from the ends" % (label, inside.sum())):
            continue
        k_min, k_max = a["Minimum_Curvature"][inside], a["Maximum_Curvature"][inside]
        error_max = numpy.abs(k_max - 1.0 / CYLINDER_RADIUS).mean()
        error_min = numpy.abs(k_min).mean()
        check(error_max < 0.02, "%s: k_max = 1, mean |k_max - 1| = %.5f < 0.02" % (label, error_max))
        check(error_min < 0.02, "%s: k_min = 0, mean |k_min| = %.5f < 0.02" % (label, error_min))
        along_axis = numpy.median(numpy.abs(a["Maximum_Curvature_Direction"][inside][:, 2]))
        check(along_axis < 0.035, "%s: maximum direction around the axis, median |dot with axis| = %.5f < 0.035"
              % (label, along_axis))
        check((a["Maximum_Curvature"][valid] >= a["Minimum_Curvature"][valid]).all(),
              "%s: Maximum_Curvature >= Minimum_Curvature" % label)
        check_directions(a, normals, valid, label)
    simple.Delete(source)


def check_property_errors():
    """FitMode by name works; wrong values and unknown properties raise."""
    points, normals = fibonacci_sphere(2000, SPHERE_RADIUS)
    source = cloud_source(points, normals)
    factory = curvature_filter_factory()
    curvatures = factory(Input=source)
    check(curvatures.FitMode == "OrientedCircles", "FitMode defaults to 'OrientedCircles' (is %r)" % curvatures.FitMode)
    check(curvatures.NeighborhoodMode == "Automatic",
          "NeighborhoodMode defaults to 'Automatic' (is %r)" % curvatures.NeighborhoodMode)
    for mode in FIT_MODES:
        built = factory(Input=source, FitMode=mode)
        check(built.FitMode == mode, "PrincipalCurvatures(FitMode='%s') keeps the name" % mode)
        simple.Delete(built)

    def raises(action, description, expected):
        try:
            action()
        except expected as error:
            check(True, "%s raises %s (%s)" % (description, type(error).__name__, str(error).split(".")[0]))
        else:
            check(False, "%s raises %s" % (description, expected.__name__))

    raises(lambda: setattr(curvatures, "FitMode", "NoSuchMode"), "FitMode = 'NoSuchMode'", ValueError)
    raises(lambda: setattr(curvatures, "NeighborhoodMode", "Bogus"), "NeighborhoodMode = 'Bogus'", ValueError)
    raises(lambda: setattr(curvatures, "NumberOfNeighbors", "many"), "NumberOfNeighbors = 'many'", TypeError)
    raises(lambda: setattr(curvatures, "NoSuchProperty", 1), "an unknown property", AttributeError)
    raises(lambda: factory(Input=source, FitMode="NoSuchMode"), "PrincipalCurvatures(FitMode='NoSuchMode')",
           ValueError)
    check(curvatures.FitMode == "OrientedCircles", "a rejected value leaves FitMode unchanged")
    simple.Delete(curvatures)
    simple.Delete(source)


def check_file_cloud(path):
    """A GenerateAnalyticCloud .vtp against its exact curvatures, with fixed
    and with dynamically adjusted thresholds (median errors, 2 % of the
    largest exact curvature, at points 2 s away from any boundary)."""
    name = os.path.basename(path)
    if not check(os.path.isfile(path), "%s exists" % path):
        return
    reader = simple.XMLPolyDataReader(FileName=[path])
    reader.UpdatePipeline()
    for label, properties in (("fixed thresholds", {}), ("dynamic adjustment", {"DynamicAdjustment": 1})):
        a = estimate(reader, Normals=["POINTS", "Normals"], **properties)
        if not check("Exact_Minimum_Curvature" in a and "Boundary_Distance" in a,
                     "%s: has Exact_*_Curvature and Boundary_Distance arrays" % name):
            break
        adjusted = bool(properties)
        check(("Target_Neighbor_Count" in a) == adjusted,
              "%s, %s: Target_Neighbor_Count %s" % (name, label, "present" if adjusted else "absent"))
        if adjusted and "Target_Neighbor_Count" in a:
            ratio = a["Neighbor_Count"] / a["Target_Neighbor_Count"]
            p5, p95 = numpy.percentile(ratio, [5, 95])
            check(p5 >= 0.8 and p95 <= 1.25,
                  "%s, %s: neighbor count / target within 0.8..1.25 (p5 %.2f, p95 %.2f)" % (name, label, p5, p95))
        valid = valid_mask(a, "%s, %s" % (name, label))
        inside = valid & (a["Boundary_Distance"] > 2.0 * a["Surroundings_Threshold"])
        scale = max(numpy.abs(a["Exact_Minimum_Curvature"]).max(), numpy.abs(a["Exact_Maximum_Curvature"]).max())
        for which in ("Minimum", "Maximum"):
            error = numpy.median(numpy.abs(a[which + "_Curvature"][inside] - a["Exact_%s_Curvature" % which][inside]))
            check(inside.any() and error < 0.02 * scale,
                  "%s, %s: median |k_%s - exact| = %.5f < %.5f" % (name, label, which[:3].lower(), error, 0.02 * scale))
    simple.Delete(reader)


def main(argv):
    if len(argv) < 1 or argv[0] in ("-h", "--help"):
        print(__doc__)
        return 2
    if not check_plugin_available(argv[0]):
        print("the PrincipalCurvatures filter is not available: nothing else can be tested")
        print("%d failed" % len(failures))
        return 1
    check_sphere()
    check_cylinder()
    check_property_errors()
    for path in argv[1:]:
        check_file_cloud(path)
    print("%d failed" % len(failures))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
