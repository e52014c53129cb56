/**
 * @file EstimationSettings.h
 * @brief Every setting of an estimation, with the filter's defaults. No
 * VTK.
 */
#ifndef EstimationSettings_h
#define EstimationSettings_h

#include "Fits/FitResults.h"
#include "Normals/NormalSettings.h"
#include "Scale/DynamicAdjustment.h"

namespace pcurv
{

/// How the neighbours of a point are chosen.
enum class NeighborhoodMode : int
{
  Radius = 0,   ///< all points closer than the surroundings-threshold
  KNearest = 1, ///< the NumberOfNeighbors nearest points
  /// Per point, from the data: the largest neighbourhood whose estimate
  /// agrees with those of the smaller ones within their standard errors
  /// (FitMode::OrientedCircles with automatic thresholds; otherwise, the
  /// paper's fits or fixed thresholds, Radius).
  Automatic = 2
};

/// Every setting of an estimation, lengths in the input's unit. The
/// defaults here are the filter's defaults.
struct EstimationSettings
{
  FitMode Mode = FitMode::OrientedCircles;
  NeighborhoodMode Neighborhood = NeighborhoodMode::Automatic;
  /// s and p derived from the cloud (s: median distance to the
  /// NumberOfNeighbors-th neighbour; p = PlaneDistanceRatio s).
  bool AutomaticThresholds = true;
  int NumberOfNeighbors = 375;
  double SurroundingsThreshold = 1.0;  ///< s when not automatic
  double PlaneDistanceThreshold = 0.1; ///< p when not automatic
  double PlaneDistanceRatio = 0.1;     ///< p / s when automatic or k nearest
  int MinimumPointsPerDirection = 3;
  /// OrientedCircles: a point whose neighbours' normals oppose its own for
  /// more than this fraction of them is not estimated (the neighbourhood
  /// reaches across the surface).
  double MaximumOpposingFraction = 0.05;
  /// NeighborhoodMode::Automatic: how many standard errors the estimates of
  /// two radii may differ by for the larger to be kept.
  double AutomaticScaleTolerance = 2.0;
  /// NeighborhoodMode::Automatic: a point near an anchor point whose
  /// neighbourhood is wide takes the anchor's fitted surface, evaluated at
  /// its own position, instead of gathering nearly the same neighbours
  /// again (SharedFits.h). Off: every point fits its own.
  bool ShareFits = true;

  /// The paper's dynamic variable adjustment instead of the above.
  bool DynamicAdjustment = false;
  /// L derived from the cloud: InitialSurroundingsThreshold L then holds
  /// about the first target count at a typical point.
  bool AutomaticLengthUnit = true;
  double LengthUnit = 1.0; ///< L when not automatic
  /// The initial s, target counts, target plane distances and switch
  /// lengths (lengths in units of L). The paper's constants by default.
  AdjustmentSettings Adjustment;
  /// s never exceeds this times the initial s.
  double MaximumSurroundingsFactor = 4.0;
  /// Side of an adjustment block, in units of L.
  double AdjustmentBlockLength = 8.0;

  /// Estimate the normals (NormalEstimation.h) instead of using the
  /// cloud's; they are written to CurvatureBuffers::Normals.
  bool EstimateNormals = false;
  NormalSettings Normals;
};

} // namespace pcurv

#endif
