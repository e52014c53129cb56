"""Parallel runs must give the serial numbers.

Serial reference (pvpython):
    TestDistributed.py PLUGIN CLOUD.vtp --write-reference PREFIX
Parallel check (mpiexec -n N pvbatch --mpi):
    TestDistributed.py PLUGIN CLOUD.vtp --compare PREFIX

Points are matched across runs by their coordinates (the clouds have no
duplicates; an empty piece drops the input's arrays from a fetched result). Each parallel run is made twice: as the reader splits
the file (one piece: all points on rank 0, the others empty) and after
RedistributeDataSet, which cuts the cloud into spatial pieces, one per rank,
so the cuts go through the surface. Fixed thresholds and the dynamic
adjustment are both checked: max |k - k_serial| / max |k| below 1e-12, and
the same points unestimated.
"""

import sys

import numpy
from paraview import servermanager, simple
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader, vtkXMLPolyDataWriter, vtkXMLPPolyDataReader

ARRAYS = ("Minimum_Curvature", "Maximum_Curvature", "Neighbor_Count")
VARIANTS = {"fixed": {}, "dva": {"DynamicAdjustment": 1}}


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
    result = {name: vtk_to_numpy(point_data.GetArray(name))[order] for name in ARRAYS}
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
    for name in ARRAYS:
        a, b = reference[name].astype(float), result[name].astype(float)
        if not numpy.array_equal(numpy.isnan(a), numpy.isnan(b)):
            failures.append("%s: %s: different points without an estimate" % (label, name))
            continue
        finite = ~numpy.isnan(a)
        difference = numpy.abs(a[finite] - b[finite]).max() if finite.any() else 0.0
        relative = difference / (scale if name != "Neighbor_Count" else 1.0)
        print("%-32s %-18s max difference %.3g (relative %.3g)" % (label, name, difference, relative))
        if relative > 1e-12:
            failures.append("%s: %s differs by %.3g" % (label, name, relative))
    return failures


def main(plugin, cloud, action, prefix):
    simple.LoadPlugin(plugin, remote=False, ns=globals())
    reader = simple.XMLPolyDataReader(FileName=[cloud])
    reader.UpdatePipeline()
    if action == "--write-reference":
        for variant, properties in VARIANTS.items():
            write(estimate(reader, properties, "%s_%s_pieces.pvtp" % (prefix, variant)),
                  "%s_%s.vtp" % (prefix, variant))
        return 0
    ranks = servermanager.vtkProcessModule.GetProcessModule().GetNumberOfLocalPartitions()
    redistributed = simple.RedistributeDataSet(Input=reader)
    failures = []
    for split, source in (("as read", reader), ("redistributed", redistributed)):
        for variant, properties in VARIANTS.items():
            pieces = "%s_%d_%s_%s.pvtp" % (prefix, ranks, split.replace(" ", "_"), variant)
            result = as_arrays(estimate(source, properties, pieces))
            label = "%d ranks, %s, %s" % (ranks, split, variant)
            if split == "redistributed" and result["processes"] != ranks:
                failures.append("%s: points came from %d processes" % (label, result["processes"]))
            failures += compare(as_arrays(read("%s_%s.vtp" % (prefix, variant))), result, label)
    for failure in failures:
        print("FAILED " + failure)
    print("%d failed" % len(failures))
    return 1 if failures else 0


if __name__ == "__main__":
    if len(sys.argv) != 5:
        print(__doc__)
        sys.exit(2)
    status = main(*sys.argv[1:])
    # Under pvbatch --mpi the script runs on rank 0 only: sys.exit there
    # skips the final barrier and the other ranks are killed. The result is
    # the "N failed" line (CTest matches it); exit only on failure.
    if status:
        sys.exit(status)
