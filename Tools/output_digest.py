"""Digests of every output array of the filter, over a fixed set of clouds
and settings, so that a refactoring can be checked to leave the results
bit-identical: run it before and after, and compare the two listings.

    pvpython Tools/output_digest.py CLOUD.(vtp|bin) [...] > digest.txt

A .bin is a cloud of the shared accuracy suite (little-endian float64 rows
of x y z nx ny nz and eight more columns). Every cloud is also run without
its normals (the normals estimated), and through the normals filter alone.

Needs the wrapped Python package on PYTHONPATH (the build's
lib/python3.X/site-packages). One line per (cloud, setting, array): the
SHA-256 of the array's raw values, with the array's type and shape.
"""

import hashlib
import sys

import numpy

from vtkmodules.vtkCommonDataModel import vtkPolyData
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkPoints

from principal_curvatures import vtkPointCloudNormalEstimation, vtkPrincipalCurvatureEstimation


def configure_default(f):
    pass


def configure_paper_default(f):
    """The filter's defaults before the fit beyond the paper became one."""
    f.SetFitModeToNew01()
    f.SetNeighborhoodModeToRadius()


def configure_previous(f):
    f.SetFitModeToPrevious()


def configure_new02(f):
    f.SetFitModeToNew02()


def configure_k_nearest(f):
    f.SetFitModeToNew01()
    f.SetNeighborhoodModeToKNearest()
    f.SetNumberOfNeighbors(120)


def configure_fixed(f):
    f.SetFitModeToNew01()
    f.AutomaticThresholdsOff()
    f.SetSurroundingsThreshold(0.35)
    f.SetPlaneDistanceThreshold(0.04)


def configure_dva_paper(f):
    f.SetFitModeToNew01()
    f.DynamicAdjustmentOn()


def configure_dva_ladder(f):
    f.SetFitModeToNew01()
    f.DynamicAdjustmentOn()
    f.SetAdjustmentConstantsToBandedLadder(375, 0.2)


def configure_one_thread(f):
    f.SetNumberOfThreads(1)
    f.SetFitModeToNew02()


SETTINGS = [
    ("default", configure_default),
    ("paper_default", configure_paper_default),
    ("previous", configure_previous),
    ("new02", configure_new02),
    ("k_nearest", configure_k_nearest),
    ("fixed", configure_fixed),
    ("dva_paper", configure_dva_paper),
    ("dva_ladder", configure_dva_ladder),
    ("one_thread", configure_one_thread),
]


def scaled(cloud):
    """The cloud with its coordinates times 2^-600: the working-unit path."""
    copy = vtkPolyData()
    copy.DeepCopy(cloud)
    vtk_to_numpy(copy.GetPoints().GetData())[:] *= 2.0 ** -600
    return copy


def damaged(cloud):
    """A few non-finite coordinates and zero or non-finite normals."""
    copy = vtkPolyData()
    copy.DeepCopy(cloud)
    x = vtk_to_numpy(copy.GetPoints().GetData())
    n = vtk_to_numpy(copy.GetPointData().GetNormals())
    x[::997, 1] = float("nan")
    n[5::1009] = 0.0
    n[7::1013, 2] = float("inf")
    return copy


def without_normals(cloud):
    """The positions alone: the filter estimates the normals."""
    copy = vtkPolyData()
    copy.DeepCopy(cloud)
    copy.GetPointData().SetNormals(None)
    return copy


VARIANTS = [("", lambda cloud: cloud), ("scaled", scaled), ("damaged", damaged),
            ("positions", without_normals)]


def read_cloud(path):
    if path.endswith(".bin"):
        data = numpy.fromfile(path, dtype="<f8").reshape(-1, 14)
        cloud = vtkPolyData()
        points = vtkPoints()
        points.SetData(numpy_to_vtk(numpy.ascontiguousarray(data[:, 0:3]), deep=True))
        cloud.SetPoints(points)
        normals = numpy_to_vtk(numpy.ascontiguousarray(data[:, 3:6]), deep=True)
        normals.SetName("Normals")
        cloud.GetPointData().SetNormals(normals)
        return cloud
    reader = vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


def array_lines(label, name, point_data):
    for i in range(point_data.GetNumberOfArrays()):
        array = point_data.GetArray(i)
        values = vtk_to_numpy(array)
        digest = hashlib.sha256(values.tobytes()).hexdigest()[:16]
        yield "%s %s %s %s %s %s" % (
            label, name, array.GetName(), values.dtype, values.shape, digest)


def digest_lines(path):
    cloud = read_cloud(path)
    for variant, make in VARIANTS:
        for line in digest_variant(path.split("/")[-1] + variant, make(cloud)):
            yield line
    normals = vtkPointCloudNormalEstimation()
    normals.SetInputData(without_normals(cloud))
    normals.Update()
    for line in array_lines(path.split("/")[-1], "normals_filter", normals.GetOutput().GetPointData()):
        yield line


def digest_variant(label, cloud):
    for name, configure in SETTINGS:
        f = vtkPrincipalCurvatureEstimation()
        f.SetInputData(cloud)
        configure(f)
        f.Update()
        for line in array_lines(label, name, f.GetOutput().GetPointData()):
            yield line
        yield "%s %s used s=%r p=%r L=%r unestimated=%d" % (
            label, name, f.GetUsedSurroundingsThreshold(),
            f.GetUsedPlaneDistanceThreshold(), f.GetUsedLengthUnit(),
            f.GetNumberOfUnestimatedPoints())


for cloud in sys.argv[1:]:
    for line in digest_lines(cloud):
        print(line)
