"""pvpython test of the PrincipalCurvatures plugin through paraview.simple.

    pvpython TestPluginPython.py PLUGIN.so|--autoload SPHERE.vtp CYLINDER.vtp

With --autoload the plugin must already be loaded (PV_PLUGIN_CONFIG_FILE
pointing at the build's plugins XML). The clouds come from
GenerateAnalyticCloud and carry exact curvature arrays.
Exit code 0 on success; every failed check is printed.
"""

import sys

import numpy
from paraview import servermanager, simple
from vtkmodules.util.numpy_support import vtk_to_numpy

failures = []


def check(condition, message):
    print(("ok     " if condition else "FAILED ") + message)
    if not condition:
        failures.append(message)


def run(source, **properties):
    # LoadPlugin(ns=globals()) defines it here; autoloading, in paraview.simple.
    factory = globals().get("PrincipalCurvatures") or simple.PrincipalCurvatures
    curvatures = factory(Input=source, **properties)
    data = servermanager.Fetch(curvatures).GetPointData()
    simple.Delete(curvatures)
    return {data.GetArrayName(i): vtk_to_numpy(data.GetArray(i)) for i in range(data.GetNumberOfArrays())}


def main(plugin, sphere_file, cylinder_file):
    if plugin == "--autoload":
        check(hasattr(simple, "PrincipalCurvatures"), "plugin autoloaded through PV_PLUGIN_CONFIG_FILE")
        if failures:
            return 1
    else:
        simple.LoadPlugin(plugin, remote=False, ns=globals())
        check("PrincipalCurvatures" in globals(), "LoadPlugin puts PrincipalCurvatures in the script's globals")

    sphere = simple.XMLPolyDataReader(FileName=[sphere_file])
    sphere.UpdatePipeline()
    for mode in ("Previous", "New01", "New02"):
        a = run(sphere, FitMode=mode)
        valid = a["Curvature_Valid"]
        check(valid.all(), "%s: every sphere point estimated" % mode)
        check(abs(a["Minimum_Curvature"].mean() - 1.0) < 0.02, "%s: sphere R=1 k_min = +1" % mode)
        check(abs(a["Maximum_Curvature"].mean() - 1.0) < 0.02, "%s: sphere R=1 k_max = +1" % mode)
        check((a["Maximum_Curvature"] >= a["Minimum_Curvature"]).all(), "%s: max >= min" % mode)
        for name in ("Minimum_Curvature_Direction", "Maximum_Curvature_Direction"):
            d = a[name]
            check(numpy.abs(numpy.linalg.norm(d, axis=1) - 1).max() < 1e-9, "%s: %s unit" % (mode, name))
            check(numpy.abs((d * a["Normals"]).sum(axis=1)).max() < 1e-9, "%s: %s tangent" % (mode, name))

    # Inward normals flip the sign.
    flipped = simple.Calculator(Input=sphere, ResultArrayName="Inward", Function="-Normals")
    flipped.UpdatePipeline()
    a = run(flipped, Normals=["POINTS", "Inward"])
    check(abs(a["Mean_Curvature"].mean() + 1.0) < 0.02, "inward normals: mean curvature -1")

    cylinder = simple.XMLPolyDataReader(FileName=[cylinder_file])
    cylinder.UpdatePipeline()
    a = run(cylinder, FitMode="New02", DynamicAdjustment=0)
    inside = a["Boundary_Distance"] > 2 * a["Surroundings_Threshold"]
    axis_alignment = numpy.abs(a["Maximum_Curvature_Direction"][inside][:, 2])
    check(abs(numpy.median(a["Maximum_Curvature"][inside]) - 1.0) < 0.02, "cylinder r=1: k_max = 1")
    check(abs(numpy.median(a["Minimum_Curvature"][inside])) < 0.02, "cylinder: k_min = 0")
    check(numpy.median(axis_alignment) < 0.035, "cylinder: max direction around the axis (2 degrees)")
    a = run(cylinder, DynamicAdjustment=1)
    check(abs(numpy.median(a["Maximum_Curvature"][inside]) - 1.0) < 0.02, "cylinder, DVA: k_max = 1")

    try:
        (globals().get("PrincipalCurvatures") or simple.PrincipalCurvatures)(Input=sphere, FitMode="NoSuchMode")
        check(False, "an unknown FitMode raises")
    except Exception:
        check(True, "an unknown FitMode raises")

    print("%d failed" % len(failures))
    return 1 if failures else 0


if __name__ == "__main__":
    if len(sys.argv) != 4:
        print(__doc__)
        sys.exit(2)
    sys.exit(main(*sys.argv[1:]))
