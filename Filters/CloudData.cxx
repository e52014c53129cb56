#include "CloudData.h"

#include "vtkArrayDispatch.h"
#include "vtkCellArray.h"
#include "vtkDataArrayRange.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkStringArray.h"
#include "vtkTypeInt32Array.h"
#include "vtkTypeInt64Array.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPolyData.h"
#include "vtkPoints.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <future>
#include <string>
#include <utility>

namespace pcurv
{

void AddCurvatureUnit(vtkPolyData* output)
{
  vtkStringArray* length =
    vtkStringArray::SafeDownCast(output->GetFieldData()->GetAbstractArray("Length_Unit"));
  const bool declared = length && length->GetNumberOfValues() > 0 && !length->GetValue(0).empty();
  vtkNew<vtkStringArray> unit;
  unit->SetName("Curvature_Unit");
  unit->InsertNextValue(
    declared ? "1/" + length->GetValue(0) : "1/length unit of the input coordinates");
  output->GetFieldData()->AddArray(unit);
}

void SetSymmetricRange(vtkDataArray* array, double clip)
{
  if (!array || array->GetNumberOfComponents() != 1 || !(clip > 0.0) || !std::isfinite(clip))
  {
    return;
  }
  // Computing the ranges once makes VTK create the per-component
  // information that holds them; then they are replaced.
  double range[2];
  array->GetRange(range, 0);
  array->GetFiniteRange(range, 0);
  const double symmetric[2] = { -clip, clip };
  for (vtkInformationInformationVectorKey* key :
    { vtkAbstractArray::PER_COMPONENT(), vtkAbstractArray::PER_FINITE_COMPONENT() })
  {
    vtkInformationVector* components = array->GetInformation()->Get(key);
    if (components && components->GetNumberOfInformationObjects() > 0)
    {
      components->GetInformationObject(0)->Set(vtkDataArray::COMPONENT_RANGE(), symmetric, 2);
    }
  }
}

namespace
{
/// Reads the points (and normals) of a cloud through typed ranges: a
/// virtual GetTuple per point was a noticeable part of a run's serial time.
/// The values are converted to double as GetTuple converts them.
struct ReadWorker
{
  CloudPoints& Cloud;

  template<typename Tuple>
  static void ToDouble(const Tuple& tuple, double out[3])
  {
    for (int k = 0; k < 3; ++k)
    {
      out[k] = static_cast<double>(tuple[k]);
    }
  }

  template<typename PointArray, typename NormalArray>
  void operator()(PointArray* points, NormalArray* normals) const
  {
    const auto x = vtk::DataArrayTupleRange<3>(points);
    const auto n = vtk::DataArrayTupleRange<3>(normals);
    for (vtkIdType i = 0; i < x.size(); ++i)
    {
      double point[3], normal[3];
      ToDouble(x[i], point);
      ToDouble(n[i], normal);
      this->Cloud.AddInputPoint(i, point, normal);
    }
  }

  template<typename PointArray>
  void operator()(PointArray* points) const
  {
    const auto x = vtk::DataArrayTupleRange<3>(points);
    const double none[3] = { 0.0, 0.0, 0.0 };
    for (vtkIdType i = 0; i < x.size(); ++i)
    {
      double point[3];
      ToDouble(x[i], point);
      this->Cloud.AddInputPoint(i, point, none);
    }
  }
};
} // namespace

CloudPoints ReadCloud(vtkPointSet* input, vtkDataArray* normals)
{
  const vtkIdType numberOfPoints = input->GetNumberOfPoints();
  CloudPoints cloud;
  cloud.Reset(numberOfPoints);
  if (numberOfPoints == 0)
  {
    return cloud;
  }
  vtkDataArray* points = input->GetPoints()->GetData();
  const ReadWorker worker{ cloud };
  using Reals = vtkArrayDispatch::Reals;
  const bool read = normals
    ? vtkArrayDispatch::Dispatch2ByValueType<Reals, Reals>::Execute(points, normals, worker)
    : vtkArrayDispatch::DispatchByValueType<Reals>::Execute(points, worker);
  if (read)
  {
    return cloud;
  }
  for (vtkIdType i = 0; i < numberOfPoints; ++i)
  {
    double x[3], n[3] = { 0.0, 0.0, 0.0 };
    points->GetTuple(i, x);
    if (normals)
    {
      normals->GetTuple(i, n);
    }
    cloud.AddInputPoint(i, x, n);
  }
  return cloud;
}

namespace
{
/// One vertex cell per point, so that the output shows in a render view;
/// with 32-bit ids where they suffice, which halves the cells' memory and
/// their share of a written file.
template<typename IdArray>
vtkNew<vtkCellArray> MakeVertexCells(vtkIdType numberOfPoints)
{
  vtkNew<IdArray> offsets;
  vtkNew<IdArray> connectivity;
  offsets->SetNumberOfValues(numberOfPoints + 1);
  connectivity->SetNumberOfValues(numberOfPoints);
  for (vtkIdType i = 0; i < numberOfPoints; ++i)
  {
    offsets->SetValue(i, static_cast<typename IdArray::ValueType>(i));
    connectivity->SetValue(i, static_cast<typename IdArray::ValueType>(i));
  }
  offsets->SetValue(numberOfPoints, static_cast<typename IdArray::ValueType>(numberOfPoints));
  vtkNew<vtkCellArray> cells;
  cells->SetData(offsets, connectivity);
  return cells;
}
} // namespace

void CopyGeometry(vtkPointSet* input, vtkPolyData* output)
{
  vtkPolyData* inputPolyData = vtkPolyData::SafeDownCast(input);
  if (inputPolyData && inputPolyData->GetNumberOfCells() > 0)
  {
    output->CopyStructure(inputPolyData);
    output->GetCellData()->PassData(inputPolyData->GetCellData());
  }
  else
  {
    output->SetPoints(input->GetPoints());
    const vtkIdType n = input->GetNumberOfPoints();
    output->SetVerts(n < VTK_INT_MAX ? MakeVertexCells<vtkTypeInt32Array>(n)
                                     : MakeVertexCells<vtkTypeInt64Array>(n));
  }
  output->GetPointData()->PassData(input->GetPointData());
  // The input's description (a LAS file's scale, offset, coordinate system
  // and unit) goes on with the points, for the unit and for writers. Only
  // that: a previous run's counts in the input would read as this run's.
  vtkFieldData* field = input->GetFieldData();
  for (int i = 0; field && i < field->GetNumberOfArrays(); ++i)
  {
    const std::string name =
      field->GetAbstractArray(i)->GetName() ? field->GetAbstractArray(i)->GetName() : "";
    if (name.compare(0, 4, "LAS_") == 0 || name == "Coordinate_System" || name == "Length_Unit" ||
      name == "Vertical_Unit")
    {
      output->GetFieldData()->AddArray(field->GetAbstractArray(i));
    }
  }
}

} // namespace pcurv
