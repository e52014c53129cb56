#include "vtkPrincipalCurvatureEstimation.h"

#include "Estimation/CloudEstimation.h"
#include "CurvatureArrays.h"
#include "EstimationReport.h"
#include "NormalsChoice.h"
#include "CloudData.h"
#include "ControllerCollectives.h"
#include "FilterProgress.h"

#include "vtkDataArray.h"
#include "vtkDataSetAttributes.h"
#include "vtkDoubleArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkMath.h"
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
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkPrincipalCurvatureEstimation);

namespace
{
/// The Normals property's entry for "no array" in the plugin's panel (the
/// ArrayListDomain's none_string): the normals attribute or estimated ones.
constexpr const char* NO_NORMALS_ARRAY = "None (automatic)";
}

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
      static_cast<int>(pcurv::NeighborhoodMode::KNearest) &&
    vtkPrincipalCurvatureEstimation::AUTOMATIC_SCALE ==
      static_cast<int>(pcurv::NeighborhoodMode::Automatic),
  "NeighborhoodModes must match pcurv::NeighborhoodMode");
static_assert(vtkPrincipalCurvatureEstimation::PAPER_CONSTANTS ==
      static_cast<int>(pcurv::AdjustmentPreset::Paper) &&
    vtkPrincipalCurvatureEstimation::LADDER == static_cast<int>(pcurv::AdjustmentPreset::Ladder) &&
    vtkPrincipalCurvatureEstimation::NOISY_LADDER ==
      static_cast<int>(pcurv::AdjustmentPreset::NoisyLadder),
  "AdjustmentPresets must match pcurv::AdjustmentPreset");

namespace
{
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
  settings.AutomaticScaleTolerance = self->GetAutomaticScaleTolerance();
  settings.ShareFits = self->GetShareFits();
  settings.NormalFieldFit = self->GetNormalFieldFit();
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
  settings.Normals.NumberOfNeighbors = self->GetNormalNeighbors();
  settings.Normals.Orientation =
    static_cast<pcurv::NormalOrientation>(self->GetNormalOrientation());
  std::copy_n(self->GetViewpoint(), 3, settings.Normals.Viewpoint.begin());
  std::copy_n(self->GetOrientationAxis(), 3, settings.Normals.Axis.begin());
  return settings;
}

// What ParaView's progress bar says while the filter runs (its class name
// while the filter has no progress text: VTK reports progress 0 before
// RequestData).
const char* const ProgressLabel = "Principal curvatures";

/// Runs the core's estimation of the input's points into buffers and
/// returns its summary.
pcurv::EstimationSummary RunEstimation(vtkPrincipalCurvatureEstimation* self,
  vtkPointSet* input,
  vtkDataArray* normals,
  const pcurv::EstimationSettings& settings,
  const pcurv::ControllerCollectives& processes,
  const pcurv::CurvatureBuffers& buffers)
{
  const vtkIdType numberOfPoints = input->GetNumberOfPoints();
  pcurv::AlgorithmProgress progress(self, ProgressLabel);
  // One process: the whole estimation on a thread of its own, this one
  // passing progress and Abort all along; distributed: here, passing them
  // in the parallel stages (see RunPassingProgress).
  const bool distributed = processes.IsDistributed();
  pcurv::SMPToolsRunner runner(self->GetNumberOfThreads(), distributed ? &progress : nullptr);
  auto runEstimation = [&]()
  {
    return pcurv::EstimateCloud(
      numberOfPoints > 0 ? pcurv::ReadCloud(input, normals) : pcurv::CloudPoints{},
      settings,
      processes,
      runner,
      &progress,
      buffers);
  };
  return distributed ? runEstimation() : pcurv::RunPassingProgress(progress, runEstimation);
}

