#include "vtkPrincipalCurvatureEstimation.h"

#include "DynamicAdjustment.h"
#include "PointGrid.h"
#include "PrincipalCurvatureCloud.h"
#include "PrincipalCurvatureCore.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDataSetAttributes.h"
#include "vtkDoubleArray.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <string>
#include <tuple>
#include <vector>

vtkStandardNewMacro(vtkPrincipalCurvatureEstimation);

namespace
{
constexpr double NaN = std::numeric_limits<double>::quiet_NaN();

/// One named double point-data array of the output.
vtkSmartPointer<vtkDoubleArray> NewDoubleArray(const char* name, int components, vtkIdType tuples)
{
  auto array = vtkSmartPointer<vtkDoubleArray>::New();
  array->SetName(name);
  array->SetNumberOfComponents(components);
  array->SetNumberOfTuples(tuples);
  return array;
}

template<typename ArrayT>
vtkSmartPointer<ArrayT> NewIntegerArray(const char* name, vtkIdType tuples)
{
  auto array = vtkSmartPointer<ArrayT>::New();
  array->SetName(name);
  array->SetNumberOfTuples(tuples);
  return array;
}

/// The output arrays, written point by point from the worker threads (each
/// point by exactly one thread).
struct CurvatureArrays
{
  vtkSmartPointer<vtkDoubleArray> Minimum, Maximum, Mean, Gauss, MinimumDirection, MaximumDirection,
    SineFitRms, Surroundings, PlaneDistance;
  vtkSmartPointer<vtkUnsignedCharArray> Valid;
  vtkSmartPointer<vtkIntArray> NeighborCount, ValidDirections;
  /// With the dynamic adjustment only: the neighbour count it aimed at for
  /// the point (its target combination's N_t), to compare with Neighbor_Count.
  vtkSmartPointer<vtkIntArray> TargetCount;

  CurvatureArrays(vtkIdType n, bool adjusted)
    : Minimum(NewDoubleArray("Minimum_Curvature", 1, n))
    , Maximum(NewDoubleArray("Maximum_Curvature", 1, n))
    , Mean(NewDoubleArray("Mean_Curvature", 1, n))
    , Gauss(NewDoubleArray("Gauss_Curvature", 1, n))
    , MinimumDirection(NewDoubleArray("Minimum_Curvature_Direction", 3, n))
    , MaximumDirection(NewDoubleArray("Maximum_Curvature_Direction", 3, n))
    , SineFitRms(NewDoubleArray("Sine_Fit_RMS", 1, n))
    , Surroundings(NewDoubleArray("Surroundings_Threshold", 1, n))
    , PlaneDistance(NewDoubleArray("Plane_Distance_Threshold", 1, n))
    , Valid(NewIntegerArray<vtkUnsignedCharArray>("Curvature_Valid", n))
    , NeighborCount(NewIntegerArray<vtkIntArray>("Neighbor_Count", n))
    , ValidDirections(NewIntegerArray<vtkIntArray>("Valid_Direction_Count", n))
    , TargetCount(adjusted ? NewIntegerArray<vtkIntArray>("Target_Neighbor_Count", n) : nullptr)
  {
  }

  /// `target`: the adjustment's target count (0 where it has none).
  void Store(vtkIdType i, const pcurv::PointCurvature& r, double s, double p, int target = 0)
  {
    const double kMin = r.Valid ? r.MinimumCurvature : NaN;
    const double kMax = r.Valid ? r.MaximumCurvature : NaN;
    this->Minimum->SetValue(i, kMin);
    this->Maximum->SetValue(i, kMax);
    this->Mean->SetValue(i, 0.5 * (kMin + kMax));
    this->Gauss->SetValue(i, kMin * kMax);
    this->MinimumDirection->SetTypedTuple(i, r.MinimumDirection.data());
    this->MaximumDirection->SetTypedTuple(i, r.MaximumDirection.data());
    this->SineFitRms->SetValue(i, r.Valid ? r.SineFitRms : NaN);
    this->Surroundings->SetValue(i, s);
    this->PlaneDistance->SetValue(i, p);
    this->Valid->SetValue(i, r.Valid ? 1 : 0);
    this->NeighborCount->SetValue(i, r.NeighborCount);
    this->ValidDirections->SetValue(i, r.ValidDirections);
    if (this->TargetCount)
    {
      this->TargetCount->SetValue(i, target);
    }
  }

