"""The first progress event of each filter already names it: ParaView's
progress bar shows an algorithm's progress text, or its class name while it
has none, and VTK's executive reports progress 0 before the filter runs.

    pvpython TestProgressLabel.py   (the wrapped package on PYTHONPATH)

Every check prints one line; the exit code is 0 when all pass."""

import math
import sys

from principal_curvatures import vtkPointCloudNormalEstimation, vtkPrincipalCurvatureEstimation
from vtkmodules.vtkCommonCore import vtkCommand, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkPolyData


def sphere_cloud(count=400):
    """Points on a unit sphere (a Fibonacci spiral: no random numbers)."""
    points = vtkPoints()
    golden = math.pi * (3.0 - math.sqrt(5.0))
    for i in range(count):
        z = 1.0 - 2.0 * (i + 0.5) / count
        r = math.sqrt(1.0 - z * z)
        points.InsertNextPoint(r * math.cos(golden * i), r * math.sin(golden * i), z)
    cloud = vtkPolyData()
    cloud.SetPoints(points)
    return cloud


def first_progress_text(algorithm):
    """The progress text at the algorithm's first progress event of a run."""
    texts = []
    algorithm.AddObserver(vtkCommand.ProgressEvent, lambda caller, event: texts.append(caller.GetProgressText()))
    algorithm.SetInputData(sphere_cloud())
    algorithm.Update()
    return texts[0] if texts else None


failed = 0
for algorithm, label in ((vtkPrincipalCurvatureEstimation(), "Principal curvatures"),
                         (vtkPointCloudNormalEstimation(), "Point cloud normals")):
    text = first_progress_text(algorithm)
    ok = bool(text) and text.startswith(label)
    failed += not ok
    print("%s %s: first progress text %r" % ("ok" if ok else "FAILED", algorithm.GetClassName(), text))
print("%d failed" % failed)
sys.exit(1 if failed else 0)
