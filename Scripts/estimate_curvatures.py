"""Estimate the principal curvatures of a point cloud with normals.

Run with ParaView's Python:

    pvpython Scripts/estimate_curvatures.py INPUT OUTPUT.vtp [options]

INPUT may be .vtp, .vtu, .ply, an .off triangle mesh (its vertices, with
normals from the triangles, oriented outwards), or text with one point per
line (``x y z nx ny nz``, whitespace or comma separated: .xyz, .pwn, .txt,
.csv).
Writes OUTPUT (.vtp) with the curvature arrays and prints a summary table.
"""

import argparse
import os
import sys
import time

from paraview import simple
from paraview import servermanager

REPOSITORY = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DEFAULT_PLUGIN = os.path.join(
    REPOSITORY, "build", "lib", "paraview-plugins", "PrincipalCurvatures", "PrincipalCurvatures.so")
TEXT_EXTENSIONS = (".xyz", ".pwn", ".txt", ".csv")


def fail(message):
    sys.stderr.write("estimate_curvatures: %s\n" % message)
    sys.exit(2)


def parse_arguments(argv):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("input", help="point cloud with normals (.vtp .vtu .ply .xyz .pwn .txt .csv)")
    parser.add_argument("output", help="result (.vtp)")
    parser.add_argument("--fit-mode", choices=["Previous", "New01", "New02"], default="New01")
    parser.add_argument("--neighbors", type=int, help="target neighbour count (automatic radius) or k")
    parser.add_argument("--k-nearest", action="store_true", help="use the k nearest neighbours")
    parser.add_argument("--radius", type=float, help="fixed surroundings-threshold s (turns automatic off)")
    parser.add_argument("--plane-distance", type=float, help="fixed plane-distance-threshold p (with --radius)")
    parser.add_argument("--dynamic-adjustment", action="store_true", help="the paper's dynamic variable adjustment")
    parser.add_argument("--normals", default=None, help="name of the point-data normals array")
    parser.add_argument("--threads", type=int, default=0, help="0 = all cores")
    parser.add_argument("--plugin", default=os.environ.get("PRINCIPAL_CURVATURES_PLUGIN", DEFAULT_PLUGIN))
    return parser.parse_args(argv)


def load_plugin(path):
    """Loads the plugin unless it was autoloaded (PV_PLUGIN_CONFIG_FILE)."""
    if hasattr(simple, "PrincipalCurvatures"):
        return
    if not os.path.exists(path):
        fail("plugin not found at %s (build it with Scripts/setup.sh, or pass --plugin)" % path)
    simple.LoadPlugin(path, remote=False)
    if not hasattr(simple, "PrincipalCurvatures"):
        fail("loading %s did not provide the PrincipalCurvatures filter" % path)


def read_text_cloud(path):
    """A trivial producer holding the x y z nx ny nz points of a text file."""
    import numpy
    from vtkmodules.numpy_interface import dataset_adapter
    from vtkmodules.vtkCommonDataModel import vtkPolyData

    with open(path) as handle:
        rows = [line.replace(",", " ").split() for line in handle if line.strip() and not line.startswith("#")]
    try:
        values = numpy.array([[float(v) for v in row[:6]] for row in rows if len(row) >= 6])
    except ValueError as error:
        fail("%s: not 'x y z nx ny nz' per line (%s)" % (path, error))
    if values.size == 0:
        fail("%s: no line with 6 numbers (x y z nx ny nz)" % path)
    cloud = dataset_adapter.WrapDataObject(vtkPolyData())
    cloud.Points = numpy.ascontiguousarray(values[:, :3])
    cloud.PointData.append(numpy.ascontiguousarray(values[:, 3:6]), "Normals")
    cloud.VTKObject.GetPointData().SetActiveNormals("Normals")
    producer = simple.TrivialProducer()
    producer.GetClientSideObject().SetOutput(cloud.VTKObject)
    return producer


def read_off_mesh(path):
    """The vertices of an OFF triangle mesh, with point normals computed from
    the triangles and turned to point away from the centroid (for a closed,
    roughly star-shaped scan such as the Stanford bunny)."""
    import numpy
    from vtkmodules.numpy_interface import dataset_adapter
    from vtkmodules.vtkCommonCore import vtkIdTypeArray
    from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
    from vtkmodules.vtkFiltersCore import vtkPolyDataNormals

    with open(path) as handle:
        words = [line.split("#")[0].split() for line in handle]
    words = [w for w in words if w]
    if not words or words[0][0] != "OFF":
        fail("%s: not an OFF file" % path)
    header = words[1] if len(words[0]) == 1 else words[0][1:]
    first = 2 if len(words[0]) == 1 else 1
    vertices, faces = int(header[0]), int(header[1])
    points = numpy.array([[float(v) for v in row[:3]] for row in words[first:first + vertices]])
    polygons = [[int(v) for v in row[1:1 + int(row[0])]] for row in words[first + vertices:first + vertices + faces]]
    mesh = dataset_adapter.WrapDataObject(vtkPolyData())
    mesh.Points = points
    connectivity = numpy.concatenate([[len(p)] + p for p in polygons]).astype(numpy.int64)
    cells = vtkCellArray()
    ids = vtkIdTypeArray()
    ids.SetNumberOfValues(len(connectivity))
    for i, v in enumerate(connectivity):
        ids.SetValue(i, int(v))
    cells.ImportLegacyFormat(ids)
    mesh.VTKObject.SetPolys(cells)
    normals = vtkPolyDataNormals()
    normals.SetInputData(mesh.VTKObject)
    normals.ComputePointNormalsOn()
    normals.ComputeCellNormalsOff()
    normals.SplittingOff()
    normals.ConsistencyOn()
    normals.Update()
    cloud = dataset_adapter.WrapDataObject(normals.GetOutput())
    outward = ((cloud.Points - cloud.Points.mean(axis=0)) * cloud.PointData["Normals"]).sum(axis=1)
    if numpy.median(outward) < 0:
        cloud.PointData["Normals"][:] *= -1
    producer = simple.TrivialProducer()
    producer.GetClientSideObject().SetOutput(cloud.VTKObject)
    return producer


