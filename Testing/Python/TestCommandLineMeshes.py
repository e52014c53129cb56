"""Meshes as input: Wavefront OBJ files in the command-line tool (ParaView
reads them; the tool used to refuse them), and OFF files, which the tool
read and ParaView did not, through the plugin's OFF Mesh Reader in both.

    pvpython TestCommandLineMeshes.py TOOL.py PLUGIN.so FOLDER

* vertices with their normals (v and vn lines, no faces) on a sphere of
  radius 2: the file's normals are used, the mean curvature is 1/2;
* a triangle mesh without normals (a sphere of radius 2 from
  vtkSphereSource): normals from the faces, turned outwards, mean
  curvature 1/2;
* an OBJ file with no vertices: exit status 2 and a message;
* an OFF sphere of radius 2 with its faces ordered clockwise: OpenDataFile
  picks the OFF Mesh Reader, its normals point outward; the tool gives mean
  curvature 1/2 from it; bad OFF files (not OFF, a short vertex line, an
  index out of range, missing faces) are an error naming the line, in
  OpenDataFile and in the tool (exit status 2).

Every check prints one line; the exit code is 0 when all pass, 1 otherwise.
"""

import os
import shutil
import subprocess
import sys

import numpy
from paraview import servermanager, simple
from vtkmodules.util.misc import calldata_type
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonCore import VTK_STRING
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
    check_off(tool, plugin, folder, points, polys)
    check_same_orientation(tool, plugin, folder, points, polys)
    print("%d failed" % len(failures))
    return 1 if failures else 0


def output_normals(path):
    reader = vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    return vtk_to_numpy(reader.GetOutput().GetPointData().GetArray("Normals"))


def check_same_orientation(tool, plugin, folder, points, polys):
    """The same mesh, faces clockwise (normals from them point inward), as
    OBJ (the tool turns them) and as OFF (the OFF Mesh Reader turns them):
    the same outward normals, so that the rule is the same in both."""
    inward = polys[:, ::-1]
    obj = os.path.join(folder, "inward.obj")
    with open(obj, "w") as handle:
        handle.writelines("v %.17g %.17g %.17g\n" % tuple(p) for p in points)
        handle.writelines("f %d %d %d\n" % tuple(t + 1) for t in inward)
    off = os.path.join(folder, "inward.off")
    with open(off, "w") as handle:
        handle.write("OFF\n%d %d 0\n" % (len(points), len(inward)))
        handle.writelines("%.17g %.17g %.17g\n" % tuple(p) for p in points)
        handle.writelines("3 %d %d %d\n" % tuple(t) for t in inward)
    outputs = [os.path.join(folder, "inward_obj.vtp"), os.path.join(folder, "inward_off.vtp")]
    done = [run(tool, plugin, path, output) for path, output in zip((obj, off), outputs)]
    if not check(all(d.returncode == 0 for d in done), "inward-wound OBJ and OFF: exit %s"
                 % [d.returncode for d in done]):
        return
    from_obj, from_off = (output_normals(path) for path in outputs)
    outward = float(numpy.median(numpy.sum(points * from_obj, axis=1) / numpy.linalg.norm(points, axis=1)))
    check(outward > 0.9, "inward-wound OBJ: normals turned outward (median n . x / |x| %.3f)" % outward)
    check(from_obj.shape == from_off.shape and numpy.allclose(from_obj, from_off, atol=1e-6),
          "inward-wound mesh: the tool's OBJ normals equal the OFF Mesh Reader's (largest difference %.2g)"
          % (numpy.abs(from_obj - from_off).max() if from_obj.shape == from_off.shape else float("inf")))


def open_with_errors(path):
    """OpenDataFile, updated; its reader's error messages; its output."""
    reader = simple.OpenDataFile(path)
    messages = []

    @calldata_type(VTK_STRING)
    def keep(caller, event, text):
        messages.append(text)

    reader.GetClientSideObject().AddObserver("ErrorEvent", keep)
    reader.UpdatePipeline()
    return reader, " ".join(messages), servermanager.Fetch(reader)


def check_off(tool, plugin, folder, points, polys):
    simple.LoadPlugin(plugin, remote=False)
    path = os.path.join(folder, "sphere_mesh.off")
    with open(path, "w") as handle:
        handle.write("OFF\n# a sphere, faces clockwise seen from outside\n%d %d 0\n" % (len(points), len(polys)))
        handle.writelines("%.17g %.17g %.17g\n" % tuple(p) for p in points)
        handle.writelines("3 %d %d %d\n" % (t[0], t[2], t[1]) for t in polys)
    reader, errors, mesh = open_with_errors(path)
    check(reader.GetXMLName() == "OFFMeshReader" and not errors,
          "OFF: OpenDataFile chose %s (OFFMeshReader), no error" % reader.GetXMLName())
    normals = mesh.GetPointData().GetNormals()
    if check(normals is not None and mesh.GetNumberOfPoints() == len(points) and mesh.GetNumberOfPolys() == len(polys),
             "OFF: %d vertices, %d faces, Normals" % (mesh.GetNumberOfPoints(), mesh.GetNumberOfPolys())):
        outward = (vtk_to_numpy(mesh.GetPoints().GetData()) * vtk_to_numpy(normals)).sum(axis=1)
        check((outward > 0).all(), "OFF: clockwise faces, normals turned outward (%d of %d)"
              % ((outward > 0).sum(), len(outward)))
    output = os.path.join(folder, "sphere_mesh_off.vtp")
    done = run(tool, plugin, path, output)
    if check(done.returncode == 0, "OFF in the tool: exit %d" % done.returncode):
        count, mean = median_mean_curvature(output)
        check(count == len(points) and abs(mean - 1.0 / RADIUS) < 0.01,
              "OFF in the tool: %d points, median mean curvature %.5f (1/%g)" % (count, mean, RADIUS))
    bad = (("notoff.off", "hello\n", "line 1: 'hello' where the OFF header belongs"),
           ("short.off", "OFF\n2 0 0\n0 0 0\n1 0\n", "line 4: vertex 1: 2 number(s); a vertex needs x y z"),
           ("index.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n",
            "line 6: face 0: '7' is not a vertex index (0 to 2)"),
           ("truncated.off", "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", "the file ends after 1 of its 2 faces"))
    for name, text, expected in bad:
        path = os.path.join(folder, name)
        with open(path, "w") as handle:
            handle.write(text)
        reader, errors, mesh = open_with_errors(path)
        check(reader.GetXMLName() == "OFFMeshReader" and (name + ": " + expected) in errors
              and mesh.GetNumberOfPoints() == 0, "bad OFF %s: %s" % (name, errors.strip().splitlines()[-1:]))
        done = run(tool, plugin, path, os.path.join(folder, "bad_off.vtp"))
        check(done.returncode == 2 and expected in done.stderr,
              "bad OFF %s in the tool: exit %d, %s" % (name, done.returncode, done.stderr.strip().splitlines()[-1:]))


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:4]))
