"""pvpython test of the plugin's LAS writer and of the units a LAS file
declares, through ParaView and the command-line tool:

    pvpython TestLASWriter.py PLUGIN.so PVPYTHON CLI_SCRIPT

Writes its own files into a temporary folder:

* a 20 ft sphere as LAS 1.2 format 3 with GeoTIFF keys (EPSG:2231, US
  survey feet): the reader's field data must say Length_Unit "US survey
  foot" and Coordinate_System "EPSG:2231"; the curvature filter's
  Curvature_Unit "1/US survey foot"; SaveData('out.las') must write LAS 1.4
  that reads back with every curvature array (vectors as 3 components)
  equal to the filter's output, the lidar arrays, the unit and the
  coordinates within the file's scale;
* the same sphere without the keys: Curvature_Unit keeps the old text;
  ParaView's CSV writer prints its ScanAngleRank as numbers;
* the command-line tool on the feet sphere writing .las: exit 0, the
  summary shows the coordinate system and the unit, the output has the
  curvature arrays.

Every check prints one line; the exit code is 0 when all pass, 1 otherwise.
"""

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

from test_checks import check, failures  # noqa: E402 (the tests' folder is on sys.path)

CENTER = numpy.array([2200000.0, 7100000.0, 600.0])  # feet
RADIUS = 20.0
SCALE = 0.001
CURVATURE_ARRAYS = ("Mean_Curvature", "Gauss_Curvature", "Minimum_Curvature", "Maximum_Curvature",
                    "Minimum_Curvature_Direction", "Maximum_Curvature_Direction", "Normals",
                    "Curvature_Valid", "Neighbor_Count")


def sphere(count):
    i = numpy.arange(count) + 0.5
    z = 1.0 - 2.0 * i / count
    phi = i * math.pi * (3.0 - math.sqrt(5.0))
    r = numpy.sqrt(1.0 - z * z)
    return CENTER + RADIUS * numpy.column_stack([r * numpy.cos(phi), r * numpy.sin(phi), z])


def geokeys(code, unit):
    """A GeoKeyDirectory: projected, EPSG system `code`, linear unit `unit`."""
    keys = [1, 1, 0, 3, 1024, 0, 1, 1, 3072, 0, 1, code, 3076, 0, 1, unit]
    return struct.pack("<%dH" % len(keys), *keys)


def write_las12(path, points, with_keys):
    """LAS 1.2, point format 3 (GPS time, RGB), optionally with GeoTIFF keys."""
    count = len(points)
    vlr = b""
    if with_keys:
        payload = geokeys(2231, 9003)
        vlr = struct.pack("<H16sHH32s", 0, b"LASF_Projection", 34735, len(payload), b"") + payload
    record = numpy.zeros(count, dtype=[("xyz", "<i4", 3), ("intensity", "<u2"), ("returns", "u1"),
                                       ("class", "u1"), ("rank", "i1"), ("user", "u1"), ("source", "<u2"),
                                       ("gps", "<f8"), ("rgb", "<u2", 3)])
    record["xyz"] = numpy.round((points - CENTER) / SCALE).astype("<i4")
    record["intensity"] = numpy.arange(count) % 4000
    record["returns"] = 1 | (1 << 3)
    record["class"] = 6
    record["rank"] = (numpy.arange(count) % 61) - 30
    record["source"] = 17
    record["gps"] = numpy.arange(count) * 0.25
    record["rgb"] = [100, 20000, 65535]
    header = bytearray(227)
    header[0:4] = b"LASF"
    header[24], header[25] = 1, 2
    struct.pack_into("<HIIBHI", header, 94, 227, 227 + len(vlr), 1 if with_keys else 0, 3, 34, count)
    struct.pack_into("<3d3d", header, 131, SCALE, SCALE, SCALE, *CENTER)
    with open(path, "wb") as handle:
        handle.write(bytes(header) + vlr + record.tobytes())


def field_string(cloud, name):
    array = cloud.GetFieldData().GetAbstractArray(name)
    return array.GetValue(0) if array is not None and array.GetNumberOfValues() else None


def arrays_of(cloud):
    data = cloud.GetPointData()
    return {data.GetArrayName(i): vtk_to_numpy(data.GetArray(i)) for i in range(data.GetNumberOfArrays())}


