"""Principal curvatures of point clouds by osculating-circle fitting in
conformal geometric algebra (Getto & Hildenbrand 2011), for VTK Python.

    from principal_curvatures import vtkPrincipalCurvatureEstimation
    from principal_curvatures import vtkPointCloudNormalEstimation
    from principal_curvatures import vtkTextPointCloudReader
    from principal_curvatures import vtkLASPointCloudReader, vtkPLYPointCloudReader

Needs the VTK that ParaView bundles (run it in pvpython or pvbatch).
"""

# The wrapped classes need VTK's Python modules of their dependencies.
import vtkmodules.vtkCommonExecutionModel  # noqa: F401

from .vtkPrincipalCurvatureFilters import (  # noqa: F401
    vtkPointCloudNormalEstimation,
    vtkPrincipalCurvatureEstimation,
)
from .vtkPrincipalCurvatureIO import (  # noqa: F401
    vtkLASPointCloudReader,
    vtkOFFMeshReader,
    vtkPLYPointCloudReader,
    vtkTextPointCloudReader,
)

__all__ = ["vtkLASPointCloudReader", "vtkOFFMeshReader", "vtkPLYPointCloudReader",
           "vtkPointCloudNormalEstimation", "vtkPrincipalCurvatureEstimation", "vtkTextPointCloudReader"]
