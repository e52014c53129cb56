"""pvpython test of the plugin's Point Cloud Text Reader
(vtkTextPointCloudReader) and of the command-line tool's text input and its
.ply and .csv output.

    pvpython TestTextReader.py PLUGIN.so|--autoload CLOUDS_DIR [PVPYTHON CLI_SCRIPT]

PLUGIN.so is loaded with LoadPlugin; with --autoload the plugin must already
be loaded (PV_PLUGIN_CONFIG_FILE). CLOUDS_DIR holds torus.xyz (6 columns,
from GenerateAnalyticCloud). With PVPYTHON and CLI_SCRIPT
(Tools/estimate_curvatures.py) the tool is run on a copy of torus.xyz to
.ply and .csv outputs, on a copy with colors to .ply, and on a 3-column file (which must either work or
exit with status 2 and a message, never crash).

The reader checks write small files into a temporary folder and read them
with OpenDataFile (the reader factory must choose this reader for .xyz .pwn
.txt .pts: ParaView also offers PLOT3D and the molecule reader for .xyz, the
CSV reader for .txt, its PTS reader for .pts): 3 columns with comments and
blank lines, 6 columns (Normals), 6 columns and colors (Normals, RGB), a PTS
file with its count line (Intensity, RGB), comma and semicolon separated
files, a header of names, CRLF line ends, number syntax, pieces, and bad
files (a non-numeric word, a line with another column count, too few
columns, no points, a missing file), which must report the file and line
and give no points.

Every check prints one line; the exit code is 0 when all pass, 1 otherwise.
"""

import os
import re
import shutil
import subprocess
import struct
import sys
import tempfile

from paraview import servermanager, simple
from vtkmodules.util.misc import calldata_type
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonCore import VTK_DOUBLE, VTK_STRING, VTK_UNSIGNED_CHAR

READER_NAME = "ASCIIPointCloudReader"
from test_checks import check, failures  # noqa: E402 (the tests' folder is on sys.path)


def write(folder, name, text, mode="w"):
    path = os.path.join(folder, name)
    with open(path, mode) as handle:
        handle.write(text)
    return path


class Errors:
    """Collects the error (and, apart, warning) messages of a reader's VTK
    object (builtin session: the client-side object is the reader)."""

    def __init__(self, proxy):
        self.messages = []
        self.warnings = []
        proxy.GetClientSideObject().AddObserver("ErrorEvent", self.on_error)
        proxy.GetClientSideObject().AddObserver("WarningEvent", self.on_warning)

    @calldata_type(VTK_STRING)
    def on_error(self, caller, event, message):
        self.messages.append(message)

    @calldata_type(VTK_STRING)
    def on_warning(self, caller, event, message):
        self.warnings.append(message)

    def text(self):
        return " ".join(self.messages)


def open_file(path, direct=False):
    """A reader for path (OpenDataFile, or the reader's proxy itself with
    direct), its collected errors, and its output, fetched."""
    reader = simple.PointCloudTextReader(FileName=path) if direct else simple.OpenDataFile(path)
    errors = Errors(reader)
    reader.UpdatePipeline()
    return reader, errors, servermanager.Fetch(reader)


def arrays_of(cloud):
    data = cloud.GetPointData()
    return sorted(data.GetArrayName(i) for i in range(data.GetNumberOfArrays()))


def points_of(cloud):
    return vtk_to_numpy(cloud.GetPoints().GetData()).tolist() if cloud.GetNumberOfPoints() else []


def check_read(folder, name, text, points, arrays, label, direct=False, mode="w"):
    """Reads the file name made of text; checks its points (exactly) and
    point arrays; returns the output."""
    path = write(folder, name, text, mode)
    reader, errors, cloud = open_file(path, direct)
    if not direct:
        check(reader.GetXMLName() == READER_NAME,
              "%s: OpenDataFile('%s') chose %s" % (label, name, reader.GetXMLName()))
    check(not errors.messages, "%s: no error (%s)" % (label, errors.text() or "none"))
    check(cloud.GetNumberOfPoints() == len(points), "%s: %d points (expected %d)"
          % (label, cloud.GetNumberOfPoints(), len(points)))
    check(cloud.GetPoints() is not None and cloud.GetPoints().GetDataType() == VTK_DOUBLE,
          "%s: double points" % label)
    check(points_of(cloud) == points, "%s: coordinates %s" % (label, points_of(cloud)[:4]))
    check(cloud.GetNumberOfVerts() == len(points) and cloud.GetNumberOfCells() == len(points),
          "%s: one vertex cell per point (%d)" % (label, cloud.GetNumberOfVerts()))
    check(arrays_of(cloud) == sorted(arrays), "%s: point arrays %s (expected %s)"
          % (label, arrays_of(cloud), sorted(arrays)))
    return cloud


