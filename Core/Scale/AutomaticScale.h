/**
 * @file AutomaticScale.h
 * @brief NeighborhoodMode::Automatic with OrientedCircles: per point, the
 * largest neighbourhood whose estimate agrees with those of the smaller
 * ones (Lepski's rule), and the anchors of shared fits (SharedFits.h) that
 * serve the points near them. No VTK.
 */
#ifndef AutomaticScale_h
#define AutomaticScale_h

#include "Cloud/CloudStatistics.h"
#include "Fits/OrientedCircleFit.h"
#include "Neighbors/PointGrid.h"
#include "Scale/SharedFits.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <vector>

namespace pcurv
{

/// NeighborhoodMode::Automatic: the radii tried at each point and the rule
/// that picks one (AutomaticScaleEstimator).
struct AutomaticScaleRule
{
  int BaseCount = 16;       // the first radius holds this many neighbours
  int Levels = 8;           // radii base 2^(i/2), i < Levels: about 2000 neighbours at most
  double Precision = 1e-3;  // a standard error this small (times the curvature) ends the growth
  int MinimumCount = 12;    // fewer neighbours give no estimate to compare
  double Tolerance = 2.0;   // standard errors two estimates may differ by
  double LargestRadius = 0; // no radius beyond this (a length)
  double TypicalRadius = 0; // the cloud's typical first radius (a length)
  bool ShareFits = false;   // points near an anchor take its fit (SharedFits.h)
  bool FourthOrder = false; // wide radii fit the surface's fourth order too
  /// Levels where the normals do not follow the surface (FourthOrder
  /// false): one radius more, about 4000 neighbours. Estimated normals are
  /// about as uncertain as the positions, so the ladder's band (the
  /// positions' standard error) is the estimate's own and shows the bias
  /// of a wider radius; where the normals follow the surface the combined
  /// fit is far more precise than that band, which hides the bias a wider
  /// radius adds.
  int WideLevels = 9;
  /// The coordinates' lattice step per axis (CoordinateSteps; 0: none):
  /// rounding to it is noise the positions' residual need not show (where
  /// a few neighbours round to one plane), so it floors their variance.
  std::array<double, 3> CoordinateStep{};
  SharingRule Sharing;

  /// The last radius of a ladder of `levels` radii from TypicalRadius.
  double LargestRadiusOf(int levels) const
  {
    return this->TypicalRadius * std::pow(2.0, 0.5 * (levels - 1));
  }

  /// A ladder of `levels` radii: Levels and the LargestRadius it reaches.
  void SetLevels(int levels)
  {
    this->Levels = levels;
    this->LargestRadius = this->LargestRadiusOf(levels);
  }
};

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

/// The anchors of a run with shared fits (SharedFits.h): which points they
/// are, in the grid's order, and their estimates once the first pass made
/// them. Own anchors are output; halo anchors serve own points near them.
struct AnchorTable
{
  AnchorCells Cells;
  std::vector<std::int64_t> Points;
  std::vector<AnchorFit> Fits;     // by position in Points
  std::vector<unsigned char> Kept; // by cloud point: 1 for the anchors in Points

  bool IsAnchor(std::int64_t point) const { return this->Kept[point] != 0; }