/// The output: the input's geometry, the estimated arrays and normals,
/// the run's reports and field data, and the curvature colored by default.
void WriteOutput(vtkPrincipalCurvatureEstimation* self,
  vtkPointSet* input,
  vtkPolyData* output,
  pcurv::output::CurvatureArrays& arrays,
  vtkDataArray* estimatedNormals,
  const pcurv::EstimationSummary& summary,
  const pcurv::EstimationSettings& settings,
  const pcurv::ControllerCollectives& processes)
{
  pcurv::CopyGeometry(input, output);
  arrays.AddTo(output->GetPointData(), self->GetDiagnosticArrays());
  pcurv::report::ReportUnestimated(self, summary, processes, output);
  pcurv::report::WarnOnCoarseCoordinates(self,
    input,
    summary.UsedSurroundingsThreshold,
    settings.Neighborhood == pcurv::NeighborhoodMode::Automatic &&
        settings.Mode == pcurv::FitMode::OrientedCircles
      ? 16
      : settings.NumberOfNeighbors);
  pcurv::report::AddRunFields(output,
    summary,
    arrays.Buffers.Trusted != nullptr,
    settings.Mode == pcurv::FitMode::OrientedCircles &&
      settings.Neighborhood == pcurv::NeighborhoodMode::Automatic,
    settings.ShareFits);
  if (estimatedNormals)
  {
    output->GetPointData()->SetNormals(estimatedNormals);
  }
  // The active scalars: ParaView colors a new display by them, over their
  // range, so the first Apply shows the curvature rather than a solid
  // color, and its structure rather than a few outliers.
  output->GetPointData()->SetActiveScalars(
    self->GetDiagnosticArrays() ? "Mean_Curvature_Clipped" : "Mean_Curvature");
  // White (zero) in the middle of the colors, whichever tail was clipped.
  pcurv::SetSymmetricRange(
    output->GetPointData()->GetArray("Mean_Curvature_Clipped"), summary.MeanCurvatureClip);
  pcurv::AddCurvatureUnit(output);
}

} // namespace

