#include "vtkPLYPointCloudReader.h"

#include "FileFormats/PlyFile.h"
#include "PointCloudReaderSupport.h"

#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkErrorCode.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStringArray.h"

#include <string>
#include <vector>

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
    else if (index == layout.Colors)
    {
      pointData->SetScalars(array);
    }
    else
    {
      pointData->AddArray(array);
    }
  }
}

/// The header's "field" comments (PlyComments.h) as field data: numbers
/// as a double array, other text as a string.
void AddFieldComments(const pcurv::ply::Header& header, vtkPolyData* output)
{
  for (const std::string& comment : header.Comments)
  {
    std::string name, value;
    std::vector<double> numbers;
    if (!pcurv::ply::ParseFieldComment(comment, name, value))
    {
      continue;
    }
    if (pcurv::ply::ParseNumbers(value, numbers))
    {
      vtkNew<vtkDoubleArray> array;
      array->SetName(name.c_str());
      array->SetNumberOfComponents(static_cast<int>(numbers.size()));
      array->InsertNextTuple(numbers.data());
      output->GetFieldData()->AddArray(array);
    }
    else
    {
      vtkNew<vtkStringArray> array;
      array->SetName(name.c_str());
      array->InsertNextValue(value);
      output->GetFieldData()->AddArray(array);
    }
  }
}

/// The piece of the file's vertices that outInfo asks for, in output; an
/// empty string, or what is wrong.
std::string ReadVertices(const char* fileName, vtkPolyData* output, vtkInformation* outInfo)
{
  pcurv::ply::File file;
  std::string error = file.Open(fileName);
  if (!error.empty())
  {
    return error;
  }
  const auto piece = pcurv::readers::RequestedPiece(outInfo, file.Vertices().Count);
  const vtkIdType count = static_cast<vtkIdType>(piece.End - piece.Begin);
  MakeArrays(output, file.Layout(), count);
  error = file.Read(piece.Begin, piece.End);
  pcurv::readers::AddVertexCells(output, count);
  AddFieldComments(file.GetHeader(), output);
  return error;
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
  return pcurv::readers::CanOpenFile(fileName);
}

//------------------------------------------------------------------------------
int vtkPLYPointCloudReader::RequestInformation(vtkInformation*,
  vtkInformationVector**,
  vtkInformationVector* outputVector)
{
  return pcurv::readers::AllowPieceRequests(outputVector);
}

//------------------------------------------------------------------------------
int vtkPLYPointCloudReader::RequestData(vtkInformation*,
  vtkInformationVector**,
  vtkInformationVector* outputVector)
{
  unsigned long errorCode = this->GetErrorCode();
  const int result = pcurv::readers::RunRead(
    this, this->FileName, outputVector, vtkErrorCode::FileFormatError, ReadVertices, errorCode);
  this->SetErrorCode(errorCode);
  return result;
}

//------------------------------------------------------------------------------
void vtkPLYPointCloudReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
}
