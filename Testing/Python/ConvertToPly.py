"""pvpython ConvertToPly.py IN.vtp OUT.ply: a binary PLY with normals (nx ny nz)."""
import sys
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader
from vtkmodules.vtkIOPLY import vtkPLYWriter
from vtkmodules.vtkCommonCore import vtkFloatArray

reader = vtkXMLPolyDataReader()
reader.SetFileName(sys.argv[1])
reader.Update()
cloud = reader.GetOutput()
# vtkPLYWriter writes float normals only.
normals = vtkFloatArray()
normals.DeepCopy(cloud.GetPointData().GetNormals())
normals.SetName("Normals")
cloud.GetPointData().SetNormals(normals)
writer = vtkPLYWriter()
writer.SetInputData(cloud)
writer.SetFileName(sys.argv[2])
writer.SetFileTypeToBinary()
sys.exit(0 if writer.Write() == 1 else 1)