vtkPrincipalCurvatureEstimation::vtkPrincipalCurvatureEstimation()
{
  this->SetProgressText(ProgressLabel);
  const pcurv::EstimationSettings defaults;
  this->FitMode = static_cast<int>(defaults.Mode);
  this->NeighborhoodMode = static_cast<int>(defaults.Neighborhood);
  this->AutomaticThresholds = defaults.AutomaticThresholds;
  this->NumberOfNeighbors = defaults.NumberOfNeighbors;
  this->SurroundingsThreshold = defaults.SurroundingsThreshold;
  this->PlaneDistanceThreshold = defaults.PlaneDistanceThreshold;
  this->PlaneDistanceRatio = defaults.PlaneDistanceRatio;
  this->MinimumPointsPerDirection = defaults.MinimumPointsPerDirection;
  this->AutomaticScaleTolerance = defaults.AutomaticScaleTolerance;
  this->ShareFits = defaults.ShareFits;
  this->NormalFieldFit = defaults.NormalFieldFit;
  this->DynamicAdjustment = defaults.DynamicAdjustment;
  this->AutomaticLengthUnit = defaults.AutomaticLengthUnit;
  this->LengthUnit = defaults.LengthUnit;
  this->InitialSurroundingsThreshold = defaults.Adjustment.InitialSurroundingsThreshold;
  std::copy_n(defaults.Adjustment.TargetNeighborCounts.data(), 3, this->TargetNeighborCounts);
  std::copy_n(defaults.Adjustment.TargetPlaneDistances.data(), 3, this->TargetPlaneDistances);
  std::copy_n(defaults.Adjustment.SwitchLengths.data(), 3, this->SwitchLengths);
  this->MaximumSurroundingsFactor = defaults.MaximumSurroundingsFactor;
  this->AdjustmentBlockLength = defaults.AdjustmentBlockLength;
  this->NormalNeighbors = defaults.Normals.NumberOfNeighbors;
  this->NormalOrientation = static_cast<int>(defaults.Normals.Orientation);
  std::copy_n(defaults.Normals.Viewpoint.data(), 3, this->Viewpoint);
  std::copy_n(defaults.Normals.Axis.data(), 3, this->OrientationAxis);
  // The settings the core does not see.
  this->NumberOfThreads = static_cast<int>(PCURV_DEFAULT("NumberOfThreads"));
  this->SinglePrecisionOutput = PCURV_DEFAULT("SinglePrecisionOutput") != 0;
  this->DiagnosticArrays = PCURV_DEFAULT("DiagnosticArrays") != 0;
  this->NormalsSource = static_cast<int>(PCURV_DEFAULT("NormalsSource"));
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
  this->UsedEstimatedNormals = false;
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
    pcurv::CopyGeometry(input, output);
    return 1;
  }
  bool estimate = true;
  vtkDataArray* normals =
    numberOfPoints > 0 ? this->ChooseNormals(inputVector, input, estimate) : nullptr;
  const bool normalsUsable =
    numberOfPoints == 0 || estimate || (normals && this->CheckNormals(normals, numberOfPoints));
  if (!processes.Min(normalsUsable ? 1 : 0))
  {
    return 0;
  }
  // Every process estimates, or none: a piece without points has no say.
  this->UsedEstimatedNormals = !processes.Min(numberOfPoints == 0 || !estimate ? 1 : 0);
  if (this->UsedEstimatedNormals)
  {
    normals = nullptr;
  }

  pcurv::output::CurvatureArrays arrays(numberOfPoints,
    this->DynamicAdjustment,
    this->FitMode == ORIENTED_CIRCLES,
    this->DiagnosticArrays,
    this->SinglePrecisionOutput);
  vtkSmartPointer<vtkDataArray> estimatedNormals;
  if (this->UsedEstimatedNormals)
  {
    estimatedNormals = pcurv::output::NewRealArray(
      "Normals", 3, numberOfPoints, this->SinglePrecisionOutput, arrays.Buffers.Normals);
  }
  pcurv::EstimationSettings settings = CoreSettings(this);
  settings.EstimateNormals = this->UsedEstimatedNormals;
  const pcurv::EstimationSummary summary =
    RunEstimation(this, input, normals, settings, processes, arrays.Buffers);
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
  this->NumberOfSharedFitPoints = summary.NumberOfSharedPoints;
  this->NumberOfJetFitPoints = summary.NumberOfJetPoints;
  this->FourthOrderFits = summary.FourthOrderFits;
  WriteOutput(this, input, output, arrays, estimatedNormals, summary, settings, processes);
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

vtkDataArray* vtkPrincipalCurvatureEstimation::ChooseNormals(vtkInformationVector** inputVector,
  vtkPointSet* input,
  bool& estimate)
{
  estimate = false;
  if (this->NormalsSource == ESTIMATED_NORMALS)
  {
    estimate = true;
    return nullptr;
  }
  vtkDataArray* chosen = this->GetInputArrayToProcess(0, inputVector);
  vtkInformation* request = this->GetInputArrayInformation(0);
  // ParaView's "no selection": an empty name, the panel's entry for none
  // (the XML's none_string), or "0" when the input has no 3-component array.
  const std::string requested = request && request->Has(vtkDataObject::FIELD_NAME())
    ? request->Get(vtkDataObject::FIELD_NAME())
    : "";
  const bool byName = !requested.empty() && requested != NO_NORMALS_ARRAY;
  if (!chosen && byName && this->NormalsSource == AUTOMATIC_NORMALS &&
    input->GetPointData()->GetNumberOfArrays() > 0)
  {
    vtkWarningMacro("No point-data array named '" << request->Get(vtkDataObject::FIELD_NAME())
                                                  << "'; the normals attribute is used, or normals "
                                                     "are estimated.");
  }
  if (!chosen && (!byName || this->NormalsSource == AUTOMATIC_NORMALS))
  {
    // The attribute, for no selection too.
    chosen = input->GetPointData()->GetNormals();
  }
  if (chosen || this->NormalsSource == INPUT_NORMALS)
  {
    // ParaView's default choice is the first 3-component array, such as a
    // PLY's RGB: in automatic mode such an array is not taken for normals.
    if (chosen && this->NormalsSource == AUTOMATIC_NORMALS &&
      !pcurv::normals_choice::NamedLikeNormals(chosen, input) &&
      chosen->GetNumberOfComponents() == 3)
    {
      const std::string reason = pcurv::normals_choice::NotNormalsReason(chosen);
      if (!reason.empty())
      {
        vtkWarningMacro("The array '" << (chosen->GetName() ? chosen->GetName() : "") << "' "
                                      << reason << "; normals were estimated instead.");
        estimate = true;
        return nullptr;
      }
    }
    if (!chosen)
    {
      vtkErrorMacro("No normals: the input needs a 3-component point-data normals array (the "
                    "active normals, or one chosen with SetInputArrayToProcess), or set "
                    "NormalsSource to estimate them (Normals Source 'Estimated' in ParaView, "
                    "--estimate-normals in the command-line tool).");
    }
    return chosen;
  }
  estimate = true; // automatic, and the input has no normals
  return nullptr;
}

