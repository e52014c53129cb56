"""pvpython test of the plugin's PLY and CSV writers through ParaView's
writer factory, as File > Save Data and SaveData() use it:

    pvpython TestPointCloudWriters.py PLUGIN.so
    mpiexec -n 2 pvbatch --mpi TestPointCloudWriters.py PLUGIN.so --distributed

On a georeferenced sphere (coordinates near 637180 and 4.1e6, double, one
point at exactly 637180.123456) read with the plugin's PLY reader and run
through the curvature filter:

* the writer factory must pick the plugin's writers for .ply and .csv (over
  ParaView's PPLYWriter, CSVWriter and DataSetCSVWriter), and still
  ParaView's CSVWriter for a table;
* SaveData('x.ply') must keep the double coordinates bit for bit and every
  point array of the filter's output (names, types, components, values
  bit for bit, NaN included) when the plugin's PLY reader reads it back,
  and the field data Curvature_Unit;
* SaveData('x.csv') must keep every coordinate exactly (full precision, not
  ParaView's 5 digits) and the curvature arrays.

With --distributed (pvbatch on several ranks, each reading a piece), the
factory must still pick the plugin's writers, and both files must hold
every rank's points, in order, bit for bit (the writers gather the pieces).

Every check prints one line; the exit code is 0 when all pass, 1 otherwise.
"""

import math
import os
import shutil
import sys
import tempfile

import numpy
from paraview import servermanager, simple
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonCore import VTK_DOUBLE, VTK_ID_TYPE, VTK_LONG, VTK_LONG_LONG

from test_checks import check, failures  # noqa: E402 (the tests' folder is on sys.path)

CENTER = numpy.array([637180.123456, 4100000.654321, 12.25])
RADIUS = 2.0
SIXTY_FOUR_BIT = (VTK_ID_TYPE, VTK_LONG, VTK_LONG_LONG)


def sphere_file(path, count=3000):
    """A Fibonacci sphere as a binary double PLY with outward normals; point
    0 moved onto the center's exact coordinates (a value the CSV must keep)."""
    i = numpy.arange(count) + 0.5
    z = 1.0 - 2.0 * i / count
    phi = i * math.pi * (3.0 - math.sqrt(5.0))
    r = numpy.sqrt(1.0 - z * z)
    normals = numpy.column_stack([r * numpy.cos(phi), r * numpy.sin(phi), z])
    points = CENTER + RADIUS * normals
    points[0] = CENTER
    header = ("ply\nformat binary_little_endian 1.0\nelement vertex %d\n"
              "property double x\nproperty double y\nproperty double z\n"
              "property double nx\nproperty double ny\nproperty double nz\nend_header\n" % count)
    records = numpy.empty(count, dtype=[(name, "<f8") for name in ("x", "y", "z", "nx", "ny", "nz")])
    for k, axis in enumerate("xyz"):
        records[axis] = points[:, k]
        records["n" + axis] = normals[:, k]
    with open(path, "wb") as handle:
        handle.write(header.encode("ascii") + records.tobytes())
    return points


def chosen_writer(path, proxy):
    """The writer proxy ParaView's writer factory creates for path (as File >
    Save Data and SaveData do)."""
    factory = servermanager.vtkSMProxyManager.GetProxyManager().GetWriterFactory()
    writer = factory.CreateWriter(path, proxy.SMProxy, 0)
    name = writer.GetXMLName() if writer else None
    if writer:
        writer.UnRegister(None)
    return name


def same_values(a, b):
    """Bit for bit (NaN's included)."""
    a, b = vtk_to_numpy(a), vtk_to_numpy(b)
    return a.shape == b.shape and a.tobytes() == b.tobytes()


def check_ply(folder, curvatures, result):
    path = os.path.join(folder, "curvatures.ply")
    simple.SaveData(path, proxy=curvatures)
    with open(path, "rb") as handle:
        start = handle.read(200)
    check(b"written by the PrincipalCurvatures plugin" in start, "SaveData('x.ply') used the plugin's writer")
    reader = simple.PLYPointCloudReader(FileName=path)
    reader.UpdatePipeline()
    cloud = servermanager.Fetch(reader)
    check(cloud.GetNumberOfPoints() == result.GetNumberOfPoints(), "ply: %d points" % cloud.GetNumberOfPoints())
    check(cloud.GetPoints().GetDataType() == VTK_DOUBLE
          and same_values(cloud.GetPoints().GetData(), result.GetPoints().GetData()),
          "ply: double coordinates, bit for bit")
    data, read = result.GetPointData(), cloud.GetPointData()
    for i in range(data.GetNumberOfArrays()):
        original = data.GetArray(i)
        if original is None:
            continue
        name = original.GetName()
        back = read.GetArray(name)
        expected = VTK_DOUBLE if original.GetDataType() in SIXTY_FOUR_BIT else original.GetDataType()
        ok = (back is not None and back.GetDataType() == expected
              and back.GetNumberOfComponents() == original.GetNumberOfComponents())
        if ok and expected == original.GetDataType():
            ok = same_values(back, original)
        elif ok:
            ok = numpy.array_equal(vtk_to_numpy(back), vtk_to_numpy(original).astype(numpy.float64))
        check(ok, "ply: %s (%s, %d components) read back the same" % (
            name, original.GetDataTypeAsString(), original.GetNumberOfComponents()))
    check(read.GetNumberOfArrays() == data.GetNumberOfArrays(),
          "ply: %d arrays read back (%d written)" % (read.GetNumberOfArrays(), data.GetNumberOfArrays()))
    unit = cloud.GetFieldData().GetAbstractArray("Curvature_Unit")
    check(unit is not None and unit.GetValue(0).startswith("1/"), "ply: field data Curvature_Unit")


