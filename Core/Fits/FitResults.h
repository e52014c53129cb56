/**
 * @file FitResults.h
 * @brief The vocabulary of the fits at one point: the fit modes, the
 * tangent frame, what one point's estimate holds and why a point has none,
 * and the surface the oriented circles fit. Types only, so that the fits,
 * the scale and the estimation name them without taking in each other.
 * No VTK.
 *
 * Sign convention: results (PointCurvature) are in the output sign,
 * positive where the surface bends away from the normal, so a sphere with
 * outward normals has k_min = k_max = +1/R.
 */
#ifndef FitResults_h
#define FitResults_h

#include <array>
#include <cstdint>

namespace pcurv
{

/// Number of half planes around the normal (the paper's 16 directions).
constexpr int NumberOfDirections = 16;

/// The three osculating-circle fits of the paper, and one beyond it.
enum class FitMode : int
{
  Previous = 0, ///< eigenvector of the smallest eigenvalue of B (Seibert et al.)
  New01 = 1,    ///< closed form from equations (2) and (3)
  New02 = 2,    ///< better of the closed forms from (1)+(2) and (2)+(3)
  /// Every neighbor's circle, from its position and its normal, fitted by
  /// the sine at the neighbors' own angles (OrientedCircleFit.h).
  OrientedCircles = 3
};

using Vector3 = std::array<double, 3>;

/// Orthonormal frame at a query point: normal n, first direction v0, w0 = n x v0.
struct TangentFrame
{
  Vector3 Normal;
  Vector3 V0;
  Vector3 W0;
};

/// Builds the frame; `unitNormal` must have length 1. v0 is n x e normalized,
/// with e the coordinate axis least aligned with n (deterministic, stable).
TangentFrame MakeTangentFrame(const Vector3& unitNormal);

/// Everything estimated at one point, output sign.
/// Why a point has no estimate (None where it has one).
enum class UnestimatedReason : std::uint8_t
{
  None = 0,
  /// A coordinate is NaN or infinite.
  BadCoordinate,
  /// The normal is zero or not finite (given so, or not determinable).
  NoNormal,
  /// Fewer neighbors than a fit needs.
  TooFewNeighbors,
  /// The neighbors do not surround the point: too few directions, or
  /// directions within half a turn.
  TooFewDirections,
  /// OrientedCircles: the neighborhood reaches across the surface
  /// (neighbors with opposing normals on another level).
  ReachesAcross,
  /// Any other failure of the fit (a singular system, a result beyond the
  /// double range).
  FitFailed,
  Count
};

struct PointCurvature
{
  bool Valid = false;
  double MinimumCurvature = 0.0;
  double MaximumCurvature = 0.0;
  Vector3 MinimumDirection{ { 0.0, 0.0, 0.0 } };
  Vector3 MaximumDirection{ { 0.0, 0.0, 0.0 } };
  /// FitMode::OrientedCircles: the unit normal of the fitted surface, to
  /// which the directions are tangent (zero with the paper's fits, whose
  /// directions are tangent to the given normal).
  Vector3 FittedNormal{ { 0.0, 0.0, 0.0 } };
  int NeighborCount = 0;
  int ValidDirections = 0;
  double SineFitRms = 0.0;
  /// Set where the fit knows better than UnestimatedReasonOf can tell.
  UnestimatedReason Reason = UnestimatedReason::None;
};

/// Why `r` has no estimate: its own reason, else told by its counts.
UnestimatedReason UnestimatedReasonOf(const PointCurvature& r, int minimumPointsPerDirection);

/// Settings of the per-point estimate that do not change between points.
struct FitSettings
{
  FitMode Mode = FitMode::New01;
  int MinimumPointsPerDirection = 3;
  /// A direction's points must reach this far along it, as a fraction of
  /// the neighborhood's size: points bunched near the query point (as
  /// where there is no surface around it, e.g. points on a line) do not
  /// determine a circle. Default 0.5.
  double MinimumDirectionExtent = 0.5;
  /// OrientedCircles: a point is not estimated when more of its neighbors
  /// than this fraction have a normal opposing its own.
  double MaximumOpposingFraction = 0.05;
};

/// What the sums of a neighborhood hold besides the normal equations'
/// matrices and right-hand sides: the same for every fit of the oriented
/// circles and of the normal field (OrientedCircleFit.h, NormalFieldFit.h).
struct OrientedCircleTallies
{
  /// The sums of the positions' and the normals' squared targets.
  double PositionTargets = 0.0, NormalTargets = 0.0;
  int Neighbors = 0;
  int NeighborsWithNormal = 0;
  /// Neighbors whose normal points against the query's, and the sums of
  /// the heights of those and of the others, and of D (all neighbors).
  int Opposing = 0;
  double OpposingHeights = 0.0, AgreeingHeights = 0.0, SquaredDistances = 0.0;
  double OpposingSquaredHeights = 0.0, AgreeingSquaredHeights = 0.0;
  /// Occupied sixteenths of the turn (phi), and eighths of 2 phi.
  std::uint32_t Sectors = 0;
  std::uint32_t HalfTurnPositions = 0;

