#include "Scale/SimplestOrder.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

namespace pcurv
{
namespace
{
/// AgreesWithRicher's tolerance: two standard errors of the two fits'
/// difference, each the combined fit's covariance's inflated as the
/// reported error's.
constexpr double OrderTolerance = 2.0 * CombinedErrorFactor;
/// AgreesWithRicher's tolerance where the normals were estimated: two of the
/// positions-only fits' standard errors of the difference, which need no
/// inflation.
constexpr double EstimatedOrderTolerance = 2.0;

/// Whether `simpler` agrees with `richer`, a fit of more unknowns of the
/// same neighbors, within what the richer's extra unknowns add to the error
/// (the standard error of their difference: of nested least squares, the
/// root of the difference of their variances).
bool AgreesWithRicher(const OrientedCircleResult& simpler,
  const OrientedCircleResult& richer,
  bool estimatedNormals)
{
  // Estimated normals share their errors with their neighbors, so the
  // combined fit's covariance overstates its precision; the positions'
  // rows are independent, and their errors judge the difference.
  const double simplerError =
    estimatedNormals ? simpler.StandardError : simpler.CombinedStandardError;
  const double richerError = estimatedNormals ? richer.StandardError : richer.CombinedStandardError;
  const double difference =
    std::sqrt(std::max(0.0, richerError * richerError - simplerError * simplerError));
  const double allowed = (estimatedNormals ? EstimatedOrderTolerance : OrderTolerance) * difference;
  return std::fabs(simpler.Curvature.MinimumCurvature - richer.Curvature.MinimumCurvature) <=
    allowed &&
    std::fabs(simpler.Curvature.MaximumCurvature - richer.Curvature.MaximumCurvature) <= allowed;
}

/// Of fits of the same neighbors by more and more unknowns (the second
/// order's first, then the third's and the fourth's), the simplest valid
/// one that agrees with every richer valid one (AgreesWithRicher), so the
/// richest valid one where none simpler does; where none is valid, the
/// third order's (its reason is the one reported). The extra unknowns cost
/// precision: on a sphere, which has no fourth-order terms beyond its
/// circles', the fourth order's error is about twice the third's at the
/// same radius; where the neighborhood is one-sided (a boundary), the
/// cubic's columns are nearly those of the curvatures and the tilt, and the
/// third order's error is many times the second's.
template<std::size_t Count>
const OrientedCircleResult& Simplest(const std::array<const OrientedCircleResult*, Count>& fits,
  bool estimatedNormals)
{
  for (std::size_t i = 0; i < Count; ++i)
  {
    bool agrees = fits[i]->Curvature.Valid;
    for (std::size_t j = i + 1; j < Count && agrees; ++j)
    {
      agrees = !fits[j]->Curvature.Valid || AgreesWithRicher(*fits[i], *fits[j], estimatedNormals);
    }
    if (agrees)
    {
      return *fits[i];
    }
  }
  return *fits[1];
}

} // namespace

template<int Order>
bool FitSimplestOrder(OrientedCircleAccumulatorOf<Order>& accumulator,
  const TangentFrame& frame,
  double inverseUnit,
  double roundingVariance,
  const FitSettings& settings,
  bool estimatedNormals,
  OrientedCircleResult& result)
{
  const OrientedCircleSumsOf<Order>& sums = accumulator.Sums();
  if (sums.ReachesAcross(settings.MaximumOpposingFraction))
  {
    return false;
  }
  auto fit = [&](const auto& part)
  {
    return FitOrientedCircles(part,
      frame,
      inverseUnit,
      roundingVariance,
      settings.MinimumPointsPerDirection,
      settings.MaximumOpposingFraction,
      Order == 4);
  };
  const OrientedCircleResult second = fit(LowerOrderPart<2>(sums));
  if constexpr (Order == 4)
  {
    const OrientedCircleResult fourth = fit(sums);
    const OrientedCircleResult third = fit(ThirdOrderPart(sums));
    result = Simplest<3>({ &second, &third, &fourth }, estimatedNormals);
  }
  else
  {
    const OrientedCircleResult third = fit(sums);
    result = Simplest<2>({ &second, &third }, estimatedNormals);
  }
  return true;
}

template bool FitSimplestOrder<3>(OrientedCircleAccumulator&,
  const TangentFrame&,
  double,
  double,
  const FitSettings&,
  bool,
  OrientedCircleResult&);
template bool FitSimplestOrder<4>(QuarticCircleAccumulator&,
  const TangentFrame&,
  double,
  double,
  const FitSettings&,
  bool,
  OrientedCircleResult&);
} // namespace pcurv
