"""The Python-wrapped module, without the plugin or its XML:

    pvpython TestWrappedPython.py     (with the package's folder on PYTHONPATH)
"""

import sys

from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkPolyData
from vtkmodules.util.numpy_support import vtk_to_numpy

from principal_curvatures import vtkPrincipalCurvatureEstimation

import math

points, normals = vtkPoints(), vtkDoubleArray()
normals.SetName("Normals")
normals.SetNumberOfComponents(3)
count, radius = 20000, 4.0
golden = math.pi * (3.0 - math.sqrt(5.0))
for i in range(count):
    z = 1.0 - 2.0 * (i + 0.5) / count
    r = math.sqrt(1.0 - z * z)
    n = (r * math.cos(golden * i), r * math.sin(golden * i), z)
    points.InsertNextPoint(radius * n[0], radius * n[1], radius * n[2])
    normals.InsertNextTuple(n)
cloud = vtkPolyData()
cloud.SetPoints(points)
cloud.GetPointData().SetNormals(normals)

curvatures = vtkPrincipalCurvatureEstimation()
curvatures.SetInputData(cloud)
curvatures.SetFitModeToNew01()
curvatures.DynamicAdjustmentOn()
curvatures.Update()
mean = vtk_to_numpy(curvatures.GetOutput().GetPointData().GetArray("Mean_Curvature"))
print("mean curvature %.6f (expected 0.25), length unit %.4g" % (mean.mean(), curvatures.GetUsedLengthUnit()))
ok = abs(mean.mean() - 0.25) < 0.0025 and curvatures.GetFitMode() == 1 and curvatures.GetDynamicAdjustment()
print("ok" if ok else "FAILED")
sys.exit(0 if ok else 1)
