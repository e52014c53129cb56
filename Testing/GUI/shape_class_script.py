"""Runs inside the ParaView GUI (paraview --script=...), driven by
RunShapeClassTest.sh: a noisy torus with exact outward normals (domes on
its outer half, saddles on its inner half) applied Principal Curvatures,
shown, then colored by Shape_Class as the toolbar's array menu does
(ColorBy, with the display's own map). Writes GUI_TEST_MARKER: whether the display's color map is
categorical, its annotations and indexed colors, whether its scalar bar
(the legend) is visible, and the classes the output holds."""

import os

import numpy
from paraview import servermanager, simple
from vtkmodules.util.numpy_support import vtk_to_numpy

marker = os.environ["GUI_TEST_MARKER"]
work = os.environ["GUI_TEST_WORK"]


def write_torus(path, count=30000, seed=7):
    """A torus (radii 3 and 1) with exact outward normals and a little noise."""
    generator = numpy.random.default_rng(seed)
    u, v = generator.uniform(0.0, 2.0 * numpy.pi, (2, count))
    ring = 3.0 + numpy.cos(v)
    points = numpy.column_stack([ring * numpy.cos(u), ring * numpy.sin(u), numpy.sin(v)])
    points += generator.normal(0.0, 0.01, points.shape)
    normals = numpy.column_stack([numpy.cos(v) * numpy.cos(u), numpy.cos(v) * numpy.sin(u), numpy.sin(v)])
    numpy.savetxt(path, numpy.hstack([points, normals]), fmt="%.9g")


try:
    simple.LoadPlugin(os.environ["GUI_TEST_PLUGIN"], remote=False)
    path = os.path.join(work, "torus_classes.xyz")
    write_torus(path)
    cloud = simple.OpenDataFile(path)
    cloud.UpdatePipeline()
    curvatures = simple.PrincipalCurvatures(Input=cloud)
    simple.SetActiveSource(curvatures)
    view = simple.GetActiveViewOrCreate("RenderView")
    display = simple.Show(curvatures, view)
    view.CameraPosition = [0, -8, 10]
    view.CameraViewUp = [0, 0, 1]
    simple.ResetCamera(view)
    # The plugin gives each display its own map ("Use Separate Color
    # Map"), which the toolbar's array menu keeps: the map of this display.
    simple.ColorBy(display, ("POINTS", "Shape_Class"), separate=True)
    simple.Render(view)
    color_map = display.LookupTable
    classes = sorted(set(vtk_to_numpy(
        servermanager.Fetch(curvatures).GetPointData().GetArray("Shape_Class")).tolist()))
    lines = ["colored by %s" % display.ColorArrayName[1],
             "own map %d" % display.UseSeparateColorMap,
             "categorical %d" % color_map.InterpretValuesAsCategories,
             "annotations %s" % ",".join(color_map.Annotations),
             "colors %d" % len(color_map.IndexedColors),
             "distinct %d" % len(set(tuple(color_map.IndexedColors[i:i + 3])
                                     for i in range(0, len(color_map.IndexedColors), 3))),
             "legend %d" % (1 if display.IsScalarBarVisible(view) else 0),
             "classes %s" % ",".join(str(c) for c in classes)]
    with open(marker, "w") as handle:
        handle.write("ok\n" + "\n".join(lines) + "\n")
except Exception as error:  # report to the driver instead of a silent GUI
    with open(marker, "w") as handle:
        handle.write("error %s\n" % error)