  /// Chooses the anchors (every eligible point of the cloud takes part, so
  /// each cell's choice is the same on every process) and keeps those an
  /// own point may ask for: in the cells around an own point's. Asks
  /// `keepGoing()` now and then; false when it said to stop.
  template<typename Eligible>
  bool Choose(const CloudPoints& cloud,
    const PointGrid& grid,
    const GridLattice& lattice,
    double cellSide,
    const Eligible& eligible,
    const std::function<bool()>& keepGoing)
  {
    const std::int64_t count = cloud.GetNumberOfPoints();
    // The grid's order keeps a cell's points together.
    const auto inGridOrder = [&](std::int64_t j) { return grid.GetSortedId(j); };
    if (!this->Cells.Build(cloud.Coordinates.data(),
          cloud.Normals.data(),
          count,
          inGridOrder,
          lattice.Origin.data(),
          cellSide,
          eligible,
          keepGoing))
    {
      return false;
    }
    std::vector<unsigned char>& needed = this->Kept;
    needed.assign(static_cast<std::size_t>(count), 0);
    if (count == cloud.NumberOfOwnPoints)
    {
      this->Cells.MarkEveryAnchor(needed); // no halo: every anchor is an own point
    }
    else
    {
      std::vector<std::int64_t> own;
      own.reserve(static_cast<std::size_t>(cloud.NumberOfOwnPoints));
      for (std::int64_t j = 0; j < count; ++j)
      {
        if (cloud.IsOwn(grid.GetSortedId(j)))
        {
          own.push_back(grid.GetSortedId(j));
        }
      }
      if (!this->Cells.MarkAnchorsAround(
            static_cast<std::int64_t>(own.size()),
            [&](std::int64_t j) { return own[static_cast<std::size_t>(j)]; },
            needed,
            keepGoing))
      {
        return false;
      }
    }
    for (std::int64_t j = 0; j < grid.GetNumberOfPoints(); ++j)
    {
      const std::int64_t point = grid.GetSortedId(j);
      if (needed[point])
      {
        this->Points.push_back(point);
      }
    }
    this->Cells.NumberAnchors(this->Points);
    this->Fits.resize(this->Points.size());
    return true;
  }

  /// Whether any anchor's fit may be shared (none on a noise-free cloud,
  /// where every radius is small): else the second pass skips the lookup.
  bool AnyShareable(const SharingRule& rule) const
  {
    return std::any_of(this->Fits.begin(),
      this->Fits.end(),
      [&](const AnchorFit& fit) { return fit.Valid && fit.Radius >= rule.MinimumRadius; });
  }
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
  ShellPoints Jet;
  AnchorCells::Around Anchors;
  std::vector<AnchorEstimate> NearbyAnchors;
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

  /// The neighbourhood grows from the BaseCount nearest by a factor of 2
  /// in count (sqrt 2 in radius), shell by shell into the same sums, and
  /// the largest radius is kept whose curvatures agree with those of every
  /// smaller radius within Tolerance times their standard errors (Lepski's
  /// rule): as long as the estimates agree, a larger neighbourhood only
  /// averages the noise out; once they part, the surface's shape (bias)
  /// has begun to show. A radius at which too many neighbours' normals
  /// oppose the point's stops the growth (the neighbourhood would reach
  /// across the surface).
  /// With FourthOrder, the radii from four first radii on fit the
  /// surface's fourth-order terms too. Where the growth stopped within the
  /// first radii (positions with little or no noise), a height jet of the
  /// nearest neighbours (HeightJet.h) replaces the estimate where its error
  /// is the smaller (PreferJet).
  ScaleEstimate Estimate(std::int64_t point, AutomaticScaleScratch& scratch) const;

  /// Whether the point's normal follows the surface as closely as exact
  /// normals of a noisy cloud do: at four first radii (about 256
  /// neighbours), the tilt the fit finds in it is within what the point's
  /// own displacement along the surface explains (the square of the tilt
  /// at most NormalTiltAllowance times its expected square). An estimated
  /// normal is off by its own error, several times more. 1: it follows,
  /// 0: it does not, -1: no fit there.
  int NormalFollowsSurface(std::int64_t point, AutomaticScaleScratch& scratch) const;

  /// The point's estimate from the anchors around it (in the cells' fixed
  /// order: the same on every process) that the sharing rule lets it blend;
  /// not valid where none does.
  SharedEstimate FromAnchors(std::int64_t point,
    const AnchorTable& anchors,
    AutomaticScaleScratch& scratch) const;

private:
  /// Replaces `estimate` by the height jet of the JetCount nearest
  /// neighbours where the jet's error (its standard error, inflated for
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

  /// The distance from `x` to its BaseCount-th nearest neighbour: the
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
  template<int Order>
  void AddShell(const ShellPoints& shell,
    double inverseUnit,
    OrientedCircleAccumulatorOf<Order>& sums) const
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

  /// Lepski's test: the principal curvatures agree with each smaller
  /// radius's within `tolerance` times the sum of their standard errors.
  static bool AgreesWithSmaller(const OrientedCircleResult& candidate,
    const std::vector<OrientedCircleResult>& smaller,
    double tolerance);

  const CloudPoints& Cloud;
  const PointGrid& Grid;
  AutomaticScaleRule Rule;
  FitSettings Settings;
};

} // namespace pcurv

#endif
