#include "vtkPrincipalCurvatureEstimation.h"

#include "CloudEstimation.h"
#include "PrincipalCurvatureCloud.h"

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
#include <cstdlib>
#include <string>

vtkStandardNewMacro(vtkPrincipalCurvatureEstimation);

// The wrapped header cannot include the core: its enumerations are kept
// equal to the core's here.
static_assert(
  vtkPrincipalCurvatureEstimation::PREVIOUS == static_cast<int>(pcurv::FitMode::Previous) &&
    vtkPrincipalCurvatureEstimation::NEW01 == static_cast<int>(pcurv::FitMode::New01) &&
    vtkPrincipalCurvatureEstimation::NEW02 == static_cast<int>(pcurv::FitMode::New02),
  "FitModes must match pcurv::FitMode");
static_assert(
  vtkPrincipalCurvatureEstimation::RADIUS == static_cast<int>(pcurv::NeighborhoodMode::Radius) &&
    vtkPrincipalCurvatureEstimation::K_NEAREST ==
      static_cast<int>(pcurv::NeighborhoodMode::KNearest),
  "NeighborhoodModes must match pcurv::NeighborhoodMode");
static_assert(vtkPrincipalCurvatureEstimation::PAPER_CONSTANTS ==
      static_cast<int>(pcurv::AdjustmentPreset::Paper) &&
    vtkPrincipalCurvatureEstimation::LADDER == static_cast<int>(pcurv::AdjustmentPreset::Ladder) &&
    vtkPrincipalCurvatureEstimation::NOISY_LADDER ==
      static_cast<int>(pcurv::AdjustmentPreset::NoisyLadder),
  "AdjustmentPresets must match pcurv::AdjustmentPreset");

namespace
{
template<typename ArrayT>
vtkSmartPointer<ArrayT> NewArray(const char* name, int components, vtkIdType tuples)
{
  auto array = vtkSmartPointer<ArrayT>::New();
  array->SetName(name);
  array->SetNumberOfComponents(components);
  array->SetNumberOfTuples(tuples);
  return array;
}

/// The output arrays, and the core's view of them.
struct CurvatureArrays
{
  std::vector<vtkSmartPointer<vtkDataArray>> InOrder;
  pcurv::CurvatureBuffers Buffers;

  CurvatureArrays(vtkIdType n, bool adjusted)
  {
    pcurv::CurvatureBuffers& b = this->Buffers;
    b.Minimum = this->Add<vtkDoubleArray>("Minimum_Curvature", 1, n);
    b.Maximum = this->Add<vtkDoubleArray>("Maximum_Curvature", 1, n);
    b.Mean = this->Add<vtkDoubleArray>("Mean_Curvature", 1, n);
    b.Gauss = this->Add<vtkDoubleArray>("Gauss_Curvature", 1, n);
    b.MinimumDirection = this->Add<vtkDoubleArray>("Minimum_Curvature_Direction", 3, n);
    b.MaximumDirection = this->Add<vtkDoubleArray>("Maximum_Curvature_Direction", 3, n);
    b.Valid = this->Add<vtkUnsignedCharArray>("Curvature_Valid", 1, n);
    b.NeighborCount = this->Add<vtkIntArray>("Neighbor_Count", 1, n);
    b.ValidDirections = this->Add<vtkIntArray>("Valid_Direction_Count", 1, n);
    b.SineFitRms = this->Add<vtkDoubleArray>("Sine_Fit_RMS", 1, n);
    b.Surroundings = this->Add<vtkDoubleArray>("Surroundings_Threshold", 1, n);
    b.PlaneDistance = this->Add<vtkDoubleArray>("Plane_Distance_Threshold", 1, n);
    // With the dynamic adjustment only: the neighbour count it aimed at for
    // the point, to compare with Neighbor_Count.
    b.TargetCount = adjusted ? this->Add<vtkIntArray>("Target_Neighbor_Count", 1, n) : nullptr;
  }

  template<typename ArrayT>
  typename ArrayT::ValueType* Add(const char* name, int components, vtkIdType tuples)
  {
    auto array = NewArray<ArrayT>(name, components, tuples);
    this->InOrder.push_back(array);
    return array->GetPointer(0);
  }

  void AddTo(vtkPointData* pd) const
  {
    for (vtkDataArray* array : this->InOrder)
    {
      pd->AddArray(array);
    }
  }
};

/// The filter's settings for the core.
pcurv::EstimationSettings CoreSettings(vtkPrincipalCurvatureEstimation* self)
{
  pcurv::EstimationSettings settings;
  settings.Mode = static_cast<pcurv::FitMode>(self->GetFitMode());
  settings.Neighborhood = static_cast<pcurv::NeighborhoodMode>(self->GetNeighborhoodMode());
  settings.AutomaticThresholds = self->GetAutomaticThresholds();
  settings.NumberOfNeighbors = self->GetNumberOfNeighbors();
  settings.SurroundingsThreshold = self->GetSurroundingsThreshold();
  settings.PlaneDistanceThreshold = self->GetPlaneDistanceThreshold();
  settings.PlaneDistanceRatio = self->GetPlaneDistanceRatio();
  settings.MinimumPointsPerDirection = self->GetMinimumPointsPerDirection();
  settings.DynamicAdjustment = self->GetDynamicAdjustment();
  settings.AutomaticLengthUnit = self->GetAutomaticLengthUnit();
  settings.LengthUnit = self->GetLengthUnit();
  pcurv::AdjustmentSettings& adjustment = settings.Adjustment;
  adjustment.InitialSurroundingsThreshold = self->GetInitialSurroundingsThreshold();
  std::copy_n(self->GetTargetNeighborCounts(), 3, adjustment.TargetNeighborCounts.begin());
  std::copy_n(self->GetTargetPlaneDistances(), 3, adjustment.TargetPlaneDistances.begin());
  std::copy_n(self->GetSwitchLengths(), 3, adjustment.SwitchLengths.begin());
  settings.MaximumSurroundingsFactor = self->GetMaximumSurroundingsFactor();
  settings.AdjustmentBlockLength = self->GetAdjustmentBlockLength();
  return settings;
}

/// The core's work items on vtkSMPTools threads, each with its own scratch.
class SMPToolsRunner : public pcurv::WorkRunner
{
public:
  explicit SMPToolsRunner(int maximumThreads)
    : MaximumThreads(maximumThreads)
  {
  }

