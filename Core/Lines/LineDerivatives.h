/**
 * @file LineDerivatives.h
 * @brief Per point: the derivatives of each principal curvature along its
 * own direction, from cubic least-squares fits of the neighbors'
 * curvatures (CurvatureFit.h). No VTK.
 *
 * A fit takes at least about a hundred points. Where the curvatures'
 * neighborhoods hold that many or more (every noisy cloud), nearby points
 * fit nearly the same samples: only anchor points (AnchorCells.h) fit,
 * and each point blends the fits of the anchors near it, evaluated at its
 * own position along its own directions. Elsewhere, and where no anchor
 * serves a point, it fits its own neighborhood.
 */
#ifndef LineDerivatives_h
#define LineDerivatives_h

#include "Lines/LineTypes.h"

#include <array>
#include <cstdint>
#include <vector>

namespace pcurv
{
class PointGrid;
class WorkRunner;

/// One principal curvature's extremality at a point, along the direction
/// Direction (d_max for k_max; n x d_max for k_min).
struct Extremality
{
  double Slope = 0.0;      ///< e = dk/dd
  double Bend = 0.0;       ///< d e / d d (negative at a maximum)
  double SlopeError = 0.0; ///< standard error of Slope
  /// The least |d e / d d| an extremum needs here (LineSettings::RelativeBend).
  double BendFloor = 0.0;
  /// Whether Bend stands out of its standard error where the curvatures
  /// differ (directions are defined).
  bool Significant = false;
  std::array<double, 3> Direction{ { 0.0, 0.0, 0.0 } };
  std::array<double, 3> Tangent{ { 0.0, 0.0, 0.0 } }; ///< of the zero set of e
};

/// What the crossings need of every point.
struct PointDerivatives
{
  std::vector<Extremality> Maximum, Minimum; ///< of k_max, of k_min
  std::vector<unsigned char> Fitted;         ///< 1 where the fit held
  std::vector<double> Radius;
  /// Each point's GraphNeighbors nearest points (-1 fills), nearest first.
  std::vector<std::int64_t> Graph;
  int GraphWidth = 0;
};

/// The radius of a point's fit: `fitRadius` (its neighborhood radius times
/// LineSettings::FitRadius), grown to hold about MinimumFitPoints where
/// its GraphNeighbors nearest points, within `graphReach`, say it holds
/// fewer.
double GrownFitRadius(double fitRadius, double graphReach, const LineSettings& settings);

/// Fits every point of `input` over its neighbors in `grid` (built on
/// input.Points).
PointDerivatives FitDerivatives(const LineInput& input,
  const LineSettings& settings,
  const PointGrid& grid,
  WorkRunner* runner);

} // namespace pcurv

#endif