def check_normals(cloud, expected, label):
    normals = cloud.GetPointData().GetNormals()
    check(normals is not None and normals.GetName() == "Normals", "%s: Normals is the normals attribute" % label)
    if normals is not None:
        check(normals.GetDataType() == VTK_DOUBLE and normals.GetNumberOfComponents() == 3,
              "%s: Normals double, 3 components" % label)
        values = vtk_to_numpy(normals).tolist()
        check(values == expected, "%s: normals %s%s" % (label, values[:3], " ..." if len(values) > 3 else ""))


def check_rgb(cloud, expected, label):
    rgb = cloud.GetPointData().GetArray("RGB")
    check(rgb is not None and rgb.GetDataType() == VTK_UNSIGNED_CHAR and rgb.GetNumberOfComponents() == 3,
          "%s: RGB unsigned char, 3 components" % label)
    if rgb is not None:
        check(vtk_to_numpy(rgb).tolist() == expected, "%s: colors %s" % (label, vtk_to_numpy(rgb).tolist()))
        scalars = cloud.GetPointData().GetScalars()
        check(scalars is not None and scalars.GetName() == "RGB", "%s: RGB is the scalars attribute" % label)


def check_bad(folder, name, text, expected, label, direct=False, mode="w"):
    """A bad file: OpenDataFile chooses this reader (unless direct), which
    reports an error naming the file and the expected words; no points."""
    path = write(folder, name, text, mode) if text is not None else os.path.join(folder, name)
    reader, errors, cloud = open_file(path, direct)
    if not direct:
        check(reader.GetXMLName() == READER_NAME,
              "%s: OpenDataFile('%s') chose %s" % (label, name, reader.GetXMLName()))
    message = errors.text()
    check(name in message and all(word in message for word in expected),
          "%s: error names the file and %s: %s" % (label, " ".join(expected), message.strip().splitlines()[-1:]))
    check(cloud.GetNumberOfPoints() == 0, "%s: no points (%d)" % (label, cloud.GetNumberOfPoints()))
    check(reader.GetClientSideObject().GetErrorCode() != 0, "%s: error code set" % label)


