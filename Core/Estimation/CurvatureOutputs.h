/**
 * @file CurvatureOutputs.h
 * @brief Where an estimation writes each point's results (the caller's
 * buffers), and what it reports of the whole cloud. No VTK.
 */
#ifndef CurvatureOutputs_h
#define CurvatureOutputs_h

#include "Common/RealBuffer.h"
#include "Fits/FitResults.h"
#include "Normals/NormalSummary.h"

#include <array>
#include <cstdint>

namespace pcurv
{

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
  /// color map over its range shows the surface's structure, not a few
  /// outliers, and is centered on 0 (flat).
  RealBuffer ClippedMean = nullptr;
  /// With FitMode::OrientedCircles only (may be null): the standard error
  /// of the curvatures, 1/length: it covers the fit's variance, the bias
  /// of the chosen neighborhood and the normals' errors, calibrated so
  /// that most errors are within twice it (docs/output-arrays.md).
  RealBuffer StandardError = nullptr;
  /// With FitMode::OrientedCircles only (may be null): 1 where the point is
  /// estimated, not an outlier, and twice its standard error is within a
  /// third of its largest |curvature| or a tenth of the cloud's curvature
  /// scale (EstimationSummary::TrustedCurvatureScale; IsTrusted).
  unsigned char* Trusted = nullptr;
  /// With FitMode::OrientedCircles only (may be null): the point's
  /// pcurv::ShapeClass, from the signs of its curvatures that differ from
  /// zero significantly against its standard error (ClassifyShape).
  unsigned char* ShapeClass = nullptr;
  /// With FitMode::OrientedCircles only (may be null): the fitted
  /// surface's unit normal, 3 per point, to which the directions are
  /// tangent (zero where not estimated).
  RealBuffer FittedNormal = nullptr;
  /// With FitMode::OrientedCircles and MoveOutliers only (may be null): 1
  /// where the point lies off the surface its neighbors sample, far beyond
  /// the noise there (its results are the nearest surface's), and every
  /// point's distance to that surface (NaN where the cloud is too small
  /// to fit one), length.
  unsigned char* Outlier = nullptr;
  RealBuffer SurfaceDistance = nullptr;
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
  /// The cloud's curvature scale, a tenth of which bounds twice the
  /// standard error of a trusted point whose curvatures are small
  /// (CurvatureBuffers::Trusted; 1/length): the larger of the 95th
  /// percentile of max(|k_min|, |k_max|) and a quarter of one over the
  /// median neighborhood radius, over the estimated points of every
  /// process (0 without the Trusted or ShapeClass buffer).
  double TrustedCurvatureScale = 0.0;
  /// Points that repeat another exactly (coordinates and normal): estimated
  /// once, every copy given the same results, counted once as a neighbor.
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
  /// Points flagged and moved onto the surface (CurvatureBuffers::Outlier).
  std::int64_t NumberOfOutliers = 0;
  /// Whether the automatic scale also fitted the surface's fourth order at
  /// its wide radii (the normals follow the surface closely).
  bool FourthOrderFits = false;
  /// The given normals disagreed with the positions beyond their noise
  /// (GivenNormals.h): estimated ones, signed as given, were used instead.
  bool GivenNormalsReplaced = false;
  /// The caller asked to stop: the buffers are incomplete.
  bool Aborted = false;
};

} // namespace pcurv

#endif
