#include "Scale/AutomaticScale.h"

#include "Fits/HeightJet.h"
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
/// The jet's neighbors (the point among them): few, for the smallest
/// radius and so the smallest bias, yet some above its 15 unknowns.
constexpr int JetCount = 20;
/// The jet's standard error over its residual's: the truncation that makes
/// the residual where positions have no noise biases the curvatures too,
/// by about as much and of one sign over a neighborhood, which the
/// residual's covariance does not show. Calibrated on the shared accuracy
/// suite's noise-free clouds (a bias estimated from a second, wider jet
/// covered as well and cost twice the time).
constexpr double JetBiasFactor = 3.0;
/// The jet's agreement with the ladder: within this many times the
/// ladder's own tolerance (PreferJet).
constexpr double JetAgreement = 2.0;
/// The most the jet's disagreement may raise the ladder's error by, as a
/// factor (PreferJet): on the shared accuracy suite's noise-free clouds,
/// where the jet was right and its error not below the ladder's, the
/// ladder's real error was about 4 times its reported one (the median).
constexpr double LadderBiasAllowance = 3.0;
/// How far the jet's neighbors may reach, in first radii, where that is
/// beyond the largest radius (the first radius is then about the largest).
constexpr double JetReach = 1.3;

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

/// The nearest points whose squared distance is below `limit`, in their
/// order (a shell's), into `out`; returns their count. Branch-free: which
/// side of the limit a point falls on is not predictable.
std::size_t KeepNearerThan(const NearestPoints& nearest, double limit, ShellPoints& out)
{
  const ShellPoints& from = nearest.Points;
  if (out.Dx.size() < from.Count)
  {
    for (std::vector<double>* axis : { &out.Dx, &out.Dy, &out.Dz })
    {
      axis->resize(from.Count);
    }
    out.Ids.resize(from.Count);
  }
  std::size_t count = 0;
  for (std::size_t i = 0; i < from.Count; ++i)
  {
    out.Dx[count] = from.Dx[i];
    out.Dy[count] = from.Dy[i];
    out.Dz[count] = from.Dz[i];
    out.Ids[count] = from.Ids[i];
    count += nearest.Squared[i] < limit;
  }
  out.Count = count;
  return count;
}
} // namespace

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
  const double inverseUnit = 1.0 / unit;
  const TangentFrame frame = MakeTangentFrame({ { n[0], n[1], n[2] } });
  const double roundingVariance = RoundingVariance(rule.CoordinateStep, frame.Normal);
  OrientedCircleAccumulator& accumulator = scratch.Sums;
  accumulator.Begin(frame);
  // The fourth order's sums, from the first radius that fits it on
  // (instead of the third's).
  QuarticCircleAccumulator& quartic = scratch.QuarticSums;
  const int quarticLevel = FirstFourthOrderLevel(rule);
  bool fourthOrder = false;
  OrientedCircleResult chosen;
  double chosenRadius = std::numeric_limits<double>::quiet_NaN();
  std::vector<OrientedCircleResult>& accepted = scratch.Scales;
  accepted.clear();
  UnestimatedReason reason = UnestimatedReason::TooFewNeighbors;
  double inner = 0.0;
  // Whether the growth ended by the precision stop.
  bool precise = false;
  // Where the precision stop came at the first radius kept, the fit of the
  // radius after it: no smaller radius shows the bias of the first one's
  // truncation, and that bias grows with the radius (with its square at
  // the third order), so the next radius's difference is about the first
  // one's own. Only where the normals were estimated: given ones fit the
  // fourth order at the first radius already, whose combined error covers
  // its smaller bias, and there the extra fit would add a fit of the fourth
  // order's sums at every point of a clean cloud.
  bool probing = false;
  OrientedCircleResult beyond;
  for (int level = 0; level < rule.Levels; ++level)
  {
    const double r = std::min(unit * std::pow(2.0, 0.5 * level), rule.LargestRadius);
    if (level >= quarticLevel && !fourthOrder)
    {
      // The inner radii's neighbors again, into the fourth order's sums.
      fourthOrder = true;
      quartic.Begin(frame);
      this->Grid.GatherShell(x, 0.0, inner, scratch.Shell);
      this->AddShell(scratch.Shell, inverseUnit, quartic);
    }
    // The inner radii's neighbors are in the sums already.
    this->GatherLevel(x, inner, r, scratch);
    if (fourthOrder)
    {
      this->AddShell(scratch.Shell, inverseUnit, quartic);
    }
    else
    {
      this->AddShell(scratch.Shell, inverseUnit, accumulator);
    }
    inner = r;
    OrientedCircleResult result;
    auto fitSimplest = [&](auto& sums)
    {
      return FitSimplestOrder(
        sums, frame, inverseUnit, roundingVariance, this->Settings, rule.EstimatedNormals, result);
    };
    const bool fitted = fourthOrder ? fitSimplest(quartic) : fitSimplest(accumulator);
    if (!fitted)
    {
      reason = UnestimatedReason::ReachesAcross;
      break;
    }
    result.EstimatedNormals = rule.EstimatedNormals;
    if (probing)
    {
      beyond = result;
      break;
    }
    const int neighbors = result.Curvature.NeighborCount;
    reason = result.Curvature.Valid
      ? UnestimatedReason::TooFewNeighbors
      : UnestimatedReasonOf(result.Curvature, this->Settings.MinimumPointsPerDirection);
    if (result.Curvature.Valid && neighbors >= rule.MinimumCount)
    {
      // Where even the first radius turns too far, its fit is the best
      // the sampling allows.
      if (!AgreesWithSmaller(result, accepted, rule.Tolerance) ||
        (TurnsTooFar(result, r, rule.Tolerance) && !accepted.empty()))
      {
        break;
      }
      accepted.push_back(result);
      chosen = result;
      chosenRadius = r;
      // More neighbors would not change the estimate measurably: done.
      const double magnitude = std::max({ std::fabs(result.Curvature.MinimumCurvature),
        std::fabs(result.Curvature.MaximumCurvature),
        1.0 / r });
      if (result.StandardError < rule.Precision * magnitude)
      {
        precise = true;
        probing = rule.EstimatedNormals && accepted.size() == 1 && r < rule.LargestRadius;
        if (!probing)
        {
          break;
        }
        continue;
      }
    }
    if (r >= rule.LargestRadius)
    {
      break;
    }
  }
  if (!chosen.Curvature.Valid)
  {
    chosen.Curvature.Reason = reason;
  }
  // The radius before the chosen one tells how much the growth moved
  // the estimate: the bias it may have added; at the first radius, the one
  // after it.
  const OrientedCircleResult* previous = accepted.size() >= 2 ? &accepted[accepted.size() - 2]
    : beyond.Curvature.Valid                                  ? &beyond
                                                              : nullptr;
  ScaleEstimate estimate{
    chosen, chosenRadius, ReportedStandardError(chosen, previous, rule.Precision)
  };
  if (precise && chosenRadius <= JetTrialRadius * unit)
  {
    this->PreferJet(x,
      frame,
      unit,
      roundingVariance,
      ReportedStandardError(chosen, previous, 0.0),
      scratch,
      estimate);
  }
  return estimate;
}