def check_reader(folder):
    cloud = check_read(folder, "three.xyz",
                       "# a comment line\n\n   \n1 2 3\n// another comment\n4 5 6 # trailing\n7\t8\t9 // trailing\n\n",
                       [[1, 2, 3], [4, 5, 6], [7, 8, 9]], [], "3 columns")
    check(cloud.GetPointData().GetNormals() is None, "3 columns: no normals")

    cloud = check_read(folder, "six.xyz", "0 0 1 0 0 1\n1 0 0 1 0 0\n0 2 0 0 -1 0\n",
                       [[0, 0, 1], [1, 0, 0], [0, 2, 0]], ["Normals"], "6 columns")
    check_normals(cloud, [[0, 0, 1], [1, 0, 0], [0, -1, 0]], "6 columns")

    cloud = check_read(folder, "color.xyz", "1 2 3 0 0 1 255 0 10\n4 5 6 0 1 0 0 128 255\n",
                       [[1, 2, 3], [4, 5, 6]], ["Normals", "RGB"], "6 columns + RGB")
    check_normals(cloud, [[0, 0, 1], [0, 1, 0]], "6 columns + RGB")
    check_rgb(cloud, [[255, 0, 10], [0, 128, 255]], "6 columns + RGB")

    cloud = check_read(folder, "rgb.xyz", "1 2 3 255 0 10\n4 5 6 0 128 255\n",
                       [[1, 2, 3], [4, 5, 6]], ["RGB"], "x y z r g b")
    check(cloud.GetPointData().GetNormals() is None, "x y z r g b: colors, not normals")
    check_rgb(cloud, [[255, 0, 10], [0, 128, 255]], "x y z r g b")
    cloud = check_read(folder, "axes.xyz", "1 2 3 0 0 1\n4 5 6 1 0 0\n",
                       [[1, 2, 3], [4, 5, 6]], ["Normals"], "axis-aligned normals (0 and 1)")
    check_normals(cloud, [[0, 0, 1], [1, 0, 0]], "axis-aligned normals (0 and 1)")

    cloud = check_read(folder, "oriented.pwn", "1 2 3 0.6 0 0.8\n-1 -2 -3 -0.6 0 -0.8\n",
                       [[1, 2, 3], [-1, -2, -3]], ["Normals"], ".pwn")
    check_normals(cloud, [[0.6, 0, 0.8], [-0.6, 0, -0.8]], ".pwn")

    # Leica PTS: the point count, then x y z intensity r g b.
    cloud = check_read(folder, "scan.pts", "2\n1.5 2.5 3.5 -120 10 20 30\n4 5 6 300 40 50 60\n",
                       [[1.5, 2.5, 3.5], [4, 5, 6]], ["Intensity", "RGB"], ".pts with its count line")
    check(cloud.GetPointData().GetNormals() is None, ".pts: no normals")
    check_rgb(cloud, [[10, 20, 30], [40, 50, 60]], ".pts")
    intensity = cloud.GetPointData().GetArray("Intensity")
    check(intensity is not None and vtk_to_numpy(intensity).tolist() == [-120, 300], ".pts: intensity")

    check_read(folder, "comma.txt", "1.0, 2.0, 3.0\n4.0,5.0,6.0\n7;8;9\n",
               [[1, 2, 3], [4, 5, 6], [7, 8, 9]], [], "comma and semicolon separated .txt")

    cloud = check_read(folder, "four.xyz", "1 2 3 0.5\n4 5 6 -0.25\n", [[1, 2, 3], [4, 5, 6]], ["Column_3"],
                       "4 columns")
    values = cloud.GetPointData().GetArray("Column_3")
    check(values is not None and vtk_to_numpy(values).tolist() == [0.5, -0.25], "4 columns: Column_3 values")

    cloud = check_read(folder, "seven.xyz", "1 2 3 0 0 1 7.5\n4 5 6 0 1 0 8.5\n", [[1, 2, 3], [4, 5, 6]],
                       ["Column_6", "Normals"], "7 columns")
    check_normals(cloud, [[0, 0, 1], [0, 1, 0]], "7 columns")

    # A header of names picks the columns (the command-line tool's rule);
    # .csv is not offered to the reader factory, so the proxy is used itself.
    cloud = check_read(folder, "named.csv", "nz,ny,nx,z,y,x,quality\n1,0,0,3,2,1,0.5\n0,1,0,6,5,4,0.75\n",
                       [[1, 2, 3], [4, 5, 6]], ["Normals", "quality"], "header of names", direct=True)
    check_normals(cloud, [[0, 0, 1], [0, 1, 0]], "header of names")

    check_read(folder, "clash.csv", "x y z nx ny nz Normals\n1 2 3 0 0 1 9\n", [[1, 2, 3]],
               ["Normals", "Normals_6"], "a header column named like an array gets its index", direct=True)

    check_read(folder, "crlf.xyz", b"1 2 3\r\n4 5 6\r\n", [[1, 2, 3], [4, 5, 6]], [], "CRLF line ends", mode="wb")

    cloud = check_read(folder, "syntax.xyz", "+4 -2.5E+3 1e-300\n0.1 .5 -0.\n1e400 -1e400 7\n",
                       [[4, -2500, 1e-300], [0.1, 0.5, -0.0], [float("inf"), float("-inf"), 7]], [],
                       "number syntax (sign, exponent, beyond the double range)")

    # Pieces: piece p of n gets the p-th of n consecutive ranges.
    reader = simple.PointCloudTextReader(FileName=os.path.join(folder, "three.xyz"))
    vtk_reader = reader.GetClientSideObject()
    counts = []
    for piece in range(2):
        vtk_reader.UpdatePiece(piece, 2, 0)
        counts.append(vtk_reader.GetOutputDataObject(0).GetNumberOfPoints())
    check(counts == [1, 2], "pieces: 3 points in 2 pieces as %s" % counts)

    check_bad(folder, "malformed.xyz", "1 2 3\n4 5 6\n# comment\n7 8 x9\n", ["line 4", "x9"],
              "a non-numeric word")
    check_bad(folder, "ragged.xyz", "1 2 3 0 0 1\n\n4 5 6 0 1\n", ["line 3", "5 columns", "line 1"],
              "a line with another column count")
    # Files that ParaView 5.11 gave to the PLOT3D reader (which crashed
    # pvpython and the GUI) while this reader declined them.
    check_bad(folder, "flat.xyz", "1 2\n3 4\n", ["line 1", "2 number(s)", "at least x y z"], "2 columns")
    check_bad(folder, "empty.xyz", "", ["the file is empty", "no points"], "an empty file (0 bytes)")
    check_bad(folder, "comments.pwn", "# only a comment\n\n", ["no points", "2 line(s) are blank or comments"],
              "only comments")
    check_bad(folder, "words.xyz", "hello world\nfoo bar baz\n",
              ["line 2", "'foo' is not a number", "line 1, 'hello world', was taken for a header"], "garbage words")
    check_bad(folder, "title.xyz", "just a title\n", ["line 1", "'just a title'", "no line of numbers follows"],
              "a header and nothing else")
    check_bad(folder, "count.pts", "12\n", ["line 1", "only a point count"], "a point count and nothing else")
    check_bad(folder, "mixed.pts", "1 2 3\n4 5 6\n7 8\n", ["line 3", "2 columns, but line 1 has 3"],
              "mixed column counts, too few numbers on a later line")
    check_bad(folder, "noise.xyz", bytes(range(256)) * 4, ["line 1", "a NUL byte", "not a text file"],
              "binary garbage", mode="wb")
    check_bad(folder, "water.xyz", "3\nwater\nO 0 0 0\nH 0.76 0.59 0\nH -0.76 0.59 0\n",
              ["an XYZ molecule file", "XYZ Reader"], "an XYZ molecule file")
    check_bad(folder, "empty.txt", "", ["the file is empty"], "an empty .txt (reader itself)", direct=True)

    # NaN and infinite coordinates are kept, with one warning naming the
    # first line: the curvature filter flags those points.
    path = write(folder, "nan.xyz", "1 2 3\nnan 5 6\n7 8 9\n10 -inf 12\n")
    reader, errors, cloud = open_file(path)
    check(reader.GetXMLName() == READER_NAME and not errors.messages and cloud.GetNumberOfPoints() == 4,
          "NaN coordinates: kept, no error (%d points)" % cloud.GetNumberOfPoints())
    warning = " ".join(errors.warnings)
    check(len(errors.warnings) == 1 and "2 point(s) with a NaN or infinite coordinate" in warning
          and "line 2" in warning, "NaN coordinates: one warning naming the count and line 2 (%s)"
          % warning.strip().splitlines()[-1:])

    # A binary file that starts as a PLOT3D grid (a Fortran record: its
    # length, three dimensions, its length again) stays with that reader.
    plot3d = write(folder, "grid.xyz", struct.pack("<iiiii", 12, 2, 2, 1, 12) + bytes(64), "wb")
    check(simple.OpenDataFile(plot3d).GetXMLName() == "P3DReader",
          "a binary PLOT3D grid .xyz goes to %s (P3DReader)" % simple.OpenDataFile(plot3d).GetXMLName())
    check_bad(folder, "missing.xyz", None, ["cannot read"], "a missing file (reader itself)", direct=True)
    try:
        simple.OpenDataFile(os.path.join(folder, "missing.xyz"))
        check(False, "a missing file: OpenDataFile raises")
    except RuntimeError as error:
        check("not readable" in str(error), "a missing file: OpenDataFile raises (%s)" % error)

    # .txt is shared with the CSV reader: only a file whose first data line
    # holds x y z is a cloud; tables stay with the CSV reader.
    for name, text in (("table.txt", "name,value\nfirst,1\nsecond,2\n"), ("pairs.txt", "1 2\n3 4\n")):
        reader = simple.OpenDataFile(write(folder, name, text))
        check(reader.GetXMLName() == "CSVReader", "a text table %s goes to %s (CSVReader)"
              % (name, reader.GetXMLName()))


