#include "vtkPLYPointCloudReader.h"

#include "FileFormats/PlyFile.h"
#include "PointCloudReaderSupport.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
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
#include "vtkSmartPointer.h"
#include "vtkStringArray.h"

#include <cstdint>
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

/// The header's "field" comments (PlyComments.h) as field data.
void AddFieldComments(const pcurv::ply::Header& header, vtkPolyData* output)
{
  std::vector<std::pair<std::string, std::string>> fields;
  std::string name, value;
  for (const std::string& comment : header.Comments)
  {
    if (pcurv::ply::ParseFieldComment(comment, name, value))
    {
      fields.emplace_back(name, value);
    }
  }
  pcurv::readers::AddFieldTexts(fields, output->GetFieldData());
}

/// The file's edges between two vertices of the piece [begin, end) as line
/// cells, their other scalar properties as cell data in their own types.
std::string AddEdgeLines(pcurv::ply::File& file,
  std::uint64_t begin,
  std::uint64_t end,
  vtkPolyData* output)
{
  std::vector<double> rows;
  std::string error = file.ReadEdges(rows);
  std::size_t edge = 0;
  int first = -1, second = -1;
  pcurv::ply::FindEdgeElement(file.GetHeader(), edge, first, second);
  const std::vector<pcurv::ply::Property>& properties = file.Edges()->Properties;
  std::vector<vtkSmartPointer<vtkDataArray>> arrays(properties.size());
  for (std::size_t p = 0; p < properties.size(); ++p)
  {
    if (static_cast<int>(p) != first && static_cast<int>(p) != second && !properties[p].IsList)
    {
      arrays[p] = pcurv::readers::NewArray(
        VtkTypeOf(properties[p].ValueType), properties[p].Name.c_str(), 1, 0);
      output->GetCellData()->AddArray(arrays[p]);
    }
  }
  vtkNew<vtkCellArray> lines;
  for (std::size_t row = 0; error.empty() && row < rows.size() / properties.size(); ++row)
  {
    const double* values = rows.data() + row * properties.size();
    const auto a = static_cast<std::uint64_t>(values[first]);
    const auto b = static_cast<std::uint64_t>(values[second]);
    if (a < begin || a >= end || b < begin || b >= end)
    {
      continue; // an edge across pieces belongs to neither
    }
    const vtkIdType ends[2] = { static_cast<vtkIdType>(a - begin),
      static_cast<vtkIdType>(b - begin) };
    lines->InsertNextCell(2, ends);
    for (std::size_t p = 0; p < arrays.size(); ++p)
    {
      if (arrays[p])
      {
        arrays[p]->InsertNextTuple1(values[p]);
      }
    }
  }
  output->SetLines(lines);
  return error;
}

/// The piece of the file's vertices that outInfo asks for, in output (as
/// vertex cells, or the file's edges as line cells); an empty string, or
/// what is wrong.
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
  if (error.empty() && file.Edges())
  {
    error = AddEdgeLines(file, piece.Begin, piece.End, output);
  }
  else
  {
    pcurv::readers::AddVertexCells(output, count);
  }
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
