"""pvpython test of Curvature Lines through paraview.simple.

    pvpython TestCurvatureLinesPython.py PLUGIN.so

An extruded Gaussian bump z = 0.5 exp(-x^2 / 2) over [-4, 4]^2 (30000
jittered grid points, exact normals, fixed seed) through
PrincipalCurvatures and then CurvatureLines with its defaults: polylines
with the arrays Line_Kind, Line_Strength, Line_Length and Line_Curvature; a
ridge (kind 0) along the crest x = 0 and a valley (kind 1) on each side,
near x = +-1.77 where the profile's curvature is least. A plane gives no
line. Every check prints one line; the exit code is 0 when all pass.
"""

import os
import sys

import numpy
from paraview import servermanager, simple
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkPolyData

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from test_checks import check, failures  # noqa: E402

HALF = 4.0
HEIGHT = 0.5


def cloud_source(bump):
    """A TrivialProducer with a jittered grid on the bump (or the plane)."""
    rng = numpy.random.default_rng(5)
    side = 173
    step = 2.0 * HALF / side
    grid = (numpy.arange(side) + 0.5) * step - HALF
    x, y = numpy.meshgrid(grid, grid)
    x = (x + rng.uniform(-0.3, 0.3, x.shape) * step).ravel()
    y = (y + rng.uniform(-0.3, 0.3, y.shape) * step).ravel()
    height = HEIGHT * numpy.exp(-0.5 * x * x) if bump else numpy.zeros_like(x)
    slope = -x * height
    points = numpy.column_stack([x, y, height])
    normals = numpy.column_stack([-slope, numpy.zeros_like(x), numpy.ones_like(x)])
    normals /= numpy.linalg.norm(normals, axis=1)[:, None]
    cloud = vtkPolyData()
    vtk_points = vtkPoints()
    vtk_points.SetData(numpy_to_vtk(numpy.ascontiguousarray(points), deep=True))
    cloud.SetPoints(vtk_points)
    vtk_normals = numpy_to_vtk(numpy.ascontiguousarray(normals), deep=True)
    vtk_normals.SetName("Normals")
    cloud.GetPointData().SetNormals(vtk_normals)
    source = simple.TrivialProducer()
    source.GetClientSideObject().SetOutput(cloud)
    source.UpdatePipeline()
    return source


def lines_of(source):
    curvatures = PrincipalCurvatures(Input=source)  # noqa: F821 (LoadPlugin's)
    lines = CurvatureLines(Input=curvatures)  # noqa: F821
    lines.UpdatePipeline()
    return servermanager.Fetch(lines)


def line_cells(output):
    """Each polyline's point ids, from the connectivity."""
    cells = output.GetLines()
    offsets = vtk_to_numpy(cells.GetOffsetsArray())
    ids = vtk_to_numpy(cells.GetConnectivityArray())
    return [ids[offsets[i]:offsets[i + 1]] for i in range(len(offsets) - 1)]


def main():
    simple.LoadPlugin(sys.argv[1], remote=False, ns=globals())
    check("CurvatureLines" in globals(), "LoadPlugin defines CurvatureLines")
    output = lines_of(cloud_source(bump=True))
    cells = line_cells(output)
    check(len(cells) >= 3, "bump: at least 3 lines (%d)" % len(cells))
    cell_data = output.GetCellData()
    for name in ("Line_Kind", "Line_Strength", "Line_Length"):
        check(cell_data.GetArray(name) is not None, "cell array " + name)
    check(output.GetPointData().GetArray("Line_Curvature") is not None, "point array Line_Curvature")
    if failures:
        return 1
    kinds = vtk_to_numpy(cell_data.GetArray("Line_Kind"))
    lengths = vtk_to_numpy(cell_data.GetArray("Line_Length"))
    x = vtk_to_numpy(output.GetPoints().GetData())[:, 0]
    ridge = [c for c, k in zip(cells, kinds) if k == 0]
    valley = [c for c, k in zip(cells, kinds) if k == 1]
    ridge_x = numpy.concatenate(ridge) if ridge else numpy.array([], dtype=int)
    check(len(ridge) >= 1 and numpy.all(numpy.abs(x[ridge_x]) < 0.1),
          "bump: ridges on the crest |x| < 0.1 (%d lines)" % len(ridge))
    sides = [numpy.median(x[c]) for c in valley]
    check(any(abs(s + 1.77) < 0.2 for s in sides) and any(abs(s - 1.77) < 0.2 for s in sides),
          "bump: valleys near x = -1.77 and +1.77 (%s)" % ", ".join("%.3f" % s for s in sides))
    check(float(numpy.sum(lengths)) > 0.8 * 3 * 2 * HALF,
          "bump: lines cover most of the 3 true lines (length %.2f)" % float(numpy.sum(lengths)))
    flat = lines_of(cloud_source(bump=False))
    check(flat.GetNumberOfCells() == 0, "plane: no line (%d)" % flat.GetNumberOfCells())
    print("%d failed" % len(failures))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