  /// Asks for the cache lines Store(i, ...) will write.
  void Prefetch(vtkIdType i) const
  {
    for (vtkDoubleArray* values : { this->Minimum.Get(),
           this->Maximum.Get(),
           this->Mean.Get(),
           this->Gauss.Get(),
           this->SineFitRms.Get(),
           this->Surroundings.Get(),
           this->PlaneDistance.Get() })
    {
      __builtin_prefetch(values->GetPointer(i), 1);
    }
    __builtin_prefetch(this->MinimumDirection->GetPointer(3 * i), 1);
    __builtin_prefetch(this->MaximumDirection->GetPointer(3 * i), 1);
    __builtin_prefetch(this->Valid->GetPointer(i), 1);
    __builtin_prefetch(this->NeighborCount->GetPointer(i), 1);
    __builtin_prefetch(this->ValidDirections->GetPointer(i), 1);
  }

  /// Back from the filter's working length unit (lengths multiplied by
  /// `lengthScale`) to the input's: curvatures scale like 1 / length.
  void ToInputUnit(double lengthScale)
  {
    if (lengthScale == 1.0)
    {
      return;
    }
    for (vtkIdType i = 0; i < this->Minimum->GetNumberOfTuples(); ++i)
    {
      for (vtkDoubleArray* curvature :
        { this->Minimum.Get(), this->Maximum.Get(), this->Mean.Get(), this->SineFitRms.Get() })
      {
        curvature->SetValue(i, curvature->GetValue(i) * lengthScale);
      }
      this->Gauss->SetValue(i, this->Gauss->GetValue(i) * lengthScale * lengthScale);
      for (vtkDoubleArray* length : { this->Surroundings.Get(), this->PlaneDistance.Get() })
      {
        length->SetValue(i, length->GetValue(i) / lengthScale);
      }
    }
  }

  void AddTo(vtkPointData* pd) const
  {
    for (vtkDataArray* array : { static_cast<vtkDataArray*>(this->Minimum),
           static_cast<vtkDataArray*>(this->Maximum),
           static_cast<vtkDataArray*>(this->Mean),
           static_cast<vtkDataArray*>(this->Gauss),
           static_cast<vtkDataArray*>(this->MinimumDirection),
           static_cast<vtkDataArray*>(this->MaximumDirection),
           static_cast<vtkDataArray*>(this->Valid),
           static_cast<vtkDataArray*>(this->NeighborCount),
           static_cast<vtkDataArray*>(this->ValidDirections),
           static_cast<vtkDataArray*>(this->SineFitRms),
           static_cast<vtkDataArray*>(this->Surroundings),
           static_cast<vtkDataArray*>(this->PlaneDistance),
           static_cast<vtkDataArray*>(this->TargetCount) })
    {
      if (array)
      {
        pd->AddArray(array);
      }
    }
  }
};

/// How neighbourhoods and thresholds are chosen for every point.
struct NeighborhoodRule
{
  bool KNearest = false;
  int K = 0;
  double Radius = 0.0;             // RADIUS mode
  bool FixedPlaneDistance = false; // p = PlaneDistance, else Ratio times the radius
  double PlaneDistance = 0.0;
  double Ratio = 0.0;
  bool Adjusted = false; // dynamic variable adjustment instead of the above
  pcurv::AdjustmentSettings Adjustment;
  double BlockLength = 0.0; // side of an adjustment block (a length)
};

/// The order in which points are processed: the grid's order (cell by cell,
/// by coordinates within a cell), which is global. With fixed thresholds a
/// work item is one own point; with the dynamic adjustment it is one block:
/// the points (own and halo) in one cell of a lattice of side BlockLength,
/// processed in that order, each block started afresh. Blocks are defined
/// in space, not by counting points, so neither the threads nor the split
/// among processes change them.
struct ProcessingOrder
{
  std::vector<vtkIdType> Points;      // cloud point indices
  std::vector<vtkIdType> BlockStarts; // DVA: block b is Points[BlockStarts[b], BlockStarts[b+1])

  vtkIdType GetNumberOfItems() const
  {
    return this->BlockStarts.empty() ? static_cast<vtkIdType>(this->Points.size())
                                     : static_cast<vtkIdType>(this->BlockStarts.size()) - 1;
  }

