#include "EstimationReport.h"

#include "Cloud/Collectives.h"
#include "Estimation/CurvatureOutputs.h"
#include "Estimation/ShapeClass.h"
#include "vtkPrincipalCurvatureEstimation.h"

#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStringArray.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace pcurv
{
namespace report
{

/// The counts of unestimated points, by reason, in the output's field data;
/// a warning when most of the cloud has no estimate.
void ReportUnestimated(vtkPrincipalCurvatureEstimation* self,
  const pcurv::EstimationSummary& summary,
  const pcurv::Collectives& processes,
  vtkPolyData* output)
{
  // Counts of the whole cloud, also in a parallel run: field data shows in
  // the Information panel, which would otherwise show one piece's.
  std::vector<std::int64_t> counts(
    summary.UnestimatedByReason.begin(), summary.UnestimatedByReason.end());
  counts.push_back(output->GetNumberOfPoints());
  if (processes.IsDistributed())
  {
    processes.Sum(counts);
  }
  const std::int64_t total = counts.back();
  std::int64_t unestimated = 0;
  std::string byReason;
  for (int reason = 1; reason < static_cast<int>(pcurv::UnestimatedReason::Count); ++reason)
  {
    const char* name = pcurv::UnestimatedReasonName(static_cast<pcurv::UnestimatedReason>(reason));
    vtkNew<vtkIdTypeArray> count;
    count->SetName((std::string("Unestimated_") + name).c_str());
    count->InsertNextValue(counts[reason]);
    output->GetFieldData()->AddArray(count);
    unestimated += counts[reason];
    if (counts[reason] > 0)
    {
      byReason += (byReason.empty() ? "" : ", ") + std::to_string(counts[reason]) + " " + name;
    }
  }
  vtkNew<vtkIdTypeArray> all;
  all->SetName("Unestimated_Points");
  all->InsertNextValue(unestimated);
  output->GetFieldData()->AddArray(all);
  // Some unestimated points are normal on real scans (their borders, stray
  // points): only a failure of most of the cloud is worth a pop-up.
  if (2 * unestimated > total)
  {
    vtkWarningWithObjectMacro(self,
      << unestimated << " of " << total << " points could not be estimated (" << byReason
      << "); they have Curvature_Valid = 0 and NaN curvatures. See the "
         "Unestimated_* field data, and docs/output-arrays.md for what helps.");
  }
}

/// Float coordinates keep 24 bits: at magnitude M neighboring floats lie
/// up to M 2^-23 apart. A georeferenced scan (UTM metres, 1e5 to 1e7) in
/// float is rounded to centimetres or decimetres, which is noise of that
/// size to every fit; a warning with the numbers, when the rounding exceeds
/// a hundredth of the point spacing (noise the estimate starts to show).
/// `radius` holds about `count` neighbors at a typical point.
void WarnOnCoarseCoordinates(vtkPrincipalCurvatureEstimation* self,
  vtkPointSet* input,
  double radius,
  int count)
{
  vtkPoints* points = input->GetPoints();
  if (!points || points->GetDataType() != VTK_FLOAT || !(radius > 0.0) || count <= 0)
  {
    return;
  }
  double bounds[6];
  points->GetBounds(bounds);
  double magnitude = 0.0;
  for (const double b : bounds)
  {
    magnitude = std::isfinite(b) ? std::max(magnitude, std::fabs(b)) : magnitude;
  }
  const double resolution = magnitude > 0.0 ? std::ldexp(1.0, std::ilogb(magnitude) - 23) : 0.0;
  const double spacing = radius / std::sqrt(count / vtkMath::Pi());
  if (resolution > 0.01 * spacing)
  {
    vtkWarningWithObjectMacro(self,
      "The input's coordinates are stored as float: at their magnitude ("
        << magnitude << ") neighboring floats are up to " << resolution << " apart, "
        << resolution / spacing << " times the point spacing (about " << spacing
        << "). The positions are rounded as if by noise of that size, and the curvatures "
           "degrade. Keep the coordinates in double (the plugin's PLY, LAS and text readers "
           "do), or subtract an offset before converting them to float.");
  }
}

namespace
{
template<typename ArrayT, typename ValueT>
void AddField(vtkPolyData* output, const char* name, ValueT value)
{
  vtkNew<ArrayT> array;
  array->SetName(name);
  array->InsertNextValue(value);
  output->GetFieldData()->AddArray(array);
}
} // namespace

void AddRunFields(vtkPolyData* output,
  const pcurv::EstimationSummary& summary,
  bool trusted,
  bool automaticScale,
  bool shareFits)
{
  if (trusted)
  {
    // What Curvature_Trusted compared the standard errors with.
    AddField<vtkDoubleArray>(output, "Trusted_Curvature_Scale", summary.TrustedCurvatureScale);
  }
  if (output->GetPointData()->GetArray(pcurv::ShapeClassArrayName))
  {
    // Which code of Shape_Class is which class: the name at index code.
    vtkNew<vtkStringArray> names;
    names->SetName("Shape_Class_Names");
    for (int code = 0; code < static_cast<int>(pcurv::ShapeClass::Count); ++code)
    {
      names->InsertNextValue(pcurv::ShapeClassName(static_cast<pcurv::ShapeClass>(code)));
    }
    output->GetFieldData()->AddArray(names);
  }
  if (output->GetPointData()->GetArray("Outlier"))
  {
    AddField<vtkIdTypeArray>(output, "Outlier_Points", summary.NumberOfOutliers);
  }
  if (shareFits && automaticScale)
  {
    AddField<vtkIdTypeArray>(output, "Shared_Fit_Points", summary.NumberOfSharedPoints);
  }
  if (automaticScale)
  {
    AddField<vtkIntArray>(output, "Fourth_Order_Fits", summary.FourthOrderFits ? 1 : 0);
    AddField<vtkIntArray>(output, "Given_Normals_Replaced", summary.GivenNormalsReplaced ? 1 : 0);
    AddField<vtkIdTypeArray>(output, "Jet_Fit_Points", summary.NumberOfJetPoints);
  }
}

} // namespace report
} // namespace pcurv
