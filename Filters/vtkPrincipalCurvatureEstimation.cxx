#include "vtkPrincipalCurvatureEstimation.h"

#include "DynamicAdjustment.h"
#include "PointGrid.h"
#include "PrincipalCurvatureCore.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDataSetAttributes.h"
#include "vtkDoubleArray.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkMath.h"
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
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkPrincipalCurvatureEstimation);

namespace
{
constexpr double NaN = std::numeric_limits<double>::quiet_NaN();

/// Points of the input in double precision, with the finite ones gathered
/// into a compact cloud for the neighbour search.
struct CloudCoordinates
{
  std::vector<double> All;              // 3 per input point, as given
  std::vector<unsigned char> Good;      // 1 where all three coordinates are finite
  std::vector<double> Finite;           // 3 per finite point: what the search sees
  std::vector<vtkIdType> FiniteToInput; // input id of each finite point

  vtkIdType GetNumberOfFinitePoints() const
  {
    return static_cast<vtkIdType>(this->FiniteToInput.size());
  }
};

void ReadCoordinates(vtkPointSet* input, CloudCoordinates& cloud)
{
  const vtkIdType numberOfPoints = input->GetNumberOfPoints();
  cloud.All.resize(3 * numberOfPoints);
  cloud.Good.resize(numberOfPoints);
  cloud.Finite.reserve(3 * numberOfPoints);
  cloud.FiniteToInput.reserve(numberOfPoints);
  vtkDataArray* points = input->GetPoints()->GetData();
  for (vtkIdType i = 0; i < numberOfPoints; ++i)
  {
    double* x = &cloud.All[3 * i];
    points->GetTuple(i, x);
    cloud.Good[i] = std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2]);
    if (cloud.Good[i])
    {
      cloud.Finite.insert(cloud.Finite.end(), x, x + 3);
      cloud.FiniteToInput.push_back(i);
    }
  }
}

/// Unit normals; points whose normal is zero or not finite get a zero
/// vector and are not estimated.
std::vector<double> ReadUnitNormals(vtkDataArray* normals)
{
  const vtkIdType numberOfPoints = normals->GetNumberOfTuples();
  std::vector<double> unit(3 * numberOfPoints);
  for (vtkIdType i = 0; i < numberOfPoints; ++i)
  {
    double* n = &unit[3 * i];
    normals->GetTuple(i, n);
    const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    const bool usable = std::isfinite(length) && length > 0.0;
    for (int k = 0; k < 3; ++k)
    {
      n[k] = usable ? n[k] / length : 0.0;
    }
  }
  return unit;
}

/// Median, over an evenly strided sample of at most 512 points, of the
/// distance to the k-th nearest other point: a radius holding about k
/// neighbours at a typical point, whatever the cloud's unit.
double EstimateRadiusForNeighborCount(const pcurv::PointGrid& grid,
  const CloudCoordinates& cloud,
  int k)
{
  const vtkIdType numberOfPoints = cloud.GetNumberOfFinitePoints();
  if (numberOfPoints < 2)
  {
    return 0.0;
  }
  const vtkIdType stride = std::max<vtkIdType>(1, numberOfPoints / 512);
  std::vector<double> radii;
  std::vector<double> scratch;
  for (vtkIdType i = 0; i < numberOfPoints; i += stride)
  {
    // k + 1: the sample point itself is among the points found.
    radii.push_back(std::sqrt(grid.SquaredDistanceToKth(&cloud.Finite[3 * i], k + 1, scratch)));
  }
  std::nth_element(radii.begin(), radii.begin() + radii.size() / 2, radii.end());
  return radii[radii.size() / 2];
}

/// Radius holding about k points if the cloud were spread evenly over a
/// square as wide as its bounding box's diagonal: only a grid's cell size.
double GuessRadiusForNeighborCount(const CloudCoordinates& cloud, int k)
{
  const vtkIdType count = cloud.GetNumberOfFinitePoints();
  if (count == 0)
  {
    return 0.0;
  }
  double lower[3], upper[3];
  for (int c = 0; c < 3; ++c)
  {
    lower[c] = upper[c] = cloud.Finite[c];
  }
  for (vtkIdType i = 1; i < count; ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      lower[c] = std::min(lower[c], cloud.Finite[3 * i + c]);
      upper[c] = std::max(upper[c], cloud.Finite[3 * i + c]);
    }
  }
  const double diagonal = std::sqrt(vtkMath::Distance2BetweenPoints(lower, upper));
  return diagonal * std::sqrt(k / (vtkMath::Pi() * count));
}

