#include "vtkTextPointCloudReader.h"

#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkErrorCode.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkUnsignedCharArray.h"

#include "PointCloudReaderSupport.h"
#include "FileFormats/TextPointCloud.h"

#include <string>
#include <utility>
#include <vector>

vtkStandardNewMacro(vtkTextPointCloudReader);

namespace
{

/// Rows [begin, end) of the given columns as an array of doubles.
vtkSmartPointer<vtkDoubleArray> DoubleColumns(const pcurv::TextCloud& cloud,
  const std::vector<std::size_t>& columns,
  std::size_t begin,
  std::size_t end,
  const char* name)
{
  auto array = vtkSmartPointer<vtkDoubleArray>::New();
  const int components = static_cast<int>(columns.size());
  array->SetNumberOfComponents(components);
  array->SetNumberOfTuples(static_cast<vtkIdType>(end - begin));
  if (name)
  {
    array->SetName(name);
  }
  double* out = array->GetPointer(0);
  const double* in = cloud.Values.data();
  for (std::size_t row = begin; row < end; ++row)
  {
    for (std::size_t c : columns)
    {
      *out++ = in[row * cloud.Columns + c];
    }
  }
  return array;
}

/// One vertex cell per point, so that the cloud renders.
vtkNew<vtkCellArray> VertexCells(vtkIdType count)
{
  vtkNew<vtkIdTypeArray> offsets, connectivity;
  offsets->SetNumberOfValues(count + 1);
  connectivity->SetNumberOfValues(count);
  for (vtkIdType i = 0; i < count; ++i)
  {
    offsets->SetValue(i, i);
    connectivity->SetValue(i, i);
  }
  offsets->SetValue(count, count);
  vtkNew<vtkCellArray> vertices;
  vertices->SetData(offsets, connectivity);
  return vertices;
}

/// Rows [begin, end) of the color columns as RGB (unsigned char).
vtkNew<vtkUnsignedCharArray> ColorColumns(const pcurv::TextCloud& cloud,
  const std::vector<std::size_t>& columns,
  std::size_t begin,
  std::size_t end)
{
  vtkNew<vtkUnsignedCharArray> colors;
  colors->SetName("RGB");
  colors->SetNumberOfComponents(3);
  colors->SetNumberOfTuples(static_cast<vtkIdType>(end - begin));
  unsigned char* out = colors->GetPointer(0);
  for (std::size_t row = begin; row < end; ++row)
  {
    for (std::size_t c : columns)
    {
      *out++ = static_cast<unsigned char>(cloud.Values[row * cloud.Columns + c]);
    }
  }
  return colors;
}

/// The consecutive range of rows that this piece gets.
std::pair<std::size_t, std::size_t> PieceRows(vtkInformation* outInfo, std::size_t rows)
{
  int piece = outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER());
  int pieces = outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES());
  if (pieces < 1 || piece < 0 || piece >= pieces)
  {
    piece = 0;
    pieces = 1;
  }
  return { rows * piece / pieces, rows * (piece + 1) / pieces };
}

/// Reads and parses the file; what is wrong when it is not a cloud.
pcurv::readers::ReadFailure ReadCloud(const char* fileName, pcurv::TextCloud& cloud)
{
  std::string buffer;
  const pcurv::readers::ReadFailure failure = pcurv::readers::ReadWholeTextFile(fileName, buffer);
  if (!failure.Message.empty())
  {
    return failure;
  }
  const bool pts = pcurv::LowerExtension(fileName) == "pts";
  std::string error = pcurv::ParseTextCloud(buffer.data(), buffer.size(), pts, false, cloud);
  if (!error.empty())
  {
    if (pcurv::LooksLikeMolecule(buffer.data(), buffer.size()))
    {
      error = "an XYZ molecule file (an atom count, a comment line, then 'element x y z' "
              "lines), not a point cloud: open it with ParaView's XYZ Reader";
    }
    return error;
  }
  cloud.Values.shrink_to_fit();
  return pcurv::readers::ReadFailure();
}

