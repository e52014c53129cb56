"""Curvature Lines in parallel must draw the serial lines.

Serial reference (pvpython):
    TestCurvatureLinesDistributed.py PLUGIN CLOUD.vtp --write-reference PREFIX
Parallel check (mpiexec -n N pvbatch --mpi):
    TestCurvatureLinesDistributed.py PLUGIN CLOUD.vtp --compare PREFIX [--noisy]

The reference run estimates the curvatures of CLOUD once (serially) and
writes them, whole and cut into pieces, so that every run draws its lines
from the same numbers; then it draws the serial lines (all six kinds, and
the default ridges and valleys). Each parallel run draws them again from
the curvatures as read (every point on rank 0, the other ranks empty), cut
by planes across x into four slabs (the principal ellipses of an ellipsoid
run across the cuts) and dealt out point by point (piece i % 4: every
rank's piece spans the whole cloud), and from the whole pipeline run in
parallel (the cloud redistributed into spatial pieces, as D3 does, and its
curvatures estimated there), and compares: the same number of
lines, of the same kinds, through the same points to the last bit, with
the same lengths and strengths; every line on rank 0. A cloud with one
point that is not finite, in the last slab, gives no line on any rank (and
the run ends: the ranks agree on the error before any collective step).
"""

import os

import numpy
from paraview import servermanager, simple
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader, vtkXMLPolyDataWriter, vtkXMLPPolyDataReader

from test_checks import run_on_every_rank, summary

PIECES = 4
# VTK's type codes as VTK XML names them.
XML_TYPES = {2: "Int8", 3: "UInt8", 4: "Int16", 5: "UInt16", 6: "Int32", 7: "UInt32", 8: "Int64",
             9: "UInt64", 10: "Float32", 11: "Float64", 12: "Int64", 15: "Int8", 16: "Int64",
             17: "UInt64"}
VARIANTS = {"all": 3, "default": 0}  # Kinds: All Extremal Lines, Ridges and Valleys


def write(data, path):
    """One .vtp, inline binary (appended data is unreadable with Debian
    12's current libexpat: see TestDistributed.py)."""
    writer = vtkXMLPolyDataWriter()
    writer.SetDataModeToBinary()
    writer.SetInputData(data)
    writer.SetFileName(path)
    writer.Write()


def read(path):
    reader = vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


def subset(data, ids):
    """The points `ids` of `data` with every point array, as vertices."""
    piece = vtkPolyData()
    points = vtkPoints()
    xyz = vtk_to_numpy(data.GetPoints().GetData())[ids]
    points.SetData(numpy_to_vtk(numpy.ascontiguousarray(xyz), deep=True))
    piece.SetPoints(points)
    point_data = data.GetPointData()
    for a in range(point_data.GetNumberOfArrays()):
        array = point_data.GetArray(a)
        values = numpy.ascontiguousarray(vtk_to_numpy(array)[ids])
        copy = numpy_to_vtk(values, deep=True, array_type=array.GetDataType())
        copy.SetName(array.GetName())
        piece.GetPointData().AddArray(copy)
    vertices = vtkCellArray()
    for i in range(len(ids)):
        vertices.InsertNextCell(1)
        vertices.InsertCellPoint(i)
    piece.SetVerts(vertices)
    return piece


def write_pieces(data, parts, prefix):
    """The parts of `data` as one .vtp each and the .pvtp that lists them."""
    names = []
    for k, ids in enumerate(parts):
        names.append("%s_%d.vtp" % (os.path.basename(prefix), k))
        write(subset(data, ids), os.path.join(os.path.dirname(prefix), names[-1]))
    point_data = data.GetPointData()
    with open(prefix + ".pvtp", "w") as handle:
        handle.write('<?xml version="1.0"?>\n<VTKFile type="PPolyData" version="0.1" '
                     'byte_order="LittleEndian">\n  <PPolyData GhostLevel="0">\n'
                     '    <PPoints><PDataArray type="%s" NumberOfComponents="3"/></PPoints>\n'
                     '    <PPointData>\n' % XML_TYPES[data.GetPoints().GetData().GetDataType()])
        for a in range(point_data.GetNumberOfArrays()):
            array = point_data.GetArray(a)
            handle.write('      <PDataArray type="%s" Name="%s" NumberOfComponents="%d"/>\n'
                         % (XML_TYPES[array.GetDataType()], array.GetName(),
                            array.GetNumberOfComponents()))
        handle.write("    </PPointData>\n")
        for name in names:
            handle.write('    <Piece Source="%s"/>\n' % name)
        handle.write("  </PPolyData>\n</VTKFile>\n")


