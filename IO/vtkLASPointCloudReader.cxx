#include "vtkLASPointCloudReader.h"

#include "FileFormats/LasColors.h"
#include "FileFormats/LasFile.h"
#include "LasFieldData.h"
#include "PointCloudReaderSupport.h"

#include "vtkDataArray.h"
#include "vtkErrorCode.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <cstddef>
#include <cstdint>
#include <string>

vtkStandardNewMacro(vtkLASPointCloudReader);

namespace
{

/// A point-data array of the output and the buffer pointer the core fills.
template<typename T>
T* AddArray(vtkPointData* pointData, int vtkType, const char* name, vtkIdType count)
{
  vtkSmartPointer<vtkDataArray> array = pcurv::readers::NewArray(vtkType, name, 1, count);
  pointData->AddArray(array);
  return static_cast<T*>(array->GetVoidPointer(0));
}

/// The output's arrays for the format, and the buffers that point into them.
pcurv::las::PointBuffers MakeArrays(vtkPolyData* output, int format, vtkIdType count)
{
  using namespace pcurv::las;
  const RecordLayout layout = LayoutOf(format);
  PointBuffers out;
  vtkSmartPointer<vtkDataArray> coordinates =
    pcurv::readers::NewArray(VTK_DOUBLE, "Points", 3, count);
  vtkNew<vtkPoints> points;
  points->SetData(coordinates);
  output->SetPoints(points);
  out.Points = static_cast<double*>(coordinates->GetVoidPointer(0));

  vtkPointData* pd = output->GetPointData();
  out.Intensity = AddArray<std::uint16_t>(pd, VTK_UNSIGNED_SHORT, "Intensity", count);
  out.ReturnNumber = AddArray<std::uint8_t>(pd, VTK_UNSIGNED_CHAR, "ReturnNumber", count);
  out.NumberOfReturns = AddArray<std::uint8_t>(pd, VTK_UNSIGNED_CHAR, "NumberOfReturns", count);
  out.Classification = AddArray<std::uint8_t>(pd, VTK_UNSIGNED_CHAR, "Classification", count);
  out.ClassFlags = AddArray<std::uint8_t>(pd, VTK_UNSIGNED_CHAR, "ClassFlags", count);
  out.ScanDirectionFlag = AddArray<std::uint8_t>(pd, VTK_UNSIGNED_CHAR, "ScanDirectionFlag", count);
  out.EdgeOfFlightLine = AddArray<std::uint8_t>(pd, VTK_UNSIGNED_CHAR, "EdgeOfFlightLine", count);
  if (layout.Extended)
  {
    out.ScannerChannel = AddArray<std::uint8_t>(pd, VTK_UNSIGNED_CHAR, "ScannerChannel", count);
    out.ScanAngle = AddArray<float>(pd, VTK_FLOAT, "ScanAngle", count);
  }
  else
  {
    // A short, not a signed char: writers (ParaView's CSV) print a char as
    // a character, not as a number.
    out.ScanAngleRank = AddArray<std::int16_t>(pd, VTK_SHORT, "ScanAngleRank", count);
  }
  out.UserData = AddArray<std::uint8_t>(pd, VTK_UNSIGNED_CHAR, "UserData", count);
  out.PointSourceId = AddArray<std::uint16_t>(pd, VTK_UNSIGNED_SHORT, "PointSourceId", count);
  if (layout.GpsTime >= 0)
  {
    out.GpsTime = AddArray<double>(pd, VTK_DOUBLE, "GpsTime", count);
  }
  if (layout.Color >= 0)
  {
    out.Red = AddArray<std::uint16_t>(pd, VTK_UNSIGNED_SHORT, "Red", count);
    out.Green = AddArray<std::uint16_t>(pd, VTK_UNSIGNED_SHORT, "Green", count);
    out.Blue = AddArray<std::uint16_t>(pd, VTK_UNSIGNED_SHORT, "Blue", count);
  }
  if (layout.Infrared >= 0)
  {
    out.Infrared = AddArray<std::uint16_t>(pd, VTK_UNSIGNED_SHORT, "Infrared", count);
  }
  return out;
}

/// The colors as one 3-component unsigned char array RGB, the active
/// scalars: ParaView colors by it at the first Apply, and shows the true
/// colors with Map Scalars off. Red, Green and Blue stay as read (the LAS
/// writer writes them back; RGB is derived, and it skips it).
void AddEightBitColors(vtkPointData* pointData,
  const pcurv::las::PointBuffers& buffers,
  vtkIdType count)
{
  // An extra-bytes dimension named RGB keeps its name.
  if (!buffers.Red || !buffers.Green || !buffers.Blue || pointData->GetArray("RGB"))
  {
    return;
  }
  vtkSmartPointer<vtkDataArray> rgb = pcurv::readers::NewArray(VTK_UNSIGNED_CHAR, "RGB", 3, count);
  const auto points = static_cast<std::size_t>(count);
  const bool sixteenBit =
    pcurv::las::HasSixteenBitColors(buffers.Red, buffers.Green, buffers.Blue, points);
  pcurv::las::ToEightBitColors(buffers.Red,
    buffers.Green,
    buffers.Blue,
    points,
    sixteenBit,
    static_cast<std::uint8_t*>(rgb->GetVoidPointer(0)));
  pointData->AddArray(rgb);
  pointData->SetActiveScalars("RGB");
}

/// The piece of the file's points that outInfo asks for, in output; an
/// empty string, or what is wrong.
std::string ReadPoints(const char* fileName, vtkPolyData* output, vtkInformation* outInfo)
{
  pcurv::las::File file;
  std::string error = file.Open(fileName);
  if (!error.empty())
  {
    return error;
  }
  const auto piece = pcurv::readers::RequestedPiece(outInfo, file.GetHeader().PointCount);
  const vtkIdType count = static_cast<vtkIdType>(piece.End - piece.Begin);
  pcurv::las::PointBuffers buffers = MakeArrays(output, file.GetHeader().PointFormat, count);
  const std::vector<pcurv::las::Vlr> records = file.ReadKeptRecords();
  buffers.Extras = pcurv::readers::AddExtraArrays(
    output->GetPointData(), pcurv::las::ExtraFieldsOf(file.GetHeader(), records), count);
  pcurv::readers::AddFileDescription(output->GetFieldData(), file.GetHeader(), records);
  error = file.Read(piece.Begin, piece.End, buffers);
  if (error.empty())
  {
    AddEightBitColors(output->GetPointData(), buffers, count);
  }
  pcurv::readers::AddVertexCells(output, count);
  return error;
}

} // namespace

