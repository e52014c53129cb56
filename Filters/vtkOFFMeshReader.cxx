#include "vtkOFFMeshReader.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkErrorCode.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataNormals.h"

#include "OffMesh.h"
#include "TextPointCloud.h"

#include <algorithm>
#include <cstdint>
#include <new>
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
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  if (!output)
  {
    return 0;
  }
  this->SetErrorCode(vtkErrorCode::NoError);
  if (!this->FileName || !*this->FileName)
  {
    vtkErrorMacro(<< "No FileName to read.");
    this->SetErrorCode(vtkErrorCode::NoFileNameError);
    return 1;
  }
  try
  {
    std::string buffer, error;
    if (!pcurv::ReadTextFile(this->FileName, static_cast<std::size_t>(-1), buffer, error))
    {
      vtkErrorMacro(<< this->FileName << ": cannot read the file: " << error);
      this->SetErrorCode(vtkErrorCode::CannotOpenFileError);
      return 1;
    }
    pcurv::OffMesh mesh;
    error = pcurv::ParseOffMesh(buffer.data(), buffer.size(), mesh);
    if (!error.empty())
    {
      vtkErrorMacro(<< this->FileName << ": " << error);
      this->SetErrorCode(vtkErrorCode::FileFormatError);
      return 1;
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
      return 1;
    }
    output->SetPolys(Cells(mesh.Offsets, mesh.Connectivity));
    AddOutwardNormals(output);
  }
  catch (const std::bad_alloc&)
  {
    output->Initialize();
    vtkErrorMacro(<< this->FileName << ": out of memory");
    this->SetErrorCode(vtkErrorCode::UnknownError);
  }
  return 1;
}

//------------------------------------------------------------------------------
void vtkOFFMeshReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
}
