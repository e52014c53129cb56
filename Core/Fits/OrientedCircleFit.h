/**
 * @file OrientedCircleFit.h
 * @brief A fit beyond the paper, in its spirit: every neighbor q defines
 * the osculating circle through the query point x whose center lies on the
 * normal line (the paper's circle, for one point), and, through its normal
 * n_q, an oriented circle (one whose normal at q agrees with n_q). Both give
 * the normal curvature in q's direction; the sine of period pi of the paper,
 * kappa(phi) = C + A cos 2 phi + B sin 2 phi, is fitted to all of them at the
 * neighbors' own angles phi instead of 16 half planes. No VTK.
 *
 * In the tangent frame of x (paper sign, lengths in units of a scale):
 * with d = q - x, D = |d|^2, h = d . n, phi the angle of d's tangential part,
 * - position: the circle through x and q centered on the normal line has
 *   kappa D = 2 h exactly;
 * - normal: for an oriented circle (or sphere) -(n_q - n) . d = kappa D.
 * A tilt delta of the query normal adds delta . d to -(n_q - n) . d and
 * 2 delta . d to 2 h: two tangential unknowns absorb it, so a noisy query
 * normal (PCA normals) does not bias the curvatures. A query point a height
 * e off the surface (every point of a noisy scan is) adds -2 e to every
 * 2 h: the positions' rows have that height as an unknown. The surface's
 * cubic terms c(u, v) add 2 c to 2 h and, by Euler's rule for homogeneous
 * functions, 3 c to the normal term: both kinds of rows share their four
 * coefficients as unknowns, so that the circles fit the surface's second
 * order and not its third (which otherwise biases every curvature by an
 * amount growing with the radius, and the tilt). The two kinds of rows
 * are weighted by the inverse of their own residual variance, each kind
 * fitted alone first: positions dominate where the normals are poor,
 * normals where the positions are noisy (normals' errors grow like |d|,
 * their rows are weighted by 1 / D).
 *
 * Everything the fit needs is a sum over the neighbors (OrientedCircleSums),
 * so that a neighborhood can grow shell by shell, and the fit of every
 * radius on the way costs one small solve (the automatic scale).
 */
#ifndef OrientedCircleFit_h
#define OrientedCircleFit_h

#include "Fits/FitResults.h"
#include "Kernels/SimdKernels.h"

#include <algorithm>
#include <array>
#include <cstdint>

namespace pcurv
{

/// How many times the tilt that the query point's own displacement along
/// the surface explains the fitted tilt's square must exceed before the
/// directions are turned by it (the fitted frame's share of the tilt).
constexpr double DisplacementTiltAllowance = 8.0;

/// The share of a fitted tilt (squared, `tiltSquared`) that turns the
/// directions' plane: what the query point's displacement along the surface
/// (its squared tilt on average, `displacement`) does not explain
/// DisplacementTiltAllowance times over; 0 for no tilt.
inline double TiltShare(double tiltSquared, double displacement)
{
  return tiltSquared > 0.0
    ? std::max(0.0, 1.0 - DisplacementTiltAllowance * displacement / tiltSquared)
    : 0.0;
}

/// How much the reported standard error exceeds the root sum of squares of
/// its parts: calibrated on the shared accuracy suite (the parts are
/// estimates of errors, not their spread, and the positions' residual
/// variance has few degrees of freedom at small radii).
constexpr double ReportedErrorFactor = 1.5;

/// How much the combined fit's error exceeds its covariance's standard
/// error where the normals follow the surface (exact normals of a noisy
/// cloud): their rows' residuals are not independent noise alone (the
/// positions' noise moves both a row's target and its columns), so the
/// covariance understates the error; calibrated on the shared accuracy
/// suite. The reported error of a fourth-order fit (ReportedStandardError).
constexpr double CombinedErrorFactor = 4.0;

/// Whether the occupied eighths of 2 phi (bits) determine a sine of
/// period pi: at least three, the largest circular gap below a half-turn.
bool AnglesDetermineSine(std::uint32_t positions);

/// The frame of the fitted tangent plane, for the principal directions:
/// the query's `frame` turned by the share of the fitted tilt (tiltU,
/// tiltV) that the query point's displacement along the surface does not
/// explain (TiltShare), in units of the scale; `noiseVariance` is the
/// positions' along the normal, k1, k2 the principal curvatures.
TangentFrame FittedFrame(const TangentFrame& frame,
  double tiltU,
  double tiltV,
  double k1,
  double k2,
  double noiseVariance);

/// The least-squares sums of the neighbors added so far, in the frame of
/// the query point and in units of a fixed scale, for a fit of the
/// surface's terms up to `Order` (3: the cubic, 4: also the quartic; the
/// unknowns of oriented::Layout).
template<int Order>
struct OrientedCircleSumsOf : OrientedCircleTallies
{
  static constexpr int PositionUnknowns = oriented::Layout<Order>::PositionUnknowns;
  static constexpr int NormalUnknowns = oriented::Layout<Order>::NormalUnknowns;
  /// Upper triangles and right-hand sides of the positions' and the
  /// normals' normal equations.
  std::array<double, PositionUnknowns*(PositionUnknowns + 1) / 2> PositionMatrix{};
  std::array<double, PositionUnknowns> PositionRight{};
  std::array<double, NormalUnknowns*(NormalUnknowns + 1) / 2> NormalMatrix{};
  std::array<double, NormalUnknowns> NormalRight{};
};
using QuadraticCircleSums = OrientedCircleSumsOf<2>;
using OrientedCircleSums = OrientedCircleSumsOf<3>;
using QuarticCircleSums = OrientedCircleSumsOf<4>;

/// Adds neighbors to OrientedCircleSumsOf<Order> several at a time (eight
/// lanes of SimdKernels.h's oriented::AddNeighbors): Begin, Add per
/// neighbor, Sums whenever the sums so far are wanted. The same neighbors
/// in the same order give the same sums on every instruction set.
template<int Order>
class OrientedCircleAccumulatorOf
{
public:
  /// Starts afresh in the tangent frame of a query point.
  void Begin(const TangentFrame& frame);

