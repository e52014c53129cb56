"""The LAS writer in a parallel session: run under MPI with pvbatch,

    mpiexec -n 2 pvbatch --mpi TestLASWriterParallel.py PLUGIN.so

a LAS 1.2 sphere in US survey feet (written by TestLASWriter.write_las12)
read in pieces on every rank, its curvatures saved with SaveData('.las'):
ParaView offers only parallel writers there, so this needs the plugin's
parallel LAS writer, which gathers the pieces on the first rank. The file
must hold every point, the curvature arrays, the input's scale and unit.

Every check prints one line; the exit code is 0 when all pass, 1 otherwise.
"""

import os
import shutil
import sys
import tempfile

from paraview import servermanager, simple

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from test_checks import check, failures  # noqa: E402
from TestLASWriter import field_string, sphere, write_las12  # noqa: E402


def main(argv):
    simple.LoadPlugin(argv[0], remote=False)
    ranks = servermanager.ActiveConnection.GetNumberOfDataPartitions()
    check(ranks == 2, "ranks: %d" % ranks)
    folder = tempfile.mkdtemp(prefix="pcurv_las_parallel_")
    try:
        path, out = os.path.join(folder, "sphere_feet.las"), os.path.join(folder, "out.las")
        write_las12(path, sphere(4000), True)
        curvatures = simple.PrincipalCurvatures(Input=simple.LASPointCloudReader(FileName=path))
        simple.SaveData(out, proxy=curvatures)
        check(os.path.isfile(out), "SaveData wrote the .las in a parallel session")
        reader = simple.LASPointCloudReader(FileName=out)
        reader.UpdatePipeline()
        saved = servermanager.Fetch(reader)
        check(saved.GetNumberOfPoints() == 4000, "every rank's points: %d" % saved.GetNumberOfPoints())
        check(saved.GetPointData().GetArray("Mean_Curvature") is not None, "Mean_Curvature written")
        scale = saved.GetFieldData().GetArray("LAS_Scale")
        check(scale is not None and scale.GetTuple3(0) == (0.001, 0.001, 0.001), "the input's scale kept")
        check(field_string(saved, "Length_Unit") == "US survey foot", "the input's unit kept")
    finally:
        shutil.rmtree(folder, ignore_errors=True)
    print("%d failed" % len(failures))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