  void MakePointwise(const pcurv::PointGrid& grid, const pcurv::CloudPoints& cloud)
  {
    for (vtkIdType j = 0; j < grid.GetNumberOfPoints(); ++j)
    {
      const vtkIdType point = grid.GetSortedId(j);
      if (cloud.IsOwn(point))
      {
        this->Points.push_back(point);
      }
    }
  }

  void MakeBlocks(const pcurv::PointGrid& grid,
    const pcurv::CloudPoints& cloud,
    const pcurv::GridLattice& lattice,
    double blockLength)
  {
    using Key = std::tuple<std::int64_t, std::int64_t, std::int64_t>;
    std::vector<std::pair<Key, vtkIdType>> keyed; // (block, grid position)
    keyed.reserve(grid.GetNumberOfPoints());
    for (vtkIdType j = 0; j < grid.GetNumberOfPoints(); ++j)
    {
      const double* x = &cloud.Coordinates[3 * grid.GetSortedId(j)];
      std::array<std::int64_t, 3> b;
      for (int k = 0; k < 3; ++k)
      {
        b[k] = static_cast<std::int64_t>(std::floor((x[k] - lattice.Origin[k]) / blockLength));
      }
      keyed.emplace_back(Key{ b[2], b[1], b[0] }, j);
    }
    std::sort(keyed.begin(), keyed.end());
    for (std::size_t first = 0; first < keyed.size();)
    {
      std::size_t last = first;
      bool hasOwn = false;
      while (last < keyed.size() && keyed[last].first == keyed[first].first)
      {
        hasOwn = hasOwn || cloud.IsOwn(grid.GetSortedId(keyed[last].second));
        ++last;
      }
      if (hasOwn) // blocks of halo points only are another process's work
      {
        this->BlockStarts.push_back(static_cast<vtkIdType>(this->Points.size()));
        for (std::size_t k = first; k < last; ++k)
        {
          this->Points.push_back(grid.GetSortedId(keyed[k].second));
        }
      }
      first = last;
    }
    this->BlockStarts.push_back(static_cast<vtkIdType>(this->Points.size()));
  }
};

/// Estimates the work items; one instance is shared by all threads, each
/// point written by one thread.
class EstimateWorker
{
public:
  EstimateWorker(vtkPrincipalCurvatureEstimation* self,
    const pcurv::CloudPoints& cloud,
    const pcurv::PointGrid& grid,
    const ProcessingOrder& order,
    const NeighborhoodRule& rule,
    const pcurv::FitSettings& settings,
    CurvatureArrays& out)
    : Self(self)
    , Cloud(cloud)
    , Grid(grid)
    , Order(order)
    , Rule(rule)
    , Settings(settings)
    , Out(out)
  {
  }

  void Initialize() {}

  /// With no more items than the grain, vtkSMPTools runs the functor in the
  /// calling thread without a thread pool, and (VTK 9.2, STDThread)
  /// GetSingleThread() then crashes: that one thread reports progress.
  void SetRunsInline(bool runsInline) { this->RunsInline = runsInline; }

  void operator()(vtkIdType begin, vtkIdType end)
  {
    Scratch& scratch = this->PerThread.Local();
    const bool reportsProgress = this->RunsInline || vtkSMPTools::GetSingleThread();
    for (vtkIdType item = begin; item < end; ++item)
    {
      if (this->Aborted.load(std::memory_order_relaxed))
      {
        return;
      }
      if (reportsProgress)
      {
        this->ReportProgress(item);
      }
      if (this->Rule.Adjusted)
      {
        this->EstimateBlock(item, scratch);
      }
      else
      {
        this->PrefetchAhead(item, end);
        this->EstimateFixed(this->Order.Points[item], scratch);
      }
    }
  }

  void Reduce() {}

  bool WasAborted() const { return this->Aborted.load(); }

private:
  struct Scratch
  {
    pcurv::PointCurvatureEstimator Estimator;
    pcurv::DynamicAdjustment Adjustment;
    std::vector<double> Distances;
    pcurv::NeighborOffsets Neighbors;
  };

