#include "PointCloudReaderSupport.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkTypeInt32Array.h"
#include "vtkStreamingDemandDrivenPipeline.h"

namespace pcurv
{
namespace readers
{

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

} // namespace readers
} // namespace pcurv
