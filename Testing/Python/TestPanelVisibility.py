"""The Properties panel shows a neighborhood setting exactly where it changes
the result: for every combination of FitMode (New01, OrientedCircles),
NeighborhoodMode (Radius, K Nearest, Automatic) and AutomaticThresholds,
each setting's visibility, as the plugin XML's decorators give it (the
GenericDecorator and CompositeDecorator rules of ParaView 5.11), must agree
with whether changing the setting changes the filter's curvatures on a
small sphere.

    pvpython TestPanelVisibility.py PrincipalCurvatures.xml

(PYTHONPATH: the build's site-packages, for principal_curvatures.)
Every check prints one line; the exit code is 0 when all pass, 1 otherwise.
"""

import itertools
import sys
import xml.etree.ElementTree as ElementTree

import numpy
from principal_curvatures import vtkPrincipalCurvatureEstimation
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkPolyData

from test_checks import check, failures  # noqa: E402 (the tests' folder is on sys.path)

# Each setting, its default and another value, set through the filter.
SETTINGS = {
    "NumberOfNeighbors": (60, 120),
    "PlaneDistanceRatio": (0.1, 0.3),
    "PlaneDistanceThreshold": (0.1, 0.25),
    "AutomaticScaleTolerance": (2.0, 0.3),
}
FIT_MODES = {"New01": 1, "OrientedCircles": 3}
NEIGHBORHOOD_MODES = {"Radius": 0, "K Nearest": 1, "Automatic": 2}


def decorator_visible(element, values):
    """Whether a PropertyWidgetDecorator or Expression element shows its
    property for the property values given (name: int)."""
    if element.tag == "Expression":
        results = [decorator_visible(child, values) for child in element]
        return all(results) if element.get("type") == "and" else any(results)
    kind = element.get("type")
    if kind == "CompositeDecorator":
        return all(decorator_visible(child, values) for child in element)
    if kind == "GenericDecorator":
        assert element.get("mode") == "visibility", element.attrib
        accepted = (element.get("value") or element.get("values")).split()
        match = str(values[element.get("property")]) in accepted
        return match != (element.get("inverse") == "1")
    raise ValueError("decorator type %s not handled by this test" % kind)


def visible(proxy, name, values):
    prop = next(p for p in proxy if p.get("name") == name)
    hints = prop.find("Hints")
    decorators = [] if hints is None else hints.findall("PropertyWidgetDecorator")
    return all(decorator_visible(d, values) for d in decorators)


def sphere(count=1500):
    """Points on the unit sphere (a fixed seed) with outward normals, the
    points moved off it by a little noise (so that the automatic
    neighborhood's tolerance decides between radii)."""
    rng = numpy.random.default_rng(11)
    points = rng.normal(size=(count, 3))
    points /= numpy.linalg.norm(points, axis=1)[:, None]
    normals = points.copy()
    points += rng.normal(scale=0.01, size=points.shape)
    cloud = vtkPolyData()
    vtk_points = vtkPoints()
    vtk_points.SetData(numpy_to_vtk(points, deep=True))
    cloud.SetPoints(vtk_points)
    vtk_normals = numpy_to_vtk(normals, deep=True)
    vtk_normals.SetName("Normals")
    cloud.GetPointData().SetNormals(vtk_normals)
    return cloud


def curvatures(cloud, fit, neighborhood, automatic, name, value):
    estimation = vtkPrincipalCurvatureEstimation()
    estimation.SetInputData(cloud)
    estimation.SetFitMode(fit)
    estimation.SetNeighborhoodMode(neighborhood)
    estimation.SetAutomaticThresholds(automatic)
    estimation.SetNumberOfNeighbors(SETTINGS["NumberOfNeighbors"][0])
    estimation.SetSurroundingsThreshold(0.35)
    getattr(estimation, "Set" + name)(value)
    estimation.Update()
    output = estimation.GetOutput().GetPointData()
    return numpy.concatenate([vtk_to_numpy(output.GetArray(a)) for a in ("Minimum_Curvature", "Maximum_Curvature")])


def main(xml_path):
    proxy = next(p for p in ElementTree.parse(xml_path).iter("SourceProxy")
                 if p.get("name") == "PrincipalCurvatureEstimation")
    cloud = sphere()
    defaults = {"FitMode": 3, "NeighborhoodMode": 2, "AutomaticThresholds": 1, "DynamicAdjustment": 0}
    hidden = [name for name in ("NumberOfNeighbors", "PlaneDistanceRatio") if not visible(proxy, name, defaults)]
    check(hidden == ["NumberOfNeighbors", "PlaneDistanceRatio"],
          "the defaults (OrientedCircles, Automatic) hide Number Of Neighbors and Plane Distance Ratio (%s)"
          % " ".join(hidden))
    for (fit_name, fit), (mode_name, mode), automatic in itertools.product(
            FIT_MODES.items(), NEIGHBORHOOD_MODES.items(), (1, 0)):
        values = dict(defaults, FitMode=fit, NeighborhoodMode=mode, AutomaticThresholds=automatic)
        for name, (first, second) in SETTINGS.items():
            a = curvatures(cloud, fit, mode, automatic, name, first)
            b = curvatures(cloud, fit, mode, automatic, name, second)
            matters = not numpy.array_equal(a, b, equal_nan=True)
            shown = visible(proxy, name, values)
            check(shown == matters, "%s, %s, AutomaticThresholds %d: %s %s and %s the result"
                  % (fit_name, mode_name, automatic, name, "shown" if shown else "hidden",
                     "changes" if matters else "does not change"))
    print("%d failed" % len(failures))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
