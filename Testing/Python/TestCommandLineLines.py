"""The command-line tool's --lines: the curvature lines next to the
curvatures, as .vtp and as PLY vertices and edges, and their summary.

    pvpython TestCommandLineLines.py TOOL.py PLUGIN.so FOLDER

An extruded Gaussian bump z = 0.5 exp(-x^2 / 2) over [-4, 4]^2 (30000
jittered grid points with exact normals, fixed seed), whose ridge runs
along x = 0 and whose valleys along x = +-1.77:

* --lines: OUTPUT's stem + _lines.vtp, a ridge and two valleys where they
  are, and the summary's count per kind and total length;
* --lines=X.ply: a vertex element with Line_Curvature and an edge element
  with Line_Kind, Line_Strength and Line_Length read back equal to the
  .vtp's, as many edges as points minus open polylines; VTK's PLY reader
  reads its vertices, the plugin's PLY reader its edges as lines with
  their arrays;
* bad paths (another extension, a missing folder, the output itself): exit
  2 with a message naming the problem, before any estimate.

Every check prints one line; the exit code is 0 when all pass, 1 otherwise.
"""

import os
import shutil
import subprocess
import sys

import numpy
from paraview import servermanager, simple
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOPLY import vtkPLYReader
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader

from test_checks import check, failures  # noqa: E402 (the tests' folder is on sys.path)

VALLEY_X = 1.7725  # where the profile's curvature is least, for this height


def write_bump(path):
    rng = numpy.random.default_rng(5)
    side, half = 173, 4.0
    step = 2.0 * half / side
    grid = (numpy.arange(side) + 0.5) * step - half
    x, y = numpy.meshgrid(grid, grid)
    x = (x + rng.uniform(-0.3, 0.3, x.shape) * step).ravel()
    y = (y + rng.uniform(-0.3, 0.3, y.shape) * step).ravel()
    z = 0.5 * numpy.exp(-0.5 * x * x)
    normals = numpy.column_stack([x * z, numpy.zeros_like(x), numpy.ones_like(x)])
    normals /= numpy.linalg.norm(normals, axis=1)[:, None]
    numpy.savetxt(path, numpy.column_stack([x, y, z, normals]), fmt="%.9g")


def run(tool, plugin, *arguments):
    command = [shutil.which("pvpython") or "pvpython", tool, "--plugin", plugin] + list(arguments)
    return subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)


def read_vtp(path):
    reader = vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


def polylines(lines):
    offsets = vtk_to_numpy(lines.GetLines().GetOffsetsArray())
    ids = vtk_to_numpy(lines.GetLines().GetConnectivityArray())
    return [ids[offsets[i]:offsets[i + 1]] for i in range(len(offsets) - 1)]


def read_ply(path):
    """(header lines, vertices, edges) of a binary little-endian PLY of
    vertices and edges, read with numpy from its header's types."""
    types = {"double": "<f8", "float": "<f4", "int": "<i4", "uchar": "u1"}
    with open(path, "rb") as handle:
        header = []
        while not header or header[-1] != "end_header":
            header.append(handle.readline().decode("ascii").strip())
        elements = []
        for line in header:
            words = line.split()
            if words[0] == "element":
                elements.append((words[1], int(words[2]), []))
            elif words[0] == "property":
                elements[-1][2].append((words[2], types[words[1]]))
        data = {name: numpy.fromfile(handle, dtype=fields, count=count) for name, count, fields in elements}
    return header, data.get("vertex"), data.get("edge")


def check_vtp(lines, stdout):
    kinds = vtk_to_numpy(lines.GetCellData().GetArray("Line_Kind"))
    check(sorted(set(kinds.tolist())) == [0, 1], "vtp: ridges and valleys (%s)" % sorted(set(kinds.tolist())))
    points = vtk_to_numpy(lines.GetPoints().GetData()).reshape(-1, 3)
    cells = polylines(lines)
    ridge_x = numpy.concatenate([points[ids, 0] for ids, kind in zip(cells, kinds) if kind == 0])
    valley_x = numpy.concatenate([points[ids, 0] for ids, kind in zip(cells, kinds) if kind == 1])
    check(numpy.percentile(numpy.abs(ridge_x), 95) < 0.2, "vtp: the ridge along x = 0")
    check(numpy.percentile(numpy.abs(numpy.abs(valley_x) - VALLEY_X), 95) < 0.3, "vtp: the valleys at x = +-1.77")
    length = vtk_to_numpy(lines.GetCellData().GetArray("Line_Length")).sum()
    check("curvature lines            %d (length %.6g in all)" % (len(kinds), length) in stdout,
          "summary: the lines and their total length")
    check("  ridge " in stdout and "  valley " in stdout, "summary: the lines by kind")


