/**
 * @file AutomaticScale.h
 * @brief NeighborhoodMode::Automatic with OrientedCircles: per point, the
 * largest neighborhood whose estimate agrees with those of the smaller
 * ones (Lepski's rule). The anchors of shared fits, which serve the points
 * near them, are in SharedFits.h. No VTK.
 */
#ifndef AutomaticScale_h
#define AutomaticScale_h

#include "Cloud/CloudPoints.h"
#include "Fits/NormalFieldFit.h"
#include "Fits/OrientedCircleFit.h"
#include "Neighbors/PointGrid.h"
#include "Scale/AutomaticScaleRule.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <vector>

namespace pcurv
{

/// The automatic scale's estimate at a point: the chosen radius's fit, the
/// radius (NaN when none was kept) and the reported standard error.
struct ScaleEstimate
{
  OrientedCircleResult Fit;
  double Radius = std::numeric_limits<double>::quiet_NaN();
  double Error = std::numeric_limits<double>::quiet_NaN();
  /// The estimate is a height jet's (AutomaticScaleEstimator::PreferJet).
  bool Jet = false;
};

/// The nearest points of the point being estimated (FirstRadius): every
/// point strictly within Radius (0: none gathered) in the grid's order,
/// their squared distances, and that of the JetCount-th nearest.
struct NearestPoints
{
  ShellPoints Points;
  std::vector<double> Squared;
  double Radius = 0.0;
  double JetCountSquared = 0.0;
  RankScratch Ranks;
};

/// A thread's reusable buffers for AutomaticScaleEstimator.
struct AutomaticScaleScratch
{
  OrientedCircleAccumulator Sums;
  QuarticCircleAccumulator QuarticSums;
  ShellPoints Shell;
  std::vector<double> Distances;
  NearestPoints Nearest;
  std::vector<OrientedCircleResult> Scales;
  /// The normal field's ladder: the radius waiting to judge wider ones.
  std::vector<OrientedCircleResult> Waiting;
  ShellPoints Jet;
  NormalFieldAccumulator Field;
  /// The offsets gathered so far (in units of the first radius), shell
  /// after shell: the points within any radius of the ladder lead.
  std::array<std::vector<double>, 3> Gathered;
};

/// Estimates points of a cloud with the automatic scale; one instance is
/// shared by all threads (each with its own scratch).
class AutomaticScaleEstimator
{
public:
  AutomaticScaleEstimator(const CloudPoints& cloud,
    const PointGrid& grid,
    const AutomaticScaleRule& rule,
    const FitSettings& settings)
    : Cloud(cloud)
    , Grid(grid)
    , Rule(rule)
    , Settings(settings)
  {
  }

  /// The neighborhood grows from the BaseCount nearest by a factor of 2
  /// in count (sqrt 2 in radius), shell by shell into the same sums, and
  /// the largest radius is kept whose curvatures agree with those of every
  /// smaller radius within Tolerance times their standard errors (Lepski's
  /// rule): as long as the estimates agree, a larger neighborhood only
  /// averages the noise out; once they part, the surface's shape (bias)
  /// has begun to show. A radius at which too many neighbors' normals
  /// oppose the point's stops the growth (the neighborhood would reach
  /// across the surface).
  /// Every radius fits the surface's fourth-order terms too (where the
  /// normals were estimated, from four first radii on and with FourthOrder
  /// only), and keeps the simplest order whose curvatures the richer
  /// orders' agree with, the second order included (SimplestOrder.h).
  /// Where the growth stopped within the first radii (positions with
  /// little or no noise), a height jet of the nearest neighbors
  /// (HeightJet.h) replaces the estimate where its error is the smaller
  /// (PreferJet).
  ScaleEstimate Estimate(std::int64_t point, AutomaticScaleScratch& scratch) const;

  /// Whether the point's normal follows the surface as closely as exact
  /// normals of a noisy cloud do: at four first radii (about 256
  /// neighbors), the tilt the fit finds in it is within what the point's
  /// own displacement along the surface explains (the square of the tilt
  /// at most NormalTiltAllowance times its expected square). An estimated
  /// normal is off by its own error, several times more. 1: it follows,
  /// 0: it does not, -1: no fit there.
  int NormalFollowsSurface(std::int64_t point, AutomaticScaleScratch& scratch) const;

  /// Lepski's test: the principal curvatures agree with each smaller
  /// radius's within `tolerance` times the sum of their standard errors,
  /// the wider radius's at no more noise than the smaller measured.
  static bool AgreesWithSmaller(const OrientedCircleResult& candidate,
    const std::vector<OrientedCircleResult>& smaller,
    double tolerance);

private:
  /// Estimate's ladder of oriented circles at one point.
  struct CircleLadder;

  /// Estimate's ladder with the fit of the normal field (NormalFieldFit.h)
  /// instead of the oriented circles, where the normals were given
  /// (AutomaticScaleRule::NormalField) and the positions are noisy: the
  /// same growth and Lepski's rule, the radii with few neighbors left out
  /// of the judging. False, with `estimate` untouched, where the positions'
  /// noise at the first radius is small against it: the circles' ladder is
  /// the better there.
  bool EstimateNormalField(std::int64_t point,
    AutomaticScaleScratch& scratch,
    ScaleEstimate& estimate) const;

  /// Replaces `estimate` by the height jet of the JetCount nearest
  /// neighbors where the jet's error (its standard error, inflated for
  /// the bias its residual does not show) is below `ladderError` (the
  /// ladder's reported error without the precision floor).
  /// `roundingVariance`: the coordinates' rounding along the normal.
  void PreferJet(const double* x,
    const TangentFrame& frame,
    double firstRadius,
    double roundingVariance,
    double ladderError,
    AutomaticScaleScratch& scratch,
    ScaleEstimate& estimate) const;

  /// The distance from `x` to its BaseCount-th nearest neighbor: the
  /// first radius of its ladder. Gathers the nearest points into the
  /// scratch's Nearest on the way, as many as the jet needs.
  double FirstRadius(const double* x, AutomaticScaleScratch& scratch) const;

  /// The ladder's shell of points with inner <= distance < radius into the
  /// scratch's Shell: the first (inner 0) from the nearest points where
  /// they hold it, else from the grid.
  void GatherLevel(const double* x,
    double inner,
    double radius,
    AutomaticScaleScratch& scratch) const;

  /// Adds the points of `shell` (offsets divided by the radius unit) with
  /// their normals to `sums`.
  template<typename Accumulator>
  void AddShell(const ShellPoints& shell, double inverseUnit, Accumulator& sums) const
  {
    constexpr std::size_t Ahead = 16; // the normals are scattered in memory
    for (std::size_t i = 0; i < shell.Count; ++i)
    {
      if (i + Ahead < shell.Count)
      {
        __builtin_prefetch(&this->Cloud.Normals[3 * shell.Ids[i + Ahead]]);
      }
      const double d[3] = {
        shell.Dx[i] * inverseUnit, shell.Dy[i] * inverseUnit, shell.Dz[i] * inverseUnit
      };
      sums.Add(d, &this->Cloud.Normals[3 * shell.Ids[i]]);
    }
  }

  const CloudPoints& Cloud;
  const PointGrid& Grid;
  AutomaticScaleRule Rule;
  FitSettings Settings;
};

} // namespace pcurv

#endif