/// A grid with cells of half the query radius: a query visits at most
/// 5 x 5 x 5 cells, and reads fewer far candidates than with cells of the
/// radius (measured about 5 % faster at 375 neighbours).
void BuildGrid(pcurv::PointGrid& grid, const CloudCoordinates& cloud, double radius)
{
  grid.Build(cloud.Finite.data(), cloud.GetNumberOfFinitePoints(), 0.5 * radius);
}

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

  explicit CurvatureArrays(vtkIdType n)
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
  {
  }

  void Store(vtkIdType i, const pcurv::PointCurvature& r, double s, double p)
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
           static_cast<vtkDataArray*>(this->PlaneDistance) })
    {
      pd->AddArray(array);
    }
  }
};

/// How neighbourhoods and thresholds are chosen for every point.
struct NeighborhoodRule
{
  bool KNearest = false;
  int K = 0;
  double Radius = 0.0;        // RADIUS mode
  double PlaneDistance = 0.0; // fixed p, or 0 to use Ratio times the neighbourhood size
  double Ratio = 0.0;
  bool Adjusted = false; // dynamic variable adjustment instead of the above
  pcurv::AdjustmentSettings Adjustment;
  vtkIdType BlockSize = 256;
};

/// Estimates the points in the grid's (spatially coherent) order; one
/// instance is shared by all threads, each point written by one thread.
/// With fixed thresholds the work items are points; with the dynamic
/// adjustment they are fixed blocks of BlockSize consecutive points, each
/// started afresh, so that results do not depend on the threads.
class EstimateWorker
{
public:
  EstimateWorker(vtkPrincipalCurvatureEstimation* self,
    const CloudCoordinates& cloud,
    const std::vector<double>& normals,
    const pcurv::PointGrid& grid,
    const NeighborhoodRule& rule,
    const pcurv::FitSettings& settings,
    CurvatureArrays& out)
    : Self(self)
    , Cloud(cloud)
    , Normals(normals)
    , Grid(grid)
    , Rule(rule)
    , Settings(settings)
    , Out(out)
  {
  }

  /// Number of work items for vtkSMPTools::For.
  vtkIdType GetNumberOfItems() const
  {
    const vtkIdType points = this->Grid.GetNumberOfPoints();
    return this->Rule.Adjusted ? (points + this->Rule.BlockSize - 1) / this->Rule.BlockSize
                               : points;
  }

  void Initialize() {}

  void operator()(vtkIdType begin, vtkIdType end)
  {
    Scratch& scratch = this->PerThread.Local();
    const bool reportsProgress = vtkSMPTools::GetSingleThread();
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
        this->EstimateFixed(item, scratch);
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
    std::vector<double> Neighbors;
  };

  /// Input id of the j-th point in grid order, or -1 when its normal is unusable.
  vtkIdType UsablePoint(vtkIdType j) const
  {
    const vtkIdType i = this->Cloud.FiniteToInput[this->Grid.GetSortedId(j)];
    const double* n = &this->Normals[3 * i];
    if (n[0] == 0.0 && n[1] == 0.0 && n[2] == 0.0)
    {
      this->Out.Store(i, pcurv::PointCurvature{}, NaN, NaN);
      return -1;
    }
    return i;
  }

  void EstimateFixed(vtkIdType j, Scratch& scratch)
  {
    const vtkIdType i = this->UsablePoint(j);
    if (i < 0)
    {
      return;
    }
    const double* x = &this->Cloud.All[3 * i];
    double s = this->Rule.Radius;
    if (this->Rule.KNearest)
    {
      // k + 1: the point itself is found too (and then ignored).
      s = std::sqrt(this->Grid.SquaredDistanceToKth(x, this->Rule.K + 1, scratch.Distances));
      s = std::nextafter(s, HUGE_VAL); // the query keeps distances < s
    }
    this->Grid.GatherWithinRadius(x, s, scratch.Neighbors);
    const double p =
      this->Rule.PlaneDistance > 0.0 ? this->Rule.PlaneDistance : this->Rule.Ratio * s;
    this->EstimateGathered(i, s, p, scratch);
  }

