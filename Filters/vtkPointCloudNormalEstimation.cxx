#include "vtkPointCloudNormalEstimation.h"

#include "Estimation/CloudEstimation.h"
#include "CloudData.h"
#include "ControllerCollectives.h"
#include "FilterProgress.h"

#include "vtkDoubleArray.h"
#include "vtkInformation.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPolyData.h"

#include <algorithm>

vtkStandardNewMacro(vtkPointCloudNormalEstimation);

static_assert(
  vtkPointCloudNormalEstimation::OUTWARD == static_cast<int>(pcurv::NormalOrientation::Outward) &&
    vtkPointCloudNormalEstimation::TOWARDS_VIEWPOINT ==
      static_cast<int>(pcurv::NormalOrientation::TowardsViewpoint) &&
    vtkPointCloudNormalEstimation::ALONG_AXIS ==
      static_cast<int>(pcurv::NormalOrientation::AlongAxis),
  "Orientations must match pcurv::NormalOrientation");

namespace
{
// What ParaView's progress bar says while the filter runs (its class name
// while the filter has no progress text: VTK reports progress 0 before
// RequestData).
const char* const ProgressLabel = "Point cloud normals";
}

vtkPointCloudNormalEstimation::vtkPointCloudNormalEstimation()
{
  this->SetProgressText(ProgressLabel);
  const pcurv::NormalSettings defaults;
  this->NumberOfNeighbors = defaults.NumberOfNeighbors;
  this->Orientation = static_cast<int>(defaults.Orientation);
  std::copy_n(defaults.Viewpoint.data(), 3, this->Viewpoint);
  std::copy_n(defaults.Axis.data(), 3, this->Axis);
  this->NumberOfThreads = static_cast<int>(PCURV_DEFAULT("NumberOfThreads"));
}

int vtkPointCloudNormalEstimation::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPointSet");
  return 1;
}

int vtkPointCloudNormalEstimation::RequestData(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  vtkPointSet* input = vtkPointSet::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  this->NumberOfParts = 0;
  this->NumberOfUndeterminedNormals = 0;
  if (!input || !output)
  {
    return 0;
  }
  const pcurv::ControllerCollectives processes;
  const vtkIdType numberOfPoints = input->GetNumberOfPoints();
  if (numberOfPoints == 0 && !processes.IsDistributed())
  {
    pcurv::CopyGeometry(input, output);
    return 1;
  }
  pcurv::NormalSettings settings;
  settings.NumberOfNeighbors = this->NumberOfNeighbors;
  settings.Orientation = static_cast<pcurv::NormalOrientation>(this->Orientation);
  std::copy_n(this->Viewpoint, 3, settings.Viewpoint.begin());
  std::copy_n(this->Axis, 3, settings.Axis.begin());

  vtkNew<vtkDoubleArray> normals;
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  normals->SetNumberOfTuples(numberOfPoints);
  pcurv::AlgorithmProgress progress(this, ProgressLabel);
  // As vtkPrincipalCurvatureEstimation: the orientation is serial and long.
  const bool distributed = processes.IsDistributed();
  pcurv::SMPToolsRunner runner(this->NumberOfThreads, distributed ? &progress : nullptr);
  auto runEstimation = [&]()
  {
    return pcurv::EstimateCloudNormals(
      numberOfPoints > 0 ? pcurv::ReadCloud(input, nullptr) : pcurv::CloudPoints{},
      settings,
      processes,
      runner,
      normals->GetPointer(0),
      &progress);
  };
  const pcurv::NormalSummary summary =
    distributed ? runEstimation() : pcurv::RunPassingProgress(progress, runEstimation);
  if (summary.Aborted)
  {
    return 1;
  }
  this->UpdateProgress(1.0);
  this->NumberOfParts = summary.Components;
  this->NumberOfUndeterminedNormals = summary.Undetermined;
  pcurv::CopyGeometry(input, output);
  output->GetPointData()->SetNormals(normals);
  return 1;
}

void vtkPointCloudNormalEstimation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfNeighbors: " << this->NumberOfNeighbors << "\n";
  os << indent << "Orientation: " << this->Orientation << "\n";
  os << indent << "Viewpoint: " << this->Viewpoint[0] << " " << this->Viewpoint[1] << " "
     << this->Viewpoint[2] << "\n";
  os << indent << "Axis: " << this->Axis[0] << " " << this->Axis[1] << " " << this->Axis[2] << "\n";
  os << indent << "NumberOfThreads: " << this->NumberOfThreads << "\n";
  os << indent << "NumberOfParts: " << this->NumberOfParts << "\n";
  os << indent << "NumberOfUndeterminedNormals: " << this->NumberOfUndeterminedNormals << "\n";
}