/// The piece of the cloud that outInfo asks for, in output, with the
/// layout's normals, colors and other columns as point data.
void CopyPiece(const pcurv::TextCloud& cloud,
  const pcurv::ColumnLayout& layout,
  vtkInformation* outInfo,
  vtkPolyData* output)
{
  const auto rows = PieceRows(outInfo, cloud.Rows());
  const std::size_t begin = rows.first, end = rows.second;
  vtkNew<vtkPoints> points;
  points->SetData(DoubleColumns(cloud, layout.Position, begin, end, nullptr));
  output->SetPoints(points);
  output->SetVerts(VertexCells(static_cast<vtkIdType>(end - begin)));

  vtkPointData* pointData = output->GetPointData();
  if (!layout.Normal.empty())
  {
    pointData->SetNormals(DoubleColumns(cloud, layout.Normal, begin, end, "Normals"));
  }
  if (!layout.Color.empty())
  {
    pointData->SetScalars(ColorColumns(cloud, layout.Color, begin, end));
  }
  for (const auto& scalar : layout.Scalars)
  {
    pointData->AddArray(DoubleColumns(cloud, { scalar.first }, begin, end, scalar.second.c_str()));
  }
  pcurv::readers::AddFieldTexts(cloud.Fields, output->GetFieldData());
}

bool IsCloudExtension(const std::string& extension)
{
  return extension == "xyz" || extension == "pwn" || extension == "pts";
}

} // namespace

//------------------------------------------------------------------------------
vtkTextPointCloudReader::vtkTextPointCloudReader()
{
  this->SetNumberOfInputPorts(0);
}

//------------------------------------------------------------------------------
vtkTextPointCloudReader::~vtkTextPointCloudReader()
{
  this->SetFileName(nullptr);
}

//------------------------------------------------------------------------------
int vtkTextPointCloudReader::CanReadFile(const char* fileName)
{
  if (!fileName || !*fileName)
  {
    return 0;
  }
  std::string buffer, error;
  const bool readable = pcurv::ReadTextFile(fileName, 1 << 16, buffer, error);
  const std::string extension = pcurv::LowerExtension(fileName);
  if (IsCloudExtension(extension))
  {
    // Taken whatever they hold, so that a bad file gets this reader's
    // message rather than reaching the PLOT3D reader, which crashes on
    // text. Only a binary PLOT3D grid is left to that reader.
    return readable && pcurv::LooksLikePlot3d(buffer.data(), buffer.size()) ? 0 : 1;
  }
  // .txt (and .csv) are tables as often as clouds: only a file whose first
  // data line holds at least x y z is a cloud; others go to the CSV reader.
  pcurv::TextCloud cloud;
  return readable &&
      pcurv::ParseTextCloud(buffer.data(), buffer.size(), extension == "pts", true, cloud).empty()
    ? 1
    : 0;
}

//------------------------------------------------------------------------------
int vtkTextPointCloudReader::RequestInformation(vtkInformation*,
  vtkInformationVector**,
  vtkInformationVector* outputVector)
{
  return pcurv::readers::AllowPieceRequests(outputVector);
}

//------------------------------------------------------------------------------
void vtkTextPointCloudReader::WarnAboutNonFinitePositions(const std::vector<std::size_t>& lines)
{
  if (!lines.empty())
  {
    vtkWarningMacro(<< this->FileName << ": " << lines.size()
                    << " point(s) with a NaN or infinite coordinate (the first at line "
                    << lines.front()
                    << "); kept, and left unestimated by the curvature filter "
                       "(Curvature_Valid 0, counted in Unestimated_Bad_Coordinate)");
  }
}

//------------------------------------------------------------------------------
int vtkTextPointCloudReader::RequestData(vtkInformation*,
  vtkInformationVector**,
  vtkInformationVector* outputVector)
{
  // The warning about bad coordinates is this reader's own, so the read is
  // a lambda here rather than a free function.
  const auto readPiece = [this](const char* fileName, vtkPolyData* output, vtkInformation* outInfo)
  {
    pcurv::TextCloud cloud;
    const pcurv::readers::ReadFailure failure = ReadCloud(fileName, cloud);
    if (!failure.Message.empty())
    {
      return failure;
    }
    const bool pts = pcurv::LowerExtension(fileName) == "pts";
    const pcurv::ColumnLayout layout = pcurv::ChooseColumnLayout(cloud, pts);
    this->WarnAboutNonFinitePositions(pcurv::NonFinitePositionLines(cloud, layout));
    CopyPiece(cloud, layout, outInfo, output);
    return pcurv::readers::ReadFailure();
  };
  unsigned long errorCode = this->GetErrorCode();
  const int result = pcurv::readers::RunRead(
    this, this->FileName, outputVector, vtkErrorCode::UnknownError, readPiece, errorCode);
  this->SetErrorCode(errorCode);
  return result;
}

//------------------------------------------------------------------------------
void vtkTextPointCloudReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
}
