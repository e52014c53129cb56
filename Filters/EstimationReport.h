/**
 * @file EstimationReport.h
 * @brief What the filter tells the user of a run: the points without an
 * estimate by reason, in the field data, and warnings. Private to
 * vtkPrincipalCurvatureEstimation.
 */
#ifndef EstimationReport_h
#define EstimationReport_h

class vtkPointSet;
class vtkPolyData;
class vtkPrincipalCurvatureEstimation;

namespace pcurv
{
class Collectives;
struct EstimationSummary;

namespace report
{

/// The counts of unestimated points, by reason, in the output's field data;
/// a warning when most of the cloud has no estimate.
void ReportUnestimated(vtkPrincipalCurvatureEstimation* self,
  const pcurv::EstimationSummary& summary,
  const pcurv::Collectives& processes,
  vtkPolyData* output);

/// What the run found, in the output's field data: Trusted_Curvature_Scale
/// (with Curvature_Trusted), Shape_Class_Names (with the Shape_Class array:
/// the name of code c at index c), Outlier_Points (with the Outlier array),
/// Fourth_Order_Fits and Jet_Fit_Points (with the automatic scale) and
/// Shared_Fit_Points (with it and `shareFits`).
void AddRunFields(vtkPolyData* output,
  const pcurv::EstimationSummary& summary,
  bool trusted,
  bool automaticScale,
  bool shareFits);

/// Float coordinates keep 24 bits: at magnitude M neighboring floats lie
/// up to M 2^-23 apart. A georeferenced scan (UTM metres, 1e5 to 1e7) in
/// float is rounded to centimetres or decimetres, which is noise of that
/// size to every fit; a warning with the numbers, when the rounding exceeds
/// a hundredth of the point spacing (noise the estimate starts to show).
/// `radius` holds about `count` neighbors at a typical point.
void WarnOnCoarseCoordinates(vtkPrincipalCurvatureEstimation* self,
  vtkPointSet* input,
  double radius,
  int count);

} // namespace report
} // namespace pcurv

#endif
