#include "Scale/AutomaticScale.h"

#include "Fits/HeightJet.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace pcurv
{
namespace
{
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

/// The jet's neighbors among the nearest points: how many, how many of
/// them are other points, and the radius they reach.
struct JetNeighbors
{
  std::size_t Count = 0;
  int Others = 0;
  double Radius = 0.0;
};

/// The JetCount nearest and all as near as the last of them (a regular
/// grid has many such ties) into `neighbors`, in the grid's order (the
/// same on every process), from the nearest points FirstRadius gathered:
/// they hold every point as near as their JetCount-th. False where too few
/// were gathered or they reach beyond the jet's reach.
bool GatherJetNeighbors(const NearestPoints& nearest,
  double firstRadius,
  double largestRadius,
  ShellPoints& neighbors,
  JetNeighbors& jet)
{
  if (!(nearest.Radius > 0.0) || nearest.Points.Count < static_cast<std::size_t>(JetCount))
  {
    return false;
  }
  const double limit = nearest.JetCountSquared;
  // Within the largest radius, or JetReach first radii where the first is
  // about the largest already.
  const double reach = std::max(JetReach * firstRadius, largestRadius);
  if (!(limit < reach * reach))
  {
    return false;
  }
  // As near as the limit or nearer (below the next number up).
  jet.Count = KeepNearerThan(nearest, std::nextafter(limit, HUGE_VAL), neighbors);
  // The other points among them (the estimate's neighbor count).
  jet.Others = static_cast<int>(std::count_if(nearest.Squared.begin(),
    nearest.Squared.end(),
    [limit](double squared) { return squared > 0.0 && squared <= limit; }));
  jet.Radius = std::sqrt(limit);
  return true;
}

/// Whether the jet `near` at `radius`, of error `error`, replaces the
/// ladder's `estimate` (of error `ladderError` without the precision
/// floor): precise enough, of the smaller error, and agreeing with it.
bool JetReplacesLadder(const PointCurvature& near,
  double radius,
  double error,
  double ladderError,
  const ScaleEstimate& estimate,
  const AutomaticScaleRule& rule)
{
  // As precise as the ladder's precision stop asks (its error below
  // Precision times the curvature or the inverse radius), or the
  // positions have some noise after all, which the jet's few neighbors
  // do not average (a fifth of a spacing's thousandth already puts some
  // jets 20 % off).
  const double magnitude =
    std::max({ std::fabs(near.MinimumCurvature), std::fabs(near.MaximumCurvature), 1.0 / radius });
  if (!(error < rule.Precision * magnitude))
  {
    return false;
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
    return false;
  }
  // Lepski's test against the ladder's estimate, at twice its tolerance:
  // a residual of a few degrees of freedom can be small by chance where
  // the positions do have noise, and such a jet is off by many times both
  // errors; at its first radius the ladder's own error misses the bias
  // where the curvature varies fast (an ellipsoid's tips), where the jet
  // is right.
  const double allowed = JetAgreement * rule.Tolerance * (error + estimate.Error);
  return !(difference > allowed);
}

/// Replaces `estimate` by the jet `near` of `neighbors`, of error `error`.
void TakeJet(const PointCurvature& near,
  const JetNeighbors& neighbors,
  double error,
  ScaleEstimate& estimate)
{
  PointCurvature& out = estimate.Fit.Curvature;
  out.MinimumCurvature = near.MinimumCurvature;
  out.MaximumCurvature = near.MaximumCurvature;
  out.MinimumDirection = near.MinimumDirection;
  out.MaximumDirection = near.MaximumDirection;
  out.FittedNormal = near.FittedNormal;
  // The neighbors, as the ladder counts them: the other points, those
  // strictly within the radius.
  out.NeighborCount = neighbors.Others;
  estimate.Radius = std::nextafter(neighbors.Radius, HUGE_VAL);
  estimate.Error = error;
  estimate.Jet = true;
}
} // namespace

void AutomaticScaleEstimator::PreferJet(const double* x,
  const TangentFrame& frame,
  double firstRadius,
  double roundingVariance,
  double ladderError,
  AutomaticScaleScratch& scratch,
  ScaleEstimate& estimate) const
{
  ShellPoints& neighbors = scratch.Jet;
  JetNeighbors jetNeighbors;
  if (!GatherJetNeighbors(
        scratch.Nearest, firstRadius, this->Rule.LargestRadius, neighbors, jetNeighbors))
  {
    return;
  }
  const std::size_t count = jetNeighbors.Count;
  const double radius = jetNeighbors.Radius;
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
  if (JetReplacesLadder(jet.Curvature, radius, error, ladderError, estimate, this->Rule))
  {
    TakeJet(jet.Curvature, jetNeighbors, error, estimate);
  }
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

} // namespace pcurv
