/**
 * @file EstimationSettings.h
 * @brief Every setting of an estimation, with the filter's defaults. No
 * VTK.
 */
#ifndef EstimationSettings_h
#define EstimationSettings_h

#include "Settings/SettingsTable.h"
#include "Fits/FitResults.h"
#include "Normals/NormalSettings.h"
#include "Scale/DynamicAdjustment.h"

namespace pcurv
{

/// How the neighbors of a point are chosen.
enum class NeighborhoodMode : int
{
  Radius = 0,   ///< all points closer than the surroundings-threshold
  KNearest = 1, ///< the NumberOfNeighbors nearest points
  /// Per point, from the data: the largest neighborhood whose estimate
  /// agrees with those of the smaller ones within their standard errors
  /// (FitMode::OrientedCircles with automatic thresholds; otherwise, the
  /// paper's fits or fixed thresholds, Radius).
  Automatic = 2
};

/// Every setting of an estimation, lengths in the input's unit. The
/// defaults here are the filter's defaults.
struct EstimationSettings
{
  FitMode Mode = static_cast<FitMode>(PCURV_DEFAULT("FitMode"));
  NeighborhoodMode Neighborhood = static_cast<NeighborhoodMode>(PCURV_DEFAULT("NeighborhoodMode"));
  /// s and p derived from the cloud (s: median distance to the
  /// NumberOfNeighbors-th neighbor; p = PlaneDistanceRatio s).
  bool AutomaticThresholds = PCURV_DEFAULT("AutomaticThresholds") != 0;
  int NumberOfNeighbors = static_cast<int>(PCURV_DEFAULT("NumberOfNeighbors"));
  double SurroundingsThreshold = PCURV_DEFAULT("SurroundingsThreshold");   ///< s when not automatic
  double PlaneDistanceThreshold = PCURV_DEFAULT("PlaneDistanceThreshold"); ///< p, not automatic
  double PlaneDistanceRatio = PCURV_DEFAULT("PlaneDistanceRatio"); ///< p / s: automatic, k nearest
  int MinimumPointsPerDirection = static_cast<int>(PCURV_DEFAULT("MinimumPointsPerDirection"));
  /// OrientedCircles: a point whose neighbors' normals oppose its own for
  /// more than this fraction of them is not estimated (the neighborhood
  /// reaches across the surface).
  double MaximumOpposingFraction = 0.05;
  /// NeighborhoodMode::Automatic: how many standard errors the estimates of
  /// two radii may differ by for the larger to be kept.
  double AutomaticScaleTolerance = PCURV_DEFAULT("AutomaticScaleTolerance");
  /// NeighborhoodMode::Automatic: a point near an anchor point whose
  /// neighborhood is wide takes the anchor's fitted surface, evaluated at
  /// its own position, instead of gathering nearly the same neighbors
  /// again (SharedFits.h). Off: every point fits its own.
  bool ShareFits = PCURV_DEFAULT("ShareFits") != 0;
  /// With the automatic scale and normals given: the normal field's fit
  /// where the positions are noisy (AutomaticScaleRule::NormalField).
  bool NormalFieldFit = PCURV_DEFAULT("NormalFieldFit") != 0;
  /// OrientedCircles: points far from the surface their neighbors sample
  /// are flagged and moved onto it first (SurfaceOutliers.h), so that they
  /// pull no neighbor's normal or fit and get the nearest surface's
  /// curvatures. The paper's fits take the cloud as it is.
  bool MoveOutliers = true;

  /// The paper's dynamic variable adjustment instead of the above.
  bool DynamicAdjustment = PCURV_DEFAULT("DynamicAdjustment") != 0;
  /// L derived from the cloud: InitialSurroundingsThreshold L then holds
  /// about the first target count at a typical point.
  bool AutomaticLengthUnit = PCURV_DEFAULT("AutomaticLengthUnit") != 0;
  double LengthUnit = PCURV_DEFAULT("LengthUnit"); ///< L when not automatic
  /// The initial s, target counts, target plane distances and switch
  /// lengths (lengths in units of L). The paper's constants by default.
  AdjustmentSettings Adjustment;
  /// s never exceeds this times the initial s.
  double MaximumSurroundingsFactor = PCURV_DEFAULT("MaximumSurroundingsFactor");
  /// Side of an adjustment block, in units of L.
  double AdjustmentBlockLength = PCURV_DEFAULT("AdjustmentBlockLength");

  /// Estimate the normals (NormalEstimation.h) instead of using the
  /// cloud's; they are written to CurvatureBuffers::Normals.
  bool EstimateNormals = false;
  NormalSettings Normals;
};

} // namespace pcurv

#endif
