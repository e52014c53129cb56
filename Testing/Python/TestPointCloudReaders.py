"""pvpython test of the plugin's LAS and PLY point-cloud readers through
ParaView and the command-line tool:

    pvpython TestPointCloudReaders.py PLUGIN.so PVPYTHON CLI_SCRIPT

Writes its own files into a temporary folder:

* a 2 m sphere at (596700, 243650, 80), georeferenced, 6000 points with
  exact outward normals, as a binary double PLY: OpenDataFile must choose
  the plugin's PLY reader (over ParaView's PLYReader, which stores float),
  keep the coordinates to 1e-9 and the extra vertex property `label`; the
  command-line tool must give mean curvature 0.5 within 1e-3 at every
  estimated point and keep the double coordinates in its .vtp, .csv and
  .ply outputs (single precision too, since float would move them);
* the same sphere as LAS 1.4 format 7 (no normals; scale 0.0001):
  OpenDataFile must choose the plugin's LAS reader (over GDAL's), and the
  tool must read it, estimate normals and curvatures, and pass the LAS
  arrays through;
* bad files for the tool: a PLY vertex element with only red green blue
  (VTK's reader crashes on it), a LAZ-compressed file: exit status 2 with
  the reader's message.

The tool runs as a program on the two spheres; its writers and its reading
of the bad files are called in this process (as its main() calls them), to
keep the test short.

Every check prints one line; the exit code is 0 when all pass, 1 otherwise.
"""

import io
import math
import os
import shutil
import struct
import subprocess
import sys
import tempfile

import numpy
from paraview import servermanager, simple
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonCore import VTK_DOUBLE
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader

from test_checks import check, failures  # noqa: E402 (the tests' folder is on sys.path)

CENTER = numpy.array([596700.0, 243650.0, 80.0])
RADIUS = 2.0


def sphere(count):
    """Fibonacci points on the sphere and their outward normals."""
    i = numpy.arange(count) + 0.5
    z = 1.0 - 2.0 * i / count
    phi = i * math.pi * (3.0 - math.sqrt(5.0))
    r = numpy.sqrt(1.0 - z * z)
    normals = numpy.column_stack([r * numpy.cos(phi), r * numpy.sin(phi), z])
    return CENTER + RADIUS * normals, normals


def write_ply(path, points, normals):
    """Binary little-endian PLY: double x y z, float nx ny nz, int label."""
    header = ("ply\nformat binary_little_endian 1.0\nelement vertex %d\n"
              "property double x\nproperty double y\nproperty double z\n"
              "property float nx\nproperty float ny\nproperty float nz\n"
              "property int label\nend_header\n" % len(points))
    records = numpy.empty(len(points), dtype=[("x", "<f8"), ("y", "<f8"), ("z", "<f8"), ("nx", "<f4"),
                                              ("ny", "<f4"), ("nz", "<f4"), ("label", "<i4")])
    for k, axis in enumerate("xyz"):
        records[axis] = points[:, k]
        records["n" + axis] = normals[:, k]
    records["label"] = numpy.arange(len(points)) % 7
    with open(path, "wb") as handle:
        handle.write(header.encode("ascii") + records.tobytes())


def write_las(path, points, scale=1e-4, compressed=False):
    """LAS 1.4, point format 7 (RGB), offset the sphere's center."""
    count = len(points)
    offset = CENTER
    integers = numpy.round((points - offset) / scale).astype("<i4")
    record = numpy.zeros(count, dtype=[("xyz", "<i4", 3), ("intensity", "<u2"), ("returns", "u1"),
                                       ("flags", "u1"), ("class", "u1"), ("user", "u1"), ("angle", "<i2"),
                                       ("source", "<u2"), ("gps", "<f8"), ("rgb", "<u2", 3)])
    record["xyz"] = integers
    record["intensity"] = numpy.arange(count) % 65536
    record["returns"] = 1 | (1 << 4)
    record["class"] = 2
    record["gps"] = numpy.arange(count) * 0.5
    record["rgb"] = [1000, 2000, 3000]
    header = bytearray(375)
    header[0:4] = b"LASF"
    header[24], header[25] = 1, 4
    struct.pack_into("<HIIBHI", header, 94, 375, 375, 0, 7 | (0x80 if compressed else 0), 36, count)
    struct.pack_into("<3d3d", header, 131, scale, scale, scale, *offset)
    struct.pack_into("<Q", header, 247, count)
    with open(path, "wb") as handle:
        handle.write(bytes(header) + record.tobytes())
    return integers * scale + offset


