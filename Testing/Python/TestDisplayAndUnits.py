"""What the output says about its colors and its scale:

    pvpython TestDisplayAndUnits.py PLUGIN.so TORUS.xyz TOOL.py FOLDER

* Mean_Curvature_Clipped, the active scalars ParaView colors a new display
  by over their range, reports a range symmetric about zero (so that white
  is zero) on a torus, whose mean curvature is positive everywhere (only
  one tail is clipped);
* the field data string Curvature_Unit says the curvatures are in 1 / the
  input's length unit, and a cloud scaled by 8 gives curvatures divided by
  8 (and neighborhood radii times 8);
* Surroundings_Threshold is each point's neighborhood radius: exactly
  Neighbor_Count other points lie closer than it, with the default
  neighborhood and with K Nearest;
* the command-line tool's summary states the unit and the radius.

Every check prints one line; the exit code is 0 when all pass, 1 otherwise.
"""

import os
import subprocess
import sys

import numpy
from paraview import servermanager, simple
from vtkmodules.util.numpy_support import vtk_to_numpy

from test_checks import check, failures  # noqa: E402 (the tests' folder is on sys.path)

UNIT = "1/length unit of the input coordinates"


def estimate(path, **properties):
    """The filter's proxy (updated) on the text cloud at path, and its output."""
    reader = simple.PointCloudTextReader(FileName=path)
    curvatures = simple.PrincipalCurvatures(Input=reader, **properties)
    curvatures.UpdatePipeline()
    return curvatures, servermanager.Fetch(curvatures)


def array(output, name):
    return vtk_to_numpy(output.GetPointData().GetArray(name))


def check_symmetric_range(curvatures, output):
    valid = array(output, "Curvature_Valid") == 1
    mean = array(output, "Mean_Curvature")[valid]
    clipped = array(output, "Mean_Curvature_Clipped")[valid]
    check(valid.any() and (mean > 0).all(), "torus: mean curvature positive at every estimated point (%d)"
          % valid.sum())
    low, high = curvatures.PointData["Mean_Curvature_Clipped"].GetRange()
    check(high > 0 and low == -high, "torus: Mean_Curvature_Clipped's range %g %g is symmetric about 0"
          % (low, high))
    check(clipped.max() <= high and clipped.max() >= 0.9 * high,
          "torus: the range's end %g is the clip (values up to %g)" % (high, clipped.max()))
    scalars = output.GetPointData().GetScalars()
    check(scalars is not None and scalars.GetName() == "Mean_Curvature_Clipped",
          "torus: Mean_Curvature_Clipped are the active scalars")


def check_unit(output, label):
    unit = output.GetFieldData().GetAbstractArray("Curvature_Unit")
    value = unit.GetValue(0) if unit is not None and unit.GetNumberOfValues() == 1 else None
    check(value == UNIT, "%s: field data Curvature_Unit = %r" % (label, value))


def check_radius(output, label):
    """Neighbor_Count other points lie strictly within Surroundings_Threshold."""
    points = vtk_to_numpy(output.GetPoints().GetData())
    radius = array(output, "Surroundings_Threshold")
    count = array(output, "Neighbor_Count")
    valid = numpy.flatnonzero(array(output, "Curvature_Valid") == 1)
    sample = valid[:: max(1, len(valid) // 25)]
    within = [int(((d < radius[i]) & (d > 0)).sum())
              for i in sample for d in [numpy.linalg.norm(points - points[i], axis=1)]]
    check(len(sample) > 10 and within == [int(count[i]) for i in sample],
          "%s: Surroundings_Threshold is the neighborhood radius (Neighbor_Count points within it, %d points)"
          % (label, len(sample)))


def main(plugin, torus, tool, folder):
    simple.LoadPlugin(plugin, remote=False)
    curvatures, output = estimate(torus)
    check_symmetric_range(curvatures, output)
    check_unit(output, "torus")
    check_radius(output, "torus, default neighborhood")
    check_radius(estimate(torus, NeighborhoodMode="K Nearest", NumberOfNeighbors=40)[1], "torus, K Nearest")

    # The same torus 8 times larger (a power of two: exact in binary).
    rows = numpy.loadtxt(torus)
    rows[:, :3] *= 8.0
    scaled = os.path.join(folder, "torus_times_8.xyz")
    numpy.savetxt(scaled, rows, fmt="%.17g")
    large = estimate(scaled)[1]
    check_unit(large, "torus x 8")
    valid = array(output, "Curvature_Valid") == 1
    ratio = array(large, "Mean_Curvature")[valid] / array(output, "Mean_Curvature")[valid]
    check(numpy.allclose(ratio, 1.0 / 8.0, rtol=1e-9), "torus x 8: curvatures / 8 (ratio %g .. %g)"
          % (ratio.min(), ratio.max()))
    ratio = array(large, "Surroundings_Threshold")[valid] / array(output, "Surroundings_Threshold")[valid]
    check(numpy.allclose(ratio, 8.0, rtol=1e-9), "torus x 8: neighborhood radii x 8 (ratio %g .. %g)"
          % (ratio.min(), ratio.max()))

    run = subprocess.run(["pvpython", tool, "--plugin", plugin, torus, os.path.join(folder, "units.vtp")],
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE, universal_newlines=True)
    lines = run.stdout.splitlines()
    check(run.returncode == 0 and any(l.startswith("curvature unit") and UNIT in l for l in lines),
          "tool summary: the curvature unit (%s)" % [l for l in lines if l.startswith("curvature unit")])
    check(any(l.startswith("neighborhood radius") and "Surroundings_Threshold, a length" in l for l in lines),
          "tool summary: the neighborhood radius (%s)" % [l for l in lines if l.startswith("neighborhood radius")])
    print("%d failed" % len(failures))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:5]))