  void For(std::int64_t count, std::int64_t grain, const Work& work) override
  {
    Functor functor{ work, {}, count <= grain };
    // ParaView's bundled VTK defaults to the sequential SMP backend: all
    // cores unless a backend was requested through the environment.
    std::string backend = vtkSMPTools::GetBackend();
    if (backend == "Sequential" && !std::getenv("VTK_SMP_BACKEND_IN_USE"))
    {
      backend = "STDThread";
    }
    vtkSMPTools::LocalScope(vtkSMPTools::Config{ this->MaximumThreads, backend, false },
      [&]() { vtkSMPTools::For(0, count, grain, functor); });
  }

private:
  struct Functor
  {
    const Work& Run;
    vtkSMPThreadLocal<pcurv::EstimationScratch> Scratch;
    /// With no more items than the grain, vtkSMPTools runs the functor in
    /// the calling thread without a thread pool, and (VTK 9.2, STDThread)
    /// GetSingleThread() then crashes: that one thread reports progress.
    bool RunsInline;

    void operator()(vtkIdType begin, vtkIdType end)
    {
      this->Run(
        begin, end, this->Scratch.Local(), this->RunsInline || vtkSMPTools::GetSingleThread());
    }
  };
  int MaximumThreads;
};

/// Progress to the filter, and its abort flag back to the core.
class FilterProgress : public pcurv::ProgressMonitor
{
public:
  explicit FilterProgress(vtkAlgorithm* filter)
    : Filter(filter)
  {
  }
  bool Continue(double fraction) override
  {
    this->Filter->UpdateProgress(fraction);
    return !this->Filter->GetAbortExecute();
  }

private:
  vtkAlgorithm* Filter;
};

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
  const pcurv::EstimationSettings defaults;
  this->FitMode = static_cast<int>(defaults.Mode);
  this->NeighborhoodMode = static_cast<int>(defaults.Neighborhood);
  this->AutomaticThresholds = defaults.AutomaticThresholds;
  this->NumberOfNeighbors = defaults.NumberOfNeighbors;
  this->SurroundingsThreshold = defaults.SurroundingsThreshold;
  this->PlaneDistanceThreshold = defaults.PlaneDistanceThreshold;
  this->PlaneDistanceRatio = defaults.PlaneDistanceRatio;
  this->MinimumPointsPerDirection = defaults.MinimumPointsPerDirection;
  this->DynamicAdjustment = defaults.DynamicAdjustment;
  this->AutomaticLengthUnit = defaults.AutomaticLengthUnit;
  this->LengthUnit = defaults.LengthUnit;
  this->InitialSurroundingsThreshold = defaults.Adjustment.InitialSurroundingsThreshold;
  std::copy_n(defaults.Adjustment.TargetNeighborCounts.data(), 3, this->TargetNeighborCounts);
  std::copy_n(defaults.Adjustment.TargetPlaneDistances.data(), 3, this->TargetPlaneDistances);
  std::copy_n(defaults.Adjustment.SwitchLengths.data(), 3, this->SwitchLengths);
  this->MaximumSurroundingsFactor = defaults.MaximumSurroundingsFactor;
  this->AdjustmentBlockLength = defaults.AdjustmentBlockLength;
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
  const pcurv::ControllerCollectives processes;
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

  CurvatureArrays arrays(numberOfPoints, this->DynamicAdjustment);
  SMPToolsRunner runner(this->NumberOfThreads);
  FilterProgress progress(this);
  const pcurv::EstimationSummary summary = pcurv::EstimateCloud(
    numberOfPoints > 0 ? pcurv::ReadCloud(input, normals) : pcurv::CloudPoints{},
    CoreSettings(this),
    processes,
    runner,
    &progress,
    arrays.Buffers);
  if (summary.TargetCountsClamped)
  {
    const auto& counts = summary.TargetNeighborCounts;
    vtkWarningMacro("TargetNeighborCounts must lie within [1, 1e6]; used "
      << counts[0] << ", " << counts[1] << ", " << counts[2] << ".");
  }
  this->UsedSurroundingsThreshold = summary.UsedSurroundingsThreshold;
  this->UsedPlaneDistanceThreshold = summary.UsedPlaneDistanceThreshold;
  this->UsedLengthUnit = summary.UsedLengthUnit;
  if (summary.Aborted)
  {
    return 1;
  }
  this->UpdateProgress(1.0);
  this->NumberOfUnestimatedPoints = summary.NumberOfUnestimatedPoints;
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

void vtkPrincipalCurvatureEstimation::SetAdjustmentConstantsToPreset(int preset)
{
  preset =
    std::min(std::max(preset, static_cast<int>(PAPER_CONSTANTS)), static_cast<int>(NOISY_LADDER));
  SetAdjustmentConstants(
    this, pcurv::AdjustmentConstants(static_cast<pcurv::AdjustmentPreset>(preset)));
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
