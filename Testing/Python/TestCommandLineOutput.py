"""The command-line tool's output-size options and progress display:

    pvpython TestCommandLineOutput.py TOOL.py PLUGIN.so CLOUD.xyz FOLDER

* by default, piped: no stage or progress lines on stderr; the summary
  counts the unestimated points;
* --single-precision --no-diagnostics: float arrays, no diagnostic arrays,
  the same curvatures to float precision, a .vtp (compressed) under half
  the default's size, a .ply (the input's double normals kept) under 55 %;
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
        # The cloud's own normals pass through as they are (double), and a
        # .ply is not compressed: its share is larger than a .vtp's.
        bound = 0.5 if extension == "vtp" else 0.55
        check(sizes[extension] < bound, "%s: compact file %.1f %% of the default's (under %d %%)" % (
            extension, 100 * sizes[extension], 100 * bound))
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
    shown = run(tool, plugin, cloud, os.path.join(folder, "cli_progress.vtp"), "--progress")
    check("estimating" in shown.stderr and "%" in shown.stderr and "writing" in shown.stderr,
          "--progress: stages and a progress line on stderr")
    print("%d failed" % len(failures))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:5]))