def check_generated(clouds):
    """torus.xyz (GenerateAnalyticCloud: x y z nx ny nz, 20000 lines)."""
    path = os.path.join(clouds, "torus.xyz")
    with open(path) as handle:
        rows = [[float(w) for w in line.split()] for line in handle if line.strip()]
    reader, errors, cloud = open_file(path)
    check(reader.GetXMLName() == READER_NAME, "torus.xyz: OpenDataFile chose %s" % reader.GetXMLName())
    check(cloud.GetNumberOfPoints() == len(rows) == 20000, "torus.xyz: %d points" % cloud.GetNumberOfPoints())
    check(points_of(cloud) == [row[:3] for row in rows], "torus.xyz: coordinates as Python parses them")
    check_normals(cloud, [row[3:] for row in rows], "torus.xyz")
    return rows


def read_ply(path):
    """Header lines and the vertex records (as lists) of a binary
    little-endian PLY file with scalar double/float/uchar properties."""
    with open(path, "rb") as handle:
        data = handle.read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    header = data[:end].decode("ascii").splitlines()
    properties = [line.split()[1:] for line in header if line.startswith("property ")]
    count = int(next(line.split()[2] for line in header if line.startswith("element vertex")))
    code = "<" + "".join({"double": "d", "float": "f", "int": "i", "uchar": "B"}[kind] for kind, _ in properties)
    size = struct.calcsize(code)
    records = [struct.unpack_from(code, data, end + i * size) for i in range(count)]
    return header, [name for _, name in properties], records, len(data) - end - count * size


