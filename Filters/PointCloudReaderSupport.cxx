#include "PointCloudReaderSupport.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
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

void AddVertexCells(vtkPolyData* output, vtkIdType count)
{
  vtkNew<vtkIdTypeArray> offsets, connectivity;
  offsets->SetNumberOfValues(count + 1);
  connectivity->SetNumberOfValues(count);
  vtkIdType* offset = offsets->GetPointer(0);
  vtkIdType* id = connectivity->GetPointer(0);
  for (vtkIdType i = 0; i <= count; ++i)
  {
    offset[i] = i;
  }
  for (vtkIdType i = 0; i < count; ++i)
  {
    id[i] = i;
  }
  vtkNew<vtkCellArray> vertices;
  vertices->SetData(offsets, connectivity);
  output->SetVerts(vertices);
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
