// What the plugin's point-cloud readers (LAS, PLY) share on the VTK side: the
// piece of the points a request asks for, vertex cells, typed arrays.
#ifndef PointCloudReaderSupport_h
#define PointCloudReaderSupport_h

#include "vtkSmartPointer.h"
#include "vtkType.h"

#include <cstdint>

class vtkDataArray;
class vtkInformation;
class vtkPolyData;

namespace pcurv
{
namespace readers
{

/// Points [Begin, End) of Total: piece p of n gets the p-th of n
/// consecutive ranges (as the text reader does).
struct PieceRange
{
  std::uint64_t Begin = 0;
  std::uint64_t End = 0;
};
PieceRange RequestedPiece(vtkInformation* outInfo, std::uint64_t total);

/// One vertex cell per point of output, so that the cloud renders.
void AddVertexCells(vtkPolyData* output, vtkIdType count);

/// A new array of the VTK type (VTK_DOUBLE, ...) with count tuples.
vtkSmartPointer<vtkDataArray> NewArray(int vtkType,
  const char* name,
  int components,
  vtkIdType count);

} // namespace readers
} // namespace pcurv

#endif