def check_command_line(folder, clouds, pvpython, script, plugin, rows):
    """The tool on a 6-column .xyz (a copy of torus.xyz) to .ply and .csv;
    on a 3-column .xyz to .ply."""
    source = os.path.join(folder, "torus_copy.xyz")
    shutil.copy(os.path.join(clouds, "torus.xyz"), source)
    plugin_arguments = ["--plugin", plugin] if plugin else []
    scalars = ["Minimum_Curvature", "Maximum_Curvature", "Mean_Curvature", "Gauss_Curvature", "Curvature_Valid"]
    vectors = ["Minimum_Curvature_Direction", "Maximum_Curvature_Direction"]
    for extension in (".ply", ".csv"):
        output = os.path.join(folder, "torus_curvatures" + extension)
        run = subprocess.run([pvpython, script] + plugin_arguments + [source, output],
                             stdout=subprocess.PIPE, stderr=subprocess.STDOUT, universal_newlines=True)
        check(run.returncode == 0 and ("wrote %s" % output) in run.stdout,
              "command line to %s: exit %d %s" % (extension, run.returncode, run.stdout.strip().splitlines()[-1:]))
        if not os.path.isfile(output):
            check(False, "command line wrote %s" % output)
            continue
        if extension == ".ply":
            header, names, records, rest = read_ply(output)
            check(header[:2] == ["ply", "format binary_little_endian 1.0"], "ply: binary little endian header")
            check("element vertex 20000" in header, "ply: element vertex 20000")
            check(names[:6] == ["x", "y", "z", "nx", "ny", "nz"], "ply: properties x y z nx ny nz first")
            check(all(name in names for name in scalars), "ply: scalar properties %s" % " ".join(scalars))
            check(all("%s_%s" % (name, axis) in names for name in vectors for axis in "xyz"),
                  "ply: vector properties <name>_x _y _z")
            check("property double Mean_Curvature" in header, "ply: Mean_Curvature a double property")
            check(rest == 0 and len(records) == 20000, "ply: 20000 records, nothing after them")
            check([list(r[:6]) for r in records[:100]] == [row for row in rows[:100]],
                  "ply: x y z nx ny nz of the first 100 points are the input's")
            ply = simple.PLYReader(FileNames=[output])
            ply.UpdatePipeline()
            check(ply.GetDataInformation().GetNumberOfPoints() == 20000 and "Normals" in ply.PointData.keys(),
                  "ply: ParaView's PLY reader reads it: 20000 points, normals (%s)" % " ".join(ply.PointData.keys()))
            mean = names.index("Mean_Curvature")
            valid = names.index("Curvature_Valid")
            check(all(r[valid] == 1 for r in records) and all(-2 < r[mean] < 2 for r in records),
                  "ply: every point estimated, mean curvature finite and plausible")
        else:
            with open(output) as handle:
                lines = handle.read().splitlines()
            names = lines[0].split(",")
            check(names[:6] == ["x", "y", "z", "nx", "ny", "nz"] and all(n in names for n in scalars)
                  and all("%s_%s" % (n, a) in names for n in vectors for a in "xyz"),
                  "csv: header %s..." % ",".join(names[:8]))
            check(len(lines) == 20001, "csv: header and 20000 rows (%d lines)" % len(lines))
            values = [[float(v) for v in line.split(",")] for line in lines[1:]]
            check(all(len(v) == len(names) for v in values), "csv: every row has %d values" % len(names))
            check([v[:6] for v in values] == rows, "csv: x y z nx ny nz are the input's, exactly")

    # Colors (x y z nx ny nz r g b) go to the PLY file as red green blue.
    colored = write(folder, "colored.xyz", "".join("%r %r %r %r %r %r %d %d %d\n" % (
        tuple(row) + (i % 256, (7 * i) % 256, 255)) for i, row in enumerate(rows)))
    output = os.path.join(folder, "colored.ply")
    run = subprocess.run([pvpython, script] + plugin_arguments + [colored, output],
                         stdout=subprocess.PIPE, stderr=subprocess.STDOUT, universal_newlines=True)
    check(run.returncode == 0, "command line with colors: exit %d" % run.returncode)
    if os.path.isfile(output):
        header, names, records, rest = read_ply(output)
        check(all("property uchar %s" % c in header for c in ("red", "green", "blue")),
              "ply: colors as uchar red green blue")
        red, green = names.index("red"), names.index("green")
        check(all(r[red] == i % 256 and r[green] == (7 * i) % 256 for i, r in enumerate(records)),
              "ply: color values are the input's")

    three = write(folder, "three_columns.xyz", "".join("%r %r %r\n" % tuple(row[:3]) for row in rows[:2000]))
    output = os.path.join(folder, "three_columns.ply")
    run = subprocess.run([pvpython, script] + plugin_arguments + [three, output],
                         stdout=subprocess.PIPE, stderr=subprocess.STDOUT, universal_newlines=True)
    tail = run.stdout.strip().splitlines()[-1:]
    check(run.returncode == 0 and "estimated (outward)" in run.stdout,
          "command line on 3 columns: normals estimated, curvatures written (exit %d, %s)" % (run.returncode, tail))
    if os.path.isfile(output):
        header, names, records, rest = read_ply(output)
        check(names[3:6] == ["nx", "ny", "nz"] and len(records) == 2000,
              "ply from 3 columns: the estimated normals are written")
        mean, valid = names.index("Mean_Curvature"), names.index("Curvature_Valid")
        estimated = [r[mean] for r in records if r[valid] == 1]
        # The torus (R 3, r 1) has mean curvature (1 + r/(R + r cos v)) / 2 > 0
        # with outward normals: a sign error would make it negative.
        check(len(estimated) > 1800 and sum(1 for m in estimated if m > 0) > 0.99 * len(estimated),
              "3 columns: outward normals, positive mean curvature at %d of %d points"
              % (sum(1 for m in estimated if m > 0), len(estimated)))

    # x y z r g b: the colors are colors, never normals.
    rgb_only = write(folder, "rgb_only.xyz", "".join("%r %r %r %d %d %d\n" % (
        tuple(row[:3]) + (i % 256, (7 * i) % 256, 200)) for i, row in enumerate(rows[:2000])))
    output = os.path.join(folder, "rgb_only.ply")
    run = subprocess.run([pvpython, script] + plugin_arguments + [rgb_only, output],
                         stdout=subprocess.PIPE, stderr=subprocess.STDOUT, universal_newlines=True)
    check(run.returncode == 0 and "estimated (outward)" in run.stdout,
          "x y z r g b: colors not taken for normals, normals estimated (exit %d)" % run.returncode)
    run = subprocess.run([pvpython, script] + plugin_arguments + ["--normals", "RGB", rgb_only, output],
                         stdout=subprocess.PIPE, stderr=subprocess.STDOUT, universal_newlines=True)
    check(run.returncode != 0 and "To estimate normals instead" in run.stdout,
          "--normals RGB: refused, with the way to estimate normals (exit %d)" % run.returncode)