  /// The paper's sequence within one block: s carries over from point to
  /// point; the block's first point repeats its search with the adjusted s.
  void EstimateBlock(vtkIdType block, Scratch& scratch)
  {
    const vtkIdType first = block * this->Rule.BlockSize;
    const vtkIdType last =
      std::min<vtkIdType>(first + this->Rule.BlockSize, this->Grid.GetNumberOfPoints());
    pcurv::DynamicAdjustment& adjustment = scratch.Adjustment;
    adjustment = pcurv::DynamicAdjustment(this->Rule.Adjustment);
    bool firstPoint = true;
    for (vtkIdType j = first; j < last; ++j)
    {
      const vtkIdType i = this->UsablePoint(j);
      if (i < 0)
      {
        continue;
      }
      const double* x = &this->Cloud.All[3 * i];
      double s = adjustment.GetSurroundingsThreshold();
      this->Grid.GatherWithinRadius(x, s, scratch.Neighbors);
      if (firstPoint)
      {
        adjustment.Adjust(static_cast<int>(scratch.Neighbors.size() / 3));
        s = adjustment.GetSurroundingsThreshold();
        this->Grid.GatherWithinRadius(x, s, scratch.Neighbors);
        firstPoint = false;
      }
      const double p = adjustment.Adjust(static_cast<int>(scratch.Neighbors.size() / 3));
      this->EstimateGathered(i, s, p, scratch);
    }
  }

  void EstimateGathered(vtkIdType i, double s, double p, Scratch& scratch)
  {
    const double* x = &this->Cloud.All[3 * i];
    const double* n = &this->Normals[3 * i];
    pcurv::PointCurvatureEstimator& estimator = scratch.Estimator;
    estimator.Begin({ { x[0], x[1], x[2] } }, { { n[0], n[1], n[2] } }, p, s);
    estimator.AddNeighbors(scratch.Neighbors.data(), scratch.Neighbors.size() / 3);
    this->Out.Store(i, estimator.Estimate(this->Settings), s, p);
  }

  /// Progress every few thousand points, and the abort flag, from one thread.
  void ReportProgress(vtkIdType item)
  {
    const vtkIdType pointsPerItem = this->Rule.Adjusted ? this->Rule.BlockSize : 1;
    if ((item * pointsPerItem) % 4096 >= pointsPerItem)
    {
      return;
    }
    this->Self->UpdateProgress(static_cast<double>(item) / this->GetNumberOfItems());
    if (this->Self->GetAbortExecute())
    {
      this->Aborted.store(true);
    }
  }

