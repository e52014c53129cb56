#include "AutomaticScale.h"

#include <cmath>

namespace pcurv
{

ScaleEstimate AutomaticScaleEstimator::Estimate(std::int64_t point,
  AutomaticScaleScratch& scratch) const
{
  const double* x = &this->Cloud.Coordinates[3 * point];
  const double* n = &this->Cloud.Normals[3 * point];
  const AutomaticScaleRule& rule = this->Rule;
  // k + 1: the point itself is found too.
  const double base =
    std::sqrt(this->Grid.SquaredDistanceToKth(x, rule.BaseCount + 1, scratch.Distances));
  const double unit = std::nextafter(std::min(base, rule.LargestRadius), HUGE_VAL);
  const double inverseUnit = 1.0 / unit;
  const TangentFrame frame = MakeTangentFrame({ { n[0], n[1], n[2] } });
  OrientedCircleAccumulator& accumulator = scratch.Sums;
  accumulator.Begin(frame);
  OrientedCircleResult chosen;
  double chosenRadius = std::numeric_limits<double>::quiet_NaN();
  std::vector<OrientedCircleResult>& accepted = scratch.Scales;
  accepted.clear();
  UnestimatedReason reason = UnestimatedReason::TooFewNeighbors;
  double inner = 0.0;
  for (int level = 0; level < rule.Levels; ++level)
  {
    const double r = std::min(unit * std::pow(2.0, 0.5 * level), rule.LargestRadius);
    // The inner radii's neighbours are in the sums already.
    const ShellPoints& shell = scratch.Shell;
    this->Grid.GatherShell(x, inner, r, scratch.Shell);
    for (std::size_t i = 0; i < shell.Count; ++i)
    {
      const double d[3] = {
        shell.Dx[i] * inverseUnit, shell.Dy[i] * inverseUnit, shell.Dz[i] * inverseUnit
      };
      accumulator.Add(d, &this->Cloud.Normals[3 * shell.Ids[i]]);
    }
    inner = r;
    const OrientedCircleSums& sums = accumulator.Sums();
    if (sums.ReachesAcross(this->Settings.MaximumOpposingFraction))
    {
      reason = UnestimatedReason::ReachesAcross;
      break;
    }
    const OrientedCircleResult result = FitOrientedCircles(sums,
      frame,
      1.0 / unit,
      this->Settings.MinimumPointsPerDirection,
      this->Settings.MaximumOpposingFraction);
    reason = result.Curvature.Valid
      ? UnestimatedReason::TooFewNeighbors
      : UnestimatedReasonOf(result.Curvature, this->Settings.MinimumPointsPerDirection);
    if (result.Curvature.Valid && sums.Neighbors >= rule.MinimumCount)
    {
      if (!AgreesWithSmaller(result, accepted, rule.Tolerance))
      {
        break;
      }
      accepted.push_back(result);
      chosen = result;
      chosenRadius = r;
      // More neighbours would not change the estimate measurably: done.
      const double magnitude = std::max({ std::fabs(result.Curvature.MinimumCurvature),
        std::fabs(result.Curvature.MaximumCurvature),
        1.0 / r });
      if (result.StandardError < rule.Precision * magnitude)
      {
        break;
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
  // the estimate: the bias it may have added.
  const OrientedCircleResult* previous =
    accepted.size() >= 2 ? &accepted[accepted.size() - 2] : nullptr;
  return ScaleEstimate{
    chosen, chosenRadius, ReportedStandardError(chosen, previous, rule.Precision)
  };
}

SharedEstimate AutomaticScaleEstimator::FromAnchors(std::int64_t point,
  const AnchorTable& anchors,
  AutomaticScaleScratch& scratch) const
{
  const double* x = &this->Cloud.Coordinates[3 * point];
  std::vector<AnchorEstimate>& nearby = scratch.NearbyAnchors;
  // Points in the grid's order mostly share their cell with the one
  // before: the anchors around it, with their frames, are made once.
  if (anchors.Cells.AnchorsAround(x, scratch.Anchors))
  {
    nearby.clear();
    for (const std::int64_t position : scratch.Anchors.Anchors)
    {
      const std::int64_t anchor = anchors.Points[position];
      const double* n = &this->Cloud.Normals[3 * anchor];
      nearby.push_back(AnchorEstimate{ &anchors.Fits[position],
        &this->Cloud.Coordinates[3 * anchor],
        MakeTangentFrame({ { n[0], n[1], n[2] } }) });
    }
  }
  return EstimateFromAnchors(nearby, x, &this->Cloud.Normals[3 * point], this->Rule.Sharing);
}

bool AutomaticScaleEstimator::AgreesWithSmaller(const OrientedCircleResult& candidate,
  const std::vector<OrientedCircleResult>& smaller,
  double tolerance)
{
  for (const OrientedCircleResult& other : smaller)
  {
    const double allowed = tolerance * (candidate.StandardError + other.StandardError);
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