def check_command_line_bad_files(folder, pvpython, script, plugin):
    """The tool reads text through the same reader: each bad file exits with
    status 2 and the reader's message (file and line) on stderr; NaN
    coordinates are kept with the same warning. Its stderr, piped, is plain
    text: no terminal color codes, no VTK log prefixes."""
    plugin_arguments = ["--plugin", plugin] if plugin else []
    output = os.path.join(folder, "bad_out.vtp")
    bad = (("cli_empty.xyz", "", "cli_empty.xyz: the file is empty"),
           ("cli_flat.xyz", "1 2\n3 4\n", "cli_flat.xyz: line 1: 2 number(s); a point needs at least x y z"),
           ("cli_words.pwn", "hello world\nfoo bar baz\n", "cli_words.pwn: line 2: 'foo' is not a number"),
           ("cli_mixed.pts", "1 2 3\n4 5 6\n7 8\n", "cli_mixed.pts: line 3: 2 columns, but line 1 has 3"))
    for name, text, expected in bad:
        path = write(folder, name, text)
        run = subprocess.run([pvpython, script] + plugin_arguments + [path, output],
                             stdout=subprocess.PIPE, stderr=subprocess.PIPE, universal_newlines=True)
        check(run.returncode == 2 and ("estimate_curvatures: error: %s" % os.path.join(folder, expected)) in run.stderr,
              "command line on %s: exit %d, %s" % (name, run.returncode, run.stderr.strip().splitlines()[-1:]))
    rows = "".join("%d %d %d\n" % (i % 10, i // 10, (i % 7) * (i % 3)) for i in range(300))
    path = write(folder, "cli_nan.xyz", "nan 0 0\n" + rows)
    run = subprocess.run([pvpython, script] + plugin_arguments + [path, output],
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE, universal_newlines=True)
    check(run.returncode == 0 and "estimate_curvatures: warning: vtkTextPointCloudReader: %s: 1 point(s) with a NaN"
          % path in run.stderr and "bad coordinate" in run.stdout,
          "command line on NaN coordinates: kept, one warning, counted (exit %d, %s)"
          % (run.returncode, run.stderr.strip().splitlines()[:1]))
    check("\x1b[" not in run.stderr, "command line, piped: no terminal color codes on stderr")
    check(re.search(r"\(\s*[0-9.]+s\) \[", run.stderr) is None and "ERROR: In" not in run.stderr,
          "command line, piped: no VTK log prefixes on stderr (%s)" % run.stderr.strip().splitlines()[:1])


def main(argv):
    plugin, clouds = argv[0], argv[1]
    pvpython, script = (argv[2], argv[3]) if len(argv) >= 4 else (None, None)
    if plugin == "--autoload":
        plugin = None
        check(hasattr(simple, "PointCloudTextReader"), "the reader is autoloaded")
    else:
        simple.LoadPlugin(plugin, remote=False)  # without ns: adds to paraview.simple
        check(hasattr(simple, "PointCloudTextReader"), "LoadPlugin provides simple.PointCloudTextReader")
    folder = tempfile.mkdtemp(prefix="text_reader_")
    try:
        if not failures:
            check_reader(folder)
            rows = check_generated(clouds)
            if script:
                check_command_line(folder, clouds, pvpython, script, plugin, rows)
                check_command_line_bad_files(folder, pvpython, script, plugin)
    finally:
        shutil.rmtree(folder, ignore_errors=True)
    print("%d failed" % len(failures))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