  /// Points are processed in grid order, their data and results sit in
  /// input order: where that is random, each point's reads and writes
  /// missed the cache (8 % of the filter's time on a shuffled 1M cloud).
  /// Fetching a few points ahead hides it; two steps, since the output
  /// position itself has to be read first.
  void PrefetchAhead(vtkIdType item, vtkIdType end) const
  {
    constexpr vtkIdType Inputs = 16, Outputs = 8;
    if (item + Inputs < end)
    {
      const vtkIdType point = this->Order.Points[item + Inputs];
      __builtin_prefetch(&this->Cloud.InputIds[point]);
      __builtin_prefetch(&this->Cloud.Coordinates[3 * point]);
      __builtin_prefetch(&this->Cloud.Normals[3 * point]);
    }
    if (item + Outputs < end)
    {
      this->Out.Prefetch(this->Cloud.InputIds[this->Order.Points[item + Outputs]]);
    }
  }

  bool HasNormal(vtkIdType point) const
  {
    const double* n = &this->Cloud.Normals[3 * point];
    return n[0] != 0.0 || n[1] != 0.0 || n[2] != 0.0;
  }

  void EstimateFixed(vtkIdType point, Scratch& scratch)
  {
    if (!this->HasNormal(point))
    {
      this->Out.Store(this->Cloud.InputIds[point], pcurv::PointCurvature{}, NaN, NaN);
      return;
    }
    const double* x = &this->Cloud.Coordinates[3 * point];
    double s = this->Rule.Radius;
    if (this->Rule.KNearest)
    {
      // k + 1: the point itself is found too (and then ignored).
      s = std::sqrt(this->Grid.SquaredDistanceToKth(x, this->Rule.K + 1, scratch.Distances));
      s = std::nextafter(s, HUGE_VAL); // the query keeps distances < s
    }
    this->Grid.GatherOffsetsWithinRadius(x, s, scratch.Neighbors);
    // A fixed p of 0 stays 0: every point is then flagged, never silently
    // estimated with some other p.
    const double p =
      this->Rule.FixedPlaneDistance ? this->Rule.PlaneDistance : this->Rule.Ratio * s;
    this->EstimateGathered(point, s, p, scratch);
  }

  /// The paper's sequence within one block: s carries over from point to
  /// point; the block's first point repeats its search with the adjusted s.
  /// Halo points take part in the sequence (their neighbour counts steer s)
  /// but are not estimated: another process outputs them.
  void EstimateBlock(vtkIdType block, Scratch& scratch)
  {
    pcurv::DynamicAdjustment& adjustment = scratch.Adjustment;
    adjustment = pcurv::DynamicAdjustment(this->Rule.Adjustment);
    bool firstPoint = true;
    for (vtkIdType k = this->Order.BlockStarts[block]; k < this->Order.BlockStarts[block + 1]; ++k)
    {
      const vtkIdType point = this->Order.Points[k];
      if (!this->HasNormal(point))
      {
        if (this->Cloud.IsOwn(point))
        {
          this->Out.Store(this->Cloud.InputIds[point], pcurv::PointCurvature{}, NaN, NaN);
        }
        continue;
      }
      const double* x = &this->Cloud.Coordinates[3 * point];
      double s = adjustment.GetSurroundingsThreshold();
      this->Grid.GatherOffsetsWithinRadius(x, s, scratch.Neighbors);
      if (firstPoint)
      {
        adjustment.Adjust(NeighborCount(scratch));
        s = adjustment.GetSurroundingsThreshold();
        this->Grid.GatherOffsetsWithinRadius(x, s, scratch.Neighbors);
        firstPoint = false;
      }
      const int target = adjustment.GetTargetNeighborCount();
      const double p = adjustment.Adjust(NeighborCount(scratch));
      if (this->Cloud.IsOwn(point))
      {
        this->EstimateGathered(point, s, p, scratch, target);
      }
    }
  }

  /// Neighbours found, the point itself excluded (as the estimator counts).
  static int NeighborCount(const Scratch& scratch)
  {
    return std::max(0, static_cast<int>(scratch.Neighbors.Count) - 1);
  }

  void EstimateGathered(vtkIdType point, double s, double p, Scratch& scratch, int target = 0)
  {
    const double* x = &this->Cloud.Coordinates[3 * point];
    const double* n = &this->Cloud.Normals[3 * point];
    pcurv::PointCurvatureEstimator& estimator = scratch.Estimator;
    estimator.Begin({ { x[0], x[1], x[2] } }, { { n[0], n[1], n[2] } }, p, s);
    const pcurv::NeighborOffsets& offsets = scratch.Neighbors;
    estimator.AddNeighborOffsets(
      offsets.Dx.data(), offsets.Dy.data(), offsets.Dz.data(), offsets.Count);
    this->Out.Store(this->Cloud.InputIds[point], estimator.Estimate(this->Settings), s, p, target);
  }

