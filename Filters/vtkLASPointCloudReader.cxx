#include "vtkLASPointCloudReader.h"

#include "LasFile.h"
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
  if (layout.Extended)
  {
    out.ScanAngle = AddArray<float>(pd, VTK_FLOAT, "ScanAngle", count);
  }
  else
  {
    out.ScanAngleRank = AddArray<std::int8_t>(pd, VTK_SIGNED_CHAR, "ScanAngleRank", count);
  }
  out.UserData = AddArray<std::uint8_t>(pd, VTK_UNSIGNED_CHAR, "UserData", count);
  out.PointSourceId = AddArray<std::uint16_t>(pd, VTK_UNSIGNED_SHORT, "PointSourceId", count);
  if (layout.GpsTime >= 0)
  {
    out.GpsTime = AddArray<double>(pd, VTK_DOUBLE, "GpsTime", count);
  }
  if (layout.Colour >= 0)
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
  std::FILE* file = fileName ? std::fopen(fileName, "rb") : nullptr;
  if (file)
  {
    std::fclose(file);
  }
  return file ? 1 : 0;
}

//------------------------------------------------------------------------------
int vtkLASPointCloudReader::RequestInformation(vtkInformation*,
  vtkInformationVector**,
  vtkInformationVector* outputVector)
{
  outputVector->GetInformationObject(0)->Set(vtkAlgorithm::CAN_HANDLE_PIECE_REQUEST(), 1);
  return 1;
}

//------------------------------------------------------------------------------
int vtkLASPointCloudReader::RequestData(vtkInformation*,
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
    pcurv::las::File file;
    error = file.Open(this->FileName);
    if (error.empty())
    {
      const auto piece = pcurv::readers::RequestedPiece(outInfo, file.GetHeader().PointCount);
      const vtkIdType count = static_cast<vtkIdType>(piece.End - piece.Begin);
      const pcurv::las::PointBuffers buffers =
        MakeArrays(output, file.GetHeader().PointFormat, count);
      error = file.Read(piece.Begin, piece.End, buffers);
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
void vtkLASPointCloudReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
}
