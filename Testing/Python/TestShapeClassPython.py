"""Shape_Class through pvpython:

    pvpython TestShapeClassPython.py PLUGIN.so

* OrientedCircles (the default) writes Shape_Class (unsigned char) and the
  field data Shape_Class_Names, the name of code c at index c; a noisy
  sphere with outward normals is domes, with inward normals cups, a noisy
  cylinder ridges;
* the paper's fits have no standard error: no Shape_Class, no names;
* colored by Shape_Class, the color map set as docs/output-arrays.md says
  (categories, the names as annotations) shows a legend.

Every check prints one line; the exit code is 0 when all pass, 1 otherwise.
"""

import sys

import numpy
from paraview import servermanager, simple
from vtkmodules.numpy_interface import dataset_adapter
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonDataModel import vtkPolyData

from test_checks import check, failures  # noqa: E402 (the tests' folder is on sys.path)

NAMES = ["Undetermined", "Flat", "Dome", "Cup", "Ridge", "Valley", "Saddle"]


def cloud(points, normals):
    data = dataset_adapter.WrapDataObject(vtkPolyData())
    data.Points = points
    data.PointData.append(normals, "Normals")
    data.GetPointData().SetActiveNormals("Normals")
    source = simple.TrivialProducer()
    source.GetClientSideObject().SetOutput(data.VTKObject)
    source.UpdatePipeline()
    return source


def sphere(count=20000, seed=3, inward=False):
    generator = numpy.random.default_rng(seed)
    normals = generator.normal(size=(count, 3))
    normals /= numpy.linalg.norm(normals, axis=1)[:, None]
    points = normals + generator.normal(0.0, 0.005, (count, 3))
    return cloud(points, -normals if inward else normals)


def cylinder(count=20000, seed=4):
    generator = numpy.random.default_rng(seed)
    angle = generator.uniform(0.0, 2.0 * numpy.pi, count)
    height = generator.uniform(-4.0, 4.0, count)
    normals = numpy.column_stack([numpy.cos(angle), numpy.sin(angle), numpy.zeros(count)])
    points = normals + numpy.column_stack([numpy.zeros(count), numpy.zeros(count), height])
    points += generator.normal(0.0, 0.005, (count, 3))
    inner = numpy.abs(height) < 3.0
    return cloud(points, normals), inner


def classes(source, **properties):
    curvatures = simple.PrincipalCurvatures(Input=source, **properties)
    curvatures.UpdatePipeline()
    output = servermanager.Fetch(curvatures)
    shape = output.GetPointData().GetArray("Shape_Class")
    names = output.GetFieldData().GetAbstractArray("Shape_Class_Names")
    return curvatures, shape, names


def main(argv):
    simple.LoadPlugin(argv[0], remote=False)
    curvatures, shape, names = classes(sphere())
    check(shape is not None and shape.GetDataTypeAsString() == "unsigned char",
          "OrientedCircles: Shape_Class, unsigned char")
    check(names is not None and [names.GetValue(i) for i in range(names.GetNumberOfValues())] == NAMES,
          "OrientedCircles: Shape_Class_Names lists %s" % ", ".join(NAMES))
    tube, away_from_ends = cylinder()
    for what, source, expected, inner in (("sphere, outward normals", sphere(), 2, Ellipsis),
                                          ("sphere, inward normals", sphere(inward=True), 3, Ellipsis),
                                          ("cylinder, outward normals", tube, 4, away_from_ends)):
        share = numpy.mean(vtk_to_numpy(classes(source)[1])[inner] == expected)
        check(share >= 0.95, "%s: %.4f %s" % (what, share, NAMES[expected]))
    for mode in ("New01", "Previous"):
        _, shape, names = classes(sphere(), FitMode=mode)
        check(shape is None and names is None, "%s: no Shape_Class, no Shape_Class_Names" % mode)

    display = simple.Show(curvatures)
    view = simple.GetActiveViewOrCreate("RenderView")
    simple.ColorBy(display, ("POINTS", "Shape_Class"))
    lut = simple.GetColorTransferFunction("Shape_Class")
    lut.InterpretValuesAsCategories = 1
    lut.Annotations = [str(code) if i % 2 == 0 else NAMES[code]
                       for code in range(len(NAMES)) for i in (0, 1)]
    display.SetScalarBarVisibility(view, True)
    check(display.LookupTable.InterpretValuesAsCategories == 1 and
          list(display.LookupTable.Annotations)[1::2] == NAMES and display.IsScalarBarVisible(view),
          "colored by Shape_Class: categories named after the classes, legend shown")
    print("%d failed" % len(failures))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
