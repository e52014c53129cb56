"""Parallel runs must give the serial numbers.

Serial reference (pvpython):
    TestDistributed.py PLUGIN CLOUD.vtp --write-reference PREFIX
Parallel check (mpiexec -n N pvbatch --mpi):
    TestDistributed.py PLUGIN CLOUD.vtp --compare PREFIX

Points are matched across runs by their coordinates (the clouds have no
duplicates). Each parallel run is made twice: as the reader splits
the file (one piece: all points on rank 0, the others empty) and after
RedistributeDataSet, which cuts the cloud into spatial pieces, one per rank,
so the cuts go through the surface. Fixed thresholds and the dynamic
adjustment are both checked: max |k - k_serial| / max |k| below 1e-12, and
the same points unestimated. A noisy cloud checks the default's shared fits
(anchors from other ranks' parts among them) and, its normals being exact,
its fits of the fourth order; a clean one (last argument --clean) its
height jets (neighbors from other ranks' parts among them); one with its
positions rounded to a grid (--rounded) the lattice every rank must find
the same from its own part; a noisy sphere whose normals are tilted at
random (--tilted), as estimated normals are off, their replacement by
normals estimated from the positions, the longer ladder (nine radii, past
3,000 neighbors) estimated normals get, and its wider halo; a
noisy torus with 5 % outliers (--outliers), with given and estimated
normals, the outliers' verdicts and the surface points they are moved
onto, from any rank's part.
"""


import numpy
from paraview import servermanager, simple
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader, vtkXMLPolyDataWriter, vtkXMLPPolyDataReader

from test_checks import run_on_every_rank, summary

ARRAYS = ("Minimum_Curvature", "Maximum_Curvature", "Neighbor_Count")
COUNTS = ("Neighbor_Count", "Target_Neighbor_Count", "Curvature_Trusted", "Shape_Class",
          "Outlier")  # absolutely
OPTIONAL = ("Target_Neighbor_Count",  # the dynamic adjustment's only
            "Curvature_Standard_Error", "Curvature_Trusted", "Shape_Class", "Outlier")  # OrientedCircles only
VARIANTS = {"fixed": {}, "dva": {"DynamicAdjustment": 1}}


def variants_of(kind):
    """The variants run on a cloud: with tilted normals also every point
    fitting its own neighborhood, whose largest radius the halo alone must
    reach (shared fits widen it by the anchors' cells)."""
    if kind == "--tilted":
        return dict(VARIANTS, unshared={"ShareFits": 0})
    if kind == "--outliers":
        return dict(VARIANTS, estimated={"NormalsSource": 2})
    return VARIANTS


def estimate(source, properties, path):
    """Runs the filter; every rank writes its piece (inline binary) and the
    pieces are read back on rank 0. Not servermanager.Fetch: with a current
    Debian 12 libexpat, ParaView 5.11's gather silently drops the pieces of
    the other ranks (it moves data as appended VTK XML; VTK issue 19258)."""
    factory = globals().get("PrincipalCurvatures") or simple.PrincipalCurvatures
    curvatures = factory(Input=source, **properties)
    curvatures.Normals = ["POINTS", "Normals"]
    tagged = simple.ProcessIdScalars(Input=curvatures)
    writer = simple.XMLPPolyDataWriter(Input=tagged, FileName=path, DataMode="Binary")
    writer.UpdatePipeline()
    reader = vtkXMLPPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


def as_arrays(data):
    point_data = data.GetPointData()
    points = vtk_to_numpy(data.GetPoints().GetData())
    order = numpy.lexsort((points[:, 2], points[:, 1], points[:, 0]))
    result = {name: vtk_to_numpy(point_data.GetArray(name))[order]
              for name in ARRAYS + OPTIONAL if point_data.GetArray(name) is not None}
    result["ids"] = points[order]
    process = point_data.GetArray("ProcessId")
    result["processes"] = len(numpy.unique(vtk_to_numpy(process))) if process else 1
    return result


def write(data, path):
    """One .vtp, inline binary (appended data is unreadable here, see above)."""
    writer = vtkXMLPolyDataWriter()
    writer.SetDataModeToBinary()  # appended data: unreadable with Debian 12's current libexpat
    writer.SetInputData(data)
    writer.SetFileName(path)
    writer.Write()


def read(path):
    reader = vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


def compare(reference, result, label):
    failures = []
    if not numpy.array_equal(reference["ids"], result["ids"]):
        return ["%s: not the same points (%d against %d)" % (label, len(result["ids"]), len(reference["ids"]))]
    scale = numpy.nanmax(numpy.abs(numpy.concatenate([reference[n] for n in ARRAYS[:2]])))
    for name in ARRAYS + OPTIONAL:
        if (name in reference) != (name in result):
            failures.append("%s: %s in one of the runs only" % (label, name))
            continue
        if name not in reference:
            continue
        a, b = reference[name].astype(float), result[name].astype(float)
        if not numpy.array_equal(numpy.isnan(a), numpy.isnan(b)):
            failures.append("%s: %s: different points without an estimate" % (label, name))
            continue
        finite = ~numpy.isnan(a)
        difference = numpy.abs(a[finite] - b[finite]).max() if finite.any() else 0.0
        relative = difference / (scale if name not in COUNTS else 1.0)
        print("%-32s %-18s max difference %.3g (relative %.3g)" % (label, name, difference, relative))
        if relative > 1e-12:
            failures.append("%s: %s differs by %.3g" % (label, name, relative))
    return failures


def read_field_value(path, name):
    """A field data value of a written output (every piece holds the value
    over all processes); 0 when absent."""
    reader = vtkXMLPPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    array = reader.GetOutput().GetFieldData().GetArray(name)
    return int(array.GetValue(0)) if array else 0


