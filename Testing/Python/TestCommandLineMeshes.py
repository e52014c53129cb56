"""The command-line tool on Wavefront OBJ files, which ParaView reads and
the tool used to refuse:

    pvpython TestCommandLineMeshes.py TOOL.py PLUGIN.so FOLDER

* vertices with their normals (v and vn lines, no faces) on a sphere of
  radius 2: the file's normals are used, the mean curvature is 1/2;
* a triangle mesh without normals (a sphere of radius 2 from
  vtkSphereSource): normals from the faces, turned outwards, mean
  curvature 1/2;
* a file with no vertices: exit status 2 and a message.

Every check prints one line; the exit code is 0 when all pass, 1 otherwise.
"""

import os
import shutil
import subprocess
import sys

import numpy
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkFiltersSources import vtkSphereSource
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader

from test_checks import check, failures  # noqa: E402 (the tests' folder is on sys.path)

RADIUS = 2.0


def run(tool, plugin, path, output):
    command = [shutil.which("pvpython") or "pvpython", tool, "--plugin", plugin, path, output]
    return subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, universal_newlines=True)


def median_mean_curvature(path):
    reader = vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    data = reader.GetOutput().GetPointData()
    valid = vtk_to_numpy(data.GetArray("Curvature_Valid")) == 1
    return reader.GetOutput().GetNumberOfPoints(), float(numpy.median(vtk_to_numpy(data.GetArray("Mean_Curvature"))[valid]))


def fibonacci_sphere(count):
    i = numpy.arange(count) + 0.5
    z = 1.0 - 2.0 * i / count
    angle = numpy.pi * (1.0 + 5.0 ** 0.5) * i
    r = numpy.sqrt(1.0 - z * z)
    return numpy.column_stack([r * numpy.cos(angle), r * numpy.sin(angle), z])


def main(tool, plugin, folder):
    # Vertices and their normals, no faces.
    directions = fibonacci_sphere(3000)
    cloud = os.path.join(folder, "sphere_cloud.obj")
    with open(cloud, "w") as handle:
        handle.writelines("v %.17g %.17g %.17g\n" % tuple(RADIUS * d) for d in directions)
        handle.writelines("vn %.17g %.17g %.17g\n" % tuple(d) for d in directions)
    output = os.path.join(folder, "sphere_cloud_obj.vtp")
    done = run(tool, plugin, cloud, output)
    check(done.returncode == 0 and "normals                    Normals" in done.stdout,
          "OBJ vertices with vn: exit %d, the file's normals used" % done.returncode)
    if done.returncode == 0:
        count, mean = median_mean_curvature(output)
        check(count == 3000 and abs(mean - 1.0 / RADIUS) < 1e-3,
              "OBJ vertices with vn: %d points, median mean curvature %.6f (1/%g)" % (count, mean, RADIUS))

    # A triangle mesh without normals.
    sphere = vtkSphereSource()
    sphere.SetRadius(RADIUS)
    sphere.SetThetaResolution(80)
    sphere.SetPhiResolution(80)
    sphere.Update()
    mesh = sphere.GetOutput()
    points = vtk_to_numpy(mesh.GetPoints().GetData())
    polys = vtk_to_numpy(mesh.GetPolys().GetConnectivityArray()).reshape(-1, 3)
    faces = os.path.join(folder, "sphere_mesh.obj")
    with open(faces, "w") as handle:
        handle.writelines("v %.17g %.17g %.17g\n" % tuple(p) for p in points)
        handle.writelines("f %d %d %d\n" % tuple(t + 1) for t in polys)
    output = os.path.join(folder, "sphere_mesh_obj.vtp")
    done = run(tool, plugin, faces, output)
    check(done.returncode == 0 and "normals from the OBJ faces" in done.stdout,
          "OBJ mesh without normals: exit %d, normals from the faces" % done.returncode)
    if done.returncode == 0:
        count, mean = median_mean_curvature(output)
        check(count == len(points) and abs(mean - 1.0 / RADIUS) < 0.01,
              "OBJ mesh: %d points, median mean curvature %.5f (1/%g, outward)" % (count, mean, RADIUS))

    empty = os.path.join(folder, "empty.obj")
    with open(empty, "w") as handle:
        handle.write("# nothing\n")
    done = run(tool, plugin, empty, os.path.join(folder, "empty_obj.vtp"))
    check(done.returncode == 2 and "empty.obj: no vertices" in done.stderr,
          "OBJ without vertices: exit %d, %s" % (done.returncode, done.stderr.strip().splitlines()[-1:]))
    print("%d failed" % len(failures))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:4]))