def run_tool(pvpython, script, plugin, *arguments):
    done = subprocess.run([pvpython, script, "--plugin", plugin] + list(arguments),
                          stdout=subprocess.PIPE, stderr=subprocess.PIPE, universal_newlines=True)
    return done


def read_vtp(path):
    reader = vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


def check_opened(path, proxy_name, points, arrays, label):
    reader = simple.OpenDataFile(path)
    check(reader is not None and reader.GetXMLName() == proxy_name,
          "%s: OpenDataFile chose %s (expected %s)" % (label, reader and reader.GetXMLName(), proxy_name))
    reader.UpdatePipeline()
    cloud = servermanager.Fetch(reader)
    check(cloud.GetNumberOfPoints() == len(points), "%s: %d points" % (label, cloud.GetNumberOfPoints()))
    if cloud.GetNumberOfPoints() != len(points):
        return
    check(cloud.GetPoints().GetDataType() == VTK_DOUBLE, "%s: double points" % label)
    error = numpy.abs(vtk_to_numpy(cloud.GetPoints().GetData()) - points).max()
    check(error <= 1e-9, "%s: coordinates kept to 1e-9 (largest difference %.3g)" % (label, error))
    have = set(cloud.GetPointData().GetArrayName(i) for i in range(cloud.GetPointData().GetNumberOfArrays()))
    check(set(arrays) <= have, "%s: arrays %s among %s" % (label, " ".join(arrays), " ".join(sorted(have))))


def check_sphere_ply(folder, pvpython, script, plugin):
    points, normals = sphere(6000)
    path = os.path.join(folder, "sphere_georeferenced.ply")
    write_ply(path, points, normals)
    check_opened(path, "APLYPointCloudReader", points, ["Normals", "label"], "double PLY")
    output = os.path.join(folder, "sphere_curvatures.vtp")
    done = run_tool(pvpython, script, plugin, path, output)
    check(done.returncode == 0, "tool on the double PLY: exit %d %s" % (done.returncode, done.stderr[-300:]))
    if done.returncode != 0:
        return
    result = read_vtp(output)
    valid = vtk_to_numpy(result.GetPointData().GetArray("Curvature_Valid")) == 1
    mean = vtk_to_numpy(result.GetPointData().GetArray("Mean_Curvature"))[valid]
    check(valid.sum() > 0.99 * len(points), "tool: %d of %d points estimated" % (valid.sum(), len(points)))
    worst = numpy.abs(mean - 0.5).max() if len(mean) else float("inf")
    check(worst <= 1e-3, "tool: mean curvature 0.5 within 1e-3 at every estimated point (worst %.3g, "
          "range %.6g to %.6g)" % (worst, mean.min(), mean.max()))
    out_points = vtk_to_numpy(result.GetPoints().GetData())
    check(result.GetPoints().GetDataType() == VTK_DOUBLE and numpy.abs(out_points - points).max() <= 1e-9,
          "tool: the .vtp keeps the double coordinates to 1e-9")
    # The tool's writers (called in the tool's process as main() calls them,
    # to keep the test short) on its result.
    tool = load_tool(script)
    csv = os.path.join(folder, "sphere_curvatures.csv")
    tool.write_csv(result, "Normals", csv)
    values = numpy.loadtxt(csv, delimiter=",", skiprows=1, usecols=(0, 1, 2))
    check(numpy.abs(values - points).max() <= 1e-9, "tool: the .csv keeps the coordinates to 1e-9")
    for single in (False, True):
        ply = os.path.join(folder, "sphere_curvatures_%s.ply" % single)
        tool.write_ply(result, "Normals", ply, single)
        reader = simple.PLYPointCloudReader(FileName=ply)
        reader.UpdatePipeline()
        cloud = servermanager.Fetch(reader)
        ok = cloud.GetNumberOfPoints() == len(points) and cloud.GetPoints().GetDataType() == VTK_DOUBLE
        check(ok and numpy.abs(vtk_to_numpy(cloud.GetPoints().GetData()) - points).max() <= 1e-9,
              "tool: the .ply (single precision %s) keeps the double coordinates to 1e-9" % single)


