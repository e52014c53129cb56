#include "Scale/AutomaticScale.h"

#include "Scale/SimplestOrder.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace pcurv
{
namespace
{
/// NormalFollowsSurface's bound on the fitted tilt's square over the one
/// the point's displacement along the surface explains: on the shared
/// accuracy suite the median ratio is 0.2-1.1 with exact normals and 5-600
/// with PCA normals (at noise 0.1 and 0.5 spacings), and this is about
/// their geometric mean.
constexpr double NormalTiltAllowance = 2.4;
/// NormalFollowsSurface's radius, in first radii.
constexpr double NormalTestRadius = 4.0;
/// Jets are tried where the ladder reached its precision within its first
/// three radii (up to twice the first, about 64 neighbors): where noise
/// grows it further, or where its growth stopped for want of agreement
/// early (a feature, a thin part), a jet of a few neighbors is far less
/// precise or no more right.
constexpr double JetTrialRadius = 2.0;

/// FirstFourthOrderLevel where no level fits the fourth order.
constexpr int NoFourthOrder = std::numeric_limits<int>::max();

/// The first level of the ladder fitted at the fourth order too. Where the
/// normals were given, the first: their rows determine the fourth order's
/// 15 unknowns among a few neighbors, and at the smallest radii it removes
/// the bias where the curvature is high or varies fast. Where they were
/// estimated, four first radii (about 256 neighbors), and only where they
/// follow the surface (AutomaticScaleRule::FourthOrder): the positions
/// alone determine its unknowns poorly among fewer where the sampling is
/// uneven (scan lines), and the extra unknowns take up the errors that
/// estimated normals share with their neighbors; none (NoFourthOrder)
/// where estimated normals do not follow the surface.
int FirstFourthOrderLevel(const AutomaticScaleRule& rule)
{
  if (!rule.EstimatedNormals)
  {
    return 0;
  }
  return rule.FourthOrder ? 4 : NoFourthOrder;
}

/// A fit of the fourth order's sums (of any order) whose neighborhood the
/// surface turns through more than a radian across (radius times the
/// largest |curvature|, less `tolerance` of its standard errors, so that a
/// curvature noise makes large among a few neighbors does not end the
/// growth): a height over the tangent plane, even of the fourth order, no
/// longer follows it there (an ellipsoid's tips, a thin torus's tube), and
/// its covariance does not show it. The precise combined fit would show
/// that bias against smaller radii, but the ladder compares radii by the
/// positions-only error, within which it hides.
bool TurnsTooFar(const OrientedCircleResult& fit, double radius, double tolerance)
{
  const PointCurvature& k = fit.Curvature;
  const double largest = std::max(std::fabs(k.MinimumCurvature), std::fabs(k.MaximumCurvature));
  return (fit.Order == 4 || fit.CombinedCovariance) &&
    radius * (largest - tolerance * fit.StandardError) > 1.0;
}

/// `fit`'s standard error at a noise variance of `smallerNoise` where its
/// own residual's is larger: a residual that grows with the radius beyond
/// the noise a smaller radius measured is the surface leaving the fit's
/// model (a crease, a fold), and must not widen the band by which that
/// radius is judged against the smaller (both variances are in units of the
/// same first radius).
double NoiseOnlyError(const OrientedCircleResult& fit, double smallerNoise)
{
  const double own = fit.Surface.NoiseVariance;
  return own > smallerNoise ? fit.StandardError * std::sqrt(smallerNoise / own) : fit.StandardError;
}

/// The variance (length squared) along `normal` that rounding the
/// coordinates to their lattice adds: uniform over a step per axis.
double RoundingVariance(const std::array<double, 3>& step, const Vector3& normal)
{
  double variance = 0.0;
  for (int k = 0; k < 3; ++k)
  {
    variance += normal[k] * normal[k] * step[k] * step[k] / 12.0;
  }
  return variance;
}

/// The fit of the sums so far into `result`; false (no fit) where the
/// neighborhood reaches across the surface.
template<int Order>
bool FitSums(OrientedCircleAccumulatorOf<Order>& accumulator,
  const TangentFrame& frame,
  double inverseUnit,
  double roundingVariance,
  const FitSettings& settings,
  OrientedCircleResult& result)
{
  const OrientedCircleSumsOf<Order>& sums = accumulator.Sums();
  if (sums.ReachesAcross(settings.MaximumOpposingFraction))
  {
    return false;
  }
  result = FitOrientedCircles(sums,
    frame,
    inverseUnit,
    roundingVariance,
    settings.MinimumPointsPerDirection,
    settings.MaximumOpposingFraction);
  return true;
}
} // namespace

/// Estimate's ladder of oriented circles at one point: the point's frame
/// and radius unit, the sums grown shell by shell, and the fits kept.
struct AutomaticScaleEstimator::CircleLadder
{
  CircleLadder(const AutomaticScaleEstimator& estimator,
    const double* x,
    double unit,
    const TangentFrame& frame,
    AutomaticScaleScratch& scratch)
    : Estimator(estimator)
    , Rule(estimator.Rule)
    , Scratch(scratch)
    , X(x)
    , Unit(unit)
    , InverseUnit(1.0 / unit)
    , Frame(frame)
    , Rounding(RoundingVariance(estimator.Rule.CoordinateStep, frame.Normal))
    , QuarticLevel(FirstFourthOrderLevel(estimator.Rule))
    , Accepted(scratch.Scales)
  {
    scratch.Sums.Begin(frame);
    this->Accepted.clear();
  }

  /// Grows the sums to the radius `r` of `level` and fits them into
  /// `result`; false (no fit) where the neighborhood reaches across.
  bool Fit(int level, double r, OrientedCircleResult& result)
  {
    AutomaticScaleScratch& scratch = this->Scratch;
    OrientedCircleAccumulator& accumulator = scratch.Sums;
    QuarticCircleAccumulator& quartic = scratch.QuarticSums;
    if (level >= this->QuarticLevel && !this->FourthOrder)
    {
      // The inner radii's neighbors again, into the fourth order's sums.
      this->FourthOrder = true;
      quartic.Begin(this->Frame);
      this->Estimator.Grid.GatherShell(this->X, 0.0, this->Inner, scratch.Shell);
      this->Estimator.AddShell(scratch.Shell, this->InverseUnit, quartic);
    }
    // The inner radii's neighbors are in the sums already.
    this->Estimator.GatherLevel(this->X, this->Inner, r, scratch);
    if (this->FourthOrder)
    {
      this->Estimator.AddShell(scratch.Shell, this->InverseUnit, quartic);
    }
    else
    {
      this->Estimator.AddShell(scratch.Shell, this->InverseUnit, accumulator);
    }
    this->Inner = r;
    auto fitSimplest = [&](auto& sums)
    {
      return FitSimplestOrder(sums,
        this->Frame,
        this->InverseUnit,
        this->Rounding,
        this->Estimator.Settings,
        this->Rule.EstimatedNormals,
        result);
    };
    return this->FourthOrder ? fitSimplest(quartic) : fitSimplest(accumulator);
  }

  /// Judges the fit `result` at `r` by Lepski's rule and keeps it where it
  /// passes; false where the growth ends there.
  bool Judge(const OrientedCircleResult& result, double r)
  {
    const AutomaticScaleRule& rule = this->Rule;
    const int neighbors = result.Curvature.NeighborCount;
    this->Reason = result.Curvature.Valid
      ? UnestimatedReason::TooFewNeighbors
      : UnestimatedReasonOf(result.Curvature, this->Estimator.Settings.MinimumPointsPerDirection);
    if (result.Curvature.Valid && neighbors >= rule.MinimumCount)
    {
      // Where even the first radius turns too far, its fit is the best
      // the sampling allows.
      if (!AgreesWithSmaller(result, this->Accepted, rule.Tolerance) ||
        (TurnsTooFar(result, r, rule.Tolerance) && !this->Accepted.empty()))
      {
        return false;
      }
      this->Accepted.push_back(result);
      this->Chosen = result;
      this->ChosenRadius = r;
      // More neighbors would not change the estimate measurably: done.
      const double magnitude = std::max({ std::fabs(result.Curvature.MinimumCurvature),
        std::fabs(result.Curvature.MaximumCurvature),
        1.0 / r });
      if (result.StandardError < rule.Precision * magnitude)
      {
        this->Precise = true;
        this->Probing =
          rule.EstimatedNormals && this->Accepted.size() == 1 && r < rule.LargestRadius;
        return this->Probing;
      }
    }
    if (r >= rule.LargestRadius)
    {
      return false;
    }
    return true;
  }

  /// The chosen radius's estimate, or the height jet's where that is the
  /// better (PreferJet).
  ScaleEstimate Estimate()
  {
    if (!this->Chosen.Curvature.Valid)
    {
      this->Chosen.Curvature.Reason = this->Reason;
    }
    const OrientedCircleResult& chosen = this->Chosen;
    // The radius before the chosen one tells how much the growth moved
    // the estimate: the bias it may have added; at the first radius, the
    // one after it.
    const std::vector<OrientedCircleResult>& accepted = this->Accepted;
    const OrientedCircleResult* previous = accepted.size() >= 2 ? &accepted[accepted.size() - 2]
      : this->Beyond.Curvature.Valid                            ? &this->Beyond
                                                                : nullptr;
    ScaleEstimate estimate{
      chosen, this->ChosenRadius, ReportedStandardError(chosen, previous, this->Rule.Precision)
    };
    if (this->Precise && this->ChosenRadius <= JetTrialRadius * this->Unit)
    {
      this->Estimator.PreferJet(this->X,
        this->Frame,
        this->Unit,
        this->Rounding,
        ReportedStandardError(chosen, previous, 0.0),
        this->Scratch,
        estimate);
    }
    return estimate;
  }

  const AutomaticScaleEstimator& Estimator;
  const AutomaticScaleRule& Rule;
  AutomaticScaleScratch& Scratch;
  const double* X;
  const double Unit;
  const double InverseUnit;
  const TangentFrame Frame;
  /// The coordinates' rounding along the normal (RoundingVariance).
  const double Rounding;
  /// The fourth order's sums, from the first radius that fits it on
  /// (instead of the third's).
  const int QuarticLevel;
  bool FourthOrder = false;
  OrientedCircleResult Chosen;
  double ChosenRadius = std::numeric_limits<double>::quiet_NaN();
  std::vector<OrientedCircleResult>& Accepted;
  UnestimatedReason Reason = UnestimatedReason::TooFewNeighbors;
  double Inner = 0.0;
  /// Whether the growth ended by the precision stop.
  bool Precise = false;
  /// Where the precision stop came at the first radius kept, the fit of the
  /// radius after it: no smaller radius shows the bias of the first one's
  /// truncation, and that bias grows with the radius (with its square at
  /// the third order), so the next radius's difference is about the first
  /// one's own. Only where the normals were estimated: given ones fit the
  /// fourth order at the first radius already, whose combined error covers
  /// its smaller bias, and there the extra fit would add a fit of the fourth
  /// order's sums at every point of a clean cloud.
  bool Probing = false;
  /// The fit of the radius after the first kept, where Probing.
  OrientedCircleResult Beyond;
};

ScaleEstimate AutomaticScaleEstimator::Estimate(std::int64_t point,
  AutomaticScaleScratch& scratch) const
{
  if (this->Rule.NormalField)
  {
    ScaleEstimate field;
    if (this->EstimateNormalField(point, scratch, field))
    {
      return field;
    }
  }
  const double* x = &this->Cloud.Coordinates[3 * point];
  const double* n = &this->Cloud.Normals[3 * point];
  const AutomaticScaleRule& rule = this->Rule;
  const double unit =
    std::nextafter(std::min(this->FirstRadius(x, scratch), rule.LargestRadius), HUGE_VAL);
  const TangentFrame frame = MakeTangentFrame({ { n[0], n[1], n[2] } });
  CircleLadder ladder(*this, x, unit, frame, scratch);
  for (int level = 0; level < rule.Levels; ++level)
  {
    const double r = std::min(unit * std::pow(2.0, 0.5 * level), rule.LargestRadius);
    OrientedCircleResult result;
    if (!ladder.Fit(level, r, result))
    {
      ladder.Reason = UnestimatedReason::ReachesAcross;
      break;
    }
    result.EstimatedNormals = rule.EstimatedNormals;
    if (ladder.Probing)
    {
      ladder.Beyond = result;
      break;
    }
    if (!ladder.Judge(result, r))
    {
      break;
    }
  }
  return ladder.Estimate();
}

int AutomaticScaleEstimator::NormalFollowsSurface(std::int64_t point,
  AutomaticScaleScratch& scratch) const
{
  const double* x = &this->Cloud.Coordinates[3 * point];
  const double* n = &this->Cloud.Normals[3 * point];
  if (n[0] == 0.0 && n[1] == 0.0 && n[2] == 0.0)
  {
    return -1;
  }
  const double r = std::nextafter(
    std::min(NormalTestRadius * this->FirstRadius(x, scratch), this->Rule.LargestRadius), HUGE_VAL);
  if (!(r > 0.0) || !std::isfinite(r))
  {
    return -1;
  }
  const double inverseRadius = 1.0 / r;
  const TangentFrame frame = MakeTangentFrame({ { n[0], n[1], n[2] } });
  const double roundingVariance = RoundingVariance(this->Rule.CoordinateStep, frame.Normal);
  OrientedCircleAccumulator& accumulator = scratch.Sums;
  accumulator.Begin(frame);
  this->Grid.GatherShell(x, 0.0, r, scratch.Shell);
  this->AddShell(scratch.Shell, inverseRadius, accumulator);
  OrientedCircleResult result;
  if (!FitSums(accumulator, frame, inverseRadius, roundingVariance, this->Settings, result) ||
    !result.Curvature.Valid)
  {
    return -1;
  }
  // In units of the radius: the tilt is a slope, the displacement's is
  // the noise variance times the squared curvatures (FittedFrame).
  const std::array<double, 15>& c = result.Surface.Coefficients;
  const double tilt = c[3] * c[3] + c[4] * c[4];
  const double amplitude = std::hypot(c[1], c[2]);
  const double k1 = c[0] + amplitude, k2 = c[0] - amplitude;
  const double displacement = result.Surface.NoiseVariance * (k1 * k1 + k2 * k2);
  return tilt <= NormalTiltAllowance * displacement ? 1 : 0;
}

bool AutomaticScaleEstimator::AgreesWithSmaller(const OrientedCircleResult& candidate,
  const std::vector<OrientedCircleResult>& smaller,
  double tolerance)
{
  for (const OrientedCircleResult& other : smaller)
  {
    const double allowed =
      tolerance * (other.StandardError + NoiseOnlyError(candidate, other.Surface.NoiseVariance));
    if (std::fabs(candidate.Curvature.MinimumCurvature - other.Curvature.MinimumCurvature) >
        allowed ||
      std::fabs(candidate.Curvature.MaximumCurvature - other.Curvature.MaximumCurvature) > allowed)
    {
      return false;
    }
  }
  return true;
}

} // namespace pcurv
