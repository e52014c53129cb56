#include "vtkOFFMeshReader.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkErrorCode.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataNormals.h"

#include "FileFormats/MeshOrientation.h"
#include "FileFormats/OffMesh.h"
#include "PointCloudReaderSupport.h"

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkOFFMeshReader);

namespace
{

/// Cells from offsets and connectivity as vtkCellArray stores them.
vtkNew<vtkCellArray> Cells(const std::vector<std::int64_t>& offsets,
  const std::vector<std::int64_t>& connectivity)
{
  vtkNew<vtkIdTypeArray> offsetArray, connectivityArray;
  offsetArray->SetNumberOfValues(static_cast<vtkIdType>(offsets.size()));
  std::copy(offsets.begin(), offsets.end(), offsetArray->GetPointer(0));
  connectivityArray->SetNumberOfValues(static_cast<vtkIdType>(connectivity.size()));
  std::copy(connectivity.begin(), connectivity.end(), connectivityArray->GetPointer(0));
  vtkNew<vtkCellArray> cells;
  cells->SetData(offsetArray, connectivityArray);
  return cells;
}

/// One vertex cell per point, for a file without faces.
vtkNew<vtkCellArray> VertexCells(std::size_t count)
{
  std::vector<std::int64_t> offsets(count + 1), connectivity(count);
  for (std::size_t i = 0; i < count; ++i)
  {
    offsets[i] = connectivity[i] = static_cast<std::int64_t>(i);
  }
  offsets[count] = static_cast<std::int64_t>(count);
  return Cells(offsets, connectivity);
}

/// The mesh with point normals from its faces, turned outwards.
void AddOutwardNormals(vtkPolyData* mesh)
{
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputData(mesh);
  normals->ComputePointNormalsOn();
  normals->ComputeCellNormalsOff();
  normals->SplittingOff();
  normals->ConsistencyOn();
  normals->Update();
  vtkPolyData* result = normals->GetOutput();
  vtkDataArray* values = result->GetPointData()->GetNormals();
  vtkNew<vtkDoubleArray> outward;
  outward->SetName("Normals");
  outward->DeepCopy(values);
  vtkDataArray* points = mesh->GetPoints()->GetData();
  const bool inward =
    pcurv::NormalsMostlyInward(vtkDoubleArray::SafeDownCast(points)->GetPointer(0),
      outward->GetPointer(0),
      static_cast<std::size_t>(outward->GetNumberOfTuples()));
  if (inward)
  {
    double* n = outward->GetPointer(0);
    for (vtkIdType i = 0; i < 3 * outward->GetNumberOfTuples(); ++i)
    {
      n[i] = -n[i];
    }
  }
  mesh->GetPointData()->SetNormals(outward);
}

/// The file's mesh in output: its faces with outward normals, or a vertex
/// cell per point when it has no faces. The whole mesh, whatever piece the
/// request asks for.
pcurv::readers::ReadFailure ReadMesh(const char* fileName, vtkPolyData* output, vtkInformation*)
{
  std::string buffer;
  const pcurv::readers::ReadFailure failure = pcurv::readers::ReadWholeTextFile(fileName, buffer);
  if (!failure.Message.empty())
  {
    return failure;
  }
  pcurv::OffMesh mesh;
  const std::string error = pcurv::ParseOffMesh(buffer.data(), buffer.size(), mesh);
  if (!error.empty())
  {
    return error;
  }
  vtkNew<vtkDoubleArray> coordinates;
  coordinates->SetNumberOfComponents(3);
  coordinates->SetNumberOfTuples(static_cast<vtkIdType>(mesh.Points.size() / 3));
  std::copy(mesh.Points.begin(), mesh.Points.end(), coordinates->GetPointer(0));
  vtkNew<vtkPoints> points;
  points->SetData(coordinates);
  output->SetPoints(points);
  if (mesh.Faces() == 0)
  {
    output->SetVerts(VertexCells(mesh.Points.size() / 3));
    return pcurv::readers::ReadFailure();
  }
  output->SetPolys(Cells(mesh.Offsets, mesh.Connectivity));
  AddOutwardNormals(output);
  return pcurv::readers::ReadFailure();
}

} // namespace

//------------------------------------------------------------------------------
vtkOFFMeshReader::vtkOFFMeshReader()
{
  this->SetNumberOfInputPorts(0);
}

//------------------------------------------------------------------------------
vtkOFFMeshReader::~vtkOFFMeshReader()
{
  this->SetFileName(nullptr);
}

//------------------------------------------------------------------------------
int vtkOFFMeshReader::RequestData(vtkInformation*,
  vtkInformationVector**,
  vtkInformationVector* outputVector)
{
  unsigned long errorCode = this->GetErrorCode();
  const int result = pcurv::readers::RunRead(
    this, this->FileName, outputVector, vtkErrorCode::UnknownError, ReadMesh, errorCode);
  this->SetErrorCode(errorCode);
  return result;
}

//------------------------------------------------------------------------------
void vtkOFFMeshReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
}
