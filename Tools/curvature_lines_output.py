"""The curvature lines of estimate_curvatures.py: computed from the
curvatures with the plugin's Curvature Lines filter, written as .vtp or
as PLY edges, and summarized.

A .ply holds a vertex element (x y z as double, Line_Curvature) and an
edge element (vertex1 vertex2, the two vertices of one segment of a
polyline, as int, then the segment's line's Line_Kind as uchar,
Line_Strength and Line_Length as double), binary little endian: MeshLab
and CloudCompare read the edges as segments with those properties, the
plugin's PLY Point Cloud Reader as line cells with them as cell data. An open polyline of n vertices gives n - 1 edges, a closed
one n.
"""

import os
import sys

from paraview import simple

LINE_EXTENSIONS = (".vtp", ".ply")
# The --line-kinds names and the filter's Kinds.
LINE_KINDS = {"ridges-and-valleys": "Ridges and Valleys", "ridges": "Ridges", "valleys": "Valleys",
              "all": "All Extremal Lines"}
# Line_Kind's values, as the GUI's legend names them (pcurv::LineKindName).
KIND_NAMES = ("ridge", "valley", "max of k_max", "min of k_max", "max of k_min", "min of k_min")


def default_lines_path(output):
    """OUTPUT's stem + _lines.vtp, next to OUTPUT."""
    return os.path.splitext(output)[0] + "_lines.vtp"


def lines_path_problem(path, output):
    """Why the lines cannot be written to path (None if they can): checked
    before the curvatures are estimated, so a typo costs no run."""
    extension = os.path.splitext(path)[1].lower()
    if extension not in LINE_EXTENSIONS:
        return "--lines: %s: the lines are written as %s, by the extension" % (path, " or ".join(LINE_EXTENSIONS))
    folder = os.path.dirname(os.path.abspath(path))
    if not os.path.isdir(folder):
        return "--lines: the folder does not exist: %s" % folder
    if os.path.isdir(path):
        return "--lines: %s is a folder" % path
    if os.path.abspath(path) == os.path.abspath(output):
        return "--lines: %s is the curvatures' output too" % path
    return None


def lines_filter(curvatures, kinds):
    """The Curvature Lines proxy on the curvatures (--line-kinds name)."""
    return simple.CurvatureLines(Input=curvatures, Kinds=LINE_KINDS[kinds])


def polylines(output):
    """Each polyline's point ids (numpy arrays), in cell order."""
    from vtkmodules.util.numpy_support import vtk_to_numpy

    cells = output.GetLines()
    if cells is None or cells.GetNumberOfCells() == 0:
        return []
    offsets = vtk_to_numpy(cells.GetOffsetsArray())
    ids = vtk_to_numpy(cells.GetConnectivityArray())
    return [ids[offsets[i]:offsets[i + 1]] for i in range(len(offsets) - 1)]


def cell_values(output, name, dtype):
    import numpy
    from vtkmodules.util.numpy_support import vtk_to_numpy

    array = output.GetCellData().GetArray(name)
    if array is None:
        return numpy.zeros(output.GetNumberOfLines(), dtype=dtype)
    return vtk_to_numpy(array).astype(dtype)


def write_lines_ply(output, path):
    """The lines as a binary PLY of vertices and edges (module docstring)."""
    import numpy
    from vtkmodules.util.numpy_support import vtk_to_numpy

    count = output.GetNumberOfPoints()
    vertices = numpy.zeros(count, dtype=[("x", "<f8"), ("y", "<f8"), ("z", "<f8"), ("Line_Curvature", "<f8")])
    if count:
        points = vtk_to_numpy(output.GetPoints().GetData()).reshape(-1, 3)
        vertices["x"], vertices["y"], vertices["z"] = points[:, 0], points[:, 1], points[:, 2]
        curvature = output.GetPointData().GetArray("Line_Curvature")
        if curvature is not None:
            vertices["Line_Curvature"] = vtk_to_numpy(curvature)
    cells = polylines(output)
    kind = cell_values(output, "Line_Kind", numpy.uint8)
    strength = cell_values(output, "Line_Strength", numpy.float64)
    length = cell_values(output, "Line_Length", numpy.float64)
    edges = numpy.zeros(sum(max(len(ids) - 1, 0) for ids in cells),
                        dtype=[("vertex1", "<i4"), ("vertex2", "<i4"), ("Line_Kind", "u1"),
                               ("Line_Strength", "<f8"), ("Line_Length", "<f8")])
    start = 0
    for line, ids in enumerate(cells):
        end = start + max(len(ids) - 1, 0)
        edges["vertex1"][start:end], edges["vertex2"][start:end] = ids[:-1], ids[1:]
        edges["Line_Kind"][start:end] = kind[line]
        edges["Line_Strength"][start:end] = strength[line]
        edges["Line_Length"][start:end] = length[line]
        start = end
    header = ["ply", "format binary_little_endian 1.0", "comment curvature lines (docs/curvature-lines.md)",
              "element vertex %d" % count]
    header += ["property double %s" % name for name in vertices.dtype.names]
    header += ["element edge %d" % len(edges), "property int vertex1", "property int vertex2",
               "property uchar Line_Kind", "property double Line_Strength", "property double Line_Length",
               "end_header"]
    with open(path, "wb") as handle:
        handle.write(("\n".join(header) + "\n").encode("ascii"))
        handle.write(vertices.tobytes())
        handle.write(edges.tobytes())


def write_lines_vtp(lines, path):
    """The lines as VTK XML polydata (inline binary, as the curvatures)."""
    writer = simple.XMLPolyDataWriter(Input=lines, FileName=path, DataMode="Binary")
    writer.UpdatePipeline()
    simple.Delete(writer)


def write_lines(lines, output, path):
    """Writes the lines to path (.vtp or .ply); raises OSError when the
    file is not there afterwards."""
    if os.path.exists(path):
        os.remove(path)  # so that a failed write cannot leave an old file looking new
    if path.lower().endswith(".ply"):
        write_lines_ply(output, path)
    else:
        write_lines_vtp(lines, path)
    if not os.path.isfile(path):
        raise OSError("see the messages above")


def summarize_lines(output):
    """Prints the number of lines and their length, in all and by kind."""
    import numpy

    kind = cell_values(output, "Line_Kind", numpy.int64)
    length = cell_values(output, "Line_Length", numpy.float64)
    print("%-26s %d (length %.6g in all)" % ("curvature lines", len(kind), length.sum()))
    for code, name in enumerate(KIND_NAMES):
        chosen = kind == code
        if chosen.any():
            print("%-26s %d (length %.6g)" % ("  " + name, int(chosen.sum()), length[chosen].sum()))
    sys.stdout.flush()