  /// Progress every few thousand points, and the abort flag, from one thread.
  void ReportProgress(vtkIdType item)
  {
    const vtkIdType items = this->Order.GetNumberOfItems();
    const vtkIdType every = std::max<vtkIdType>(1, this->Rule.Adjusted ? items / 100 : 4096);
    if (item % every != 0)
    {
      return;
    }
    this->Self->UpdateProgress(static_cast<double>(item) / items);
    if (this->Self->GetAbortExecute())
    {
      this->Aborted.store(true);
    }
  }

  vtkPrincipalCurvatureEstimation* Self;
  const pcurv::CloudPoints& Cloud;
  const pcurv::PointGrid& Grid;
  const ProcessingOrder& Order;
  NeighborhoodRule Rule;
  pcurv::FitSettings Settings;
  CurvatureArrays& Out;
  vtkSMPThreadLocal<Scratch> PerThread;
  std::atomic<bool> Aborted{ false };
  bool RunsInline = false;
};

/// The largest distance from an own point to its k-th nearest neighbour
/// among this process's points alone: at least the true distance, so a halo
/// this wide holds every point's k nearest neighbours.
double LargestLocalKthDistance(pcurv::CloudPoints& cloud, const pcurv::GridLattice& lattice, int k)
{
  pcurv::PointGrid grid;
  grid.Build(cloud.Coordinates.data(), cloud.NumberOfOwnPoints, lattice);
  std::vector<double> scratch;
  double largest = 0.0;
  for (vtkIdType i = 0; i < cloud.NumberOfOwnPoints; ++i)
  {
    largest =
      std::max(largest, grid.SquaredDistanceToKth(&cloud.Coordinates[3 * i], k + 1, scratch));
  }
  return std::nextafter(std::sqrt(largest), HUGE_VAL);
}

/// Runs `work` on all cores unless the user chose otherwise: ParaView's
/// bundled VTK defaults to the sequential SMP backend, so switch to
/// STDThread when no backend was requested through the environment.
template<typename Work>
void RunOnAllCores(int maximumThreads, Work&& work)
{
  std::string backend = vtkSMPTools::GetBackend();
  if (backend == "Sequential" && !std::getenv("VTK_SMP_BACKEND_IN_USE"))
  {
    backend = "STDThread";
  }
  vtkSMPTools::LocalScope(vtkSMPTools::Config{ maximumThreads, backend, false }, work);
}

/// One vertex cell per point, so that the output shows in a render view.
vtkNew<vtkCellArray> MakeVertexCells(vtkIdType numberOfPoints)
{
  vtkNew<vtkIdTypeArray> offsets;
  vtkNew<vtkIdTypeArray> connectivity;
  offsets->SetNumberOfValues(numberOfPoints + 1);
  connectivity->SetNumberOfValues(numberOfPoints);
  for (vtkIdType i = 0; i < numberOfPoints; ++i)
  {
    offsets->SetValue(i, i);
    connectivity->SetValue(i, i);
  }
  offsets->SetValue(numberOfPoints, numberOfPoints);
  vtkNew<vtkCellArray> cells;
  cells->SetData(offsets, connectivity);
  return cells;
}

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
    output->SetVerts(MakeVertexCells(input->GetNumberOfPoints()));
  }
  output->GetPointData()->PassData(input->GetPointData());
}
/// A length the user gave, in the filter's working unit (finite: a huge
/// radius stays the largest double).
double ToWorkingUnit(double length, double lengthScale)
{
  return std::min(length * lengthScale, std::numeric_limits<double>::max());
}

/// The adjustment's target counts within [1, 1e6] (NaN: 1), with a warning
/// when one was not: a count outside it has no meaning, and beyond the int
/// range it could not be reported in Target_Neighbor_Count.
std::array<double, 3> UsableTargetCounts(vtkPrincipalCurvatureEstimation* self)
{
  std::array<double, 3> counts;
  std::copy_n(self->GetTargetNeighborCounts(), 3, counts.begin());
  bool clamped = false;
  for (double& count : counts)
  {
    const double usable = std::isnan(count) ? 1.0 : std::min(std::max(count, 1.0), 1e6);
    clamped = clamped || usable != count;
    count = usable;
  }
  if (clamped)
  {
    vtkWarningWithObjectMacro(self,
      "TargetNeighborCounts must lie within [1, 1e6]; used " << counts[0] << ", " << counts[1]
                                                             << ", " << counts[2] << ".");
  }
  return counts;
}