  vtkPrincipalCurvatureEstimation* Self;
  const CloudCoordinates& Cloud;
  const std::vector<double>& Normals;
  const pcurv::PointGrid& Grid;
  NeighborhoodRule Rule;
  pcurv::FitSettings Settings;
  CurvatureArrays& Out;
  vtkSMPThreadLocal<Scratch> PerThread;
  std::atomic<bool> Aborted{ false };
};

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
  const vtkIdType numberOfPoints = input->GetNumberOfPoints();
  if (numberOfPoints == 0)
  {
    CopyGeometry(input, output);
    return 1;
  }

  vtkDataArray* normalsArray = this->GetInputArrayToProcess(0, inputVector);
  if (!normalsArray)
  {
    vtkErrorMacro("No normals: the input needs a 3-component point-data normals array "
                  "(the active normals, or one chosen with SetInputArrayToProcess).");
    return 0;
  }
  if (normalsArray->GetNumberOfComponents() != 3 ||
    normalsArray->GetNumberOfTuples() != numberOfPoints)
  {
    vtkErrorMacro("The normals array '" << (normalsArray->GetName() ? normalsArray->GetName() : "")
                                        << "' has " << normalsArray->GetNumberOfComponents()
                                        << " components and " << normalsArray->GetNumberOfTuples()
                                        << " tuples; 3 components per point are required.");
    return 0;
  }

  CloudCoordinates cloud;
  ReadCoordinates(input, cloud);
  const std::vector<double> normals = ReadUnitNormals(normalsArray);

  NeighborhoodRule rule;
  rule.KNearest = this->NeighborhoodMode == K_NEAREST;
  rule.K = this->NumberOfNeighbors;
  rule.Ratio = this->PlaneDistanceRatio;
  rule.Adjusted = this->DynamicAdjustment;
  rule.BlockSize = this->AdjustmentBlockSize;
  // The neighbour count the cloud's typical radius is measured for.
  const int typicalCount =
    rule.Adjusted ? static_cast<int>(this->TargetNeighborCounts[0]) : this->NumberOfNeighbors;
  const bool needsTypicalRadius =
    rule.Adjusted ? this->AutomaticLengthUnit : (this->AutomaticThresholds || rule.KNearest);
  pcurv::PointGrid grid;
  double typicalRadius = 0.0;
  if (needsTypicalRadius)
  {
    // A first grid from a guess, to measure the spacing; rebuilt below with
    // cells fitting the radius actually used.
    BuildGrid(grid, cloud, GuessRadiusForNeighborCount(cloud, typicalCount));
    typicalRadius = EstimateRadiusForNeighborCount(grid, cloud, typicalCount);
  }
  double cellRadius = typicalRadius;
  if (rule.Adjusted)
  {
    pcurv::AdjustmentSettings& adjustment = rule.Adjustment;
    adjustment.InitialSurroundingsThreshold = this->InitialSurroundingsThreshold;
    std::copy(this->TargetNeighborCounts,
      this->TargetNeighborCounts + 3,
      adjustment.TargetNeighborCounts.begin());
    std::copy(this->TargetPlaneDistances,
      this->TargetPlaneDistances + 3,
      adjustment.TargetPlaneDistances.begin());
    std::copy(this->SwitchLengths, this->SwitchLengths + 3, adjustment.SwitchLengths.begin());
    // Scale free: the initial s holds about the first target count.
    adjustment.LengthUnit = this->AutomaticLengthUnit
      ? typicalRadius / this->InitialSurroundingsThreshold
      : this->LengthUnit;
    this->UsedLengthUnit = adjustment.LengthUnit;
    cellRadius = adjustment.LengthUnit * this->InitialSurroundingsThreshold;
  }
  else if (!this->AutomaticThresholds)
  {
    rule.PlaneDistance = this->PlaneDistanceThreshold;
    rule.Radius = this->SurroundingsThreshold;
  }
  else if (!rule.KNearest)
  {
    rule.Radius = typicalRadius;
    rule.PlaneDistance = this->PlaneDistanceRatio * rule.Radius;
  }
  if (!rule.Adjusted && !rule.KNearest)
  {
    this->UsedSurroundingsThreshold = rule.Radius;
    this->UsedPlaneDistanceThreshold = rule.PlaneDistance;
    cellRadius = rule.Radius;
  }
  BuildGrid(grid, cloud, cellRadius);

  pcurv::FitSettings settings;
  settings.Mode = static_cast<pcurv::FitMode>(this->FitMode);
  settings.MinimumPointsPerDirection = this->MinimumPointsPerDirection;

  CurvatureArrays arrays(numberOfPoints);
  for (vtkIdType i = 0; i < numberOfPoints; ++i)
  {
    if (!cloud.Good[i])
    {
      arrays.Store(i, pcurv::PointCurvature{}, NaN, NaN);
    }
  }
  EstimateWorker worker(this, cloud, normals, grid, rule, settings, arrays);
  const vtkIdType grain = rule.Adjusted ? 1 : 1024;
  RunOnAllCores(this->NumberOfThreads,
    [&]() { vtkSMPTools::For(0, worker.GetNumberOfItems(), grain, worker); });
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

  CopyGeometry(input, output);
  arrays.AddTo(output->GetPointData());
  return 1;
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
  os << indent << "AdjustmentBlockSize: " << this->AdjustmentBlockSize << "\n";
  os << indent << "UsedLengthUnit: " << this->UsedLengthUnit << "\n";
  os << indent << "UsedSurroundingsThreshold: " << this->UsedSurroundingsThreshold << "\n";
  os << indent << "UsedPlaneDistanceThreshold: " << this->UsedPlaneDistanceThreshold << "\n";
  os << indent << "NumberOfUnestimatedPoints: " << this->NumberOfUnestimatedPoints << "\n";
}