def write_pieces(cloud_file, prefix, pieces=4):
    """The cloud cut along x into `pieces` slabs of equal count, one .vtp
    each (inline binary), and the .pvtp that lists them."""
    import os
    from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkPoints
    from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
    from vtkmodules.util.numpy_support import numpy_to_vtk

    data = read(cloud_file)
    points = vtk_to_numpy(data.GetPoints().GetData())
    normals = vtk_to_numpy(data.GetPointData().GetNormals())
    order = numpy.argsort(points[:, 0], kind="stable")
    names = []
    for k, part in enumerate(numpy.array_split(order, pieces)):
        piece = vtkPolyData()
        coordinates = vtkPoints()
        coordinates.SetData(numpy_to_vtk(numpy.ascontiguousarray(points[part]), deep=True))
        piece.SetPoints(coordinates)
        array = numpy_to_vtk(numpy.ascontiguousarray(normals[part]), deep=True)
        array.SetName("Normals")
        piece.GetPointData().SetNormals(array)
        vertices = vtkCellArray()
        for i in range(len(part)):
            vertices.InsertNextCell(1)
            vertices.InsertCellPoint(i)
        piece.SetVerts(vertices)
        names.append("%s_piece_%d.vtp" % (os.path.basename(prefix), k))
        write(piece, os.path.join(os.path.dirname(prefix), names[-1]))
    with open(prefix + "_pieces.pvtp", "w") as handle:
        handle.write('<?xml version="1.0"?>\n<VTKFile type="PPolyData" version="0.1" byte_order="LittleEndian">\n'
                     '  <PPolyData GhostLevel="0">\n'
                     '    <PPoints><PDataArray type="Float64" NumberOfComponents="3"/></PPoints>\n'
                     '    <PPointData Normals="Normals"><PDataArray type="Float64" Name="Normals" NumberOfComponents="3"/></PPointData>\n')
        for name in names:
            handle.write('    <Piece Source="%s"/>\n' % name)
        handle.write("  </PPolyData>\n</VTKFile>\n")


def main(plugin, cloud, action, prefix, kind="--noisy"):
    simple.LoadPlugin(plugin, remote=False, ns=globals())
    reader = simple.XMLPolyDataReader(FileName=[cloud])
    reader.UpdatePipeline()
    if action == "--write-reference":
        for variant, properties in variants_of(kind).items():
            write(estimate(reader, properties, "%s_%s_output.pvtp" % (prefix, variant)),
                  "%s_%s.vtp" % (prefix, variant))
        write_pieces(cloud, prefix)
        return 0
    ranks = servermanager.vtkProcessModule.GetProcessModule().GetNumberOfLocalPartitions()
    pieces = simple.OpenDataFile(prefix + "_pieces.pvtp")
    failures = []
    for split, source in (("as read", reader), ("four pieces", pieces)):
        for variant, properties in variants_of(kind).items():
            output = "%s_%d_%s_%s.pvtp" % (prefix, ranks, split.replace(" ", "_"), variant)
            result = as_arrays(estimate(source, properties, output))
            label = "%d ranks, %s, %s" % (ranks, split, variant)
            if split == "four pieces" and result["processes"] != ranks:
                failures.append("%s: points came from %d processes" % (label, result["processes"]))
            if ("Target_Neighbor_Count" in result) != bool(properties.get("DynamicAdjustment")):
                failures.append("%s: Target_Neighbor_Count present exactly with the adjustment" % label)
            failures += compare(as_arrays(read("%s_%s.vtp" % (prefix, variant))), result, label)
            if variant == "fixed" and kind == "--clean":
                jets = read_field_value(output, "Jet_Fit_Points")
                print("%-32s Jet_Fit_Points  %d" % (label, jets))
                if not jets > 0.5 * len(result["ids"]):
                    failures.append("%s: only %d points took height jets" % (label, jets))
            elif variant == "fixed" and kind == "--noisy":
                # The default shares fits on this noisy cloud: the anchors a
                # rank needs may lie in another rank's part (the halo).
                shared = read_field_value(output, "Shared_Fit_Points")
                print("%-32s Shared_Fit_Points  %d" % (label, shared))
                if not shared > 0.5 * len(result["ids"]):
                    failures.append("%s: only %d points shared fits" % (label, shared))
                # Exact normals of a noisy cloud: the fourth order's fits too,
                # decided on a sample drawn from every rank's part.
                if read_field_value(output, "Fourth_Order_Fits") != 1:
                    failures.append("%s: no fourth-order fits with exact normals" % label)
            elif variant in ("fixed", "estimated") and kind == "--outliers":
                # Outliers moved onto points of the surface that may lie in
                # another rank's part, before the normals and the fits.
                outliers = read_field_value(output, "Outlier_Points")
                print("%-32s Outlier_Points  %d" % (label, outliers))
                if not outliers > 0.03 * len(result["ids"]):
                    failures.append("%s: only %d outliers" % (label, outliers))
            elif variant in ("fixed", "unshared") and kind == "--tilted":
                largest = int(result["Neighbor_Count"].max())
                print("%-32s largest Neighbor_Count  %d" % (label, largest))
                # Normals tilted beyond the noise: replaced by estimated
                # ones, decided on a sample drawn from every rank's part.
                if read_field_value(output, "Given_Normals_Replaced") != 1:
                    failures.append("%s: tilted normals not replaced" % label)
                if not largest > 3000:
                    failures.append("%s: no point past eight radii (%d neighbors)" % (label, largest))
    return summary(failures)


if __name__ == "__main__":
    run_on_every_rank(main, __doc__, (4, 5))