def check_save_data(folder, path):
    reader = simple.OpenDataFile(path)
    check(reader is not None and reader.GetXMLName() == "ALASPointCloudReader", "feet: the LAS reader")
    reader.UpdatePipeline()
    cloud = servermanager.Fetch(reader)
    check(field_string(cloud, "Length_Unit") == "US survey foot",
          "feet: Length_Unit %r" % field_string(cloud, "Length_Unit"))
    check(field_string(cloud, "Coordinate_System") == "EPSG:2231",
          "feet: Coordinate_System %r" % field_string(cloud, "Coordinate_System"))
    curvatures = simple.PrincipalCurvatures(Input=reader)
    curvatures.UpdatePipeline()
    result = servermanager.Fetch(curvatures)
    check(field_string(result, "Curvature_Unit") == "1/US survey foot",
          "feet: Curvature_Unit %r" % field_string(result, "Curvature_Unit"))
    # What File > Save Data offers for the curvatures (the GUI's dialog asks
    # the same writer factory).
    factory = servermanager.vtkSMProxyManager.GetProxyManager().GetWriterFactory()
    offered = factory.GetSupportedFileTypes(curvatures.SMProxy, 0)
    check("LAS lidar point files(*.las )" in offered, "File > Save Data offers .las (%s)" % offered[:200])
    out = os.path.join(folder, "saved.las")
    simple.SaveData(out, proxy=curvatures)
    check(os.path.isfile(out), "SaveData wrote %s" % out)
    if not os.path.isfile(out):
        return
    with open(out, "rb") as handle:
        head = handle.read(375)
    check(head[:4] == b"LASF" and head[24:26] == b"\x01\x04", "SaveData: LAS 1.4")
    check(head[104] == 7, "SaveData: point format 7 (the input has colors), got %d" % head[104])
    again = simple.OpenDataFile(out)
    again.UpdatePipeline()
    saved = servermanager.Fetch(again)
    check(saved.GetNumberOfPoints() == result.GetNumberOfPoints(), "saved: %d points" % saved.GetNumberOfPoints())
    before, after = arrays_of(result), arrays_of(saved)
    for name in CURVATURE_ARRAYS + ("Intensity", "Classification", "GpsTime", "Red", "PointSourceId"):
        same = name in after and before[name].shape == after[name].shape and \
            numpy.array_equal(before[name], after[name], equal_nan=True)
        check(same, "saved: %s read back equal %s" % (name, after[name].shape if name in after else "(missing)"))
    rank, angle = before["ScanAngleRank"], after.get("ScanAngle")
    check(angle is not None and numpy.abs(angle - rank).max() <= 0.0031,
          "saved: ScanAngleRank as ScanAngle within 0.003 degrees")
    error = numpy.abs(vtk_to_numpy(saved.GetPoints().GetData()) - vtk_to_numpy(result.GetPoints().GetData())).max()
    check(error <= SCALE / 2 + 1e-9, "saved: coordinates within half the scale (%.3g)" % error)
    check(field_string(saved, "Length_Unit") == "US survey foot", "saved: the unit kept")
    simple.Delete(again)
    simple.Delete(curvatures)
    simple.Delete(reader)


def check_no_crs(path):
    reader = simple.OpenDataFile(path)
    curvatures = simple.PrincipalCurvatures(Input=reader)
    curvatures.UpdatePipeline()
    result = servermanager.Fetch(curvatures)
    unit = field_string(result, "Curvature_Unit")
    check(unit == "1/length unit of the input coordinates", "no CRS: Curvature_Unit %r" % unit)
    simple.Delete(curvatures)
    simple.Delete(reader)


def check_csv_scan_angle(path, folder):
    """ParaView's CSV writer on a legacy file: ScanAngleRank (a short) as
    numbers, the file text only (a signed char was written as a raw byte)."""
    reader = simple.LASPointCloudReader(FileName=path)
    out = os.path.join(folder, "legacy.csv")
    writer = simple.CSVWriter(Input=reader, FileName=out)
    writer.UpdatePipeline()
    with open(out, "rb") as handle:
        data = handle.read()
    check(all(32 <= b < 127 or b in (10, 13) for b in data), "CSV of a legacy LAS: text only")
    lines = data.decode("ascii", "replace").splitlines()
    names = [n.strip('"') for n in lines[0].split(",")]
    column = names.index("ScanAngleRank") if "ScanAngleRank" in names else None
    values = [int(float(line.split(",")[column])) for line in lines[1:4]] if column is not None else []
    check(values == [-30, -29, -28], "CSV: ScanAngleRank as numbers %s" % values)
    simple.Delete(writer)
    simple.Delete(reader)


def check_tool(pvpython, script, plugin, path, folder):
    out = os.path.join(folder, "tool.las")
    done = subprocess.run([pvpython, script, "--plugin", plugin, path, out],
                          stdout=subprocess.PIPE, stderr=subprocess.PIPE, universal_newlines=True)
    check(done.returncode == 0, "tool: exit %d" % done.returncode)
    check("error" not in done.stderr.lower(), "tool: no error message (%s)" % done.stderr.strip()[-300:])
    lines = done.stdout.splitlines()
    check(any(l.startswith("length unit") and l.endswith("US survey foot") for l in lines),
          "tool: the summary shows the length unit")
    check(any(l.startswith("coordinate system") and "EPSG:2231" in l for l in lines),
          "tool: the summary shows the coordinate system")
    check(any(l.startswith("curvature unit") and "1/US survey foot" in l for l in lines),
          "tool: the summary shows the curvature unit in feet")
    if not os.path.isfile(out):
        check(False, "tool: wrote %s" % out)
        return
    reader = simple.LASPointCloudReader(FileName=out)
    reader.UpdatePipeline()
    arrays = arrays_of(servermanager.Fetch(reader))
    check(all(name in arrays for name in CURVATURE_ARRAYS),
          "tool: the .las has %s" % " ".join(sorted(arrays)))
    direction = arrays.get("Maximum_Curvature_Direction")
    check(direction is not None and direction.shape[1:] == (3,), "tool: directions as 3 components")
    valid = arrays["Curvature_Valid"].astype(bool) if "Curvature_Valid" in arrays else None
    if valid is not None and valid.any():
        median = float(numpy.median(arrays["Mean_Curvature"][valid]))
        check(abs(median - 1 / RADIUS) < 1e-3, "tool: median mean curvature %.5f (1/20 ft)" % median)
    simple.Delete(reader)


def main(argv):
    plugin, pvpython, script = argv[:3]
    simple.LoadPlugin(plugin, remote=False)
    folder = tempfile.mkdtemp(prefix="pcurv_las_writer_")
    try:
        points = sphere(4000)
        feet = os.path.join(folder, "sphere_feet.las")
        plain = os.path.join(folder, "sphere_plain.las")
        write_las12(feet, points, True)
        write_las12(plain, points, False)
        check_save_data(folder, feet)
        check_no_crs(plain)
        check_csv_scan_angle(plain, folder)
        check_tool(pvpython, script, plugin, feet, folder)
    finally:
        shutil.rmtree(folder, ignore_errors=True)
    print("%d failed" % len(failures))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