def open_cloud(path):
    if not os.path.exists(path):
        fail("input not found: %s" % path)
    extension = os.path.splitext(path)[1].lower()
    if extension == ".vtp":
        return simple.XMLPolyDataReader(FileName=[path])
    if extension == ".vtu":
        return simple.XMLUnstructuredGridReader(FileName=[path])
    if extension == ".ply":
        return simple.PLYReader(FileNames=[path])
    if extension in TEXT_EXTENSIONS:
        return read_text_cloud(path)
    if extension == ".off":
        return read_off_mesh(path)
    fail("unknown input type '%s' (use .vtp .vtu .ply .off .xyz .pwn .txt .csv)" % extension)


def choose_normals(source, requested):
    """The normals array: the requested one, else 'Normals', else the first 3-component array."""
    arrays = source.PointData
    names = [arrays[i].GetName() for i in range(len(arrays))]
    if requested:
        if requested not in names:
            fail("no point-data array named '%s' (have: %s)" % (requested, ", ".join(names) or "none"))
        return requested
    for name in ["Normals", "normals", "Normal"] + names:
        if name in names and arrays[name].GetNumberOfComponents() == 3:
            return name
    fail("the input has no 3-component point-data normals array (have: %s)" % (", ".join(names) or "none"))


def percentiles_row(name, values):
    import numpy
    finite = values[numpy.isfinite(values)]
    if finite.size == 0:
        return "%-20s %s" % (name, "no estimate")
    p = numpy.percentile(finite, [0, 5, 50, 95, 100])
    return "%-20s %12.5g %12.5g %12.5g %12.5g %12.5g" % ((name,) + tuple(p))


def summarize(output, seconds, fit_mode):
    import numpy
    from vtkmodules.util.numpy_support import vtk_to_numpy

    data = output.GetPointData()
    array = lambda name: vtk_to_numpy(data.GetArray(name))
    valid = array("Curvature_Valid")
    n = output.GetNumberOfPoints()
    print("points               %d" % n)
    print("estimated            %d (%.2f %%)" % (valid.sum(), 100.0 * valid.sum() / max(n, 1)))
    print("not estimated        %d" % (n - valid.sum()))
    print("fit mode             %s" % fit_mode)
    print("filter time          %.3f s" % seconds)
    print("neighbours (median)  %g" % numpy.median(array("Neighbor_Count")))
    print("s used (median)      %.6g" % numpy.nanmedian(array("Surroundings_Threshold")))
    print("p used (median)      %.6g" % numpy.nanmedian(array("Plane_Distance_Threshold")))
    print()
    print("%-20s %12s %12s %12s %12s %12s" % ("array", "min", "5 %", "median", "95 %", "max"))
    for name in ("Minimum_Curvature", "Maximum_Curvature", "Mean_Curvature", "Gauss_Curvature"):
        print(percentiles_row(name, array(name)))
    if data.GetArray("Exact_Minimum_Curvature") is not None:
        exact_min, exact_max = array("Exact_Minimum_Curvature"), array("Exact_Maximum_Curvature")
        scale = max(numpy.abs(exact_min).max(), numpy.abs(exact_max).max(), 1e-300)
        ok = valid.astype(bool)
        print()
        print("against the exact curvatures in the input (mean |k - exact| / max |exact|):")
        print("  k_min %.5f   k_max %.5f" % (
            numpy.abs(array("Minimum_Curvature")[ok] - exact_min[ok]).mean() / scale,
            numpy.abs(array("Maximum_Curvature")[ok] - exact_max[ok]).mean() / scale))


def main(argv):
    arguments = parse_arguments(argv)
    load_plugin(arguments.plugin)
    source = open_cloud(arguments.input)
    source.UpdatePipeline()  # fills the array lists the filter's domains need
    normals = choose_normals(source, arguments.normals)

    curvatures = simple.PrincipalCurvatures(Input=source)
    curvatures.Normals = ["POINTS", normals]
    curvatures.FitMode = arguments.fit_mode
    curvatures.NumberOfThreads = arguments.threads
    if arguments.neighbors:
        curvatures.NumberOfNeighbors = arguments.neighbors
    if arguments.k_nearest:
        curvatures.NeighborhoodMode = "K Nearest"
    if arguments.radius:
        curvatures.AutomaticThresholds = 0
        curvatures.SurroundingsThreshold = arguments.radius
        curvatures.PlaneDistanceThreshold = arguments.plane_distance or 0.1 * arguments.radius
    if arguments.dynamic_adjustment:
        curvatures.DynamicAdjustment = 1

    start = time.perf_counter()
    curvatures.UpdatePipeline()
    seconds = time.perf_counter() - start

    # Inline binary, not the default appended data: ParaView 5.11 with a
    # current Debian 12 libexpat (2.5.0-1+deb12u2 and later) cannot read
    # appended data (VTK issue 19258).
    writer = simple.XMLPolyDataWriter(Input=curvatures, FileName=arguments.output, DataMode="Binary")
    writer.UpdatePipeline()
    summarize(servermanager.Fetch(curvatures), seconds, arguments.fit_mode)
    print()
    print("wrote %s" % arguments.output)


if __name__ == "__main__":
    main(sys.argv[1:])