/// The thresholds for every point from the settings and, where automatic,
/// from the cloud (global in a parallel run); the radius the grid's cells
/// are made for; and how far beyond its own points a process must see.
void ChooseThresholds(vtkPrincipalCurvatureEstimation* self,
  pcurv::CloudPoints& cloud,
  const pcurv::ProcessGroup& processes,
  double lengthScale,
  NeighborhoodRule& rule,
  double& cellRadius,
  double& reach)
{
  rule.KNearest = self->GetNeighborhoodMode() == vtkPrincipalCurvatureEstimation::K_NEAREST;
  rule.K = self->GetNumberOfNeighbors();
  rule.Ratio = self->GetPlaneDistanceRatio();
  rule.Adjusted = self->GetDynamicAdjustment();
  const std::array<double, 3> targetCounts =
    rule.Adjusted ? UsableTargetCounts(self) : std::array<double, 3>{};
  // The neighbour count the cloud's typical radius is measured for.
  const int typicalCount =
    rule.Adjusted ? static_cast<int>(targetCounts[0]) : self->GetNumberOfNeighbors();
  const bool needsTypicalRadius = rule.Adjusted ? self->GetAutomaticLengthUnit()
                                                : (self->GetAutomaticThresholds() || rule.KNearest);
  const double typicalRadius =
    needsTypicalRadius ? pcurv::TypicalRadius(cloud, processes, typicalCount) : 0.0;
  cellRadius = typicalRadius;
  if (rule.Adjusted)
  {
    pcurv::AdjustmentSettings& adjustment = rule.Adjustment;
    adjustment.InitialSurroundingsThreshold = self->GetInitialSurroundingsThreshold();
    adjustment.TargetNeighborCounts = targetCounts;
    std::copy_n(self->GetTargetPlaneDistances(), 3, adjustment.TargetPlaneDistances.begin());
    std::copy_n(self->GetSwitchLengths(), 3, adjustment.SwitchLengths.begin());
    adjustment.MaximumSurroundingsThreshold =
      self->GetMaximumSurroundingsFactor() * self->GetInitialSurroundingsThreshold();
    // Scale free: the initial s holds about the first target count.
    adjustment.LengthUnit = self->GetAutomaticLengthUnit()
      ? typicalRadius / self->GetInitialSurroundingsThreshold()
      : ToWorkingUnit(self->GetLengthUnit(), lengthScale);
    cellRadius = adjustment.LengthUnit * self->GetInitialSurroundingsThreshold();
    rule.BlockLength = self->GetAdjustmentBlockLength() * adjustment.LengthUnit;
    // A block's points, and every query they make.
    reach = std::sqrt(3.0) * rule.BlockLength +
      adjustment.MaximumSurroundingsThreshold * adjustment.LengthUnit;
    return;
  }
  if (!self->GetAutomaticThresholds())
  {
    rule.FixedPlaneDistance = true;
    rule.PlaneDistance = ToWorkingUnit(self->GetPlaneDistanceThreshold(), lengthScale);
    rule.Radius = ToWorkingUnit(self->GetSurroundingsThreshold(), lengthScale);
  }
  else if (!rule.KNearest)
  {
    rule.Radius = typicalRadius;
    rule.PlaneDistance = self->GetPlaneDistanceRatio() * rule.Radius;
  }
  if (!rule.KNearest)
  {
    cellRadius = rule.Radius;
    reach = rule.Radius;
  }
}

} // namespace

vtkPrincipalCurvatureEstimation::vtkPrincipalCurvatureEstimation()
{
  // Default to the active normals, as vtkGlyph3D does, so that plain C++
  // users need not call SetInputArrayToProcess.
  this->SetInputArrayToProcess(
    0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, vtkDataSetAttributes::NORMALS);
}

int vtkPrincipalCurvatureEstimation::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPointSet");
  return 1;
}