def load_tool(script):
    """Tools/estimate_curvatures.py as a module (its main() not run)."""
    sys.path.insert(0, os.path.dirname(os.path.abspath(script)))
    import estimate_curvatures

    return estimate_curvatures


def check_las(folder, pvpython, script, plugin):
    points, _ = sphere(4000)
    path = os.path.join(folder, "sphere.las")
    stored = write_las(path, points)
    arrays = ["Intensity", "ReturnNumber", "NumberOfReturns", "Classification", "ScanAngle", "GpsTime",
              "Red", "Green", "Blue"]
    check_opened(path, "ALASPointCloudReader", stored, arrays, "LAS 1.4 format 7")
    output = os.path.join(folder, "sphere_las_curvatures.vtp")
    done = run_tool(pvpython, script, plugin, path, output)
    check(done.returncode == 0 and "estimated (outward)" in done.stdout,
          "tool on the LAS file: exit %d, normals estimated %s" % (done.returncode, done.stderr[-300:]))
    if done.returncode == 0:
        result = read_vtp(output)
        data = result.GetPointData()
        check(all(data.GetArray(name) is not None for name in arrays), "tool: the LAS arrays are passed through")
        valid = vtk_to_numpy(data.GetArray("Curvature_Valid")) == 1
        mean = numpy.median(vtk_to_numpy(data.GetArray("Mean_Curvature"))[valid])
        check(abs(mean - 0.5) < 1e-2, "tool on the LAS sphere: median mean curvature %.5f (0.5)" % mean)


def check_bad_files(folder, pvpython, script, plugin):
    colors = os.path.join(folder, "colors_only.ply")
    with open(colors, "w") as handle:
        handle.write("ply\nformat ascii 1.0\nelement vertex 2\nproperty uchar red\nproperty uchar green\n"
                     "property uchar blue\nend_header\n1 2 3\n4 5 6\n")
    laz = os.path.join(folder, "compressed.laz")
    write_las(laz, sphere(10)[0], compressed=True)
    # The tool's reading (open_cloud) in this process: it exits with status
    # 2 and the message on stderr.
    tool = load_tool(script)
    for path, expected in ((colors, "the vertex element has no x, y, z properties (it has: red green blue)"),
                           (laz, "the file is LAZ-compressed")):
        stderr, sys.stderr = sys.stderr, io.StringIO()
        try:
            tool.open_cloud(path)
            status = 0
        except SystemExit as exit:
            status = exit.code
        message, sys.stderr = sys.stderr.getvalue(), stderr
        check(status == 2 and expected in message and path in message,
              "tool on %s: exit %s, %s" % (os.path.basename(path), status, message.strip()))


def main(argv):
    plugin, pvpython, script = argv[:3]
    simple.LoadPlugin(plugin, remote=False)
    folder = tempfile.mkdtemp(prefix="cloud_readers_")
    try:
        check_sphere_ply(folder, pvpython, script, plugin)
        check_las(folder, pvpython, script, plugin)
        check_bad_files(folder, pvpython, script, plugin)
    finally:
        shutil.rmtree(folder, ignore_errors=True)
    print("%d failed" % len(failures))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
