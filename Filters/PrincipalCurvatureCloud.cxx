#include "PrincipalCurvatureCloud.h"

#include "vtkArrayDispatch.h"
#include "vtkCellArray.h"
#include "vtkDataArrayRange.h"
#include "vtkCellData.h"
#include "vtkCommunicator.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkStringArray.h"
#include "vtkTypeInt32Array.h"
#include "vtkTypeInt64Array.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPolyData.h"
#include "vtkPoints.h"
#include "vtkSMPTools.h"

#include "vtkAlgorithm.h"

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
  vtkNew<vtkStringArray> unit;
  unit->SetName("Curvature_Unit");
  unit->InsertNextValue("1/length unit of the input coordinates");
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

ControllerCollectives::ControllerCollectives()
{
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  if (controller && controller->GetNumberOfProcesses() > 1)
  {
    this->Controller = controller;
  }
}

int ControllerCollectives::GetNumberOfProcesses() const
{
  return this->Controller ? this->Controller->GetNumberOfProcesses() : 1;
}

int ControllerCollectives::GetLocalProcessId() const
{
  return this->Controller ? this->Controller->GetLocalProcessId() : 0;
}

std::int64_t ControllerCollectives::Sum(std::int64_t value) const
{
  if (!this->Controller)
  {
    return value;
  }
  vtkTypeInt64 local = value, global = 0;
  this->Controller->AllReduce(&local, &global, 1, vtkCommunicator::SUM_OP);
  return global;
}

void ControllerCollectives::Sum(std::vector<std::int64_t>& values) const
{
  if (!this->Controller || values.empty())
  {
    return;
  }
  std::vector<vtkTypeInt64> local(values.begin(), values.end()), global(values.size());
  this->Controller->AllReduce(
    local.data(), global.data(), static_cast<vtkIdType>(local.size()), vtkCommunicator::SUM_OP);
  std::copy(global.begin(), global.end(), values.begin());
}

double ControllerCollectives::Max(double value) const
{
  if (!this->Controller)
  {
    return value;
  }
  double global = value;
  this->Controller->AllReduce(&value, &global, 1, vtkCommunicator::MAX_OP);
  return global;
}

int ControllerCollectives::Min(int value) const
{
  if (!this->Controller)
  {
    return value;
  }
  int global = value;
  this->Controller->AllReduce(&value, &global, 1, vtkCommunicator::MIN_OP);
  return global;
}

void ControllerCollectives::Bounds(double lower[3], double upper[3]) const
{
  if (!this->Controller)
  {
    return;
  }
  double localLower[3], localUpper[3];
  std::copy(lower, lower + 3, localLower);
  std::copy(upper, upper + 3, localUpper);
  this->Controller->AllReduce(localLower, lower, 3, vtkCommunicator::MIN_OP);
  this->Controller->AllReduce(localUpper, upper, 3, vtkCommunicator::MAX_OP);
}

std::vector<double> ControllerCollectives::Gather(const std::vector<double>& values,
  std::vector<std::int64_t>* lengthsOut) const
{
  if (!this->Controller)
  {
    if (lengthsOut)
    {
      lengthsOut->assign(1, static_cast<std::int64_t>(values.size()));
    }
    return values;
  }
  const int processes = this->Controller->GetNumberOfProcesses();
  vtkIdType length = static_cast<vtkIdType>(values.size());
  std::vector<vtkIdType> lengths(processes), offsets(processes);
  this->Controller->AllGather(&length, lengths.data(), 1);
  vtkIdType total = 0;
  for (int p = 0; p < processes; ++p)
  {
    offsets[p] = total;
    total += lengths[p];
  }
  std::vector<double> all(std::max<vtkIdType>(total, 1));
  const double dummy = 0.0;
  this->Controller->AllGatherV(
    values.empty() ? &dummy : values.data(), all.data(), length, lengths.data(), offsets.data());
  all.resize(total);
  if (lengthsOut)
  {
    lengthsOut->assign(lengths.begin(), lengths.end());
  }
  return all;
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

struct RunnerFunctor
{
  const RangeWork& Run;

  void operator()(vtkIdType begin, vtkIdType end) { this->Run(begin, end); }
};
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
}

namespace
{
/// "35 s", "2 min", "1 h 5 min": coarse enough not to flicker, rounded up
/// below a minute (to 5 s) and to the nearest minute above.
std::string RoughDuration(double seconds)
{
  if (seconds < 57.5)
  {
    return std::to_string(5 * std::max(1, static_cast<int>(std::ceil(seconds / 5.0)))) + " s";
  }
  const long minutes = std::lround(seconds / 60.0);
  if (minutes < 60)
  {
    return std::to_string(minutes) + " min";
  }
  return std::to_string(minutes / 60) + " h " + std::to_string(minutes % 60) + " min";
}
} // namespace

std::string ProgressText(const std::string& label, double fraction, double elapsedSeconds)
{
  fraction = std::min(std::max(fraction, 0.0), 1.0);
  // Before a second has passed or 1 % is done, the pace says little (the
  // first stages are not the slowest).
  if (elapsedSeconds < 1.0 || fraction < 0.01 || fraction >= 1.0)
  {
    return label;
  }
  return label + ": about " + RoughDuration(elapsedSeconds * (1.0 - fraction) / fraction) + " left";
}

AlgorithmProgress::AlgorithmProgress(vtkAlgorithm* algorithm, std::string label)
  : Algorithm(algorithm)
  , Label(std::move(label))
  , Start(std::chrono::steady_clock::now())
{
}

bool AlgorithmProgress::Continue(double fraction)
{
  this->Fraction.store(fraction, std::memory_order_relaxed);
  return !this->AbortRequested.load(std::memory_order_relaxed);
}

void AlgorithmProgress::Pass()
{
  const double fraction = this->Fraction.load(std::memory_order_relaxed);
  const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - this->Start;
  this->Algorithm->SetProgressText(ProgressText(this->Label, fraction, elapsed.count()).c_str());
  this->Algorithm->UpdateProgress(fraction);
  if (this->Algorithm->GetAbortExecute())
  {
    this->AbortRequested.store(true, std::memory_order_relaxed);
  }
}

void SMPToolsRunner::RunParallel(std::int64_t count, std::int64_t grain, const RangeWork& work)
{
  RunnerFunctor functor{ work };
  std::string backend = vtkSMPTools::GetBackend();
  if (backend == "Sequential" && !std::getenv("VTK_SMP_BACKEND_IN_USE"))
  {
    backend = "STDThread";
  }
  vtkSMPTools::LocalScope(vtkSMPTools::Config{ this->MaximumThreads, backend, false },
    [&]() { vtkSMPTools::For(0, count, grain, functor); });
}

void SMPToolsRunner::For(std::int64_t count, std::int64_t grain, const RangeWork& work)
{
  if (!this->Progress)
  {
    this->RunParallel(count, grain, work);
    return;
  }
  std::future<void> done =
    std::async(std::launch::async, [&]() { this->RunParallel(count, grain, work); });
  while (done.wait_for(std::chrono::milliseconds(100)) != std::future_status::ready)
  {
    this->Progress->Pass();
  }
  done.get();
  this->Progress->Pass();
}

} // namespace pcurv