void AutomaticScaleEstimator::PreferJet(const double* x,
  const TangentFrame& frame,
  double firstRadius,
  double roundingVariance,
  double ladderError,
  AutomaticScaleScratch& scratch,
  ScaleEstimate& estimate) const
{
  // The JetCount nearest and all as near as the last of them (a regular
  // grid has many such ties), in the grid's order (the same on every
  // process), from the nearest points FirstRadius gathered: they hold
  // every point as near as their JetCount-th.
  const NearestPoints& nearest = scratch.Nearest;
  if (!(nearest.Radius > 0.0) || nearest.Points.Count < static_cast<std::size_t>(JetCount))
  {
    return;
  }
  const double limit = nearest.JetCountSquared;
  // Within the largest radius, or JetReach first radii where the first is
  // about the largest already.
  const double reach = std::max(JetReach * firstRadius, this->Rule.LargestRadius);
  if (!(limit < reach * reach))
  {
    return;
  }
  // As near as the limit or nearer (below the next number up).
  ShellPoints& neighbors = scratch.Jet;
  const std::size_t count = KeepNearerThan(nearest, std::nextafter(limit, HUGE_VAL), neighbors);
  // The other points among them (the estimate's neighbor count).
  const int others = static_cast<int>(std::count_if(nearest.Squared.begin(),
    nearest.Squared.end(),
    [limit](double squared) { return squared > 0.0 && squared <= limit; }));
  const double radius = std::sqrt(limit);
  // Over the neighbors' own plane: there the heights, and with them the
  // terms the quartic leaves out, are the smallest (a given normal, even
  // an exact one, tilts against an uneven neighborhood).
  const TangentFrame plane = MakeTangentFrame(NeighborhoodPlaneNormal(
    neighbors.Dx.data(), neighbors.Dy.data(), neighbors.Dz.data(), count, radius, frame.Normal));
  const HeightJetFit jet = FitHeightJet(neighbors.Dx.data(),
    neighbors.Dy.data(),
    neighbors.Dz.data(),
    count,
    plane,
    radius,
    roundingVariance);
  if (!jet.Curvature.Valid)
  {
    return;
  }
  const double error = ReportedErrorFactor * JetBiasFactor * jet.StandardError;
  const PointCurvature& near = jet.Curvature;
  // As precise as the ladder's precision stop asks (its error below
  // Precision times the curvature or the inverse radius), or the
  // positions have some noise after all, which the jet's few neighbors
  // do not average (a fifth of a spacing's thousandth already puts some
  // jets 20 % off).
  const double magnitude =
    std::max({ std::fabs(near.MinimumCurvature), std::fabs(near.MaximumCurvature), 1.0 / radius });
  if (!(error < this->Rule.Precision * magnitude))
  {
    return;
  }
  const PointCurvature& ladder = estimate.Fit.Curvature;
  const double difference = std::max(std::fabs(near.MinimumCurvature - ladder.MinimumCurvature),
    std::fabs(near.MaximumCurvature - ladder.MaximumCurvature));
  // The ladder's error at its first radius leaves out the bias of its
  // truncation (no smaller radius to compare with); the jet, of a higher
  // order, shows it: where the two differ by more than the jet's error,
  // the ladder is off by at least the excess, but by no more than
  // LadderBiasAllowance times its error (a jet whose few neighbors barely
  // determine it, on the rings of a latitude-longitude grid's pole, can
  // differ by far more with a small error). The jet is taken where its
  // error is the smaller.
  const double ladderAtLeast =
    std::max(ladderError, std::min(difference - error, LadderBiasAllowance * ladderError));
  if (!(error < ladderAtLeast))
  {
    return;
  }
  // Lepski's test against the ladder's estimate, at twice its tolerance:
  // a residual of a few degrees of freedom can be small by chance where
  // the positions do have noise, and such a jet is off by many times both
  // errors; at its first radius the ladder's own error misses the bias
  // where the curvature varies fast (an ellipsoid's tips), where the jet
  // is right.
  const double allowed = JetAgreement * this->Rule.Tolerance * (error + estimate.Error);
  if (difference > allowed)
  {
    return;
  }
  PointCurvature& out = estimate.Fit.Curvature;
  out.MinimumCurvature = near.MinimumCurvature;
  out.MaximumCurvature = near.MaximumCurvature;
  out.MinimumDirection = near.MinimumDirection;
  out.MaximumDirection = near.MaximumDirection;
  out.FittedNormal = near.FittedNormal;
  // The neighbors, as the ladder counts them: the other points, those
  // strictly within the radius.
  out.NeighborCount = others;
  estimate.Radius = std::nextafter(radius, HUGE_VAL);
  estimate.Error = error;
  estimate.Jet = true;
}