def draw(source, kinds, path):
    """Curvature Lines on `source`; every rank writes its piece (inline
    binary), read back whole here (not servermanager.Fetch, which drops
    the other ranks' pieces: see TestDistributed.py)."""
    factory = globals().get("CurvatureLines") or simple.CurvatureLines
    lines = factory(Input=source, Kinds=kinds)
    tagged = simple.ProcessIdScalars(Input=lines)
    writer = simple.XMLPPolyDataWriter(Input=tagged, FileName=path, DataMode="Binary")
    writer.UpdatePipeline()
    reader = vtkXMLPPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


def lines_of(data):
    """Each polyline as (kind, points, strength, length), in order."""
    cells = data.GetLines()
    if cells is None or data.GetNumberOfCells() == 0:
        return []
    offsets = vtk_to_numpy(cells.GetOffsetsArray())
    ids = vtk_to_numpy(cells.GetConnectivityArray())
    points = vtk_to_numpy(data.GetPoints().GetData())
    cell_data = data.GetCellData()
    kind, strength, length = (vtk_to_numpy(cell_data.GetArray(n))
                              for n in ("Line_Kind", "Line_Strength", "Line_Length"))
    return [(int(kind[i]), points[ids[offsets[i]:offsets[i + 1]]], strength[i], length[i])
            for i in range(len(offsets) - 1)]


def compare(reference, result, label):
    if len(reference) != len(result):
        return ["%s: %d lines, serially %d" % (label, len(result), len(reference))]
    failures = []
    largest = 0.0
    for i, (a, b) in enumerate(zip(reference, result)):
        if a[0] != b[0] or a[1].shape != b[1].shape:
            failures.append("%s: line %d is of kind %d with %d points, serially %d with %d"
                            % (label, i, b[0], len(b[1]), a[0], len(a[1])))
            continue
        largest = max(largest, float(numpy.abs(a[1] - b[1]).max()))
        if not (numpy.array_equal(a[1], b[1]) and a[2] == b[2] and a[3] == b[3]):
            failures.append("%s: line %d differs from the serial one" % (label, i))
    print("%-40s %d lines, largest point difference %.3g" % (label, len(result), largest))
    return failures


def cut_lines(reference, cuts):
    """How many of the serial lines run across one of the planes x = cut."""
    return sum(1 for line in reference
               if any(line[1][:, 0].min() < c < line[1][:, 0].max() for c in cuts))


def write_reference(cloud, prefix):
    reader = simple.XMLPolyDataReader(FileName=[cloud])
    reader.UpdatePipeline()
    curvatures = PrincipalCurvatures(Input=reader)  # noqa: F821 (LoadPlugin's)
    curvatures.Normals = ["POINTS", "Normals"]
    curvatures.UpdatePipeline()
    data = servermanager.Fetch(curvatures)
    write(data, prefix + "_curvatures.vtp")
    x = vtk_to_numpy(data.GetPoints().GetData())[:, 0]
    order = numpy.argsort(x, kind="stable")
    slabs = numpy.array_split(order, PIECES)
    write_pieces(data, slabs, prefix + "_slabs")
    numpy.savetxt(prefix + "_cuts.txt", [x[s[0]] for s in slabs[1:]])
    ids = numpy.arange(data.GetNumberOfPoints())
    write_pieces(data, [ids[k::PIECES] for k in range(PIECES)], prefix + "_interleaved")
    # The slabs again, the last with a point whose x is not a number.
    coordinates = vtk_to_numpy(data.GetPoints().GetData())
    coordinates[slabs[-1][0], 0] = numpy.nan
    data.GetPoints().Modified()
    write_pieces(data, slabs, prefix + "_bad")
    source = simple.XMLPolyDataReader(FileName=[prefix + "_curvatures.vtp"])
    for variant, kinds in VARIANTS.items():
        write(draw(source, kinds, "%s_serial_%s.pvtp" % (prefix, variant)),
              "%s_lines_%s.vtp" % (prefix, variant))
    return 0