  /// Adds a neighbor: its offset (in units of the scale) and its unit
  /// normal, or null or zero (the position alone is used). At the query
  /// point: ignored. A normal opposing the query's is turned first: scans'
  /// normals are often not consistently oriented, and a normal's line is
  /// what it tells.
  void Add(const double d[3], const double* normal)
  {
    for (int k = 0; k < 3; ++k)
    {
      this->Pending[k][this->PendingCount] = d[k];
      this->Pending[3 + k][this->PendingCount] = normal ? normal[k] : 0.0;
    }
    if (++this->PendingCount == Capacity)
    {
      this->AddPending();
    }
  }

  /// The sums of every neighbor added since Begin.
  const OrientedCircleSumsOf<Order>& Sums();

private:
  void AddPending();

  static constexpr int Capacity = 64;
  oriented::Frame Frame{};
  oriented::BankedSums<Order> Banked{};
  /// Offsets and normals not yet in Banked, one array per coordinate.
  std::array<std::array<double, Capacity>, 6> Pending{};
  int PendingCount = 0;
  OrientedCircleSumsOf<Order> Totals;
};
using OrientedCircleAccumulator = OrientedCircleAccumulatorOf<3>;
using QuarticCircleAccumulator = OrientedCircleAccumulatorOf<4>;

/// The standard error reported for `chosen`, 1/length: it covers what the
/// positions' covariance leaves out (OrientedCircleResult) and, where the
/// neighborhood grew (the automatic scale), the bias the chosen radius
/// adds over the radius before it (`previous`, or null). `precision`: the
/// relative precision below which the automatic scale stops growing (a
/// smaller error is not claimed). The sum is scaled by a factor calibrated
/// on the shared accuracy suite (docs/output-arrays.md gives its coverage).
double ReportedStandardError(const OrientedCircleResult& chosen,
  const OrientedCircleResult* previous,
  double precision);

/// Fits the sums; invalid with fewer than `minimumNeighbors` (at least the
/// positions' unknowns and two: 12 at order 3, 17 at order 4) neighbors,
/// angles within a closed half-turn of 2 phi, or a neighborhood that
/// reaches across the surface (ReachesAcross). CombinedStandardError only
/// with `combinedError` (else the positions-only fit's). The positions'
/// variance along the normal is taken as at least `heightVarianceFloor`
/// (length squared: what rounding the coordinates adds).
template<int Order>
OrientedCircleResult FitOrientedCircles(const OrientedCircleSumsOf<Order>& sums,
  const TangentFrame& frame,
  double inverseScale,
  double heightVarianceFloor,
  int minimumNeighbors,
  double maximumOpposing,
  bool combinedError = false);

/// The sums of a lower order's fit within those of a higher (its unknowns
/// are a subset of the higher's: the leading ones and the height).
template<int Lower, int Higher>
OrientedCircleSumsOf<Lower> LowerOrderPart(const OrientedCircleSumsOf<Higher>& sums);

/// The sums of the third order's fit within those of the fourth.
inline OrientedCircleSums ThirdOrderPart(const QuarticCircleSums& sums)
{
  return LowerOrderPart<3>(sums);
}

/// One query at one scale: Begin, AddNeighbor per neighbor, Estimate.
class OrientedCircleEstimator
{
public:
  /// Starts a query at a point with unit normal `unitNormal`; lengths are
  /// divided by `scale` (the neighborhood's radius, > 0).
  void Begin(const Vector3& unitNormal, double scale);

  /// Adds a neighbor by its offset q - x and its unit normal (zero: the
  /// position alone is used).
  void AddNeighbor(const double offset[3], const double normal[3]);

  OrientedCircleResult Estimate(int minimumNeighbors, double maximumOpposing)
  {
    return FitOrientedCircles(
      this->Sums.Sums(), this->Frame, this->InverseScale, 0.0, minimumNeighbors, maximumOpposing);
  }

private:
  TangentFrame Frame{};
  double InverseScale = 1.0;
  OrientedCircleAccumulator Sums;
};

} // namespace pcurv

#endif
