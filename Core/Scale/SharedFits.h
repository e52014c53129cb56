/**
 * @file SharedFits.h
 * @brief One neighborhood fit serving the points near its center. No VTK.
 *
 * Where the automatic scale grows a neighborhood many spacings wide (every
 * noisy scan), the neighborhoods of nearby points are nearly the same set,
 * and so are their fits. OrientedCircles fits a surface over the query's
 * tangent plane: the sine's C, A, B are its second derivatives, the tilt
 * its slope, the cubic coefficients its third order, the height its level.
 * That surface can be evaluated at a nearby point's own position (its
 * slope, its shape operator there), and the cubic terms carry the change of
 * curvature over the offset. So only some points, the anchors, gather their
 * neighborhoods; the others take the fit of the nearest anchor when it is
 * close against the anchor's radius, and gather their own otherwise (small
 * radii: noise-free clouds, fine features).
 *
 * Anchors are chosen in space, not by counting points: one per cell of a
 * global lattice, the point nearest the cell's center. So the choice, and
 * every result, is the same for any thread count, split among processes
 * or input order.
 */
#ifndef SharedFits_h
#define SharedFits_h

#include "Cloud/CloudPoints.h"
#include "Fits/FitResults.h"
#include "Neighbors/AnchorCells.h"
#include "Neighbors/PointGrid.h"
#include "Scale/AutomaticScaleRule.h"

#include <algorithm>
#include <cstdint>
#include <functional>
#include <vector>

namespace pcurv
{

/// What a point near an anchor uses of the anchor's estimate (kept for
/// every anchor until the cloud is done; the rest of the estimate is
/// written out when made).
struct AnchorFit
{
  FittedSurface Surface;
  double Radius = 0.0; ///< the neighborhood's radius it was fitted over
  double Error = 0.0;  ///< its reported standard error
  double SineFitRms = 0.0;
  int NeighborCount = 0;
  int ValidDirections = 0;
  bool Valid = false; ///< its curvatures were estimated

  /// The part of `estimate` (fitted over `radius`, reported `error`) kept.
  static AnchorFit Of(const OrientedCircleResult& estimate, double radius, double error)
  {
    const PointCurvature& k = estimate.Curvature;
    return AnchorFit{
      estimate.Surface, radius, error, k.SineFitRms, k.NeighborCount, k.ValidDirections, k.Valid
    };
  }
};

/// An anchor's estimate, as a point near it may use it.
struct AnchorEstimate
{
  const AnchorFit* Fit = nullptr;
  const double* Position = nullptr;
  TangentFrame Frame{}; ///< the frame of the fit: MakeTangentFrame of the anchor's normal
};

/// A point's estimate from the anchors near it: the curvatures (output
/// sign, in 1/length), directions and fitted normal, the radius and the
/// reported standard error. Not valid where no anchor is near enough.
struct SharedEstimate
{
  PointCurvature Curvature;
  double Radius = 0.0;
  double Error = 0.0;
};

/// The fitted surfaces of the anchors near a point (at `x`, unit normal
/// `normal`), each evaluated at the point, blended with weights that fall
/// smoothly to zero at the rule's reach of each anchor: a partition of
/// unity, so the estimates vary continuously from point to point, and the
/// extrapolations of anchors on either side of the point partly cancel.
/// The anchors are used in the order given, which must not depend on the
/// thread or process (the sums are rounded in that order).
SharedEstimate EstimateFromAnchors(const std::vector<AnchorEstimate>& anchors,
  const double x[3],
  const double normal[3],
  const SharingRule& rule);

/// A thread's reusable buffers for the estimates from anchors.
struct SharedFitScratch
{
  AnchorCells::Around Anchors;
  std::vector<AnchorEstimate> NearbyAnchors;
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
  /// The estimate of point `point` of `cloud` (the cloud the table was
  /// chosen on) from the anchors around it (in the cells' fixed order: the
  /// same on every process) that the sharing rule lets it blend; not valid
  /// where none does.
  SharedEstimate EstimateAt(const CloudPoints& cloud,
    std::int64_t point,
    const SharingRule& rule,
    SharedFitScratch& scratch) const;

  bool AnyShareable(const SharingRule& rule) const
  {
    return std::any_of(this->Fits.begin(),
      this->Fits.end(),
      [&](const AnchorFit& fit) { return fit.Valid && fit.Radius >= rule.MinimumRadius; });
  }
};

} // namespace pcurv

#endif