//------------------------------------------------------------------------------
vtkLASPointCloudReader::vtkLASPointCloudReader()
{
  this->SetNumberOfInputPorts(0);
}

//------------------------------------------------------------------------------
vtkLASPointCloudReader::~vtkLASPointCloudReader()
{
  this->SetFileName(nullptr);
}

//------------------------------------------------------------------------------
int vtkLASPointCloudReader::CanReadFile(const char* fileName)
{
  return pcurv::readers::CanOpenFile(fileName);
}

//------------------------------------------------------------------------------
int vtkLASPointCloudReader::RequestInformation(vtkInformation*,
  vtkInformationVector**,
  vtkInformationVector* outputVector)
{
  return pcurv::readers::AllowPieceRequests(outputVector);
}

//------------------------------------------------------------------------------
int vtkLASPointCloudReader::RequestData(vtkInformation*,
  vtkInformationVector**,
  vtkInformationVector* outputVector)
{
  unsigned long errorCode = this->GetErrorCode();
  const int result = pcurv::readers::RunRead(
    this, this->FileName, outputVector, vtkErrorCode::FileFormatError, ReadPoints, errorCode);
  this->SetErrorCode(errorCode);
  return result;
}

//------------------------------------------------------------------------------
void vtkLASPointCloudReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
}
