#include "PointCloudReaderSupport.h"

#include "FileFormats/PlyComments.h"
#include "FileFormats/TextPointCloud.h"

#include "vtkAlgorithm.h"
#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObject.h"
#include "vtkPolyData.h"
#include "vtkSetGet.h"
#include "vtkStringArray.h"
#include "vtkTypeInt32Array.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <cstdio>
#include <new>

namespace pcurv
{
namespace readers
{

//------------------------------------------------------------------------------
int RunRead(vtkAlgorithm* reader,
  const char* fileName,
  vtkInformationVector* outputVector,
  unsigned long outOfMemoryCode,
  const ReadFunction& read,
  unsigned long& errorCode)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkPolyData* output = vtkPolyData::GetData(outInfo);
  if (!output)
  {
    return 0;
  }
  errorCode = vtkErrorCode::NoError;
  if (!fileName || !*fileName)
  {
    vtkErrorWithObjectMacro(reader, << "No FileName to read.");
    errorCode = vtkErrorCode::NoFileNameError;
    return 1;
  }
  ReadFailure failure;
  try
  {
    failure = read(fileName, output, outInfo);
  }
  catch (const std::bad_alloc&)
  {
    failure = ReadFailure("out of memory", outOfMemoryCode);
  }
  if (!failure.Message.empty())
  {
    output->Initialize();
    vtkErrorWithObjectMacro(reader, << fileName << ": " << failure.Message);
    errorCode = failure.ErrorCode;
  }
  return 1;
}

//------------------------------------------------------------------------------
ReadFailure ReadWholeTextFile(const char* fileName, std::string& buffer)
{
  std::string error;
  if (!pcurv::ReadTextFile(fileName, static_cast<std::size_t>(-1), buffer, error))
  {
    return ReadFailure("cannot read the file: " + error, vtkErrorCode::CannotOpenFileError);
  }
  return ReadFailure();
}

//------------------------------------------------------------------------------
int CanOpenFile(const char* fileName)
{
  std::FILE* file = fileName ? std::fopen(fileName, "rb") : nullptr;
  if (file)
  {
    std::fclose(file);
  }
  return file ? 1 : 0;
}

//------------------------------------------------------------------------------
int AllowPieceRequests(vtkInformationVector* outputVector)
{
  outputVector->GetInformationObject(0)->Set(vtkAlgorithm::CAN_HANDLE_PIECE_REQUEST(), 1);
  return 1;
}

//------------------------------------------------------------------------------

PieceRange RequestedPiece(vtkInformation* outInfo, std::uint64_t total)
{
  int piece = outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER());
  int pieces = outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES());
  if (pieces < 1 || piece < 0 || piece >= pieces)
  {
    piece = 0;
    pieces = 1;
  }
  PieceRange range;
  range.Begin = total / pieces * piece + total % pieces * piece / pieces;
  range.End = total / pieces * (piece + 1) + total % pieces * (piece + 1) / pieces;
  return range;
}

namespace
{
template<typename IdArray>
void SetVertexCells(vtkPolyData* output, vtkIdType count)
{
  vtkNew<IdArray> offsets, connectivity;
  offsets->SetNumberOfValues(count + 1);
  connectivity->SetNumberOfValues(count);
  auto* offset = offsets->GetPointer(0);
  auto* id = connectivity->GetPointer(0);
  for (vtkIdType i = 0; i <= count; ++i)
  {
    offset[i] = static_cast<typename IdArray::ValueType>(i);
  }
  for (vtkIdType i = 0; i < count; ++i)
  {
    id[i] = static_cast<typename IdArray::ValueType>(i);
  }
  vtkNew<vtkCellArray> vertices;
  vertices->SetData(offsets, connectivity);
  output->SetVerts(vertices);
}
} // namespace

void AddVertexCells(vtkPolyData* output, vtkIdType count)
{
  // 32-bit ids where they suffice (vtkCellArray takes either): half the
  // memory of the cells, 8 instead of 16 bytes a point.
  if (count < VTK_INT_MAX)
  {
    SetVertexCells<vtkTypeInt32Array>(output, count);
  }
  else
  {
    SetVertexCells<vtkIdTypeArray>(output, count);
  }
}

vtkSmartPointer<vtkDataArray> NewArray(int vtkType,
  const char* name,
  int components,
  vtkIdType count)
{
  vtkSmartPointer<vtkDataArray> array =
    vtkSmartPointer<vtkDataArray>::Take(vtkDataArray::CreateDataArray(vtkType));
  array->SetName(name);
  array->SetNumberOfComponents(components);
  array->SetNumberOfTuples(count);
  return array;
}

void AddFieldTexts(const std::vector<std::pair<std::string, std::string>>& fields,
  vtkFieldData* fieldData)
{
  std::vector<double> numbers;
  for (const auto& field : fields)
  {
    const char* name = field.first.c_str();
    vtkStringArray* earlier = vtkStringArray::SafeDownCast(fieldData->GetAbstractArray(name));
    if (earlier)
    {
      earlier->InsertNextValue(field.second);
    }
    else if (pcurv::ply::ParseNumbers(field.second, numbers) && !numbers.empty())
    {
      vtkNew<vtkDoubleArray> array;
      array->SetName(name);
      array->SetNumberOfComponents(static_cast<int>(numbers.size()));
      array->InsertNextTuple(numbers.data());
      fieldData->AddArray(array);
    }
    else
    {
      vtkNew<vtkStringArray> array;
      array->SetName(name);
      array->InsertNextValue(field.second);
      fieldData->AddArray(array);
    }
  }
}

} // namespace readers
} // namespace pcurv