  /// The neighborhood reaches across the surface (a thin part, two close
  /// sheets): more than the fraction `maximumOpposing` of the neighbors
  /// have a normal opposing the query's, and they lie on another level than
  /// the others (their mean heights differ by more than three standard
  /// errors of that difference, and by a twentieth of the RMS distance).
  /// Opposing normals on the query's own sheet are only inconsistently
  /// oriented normals.
  bool ReachesAcross(double maximumOpposing) const;

  /// Why a fit of these sums is not made (None where it is): fewer than
  /// `fewest` of `count` (the neighbors the fit's rows come from), a
  /// neighborhood that reaches across the surface, or angles that do not
  /// determine a sine of period pi (AnglesDetermineSine).
  UnestimatedReason WhyUnfit(int count, int fewest, double maximumOpposing) const;
};

/// The surface the combined fit describes, a height over the query
/// normal's tangent frame (MakeTangentFrame of that normal, not stored) in
/// units of the scale (u, v along V0, W0):
/// h = e + tu u + tv v + ((C + A) u^2 + 2 B u v + (C - A) v^2) / 2
///   + c30 u^3 + c21 u^2 v + c12 u v^2 + c03 v^3
///   + c40 u^4 + c31 u^3 v + c22 u^2 v^2 + c13 u v^3 + c04 v^4,
/// with Coefficients (C, A, B, tu, tv, c30, c21, c12, c03, 2 e, c40, c31,
/// c22, c13, c04), C, A, B in the paper's sign; the quartic ones are 0 for
/// a fit of the third order.
struct FittedSurface
{
  static constexpr int FirstQuarticCoefficient = 10;
  std::array<double, 15> Coefficients{};
  double InverseScale = 0.0;
  /// The positions' noise variance, in units of the scale squared.
  double NoiseVariance = 0.0;
  /// The coefficients are the oriented circles' (whose second order is
  /// that of circles through the query point, completed where the surface
  /// is evaluated elsewhere), not a height polynomial's (NormalFieldFit.h).
  bool Circles = true;
};

/// What the fit of some sums gives: the curvatures (output sign, in
/// 1/length after `inverseScale`), the positions-only fit's standard error
/// of them (the automatic scale compares radii by it: the positions' rows
/// are independent, the neighbors' estimated normals are not), and two
/// errors that no covariance shows, both in 1/length: how far the
/// positions-only fit's curvatures lie from the combined ones
/// (|d offset| + |d amplitude| of the sine), and the second-order error of
/// fitting in a frame tilted by the query normal's error (the fitted
/// tilt's square times the largest |curvature|), which the first-order tilt
/// unknowns leave.
struct OrientedCircleResult
{
  PointCurvature Curvature;
  /// The order of the surface's terms fitted: 3 or 4.
  int Order = 3;
  double StandardError = 0.0;
  /// The combined fit's own standard error of the curvatures (1/length),
  /// from its covariance: what telling a fit of the third order from one of
  /// the fourth compares (AutomaticScale), not what the scale grows by.
  double CombinedStandardError = 0.0;
  /// Whether CombinedStandardError is the combined fit's own (a fit with
  /// `combinedError`, made where the normals follow the surface).
  bool CombinedCovariance = false;
  /// Whether the normals were estimated from the positions: their errors
  /// are shared among neighbors, so the reported error is the
  /// positions-only fit's even where the combined covariance exists.
  bool EstimatedNormals = false;
  double PositionsDiscrepancy = 0.0;
  double TiltBias = 0.0;
  /// How far the curvatures move when the fit takes the surface's next
  /// order too (1/length; 0 where no richer fit was made): the model's
  /// bias, which no covariance shows (NormalFieldFit.h).
  double OrderDiscrepancy = 0.0;
  /// The fitted surface, for evaluating it elsewhere (SharedFits.h).
  FittedSurface Surface;
};

} // namespace pcurv

#endif
