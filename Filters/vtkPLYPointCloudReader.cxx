#include "vtkPLYPointCloudReader.h"

#include "PlyFile.h"
#include "PointCloudReaderSupport.h"

#include "vtkDataArray.h"
#include "vtkErrorCode.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <cstdio>
#include <new>
#include <string>

vtkStandardNewMacro(vtkPLYPointCloudReader);

namespace
{

int VtkTypeOf(pcurv::ply::Type type)
{
  static const int types[] = { VTK_SIGNED_CHAR,
    VTK_UNSIGNED_CHAR,
    VTK_SHORT,
    VTK_UNSIGNED_SHORT,
    VTK_INT,
    VTK_UNSIGNED_INT,
    VTK_FLOAT,
    VTK_DOUBLE };
  return types[static_cast<int>(type)];
}

/// The output's points and arrays, one per column of the layout, whose
/// memory the core then fills.
void MakeArrays(vtkPolyData* output, pcurv::ply::VertexLayout& layout, vtkIdType count)
{
  vtkPointData* pointData = output->GetPointData();
  for (std::size_t c = 0; c < layout.Columns.size(); ++c)
  {
    pcurv::ply::Column& column = layout.Columns[c];
    vtkSmartPointer<vtkDataArray> array = pcurv::readers::NewArray(
      VtkTypeOf(column.ValueType), column.Name.c_str(), column.Components, count);
    column.Data = array->GetVoidPointer(0);
    const int index = static_cast<int>(c);
    if (index == layout.Points)
    {
      vtkNew<vtkPoints> points;
      points->SetData(array);
      output->SetPoints(points);
    }
    else if (index == layout.Normals)
    {
      pointData->SetNormals(array);
    }
    else if (index == layout.Colours)
    {
      pointData->SetScalars(array);
    }
    else
    {
      pointData->AddArray(array);
    }
  }
}

} // namespace

//------------------------------------------------------------------------------
vtkPLYPointCloudReader::vtkPLYPointCloudReader()
{
  this->SetNumberOfInputPorts(0);
}

//------------------------------------------------------------------------------
vtkPLYPointCloudReader::~vtkPLYPointCloudReader()
{
  this->SetFileName(nullptr);
}

//------------------------------------------------------------------------------
int vtkPLYPointCloudReader::CanReadFile(const char* fileName)
{
  std::FILE* file = fileName ? std::fopen(fileName, "rb") : nullptr;
  if (file)
  {
    std::fclose(file);
  }
  return file ? 1 : 0;
}

//------------------------------------------------------------------------------
int vtkPLYPointCloudReader::RequestInformation(vtkInformation*,
  vtkInformationVector**,
  vtkInformationVector* outputVector)
{
  outputVector->GetInformationObject(0)->Set(vtkAlgorithm::CAN_HANDLE_PIECE_REQUEST(), 1);
  return 1;
}

//------------------------------------------------------------------------------
int vtkPLYPointCloudReader::RequestData(vtkInformation*,
  vtkInformationVector**,
  vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkPolyData* output = vtkPolyData::GetData(outInfo);
  this->SetErrorCode(vtkErrorCode::NoError);
  if (!this->FileName || !*this->FileName)
  {
    vtkErrorMacro(<< "No FileName to read.");
    this->SetErrorCode(vtkErrorCode::NoFileNameError);
    return 1;
  }
  std::string error;
  try
  {
    pcurv::ply::File file;
    error = file.Open(this->FileName);
    if (error.empty())
    {
      const auto piece = pcurv::readers::RequestedPiece(outInfo, file.Vertices().Count);
      const vtkIdType count = static_cast<vtkIdType>(piece.End - piece.Begin);
      MakeArrays(output, file.Layout(), count);
      error = file.Read(piece.Begin, piece.End);
      pcurv::readers::AddVertexCells(output, count);
    }
  }
  catch (const std::bad_alloc&)
  {
    error = "out of memory";
  }
  if (!error.empty())
  {
    output->Initialize();
    vtkErrorMacro(<< this->FileName << ": " << error);
    this->SetErrorCode(vtkErrorCode::FileFormatError);
  }
  return 1;
}

//------------------------------------------------------------------------------
void vtkPLYPointCloudReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
}