def check_ply(path, lines):
    header, vertices, edges = read_ply(path)
    check("element edge %d" % len(edges) in header and "property uchar Line_Kind" in header,
          "ply: an edge element with Line_Kind")
    cells = polylines(lines)
    closed = sum(1 for ids in cells if ids[0] == ids[-1])
    check(len(edges) == lines.GetNumberOfPoints() - len(cells) + closed,
          "ply: edges = points - open polylines (%d)" % len(edges))
    points = vtk_to_numpy(lines.GetPoints().GetData()).reshape(-1, 3)
    check(numpy.array_equal(numpy.column_stack([vertices["x"], vertices["y"], vertices["z"]]), points),
          "ply: the vertices are the .vtp's points")
    check(numpy.array_equal(vertices["Line_Curvature"],
                            vtk_to_numpy(lines.GetPointData().GetArray("Line_Curvature"))),
          "ply: Line_Curvature per vertex")
    line_of_edge = numpy.repeat(numpy.arange(len(cells)), [len(ids) - 1 for ids in cells])
    expected_first = numpy.concatenate([ids[:-1] for ids in cells])
    check(numpy.array_equal(edges["vertex1"], expected_first), "ply: vertex1 vertex2 follow the polylines")
    same = all(numpy.array_equal(edges[name], vtk_to_numpy(lines.GetCellData().GetArray(name))[line_of_edge])
               for name in ("Line_Kind", "Line_Strength", "Line_Length"))
    check(same, "ply: each edge has its line's Line_Kind, Line_Strength and Line_Length")
    reader = vtkPLYReader()
    reader.SetFileName(path)
    reader.Update()
    check(reader.GetOutput().GetNumberOfPoints() == len(vertices), "ply: VTK's PLY reader reads the vertices")
    plugin_reader = simple.PLYPointCloudReader(FileName=path)
    read = servermanager.Fetch(plugin_reader)
    kind = read.GetCellData().GetArray("Line_Kind")
    check(read.GetNumberOfLines() == len(edges) and kind is not None
          and numpy.array_equal(vtk_to_numpy(kind), edges["Line_Kind"]),
          "ply: the plugin's PLY reader reads the edges as lines with Line_Kind")


def check_bad_paths(tool, plugin, cloud, output):
    for path, expected in (("x_lines.txt", ".vtp or .ply"),
                           (os.path.join(os.path.dirname(output), "no_such_folder", "x.vtp"),
                            "folder does not exist"),
                           (output, "the curvatures' output too")):
        done = run(tool, plugin, cloud, output, "--lines=" + path)
        check(done.returncode == 2 and expected in done.stderr and "estimated" not in done.stdout,
              "--lines=%s: exit 2, '%s' (%s)" % (os.path.basename(path), expected, done.stderr.strip()[-90:]))


def main(tool, plugin, folder):
    simple.LoadPlugin(plugin, remote=False)
    os.makedirs(folder, exist_ok=True)
    cloud = os.path.join(folder, "lines_bump.xyz")
    write_bump(cloud)
    output = os.path.join(folder, "lines_bump.vtp")
    done = run(tool, plugin, cloud, output, "--lines")
    check(done.returncode == 0, "--lines: exit 0 (%s)" % done.stderr.strip()[-200:])
    default = os.path.join(folder, "lines_bump_lines.vtp")
    check(os.path.isfile(default) and "wrote " + default in done.stdout, "--lines: writes OUTPUT_lines.vtp")
    if not os.path.isfile(default):
        print("%d failed" % len(failures))
        return 1
    lines = read_vtp(default)
    check_vtp(lines, done.stdout)
    ply = os.path.join(folder, "lines_bump_lines.ply")
    done = run(tool, plugin, cloud, output, "--lines=" + ply)
    check(done.returncode == 0 and os.path.isfile(ply), "--lines=X.ply: exit 0, written")
    if os.path.isfile(ply):
        check_ply(ply, lines)
    check_bad_paths(tool, plugin, cloud, output)
    print("%d failed" % len(failures))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:4]))