def parallel_curvatures(cloud):
    """The whole pipeline in parallel: the cloud cut into spatial pieces
    (RedistributeDataSet, as D3), its curvatures estimated there."""
    pieces = simple.RedistributeDataSet(Input=simple.XMLPolyDataReader(FileName=[cloud]))
    curvatures = PrincipalCurvatures(Input=pieces)  # noqa: F821 (LoadPlugin's)
    curvatures.Normals = ["POINTS", "Normals"]
    return curvatures


def main(plugin, cloud, action, prefix, kind="--clean"):
    simple.LoadPlugin(plugin, remote=False, ns=globals())
    if action == "--write-reference":
        return write_reference(cloud, prefix)
    ranks = servermanager.vtkProcessModule.GetProcessModule().GetNumberOfLocalPartitions()
    cuts = numpy.atleast_1d(numpy.loadtxt(prefix + "_cuts.txt"))
    splits = (("as read", simple.XMLPolyDataReader(FileName=[prefix + "_curvatures.vtp"])),
              ("slabs", simple.OpenDataFile(prefix + "_slabs.pvtp")),
              ("interleaved", simple.OpenDataFile(prefix + "_interleaved.pvtp")),
              ("curvatures in parallel", parallel_curvatures(cloud)))
    failures = []
    for variant, kinds in VARIANTS.items():
        reference = lines_of(read("%s_lines_%s.vtp" % (prefix, variant)))
        across = cut_lines(reference, cuts)
        print("%-40s %d serial lines, %d across the slabs' cuts" % (variant, len(reference), across))
        # A noisy cloud has few lines that stand out of the noise, but its
        # wide neighborhoods take the shared fits (anchors) in every piece;
        # the clean one's ridges and valleys are a few long lines, at least
        # two of them cut by the slabs.
        least = (1, 1) if kind == "--noisy" else (2, 2)
        if len(reference) < least[0] or across < least[1]:
            failures.append("%s: too few serial lines (%d) or across the cuts (%d)"
                            % (variant, len(reference), across))
        for split, source in splits:
            label = "%d ranks, %s, %s" % (ranks, split, variant)
            output = "%s_%d_%s_%s.pvtp" % (prefix, ranks, split.replace(" ", "_"), variant)
            data = draw(source, kinds, output)
            failures += compare(reference, lines_of(data), label)
            process = data.GetPointData().GetArray("ProcessId")
            if process is not None and process.GetNumberOfTuples() > 0 and \
                    vtk_to_numpy(process).max() != 0:
                failures.append("%s: lines on other ranks than 0" % label)
    # Bad input on one rank: every rank stops (none waits for the others in
    # a collective step that never comes), and no rank draws a line.
    bad = CurvatureLines(Input=simple.OpenDataFile(prefix + "_bad.pvtp"))  # noqa: F821
    bad.UpdatePipeline()
    drawn = bad.GetDataInformation().GetNumberOfCells()
    print("%-40s %d lines" % ("%d ranks, one point not finite" % ranks, drawn))
    if drawn != 0:
        failures.append("%d ranks, one point not finite: %d lines drawn" % (ranks, drawn))
    return summary(failures)


if __name__ == "__main__":
    run_on_every_rank(main, __doc__, (4, 5))