double AutomaticScaleEstimator::FirstRadius(const double* x, AutomaticScaleScratch& scratch) const
{
  // k + 1: the point itself is found too.
  const int k = this->Rule.BaseCount + 1;
  NearestPoints& nearest = scratch.Nearest;
  const ShellPoints& points = nearest.Points;
  nearest.Radius = this->Grid.GatherNearest(x, std::max(k, JetCount), nearest.Points);
  if (!(nearest.Radius > 0.0))
  {
    return std::sqrt(this->Grid.SquaredDistanceToKth(x, k, scratch.Distances));
  }
  std::vector<double>& squared = nearest.Squared;
  squared.resize(points.Count);
  for (std::size_t i = 0; i < points.Count; ++i)
  {
    // As the grid's gathers compute it.
    squared[i] =
      points.Dx[i] * points.Dx[i] + points.Dy[i] * points.Dy[i] + points.Dz[i] * points.Dz[i];
  }
  // Fewer points than k in the whole cloud: the farthest of them, as
  // SquaredDistanceToKth.
  const std::size_t first = std::min(static_cast<std::size_t>(k), points.Count);
  const std::size_t jet =
    std::min(std::max(first, static_cast<std::size_t>(JetCount)), points.Count);
  const std::array<double, 2> kth =
    SquaredDistanceRanks(squared, { first, jet }, nearest.Radius * nearest.Radius, nearest.Ranks);
  nearest.JetCountSquared = kth[1];
  return std::sqrt(kth[0]);
}

void AutomaticScaleEstimator::GatherLevel(const double* x,
  double inner,
  double radius,
  AutomaticScaleScratch& scratch) const
{
  // The nearest points hold every point within their radius, in
  // GatherShell's order.
  if (inner == 0.0 && radius < scratch.Nearest.Radius)
  {
    KeepNearerThan(scratch.Nearest, radius * radius, scratch.Shell);
  }
  else
  {
    this->Grid.GatherShell(x, inner, radius, scratch.Shell);
  }
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