def check_csv(folder, curvatures, result, points):
    path = os.path.join(folder, "curvatures.csv")
    simple.SaveData(path, proxy=curvatures)
    with open(path) as handle:
        names = handle.readline().strip().split(",")
        first = handle.readline()
    check(names[:3] == ["x", "y", "z"] and "Mean_Curvature" in names and "Maximum_Curvature_Direction_x" in names,
          "csv: header x,y,z ... Mean_Curvature ... (%s ...)" % ",".join(names[:8]))
    check(first.startswith("637180.123456,4100000.654321,12.25,"),
          "csv: the point at 637180.123456 written in full (%s...)" % first[:40])
    values = numpy.genfromtxt(path, delimiter=",", skip_header=1)
    out = vtk_to_numpy(result.GetPoints().GetData())
    check(values.shape[0] == len(points) and numpy.array_equal(values[:, :3], out),
          "csv: every coordinate exact")
    mean = vtk_to_numpy(result.GetPointData().GetArray("Mean_Curvature"))
    column = values[:, names.index("Mean_Curvature")]
    check(numpy.array_equal(column, mean, equal_nan=True), "csv: Mean_Curvature exact")


def read_binary_ply(path):
    """The header lines and the vertex records of a binary little-endian PLY
    file without faces."""
    types = {"char": "i1", "uchar": "u1", "short": "<i2", "ushort": "<u2", "int": "<i4", "uint": "<u4",
             "float": "<f4", "double": "<f8"}
    with open(path, "rb") as handle:
        data = handle.read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    header = data[:end].decode("ascii").splitlines()
    dtype = [(line.split()[2], types[line.split()[1]]) for line in header if line.startswith("property ")]
    return header, numpy.frombuffer(data, dtype=dtype, offset=end)


def check_distributed(folder, curvatures, points):
    """Under MPI (pvbatch on several ranks, each holding a piece): the
    factory still picks the plugin's writers, and each file holds every
    rank's points, in order, with the arrays and field data."""
    ranks = servermanager.vtkProcessModule.GetProcessModule().GetNumberOfLocalPartitions()
    for extension, expected in (("ply", "APLYPointCloudWriter"), ("csv", "ACSVPointCloudWriter")):
        name = chosen_writer(os.path.join(folder, "x." + extension), curvatures)
        check(name == expected, "%d ranks, .%s: the writer factory picks %s (%s)" % (ranks, extension, expected, name))
    path = os.path.join(folder, "distributed.ply")
    simple.SaveData(path, proxy=curvatures)
    header, records = read_binary_ply(path)
    check(len(records) == len(points) and all(
        numpy.array_equal(records[axis], points[:, k]) for k, axis in enumerate("xyz")),
        "%d ranks: the .ply holds every rank's points in order, bit for bit (%d of %d)"
        % (ranks, len(records), len(points)))
    check("property double Mean_Curvature" in header and any(
        line.startswith("comment field Curvature_Unit 1/") for line in header),
        "%d ranks: the .ply has Mean_Curvature and the field data" % ranks)
    path = os.path.join(folder, "distributed.csv")
    simple.SaveData(path, proxy=curvatures)
    values = numpy.genfromtxt(path, delimiter=",", skip_header=1)
    check(values.shape[0] == len(points) and numpy.array_equal(values[:, :3], points),
          "%d ranks: the .csv holds every rank's points in order, exactly" % ranks)


def main(argv):
    plugin = argv[1]
    simple.LoadPlugin(plugin, remote=False)
    folder = tempfile.mkdtemp(prefix="pcurv_writers_")
    try:
        points = sphere_file(os.path.join(folder, "sphere.ply"))
        source = simple.OpenDataFile(os.path.join(folder, "sphere.ply"))
        source.UpdatePipeline()
        curvatures = simple.PrincipalCurvatures(Input=source)
        curvatures.UpdatePipeline()
        if "--distributed" in argv:
            check_distributed(folder, curvatures, points)
            return finish(folder)
        result = servermanager.Fetch(curvatures)
        check(result.GetPointData().GetArray("Mean_Curvature") is not None, "the filter ran")
        for extension, expected in (("ply", "APLYPointCloudWriter"), ("csv", "ACSVPointCloudWriter")):
            name = chosen_writer(os.path.join(folder, "x." + extension), curvatures)
            check(name == expected, ".%s: the writer factory picks %s (%s)" % (extension, expected, name))
        table = simple.ProgrammableSource(OutputDataSetType="vtkTable")
        table.Script = "output.RowData.append(numpy.arange(3.0), 'a')"
        table.UpdatePipeline()
        name = chosen_writer(os.path.join(folder, "t.csv"), table)
        check(name == "CSVWriter", ".csv of a table: still ParaView's CSVWriter (%s)" % name)
        check_ply(folder, curvatures, result)
        check_csv(folder, curvatures, result, points)
    except BaseException:
        shutil.rmtree(folder, ignore_errors=True)
        raise
    return finish(folder)


def finish(folder):
    shutil.rmtree(folder, ignore_errors=True)
    print("%d failed" % len(failures))
    return 1 if failures else 0


if __name__ == "__main__":
    status = main(sys.argv)
    # Under pvbatch --mpi the script runs on rank 0 only: sys.exit there
    # skips the final barrier and the other ranks are killed. Exit only on
    # failure; the "N failed" line is the result.
    if status:
        sys.exit(status)
