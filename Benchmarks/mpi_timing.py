"""Filter update time under MPI (pvbatch), for the table in docs/parallel.md.

    build/bin/GenerateAnalyticCloud torus 1000000 /tmp/torus1M.vtp
    mpiexec -n RANKS [--bind-to none] pvbatch --mpi Benchmarks/mpi_timing.py \
        build/lib/paraview-plugins/PrincipalCurvatures/PrincipalCurvatures.so /tmp/torus1M.vtp [RUNS] \
        [--lines]

The cloud is read, redistributed into one spatial piece per rank
(RedistributeDataSet, as a distributed pipeline would hold it), and the
filter's update alone is timed: pvbatch runs this script on rank 0, whose
UpdatePipeline returns when every rank has executed. Prints the median of
RUNS (default 3) runs. VTK_SMP_MAX_THREADS sets the threads per rank
(default: all cores; pass it to the ranks with mpiexec -x). With --lines,
Curvature Lines is timed instead, on the curvatures (updated beforehand).
"""

import statistics
import sys
import time

from paraview import servermanager, simple


def main(plugin, cloud, runs=3, what="--curvatures"):
    simple.LoadPlugin(plugin, remote=False, ns=globals())
    controller = servermanager.vtkProcessModule.GetProcessModule().GetGlobalController()
    reader = simple.XMLPolyDataReader(FileName=[cloud])
    pieces = simple.RedistributeDataSet(Input=reader)
    pieces.UpdatePipeline()
    times = []
    if what == "--lines":
        curvatures = PrincipalCurvatures(Input=pieces)  # noqa: F821 (from the plugin)
        curvatures.Normals = ["POINTS", "Normals"]
        curvatures.UpdatePipeline()
    for run in range(int(runs)):
        if what == "--lines":
            timed = CurvatureLines(Input=curvatures)  # noqa: F821
        else:
            timed = PrincipalCurvatures(Input=pieces)  # noqa: F821 (from the plugin)
            timed.Normals = ["POINTS", "Normals"]
        start = time.perf_counter()
        timed.UpdatePipeline()
        times.append(time.perf_counter() - start)
        simple.Delete(timed)
    print("ranks %d, runs %s s, median %.2f s"
          % (controller.GetNumberOfProcesses(), " ".join("%.2f" % t for t in times),
             statistics.median(times)))
    return 0


if __name__ == "__main__":
    if len(sys.argv) not in (3, 4, 5):
        print(__doc__)
        sys.exit(2)
    sys.exit(main(*sys.argv[1:]))
