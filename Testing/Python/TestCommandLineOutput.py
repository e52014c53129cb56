"""The command-line tool's output-size options and progress display:

    pvpython TestCommandLineOutput.py TOOL.py PLUGIN.so CLOUD.xyz FOLDER

* by default, piped: no stage or progress lines on stderr; the summary
  counts the unestimated points;
* --single-precision --no-diagnostics: float arrays, no diagnostic arrays,
  the same curvatures to float precision, a .vtp (compressed) and a .ply
  each under half the default's size (the input's double normals kept);
* a compact .ply has float points where float keeps them (this torus), and
  double ones 5,000 km from the origin;
* --progress, piped: the stages and a progress line on stderr.

Every check prints one line; the exit code is 0 when all pass, 1 otherwise.
"""

import os
import shutil
import subprocess
import sys

import numpy
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader

from test_checks import check, failures  # noqa: E402 (the tests' folder is on sys.path)


def run(tool, plugin, cloud, output, *options):
    command = [shutil.which("pvpython") or "pvpython", tool, "--plugin", plugin, cloud, output] + list(options)
    done = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    check(done.returncode == 0, "%s %s: exit 0" % (os.path.basename(output), " ".join(options)))
    return done


def read(path):
    reader = vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput().GetPointData()


def main(tool, plugin, cloud, folder):
    sizes = {}
    for extension in ("vtp", "ply"):
        full = os.path.join(folder, "cli_full." + extension)
        compact = os.path.join(folder, "cli_compact." + extension)
        plain = run(tool, plugin, cloud, full)
        run(tool, plugin, cloud, compact, "--single-precision", "--no-diagnostics")
        sizes[extension] = os.path.getsize(compact) / os.path.getsize(full)
        # The cloud's own normals pass through as they are (double): under
        # half, not the 40 % of a cloud whose normals are estimated.
        check(sizes[extension] < 0.5, "%s: compact file %.1f %% of the default's (under 50 %%)" % (
            extension, 100 * sizes[extension]))
        if extension == "vtp":
            check("estimating" not in plain.stderr and "writing" not in plain.stderr,
                  "piped, by default: no stages or progress on stderr")
            check("not estimated" in plain.stdout, "the summary counts the unestimated points")
            a, b = read(full), read(compact)
            check(b.GetArray("Mean_Curvature").GetDataType() == 10, "compact: Mean_Curvature is float")
            check(all(b.GetArray(name) is None and a.GetArray(name) is not None
                      for name in ("Neighbor_Count", "Sine_Fit_RMS", "Curvature_Standard_Error")),
                  "compact: no diagnostic arrays")
            exact, single = (vtk_to_numpy(x.GetArray("Maximum_Curvature")) for x in (a, b))
            check(numpy.allclose(exact, single, rtol=1e-6, atol=1e-6, equal_nan=True),
                  "compact: the same curvatures to float precision")
    with open(os.path.join(folder, "cli_compact.ply"), "rb") as handle:
        header = handle.read(2000).split(b"end_header")[0].decode("ascii", "replace")
    check("property float x" in header, "compact .ply: float points (float keeps this torus's coordinates)")
    # The same cloud 5,000 km from the origin, as a georeferenced scan: its
    # points stay double (float would be off by a quarter of a unit).
    far = numpy.loadtxt(cloud, comments="#")
    far[:, 0] += 5.0e6
    far_path = os.path.join(folder, "cli_far.xyz")
    numpy.savetxt(far_path, far, fmt="%.17g")
    run(tool, plugin, far_path, os.path.join(folder, "cli_far.ply"), "--single-precision", "--no-diagnostics")
    with open(os.path.join(folder, "cli_far.ply"), "rb") as handle:
        header = handle.read(2000).split(b"end_header")[0].decode("ascii", "replace")
    check("property double x" in header, "compact .ply far from the origin: the points stay double")
    shown = run(tool, plugin, cloud, os.path.join(folder, "cli_progress.vtp"), "--progress")
    check("estimating" in shown.stderr and "%" in shown.stderr and "writing" in shown.stderr,
          "--progress: stages and a progress line on stderr")
    print("%d failed" % len(failures))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:5]))