bool vtkPrincipalCurvatureEstimation::CheckNormals(vtkDataArray* normals, vtkIdType numberOfPoints)
{
  const std::string name = normals->GetName() ? normals->GetName() : "";
  if (normals->GetNumberOfComponents() != 3 || normals->GetNumberOfTuples() != numberOfPoints)
  {
    vtkErrorMacro("The normals array '" << name << "' has " << normals->GetNumberOfComponents()
                                        << " components and " << normals->GetNumberOfTuples()
                                        << " tuples; 3 components per point are required.");
    return false;
  }
  const std::string reason = pcurv::normals_choice::NotNormalsReason(normals);
  if (!reason.empty())
  {
    vtkErrorMacro("The array '" << name << "' chosen as normals " << reason
                                << ". To estimate normals instead, set NormalsSource to "
                                   "Estimated (Normals Source in ParaView, --estimate-normals "
                                   "in the command-line tool).");
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
  os << indent << "AutomaticScaleTolerance: " << this->AutomaticScaleTolerance << "\n";
  os << indent << "ShareFits: " << (this->ShareFits ? "On" : "Off") << "\n";
  os << indent << "NormalFieldFit: " << (this->NormalFieldFit ? "On" : "Off") << "\n";
  os << indent << "NumberOfThreads: " << this->NumberOfThreads << "\n";
  os << indent << "SinglePrecisionOutput: " << (this->SinglePrecisionOutput ? "On" : "Off") << "\n";
  os << indent << "DiagnosticArrays: " << (this->DiagnosticArrays ? "On" : "Off") << "\n";
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
  os << indent << "NormalsSource: " << this->NormalsSource << "\n";
  os << indent << "NormalOrientation: " << this->NormalOrientation << "\n";
  os << indent << "Viewpoint: " << this->Viewpoint[0] << " " << this->Viewpoint[1] << " "
     << this->Viewpoint[2] << "\n";
  os << indent << "OrientationAxis: " << this->OrientationAxis[0] << " " << this->OrientationAxis[1]
     << " " << this->OrientationAxis[2] << "\n";
  os << indent << "NormalNeighbors: " << this->NormalNeighbors << "\n";
  os << indent << "UsedEstimatedNormals: " << this->UsedEstimatedNormals << "\n";
  os << indent << "UsedLengthUnit: " << this->UsedLengthUnit << "\n";
  os << indent << "UsedSurroundingsThreshold: " << this->UsedSurroundingsThreshold << "\n";
  os << indent << "UsedPlaneDistanceThreshold: " << this->UsedPlaneDistanceThreshold << "\n";
  os << indent << "NumberOfUnestimatedPoints: " << this->NumberOfUnestimatedPoints << "\n";
}