int vtkPrincipalCurvatureEstimation::RequestData(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  vtkPointSet* input = vtkPointSet::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  this->UsedSurroundingsThreshold = 0.0;
  this->UsedPlaneDistanceThreshold = 0.0;
  this->UsedLengthUnit = 0.0;
  this->NumberOfUnestimatedPoints = 0;
  if (!input || !output)
  {
    return 0;
  }
  // In a parallel run every process takes part in every collective step,
  // even with an empty piece or bad input: failures are agreed on first.
  const pcurv::ProcessGroup processes;
  const vtkIdType numberOfPoints = input->GetNumberOfPoints();
  if (numberOfPoints == 0 && !processes.IsDistributed())
  {
    CopyGeometry(input, output);
    return 1;
  }
  vtkDataArray* normals = this->GetInputArrayToProcess(0, inputVector);
  if (!normals && this->NormalsNotChosen())
  {
    normals = input->GetPointData()->GetNormals(); // ParaView's "no selection"
  }
  const bool normalsUsable = numberOfPoints == 0 || this->CheckNormals(normals, numberOfPoints);
  if (!processes.Min(normalsUsable ? 1 : 0))
  {
    return 0;
  }

  pcurv::CloudPoints cloud;
  if (numberOfPoints > 0)
  {
    cloud.Read(input, normals);
  }
  const double lengthScale = pcurv::WorkingLengthScale(cloud, processes);
  cloud.ScaleCoordinates(lengthScale);
  NeighborhoodRule rule;
  double cellRadius = 0.0;
  double reach = 0.0;
  ChooseThresholds(this, cloud, processes, lengthScale, rule, cellRadius, reach);
  if (rule.Adjusted)
  {
    this->UsedLengthUnit = rule.Adjustment.LengthUnit / lengthScale;
  }
  else if (!rule.KNearest)
  {
    this->UsedSurroundingsThreshold = rule.Radius / lengthScale;
    this->UsedPlaneDistanceThreshold = rule.PlaneDistance / lengthScale;
  }

  const pcurv::GridLattice lattice = pcurv::GlobalLattice(cloud, processes, cellRadius);
  if (processes.IsDistributed())
  {
    if (rule.KNearest)
    {
      reach = processes.Max(LargestLocalKthDistance(cloud, lattice, rule.K));
    }
    processes.ExchangeHalo(cloud, reach);
  }
  pcurv::PointGrid grid;
  grid.Build(cloud.Coordinates.data(), cloud.GetNumberOfPoints(), lattice);
  ProcessingOrder order;
  if (rule.Adjusted)
  {
    order.MakeBlocks(grid, cloud, lattice, rule.BlockLength);
  }
  else
  {
    order.MakePointwise(grid, cloud);
  }

  pcurv::FitSettings settings;
  settings.Mode = static_cast<pcurv::FitMode>(this->FitMode);
  settings.MinimumPointsPerDirection = this->MinimumPointsPerDirection;
  CurvatureArrays arrays(numberOfPoints, rule.Adjusted);
  for (vtkIdType i = 0; i < numberOfPoints; ++i)
  {
    if (!cloud.FiniteInput[i])
    {
      arrays.Store(i, pcurv::PointCurvature{}, NaN, NaN);
    }
  }
  EstimateWorker worker(this, cloud, grid, order, rule, settings, arrays);
  const vtkIdType grain = rule.Adjusted ? 1 : 1024;
  worker.SetRunsInline(order.GetNumberOfItems() <= grain);
  RunOnAllCores(
    this->NumberOfThreads, [&]() { vtkSMPTools::For(0, order.GetNumberOfItems(), grain, worker); });
  if (worker.WasAborted())
  {
    return 1;
  }
  this->UpdateProgress(1.0);

  for (vtkIdType i = 0; i < numberOfPoints; ++i)
  {
    this->NumberOfUnestimatedPoints += arrays.Valid->GetValue(i) == 0;
  }
  if (this->NumberOfUnestimatedPoints > 0)
  {
    vtkWarningMacro(<< this->NumberOfUnestimatedPoints << " of " << numberOfPoints
                    << " points could not be estimated (too few neighbours or valid directions, "
                       "or a bad coordinate or normal); they have Curvature_Valid = 0 and NaN "
                       "curvatures.");
  }
  arrays.ToInputUnit(lengthScale);
  CopyGeometry(input, output);
  arrays.AddTo(output->GetPointData());
  return 1;
}

