/**
 * @file CloudEstimation.h
 * @brief The cloud-level entry point of the numeric core: from a cloud with
 * normals and the settings to the curvatures of every point. No VTK: the
 * caller provides the output buffers, the collectives of a parallel run and
 * the threads (WorkRunner), and gets a summary back.
 *
 * What happens, in order: the cloud is moved into a power-of-two working
 * unit (CloudStatistics.h), the thresholds are chosen (fixed, automatic, k
 * nearest or the dynamic adjustment), the grid lattice is made from global
 * bounds, a halo is exchanged when distributed, the points are put into a
 * global processing order (the grid's order; blocks of space with the
 * dynamic adjustment), each work item is estimated, and the results are
 * written back in the input's unit.
 */
#ifndef CloudEstimation_h
#define CloudEstimation_h

#include "Cloud/CloudStatistics.h"
#include "Scale/DynamicAdjustment.h"
#include "Normals/NormalEstimation.h"
#include "Fits/OrientedCircleFit.h"
#include "Neighbors/PointGrid.h"
#include "Fits/PrincipalCurvatureCore.h"
#include "Common/Progress.h"
#include "Common/WorkRunner.h"

#include <array>
#include <atomic>
#include <cstdint>
#include <functional>
#include <utility>
#include <vector>

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

/// Where the results go: one value (or 3 for directions) per input point,
/// the real ones in double or single precision (RealBuffer). TargetCount
/// may be null (it is written with the dynamic adjustment only).
struct CurvatureBuffers
{
  RealBuffer Minimum = nullptr;
  RealBuffer Maximum = nullptr;
  RealBuffer Mean = nullptr;
  RealBuffer Gauss = nullptr;
  RealBuffer MinimumDirection = nullptr;
  RealBuffer MaximumDirection = nullptr;
  RealBuffer SineFitRms = nullptr;
  RealBuffer Surroundings = nullptr;
  RealBuffer PlaneDistance = nullptr;
  unsigned char* Valid = nullptr;
  int* NeighborCount = nullptr;
  int* ValidDirections = nullptr;
  int* TargetCount = nullptr;
  /// Derived (may be null): Koenderink and van Doorn's shape index,
  /// (2/pi) atan2(k_max + k_min, k_max - k_min), in [-1, 1] (+1 a convex
  /// cap such as a sphere with outward normals, +1/2 a ridge such as a
  /// cylinder, 0 a symmetric saddle, -1 a cup; NaN where both curvatures
  /// are 0), and the curvedness sqrt((k_min^2 + k_max^2) / 2), 1/length.
  RealBuffer ShapeIndex = nullptr;
  RealBuffer Curvedness = nullptr;
  /// Derived, for display (may be null): the mean curvature clipped to
  /// [-c, c], c the 95th percentile of |mean curvature| over the cloud
  /// (EstimationSummary::MeanCurvatureClip), NaN where not estimated. A
  /// colour map over its range shows the surface's structure, not a few
  /// outliers, and is centred on 0 (flat).
  RealBuffer ClippedMean = nullptr;
  /// With FitMode::OrientedCircles only (may be null): the standard error
  /// of the curvatures, 1/length: it covers the fit's variance, the bias
  /// of the chosen neighbourhood and the normals' errors, calibrated so
  /// that most errors are within twice it (docs/output-arrays.md).
  RealBuffer StandardError = nullptr;
  /// With FitMode::OrientedCircles only (may be null): 1 where the point is
  /// estimated and twice its standard error is within a tenth of the
  /// cloud's curvature scale (EstimationSummary::TrustedCurvatureScale).
  unsigned char* Trusted = nullptr;
  /// With FitMode::OrientedCircles only (may be null): the fitted
  /// surface's unit normal, 3 per point, to which the directions are
  /// tangent (zero where not estimated).
  RealBuffer FittedNormal = nullptr;
  /// With EstimateNormals only (may be null): the normals estimated, 3 per
  /// input point (zero where undetermined or the coordinates not finite).
  RealBuffer Normals = nullptr;
};

/// Points without an estimate, indexed by UnestimatedReason (None: 0).
using UnestimatedCounts = std::array<std::int64_t, static_cast<int>(UnestimatedReason::Count)>;

/// The name of a reason, as the filter's field data arrays are named
/// ("Unestimated_" and it): for example "Too_Few_Neighbors".
const char* UnestimatedReasonName(UnestimatedReason reason);

/// What an estimation chose and found, lengths in the input's unit.
struct EstimationSummary
{
  /// The fixed or automatic s and p (0 with k nearest or the adjustment).
  double UsedSurroundingsThreshold = 0.0;
  double UsedPlaneDistanceThreshold = 0.0;
  /// The adjustment's length unit L (0 without the adjustment).
  double UsedLengthUnit = 0.0;
  std::int64_t NumberOfUnestimatedPoints = 0;
  /// The same points by reason (they add up to NumberOfUnestimatedPoints).
  UnestimatedCounts UnestimatedByReason{};
  /// The c of CurvatureBuffers::ClippedMean (0 when nothing is estimated,
  /// or without that buffer).
  double MeanCurvatureClip = 0.0;
  /// What CurvatureBuffers::Trusted compares the standard errors with
  /// (1/length): the larger of the 95th percentile of max(|k_min|, |k_max|)
  /// and a quarter of one over the median neighbourhood radius, over the estimated
  /// points of every process (0 without that buffer).
  double TrustedCurvatureScale = 0.0;
  /// Points that repeat another exactly (coordinates and normal): estimated
  /// once, every copy given the same results, counted once as a neighbour.
  std::int64_t NumberOfRepeatedPoints = 0;
  /// The adjustment's target counts as used: within [1, 1e6] (NaN: 1).
  std::array<double, 3> TargetNeighborCounts{ { 0.0, 0.0, 0.0 } };
  bool TargetCountsClamped = false;
  /// With EstimateNormals: connected parts oriented, and points whose
  /// normal could not be determined.
  NormalSummary Normals;
  /// NeighborhoodMode::Automatic with shared fits: the points estimated
  /// from anchors' fits rather than their own (EstimationSettings::ShareFits).
  std::int64_t NumberOfSharedPoints = 0;
  /// NeighborhoodMode::Automatic: the points whose estimate is a height
  /// jet's (positions with little or no noise; HeightJet.h).
  std::int64_t NumberOfJetPoints = 0;
  /// Whether the automatic scale also fitted the surface's fourth order at
  /// its wide radii (the normals follow the surface closely).
  bool FourthOrderFits = false;
  /// The caller asked to stop: the buffers are incomplete.
  bool Aborted = false;
};

/// The curvatures of every input point of `cloud` (consumed: it is scaled
/// and given a halo), written to `out`. The same results for any runner,
/// thread count or split of the cloud among processes.
EstimationSummary EstimateCloud(CloudPoints cloud,
  const EstimationSettings& settings,
  const Collectives& processes,
  WorkRunner& runner,
  ProgressMonitor* monitor,
  const CurvatureBuffers& out);

/// The normals of every input point of `cloud` alone (NormalEstimation.h),
/// written to `out` (3 per input point, zero where undetermined or the
/// coordinates are not finite); the same for any runner or split. With a
/// monitor that asks to stop, the summary says Aborted and `out` is
/// incomplete.
NormalSummary EstimateCloudNormals(CloudPoints cloud,
  const NormalSettings& settings,
  const Collectives& processes,
  WorkRunner& runner,
  const RealBuffer& out,
  ProgressMonitor* monitor = nullptr);

} // namespace pcurv

#endif