namespace
{
void SetAdjustmentConstants(vtkPrincipalCurvatureEstimation* self,
  pcurv::AdjustmentSettings constants)
{
  self->SetTargetNeighborCounts(constants.TargetNeighborCounts.data());
  self->SetTargetPlaneDistances(constants.TargetPlaneDistances.data());
  self->SetSwitchLengths(constants.SwitchLengths.data());
}
} // namespace

void vtkPrincipalCurvatureEstimation::SetAdjustmentConstantsToPaper()
{
  SetAdjustmentConstants(this, pcurv::AdjustmentSettings{});
}

void vtkPrincipalCurvatureEstimation::SetAdjustmentConstantsToBandedLadder(double firstCount,
  double planeDistance)
{
  SetAdjustmentConstants(this, pcurv::BandedLadder(firstCount, planeDistance));
}

bool vtkPrincipalCurvatureEstimation::NormalsNotChosen()
{
  vtkInformation* chosen = this->GetInputArrayInformation(0);
  return chosen && chosen->Has(vtkDataObject::FIELD_NAME()) &&
    std::string(chosen->Get(vtkDataObject::FIELD_NAME())).empty();
}

bool vtkPrincipalCurvatureEstimation::CheckNormals(vtkDataArray* normals, vtkIdType numberOfPoints)
{
  if (!normals)
  {
    vtkErrorMacro("No normals: the input needs a 3-component point-data normals array "
                  "(the active normals, or one chosen with SetInputArrayToProcess).");
    return false;
  }
  if (normals->GetNumberOfComponents() != 3 || normals->GetNumberOfTuples() != numberOfPoints)
  {
    vtkErrorMacro("The normals array '" << (normals->GetName() ? normals->GetName() : "")
                                        << "' has " << normals->GetNumberOfComponents()
                                        << " components and " << normals->GetNumberOfTuples()
                                        << " tuples; 3 components per point are required.");
    return false;
  }
  return true;
}

void vtkPrincipalCurvatureEstimation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FitMode: " << this->FitMode << "\n";
  os << indent << "NeighborhoodMode: " << this->NeighborhoodMode << "\n";
  os << indent << "AutomaticThresholds: " << (this->AutomaticThresholds ? "On" : "Off") << "\n";
  os << indent << "NumberOfNeighbors: " << this->NumberOfNeighbors << "\n";
  os << indent << "SurroundingsThreshold: " << this->SurroundingsThreshold << "\n";
  os << indent << "PlaneDistanceThreshold: " << this->PlaneDistanceThreshold << "\n";
  os << indent << "PlaneDistanceRatio: " << this->PlaneDistanceRatio << "\n";
  os << indent << "MinimumPointsPerDirection: " << this->MinimumPointsPerDirection << "\n";
  os << indent << "NumberOfThreads: " << this->NumberOfThreads << "\n";
  os << indent << "DynamicAdjustment: " << (this->DynamicAdjustment ? "On" : "Off") << "\n";
  os << indent << "AutomaticLengthUnit: " << (this->AutomaticLengthUnit ? "On" : "Off") << "\n";
  os << indent << "LengthUnit: " << this->LengthUnit << "\n";
  os << indent << "InitialSurroundingsThreshold: " << this->InitialSurroundingsThreshold << "\n";
  os << indent << "TargetNeighborCounts: " << this->TargetNeighborCounts[0] << " "
     << this->TargetNeighborCounts[1] << " " << this->TargetNeighborCounts[2] << "\n";
  os << indent << "TargetPlaneDistances: " << this->TargetPlaneDistances[0] << " "
     << this->TargetPlaneDistances[1] << " " << this->TargetPlaneDistances[2] << "\n";
  os << indent << "SwitchLengths: " << this->SwitchLengths[0] << " " << this->SwitchLengths[1]
     << " " << this->SwitchLengths[2] << "\n";
  os << indent << "MaximumSurroundingsFactor: " << this->MaximumSurroundingsFactor << "\n";
  os << indent << "AdjustmentBlockLength: " << this->AdjustmentBlockLength << "\n";
  os << indent << "UsedLengthUnit: " << this->UsedLengthUnit << "\n";
  os << indent << "UsedSurroundingsThreshold: " << this->UsedSurroundingsThreshold << "\n";
  os << indent << "UsedPlaneDistanceThreshold: " << this->UsedPlaneDistanceThreshold << "\n";
  os << indent << "NumberOfUnestimatedPoints: " << this->NumberOfUnestimatedPoints << "\n";
}
