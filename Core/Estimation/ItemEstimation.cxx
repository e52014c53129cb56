#include "Estimation/ItemEstimation.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <tuple>

namespace pcurv
{
namespace
{
/// The block of a coordinate given in block lengths: its floor, within the
/// int64 range; 0 when it is NaN (a block length of 0, as when the cloud has
/// no typical radius: every point then shares one block).
std::int64_t BlockIndex(double blocks)
{
  constexpr double Limit = 9.0e18; // below 2^63
  if (!(blocks == blocks))
  {
    return 0;
  }
  return static_cast<std::int64_t>(std::floor(std::min(std::max(blocks, -Limit), Limit)));
}
} // namespace

void ProcessingOrder::UsePoints()
{
  this->List = this->Points.data();
  this->Size = static_cast<std::int64_t>(this->Points.size());
}

void ProcessingOrder::MakePointwise(const PointGrid& grid, const CloudPoints& cloud)
{
  if (cloud.NumberOfOwnPoints == grid.GetNumberOfPoints())
  {
    this->List = grid.GetSortedIds();
    this->Size = grid.GetNumberOfPoints();
    return;
  }
  for (std::int64_t j = 0; j < grid.GetNumberOfPoints(); ++j)
  {
    const std::int64_t point = grid.GetSortedId(j);
    if (cloud.IsOwn(point))
    {
      this->Points.push_back(point);
    }
  }
  this->UsePoints();
}

void ProcessingOrder::MakeBlocks(const PointGrid& grid,
  const CloudPoints& cloud,
  const GridLattice& lattice,
  double blockLength)
{
  using Key = std::tuple<std::int64_t, std::int64_t, std::int64_t>;
  std::vector<std::pair<Key, std::int64_t>> keyed; // (block, grid position)
  keyed.reserve(grid.GetNumberOfPoints());
  for (std::int64_t j = 0; j < grid.GetNumberOfPoints(); ++j)
  {
    const double* x = &cloud.Coordinates[3 * grid.GetSortedId(j)];
    std::array<std::int64_t, 3> b;
    for (int k = 0; k < 3; ++k)
    {
      b[k] = BlockIndex((x[k] - lattice.Origin[k]) / blockLength);
    }
    keyed.emplace_back(Key{ b[2], b[1], b[0] }, j);
  }
  std::sort(keyed.begin(), keyed.end());
  for (std::size_t first = 0; first < keyed.size();)
  {
    std::size_t last = first;
    bool hasOwn = false;
    while (last < keyed.size() && keyed[last].first == keyed[first].first)
    {
      hasOwn = hasOwn || cloud.IsOwn(grid.GetSortedId(keyed[last].second));
      ++last;
    }
    if (hasOwn) // blocks of halo points only are another process's work
    {
      this->BlockStarts.push_back(static_cast<std::int64_t>(this->Points.size()));
      for (std::size_t k = first; k < last; ++k)
      {
        this->Points.push_back(grid.GetSortedId(keyed[k].second));
      }
    }
    first = last;
  }
  this->BlockStarts.push_back(static_cast<std::int64_t>(this->Points.size()));
  this->UsePoints();
}

PointEstimator::PointEstimator(const CloudPoints& cloud,
  const PointGrid& grid,
  const NeighborhoodRule& rule,
  const FitSettings& settings,
  const ResultStore& out)
  : Cloud(cloud)
  , Grid(grid)
  , Rule(rule)
  , Settings(settings)
  , Out(out)
  , Automatic(cloud, grid, rule.Automatic, settings)
{
}

void PointEstimator::UseAnchors(const AnchorTable* table, bool shareable, unsigned char* shared)
{
  this->Anchors = table;
  this->Shareable = shareable;
  this->SharedMarks = shared;
}

void PointEstimator::PrefetchInput(std::int64_t point) const
{
  if (!this->Cloud.InputIds.empty())
  {
    __builtin_prefetch(&this->Cloud.InputIds[point]);
  }
  __builtin_prefetch(&this->Cloud.Coordinates[3 * point]);
  __builtin_prefetch(&this->Cloud.Normals[3 * point]);
}

void PointEstimator::PrefetchOutput(std::int64_t point) const
{
  this->Out.Prefetch(this->Cloud.InputId(point));
}

void PointEstimator::EstimateFixed(std::int64_t point, EstimationScratch& scratch)
{
  if (!this->HasNormal(point))
  {
    this->Out.StoreUnestimated(this->Cloud.InputId(point), UnestimatedReason::NoNormal);
    return;
  }
  if (this->Rule.AutomaticScale)
  {
    this->EstimateAutomaticPoint(point, scratch);
    return;
  }
  const double* x = &this->Cloud.Coordinates[3 * point];
  double s = this->Rule.Radius;
  if (this->Rule.KNearest)
  {
    // k + 1: the point itself is found too (and then ignored).
    s = std::sqrt(this->Grid.SquaredDistanceToKth(x, this->Rule.K + 1, scratch.Distances));
    s = std::nextafter(s, HUGE_VAL); // the query keeps distances < s
  }
  // A fixed p of 0 stays 0: every point is then flagged, never silently
  // estimated with some other p.
  const double p = this->Rule.FixedPlaneDistance ? this->Rule.PlaneDistance : this->Rule.Ratio * s;
  if (this->Settings.Mode == FitMode::OrientedCircles)
  {
    this->EstimateOriented(point, s, p, scratch);
    return;
  }
  this->Grid.GatherOffsetsWithinRadius(x, s, scratch.Neighbors);
  this->EstimateGathered(point, s, p, scratch);
}

void PointEstimator::EstimateGathered(std::int64_t point,
  double s,
  double p,
  EstimationScratch& scratch,
  int target)
{
  const double* x = &this->Cloud.Coordinates[3 * point];
  const double* n = &this->Cloud.Normals[3 * point];
  PointCurvatureEstimator& estimator = scratch.Estimator;
  estimator.Begin({ { x[0], x[1], x[2] } }, { { n[0], n[1], n[2] } }, p, s);
  const NeighborOffsets& offsets = scratch.Neighbors;
  estimator.AddNeighborOffsets(
    offsets.Dx.data(), offsets.Dy.data(), offsets.Dz.data(), offsets.Count);
  this->Out.Store(this->Cloud.InputId(point), estimator.Estimate(this->Settings), s, p, target);
}

void PointEstimator::EstimateOriented(std::int64_t point,
  double s,
  double p,
  EstimationScratch& scratch,
  int target)
{
  const double* x = &this->Cloud.Coordinates[3 * point];
  const double* n = &this->Cloud.Normals[3 * point];
  OrientedCircleEstimator& estimator = scratch.OrientedEstimator;
  estimator.Begin({ { n[0], n[1], n[2] } }, s);
  this->Grid.ForEachWithinRadius(x,
    s,
    [&](const double* q, std::int64_t id)
    {
      const double offset[3] = { q[0] - x[0], q[1] - x[1], q[2] - x[2] };
      estimator.AddNeighbor(offset, &this->Cloud.Normals[3 * id]);
    });
  const OrientedCircleResult result = estimator.Estimate(
    this->Settings.MinimumPointsPerDirection, this->Settings.MaximumOpposingFraction);
  this->Out.Store(this->Cloud.InputId(point),
    result.Curvature,
    s,
    p,
    target,
    ReportedStandardError(result, nullptr, this->Rule.Automatic.Precision));
}

ScaleEstimate PointEstimator::EstimateAnchor(std::int64_t point, EstimationScratch& scratch)
{
  ScaleEstimate estimate = this->Automatic.Estimate(point, scratch.Automatic);
  if (this->Cloud.IsOwn(point))
  {
    this->StoreScaleEstimate(point, estimate);
  }
  return estimate;
}

void PointEstimator::StoreScaleEstimate(std::int64_t point, const ScaleEstimate& estimate) const
{
  if (estimate.Jet && this->JetMarks)
  {
    this->JetMarks[point] = 1;
  }
  this->Out.Store(
    this->Cloud.InputId(point), estimate.Fit.Curvature, estimate.Radius, 0.0, 0, estimate.Error);
}

/// An anchor's estimate is stored already; a point near an anchor whose
/// radius is wide takes its fit; any other gathers its own neighborhood.
void PointEstimator::EstimateAutomaticPoint(std::int64_t point, EstimationScratch& scratch)
{
  if (this->Anchors && this->Anchors->IsAnchor(point))
  {
    return;
  }
  if (this->Shareable && this->EstimateFromAnchors(point, scratch))
  {
    return;
  }
  this->StoreScaleEstimate(point, this->Automatic.Estimate(point, scratch.Automatic));
}

/// The anchors around the point whose fits the sharing rule lets it blend
/// (AnchorTable::EstimateAt).
bool PointEstimator::EstimateFromAnchors(std::int64_t point, EstimationScratch& scratch)
{
  const SharedEstimate shared =
    this->Anchors->EstimateAt(this->Cloud, point, this->Rule.Automatic.Sharing, scratch.Shared);
  if (!shared.Curvature.Valid)
  {
    return false;
  }
  this->Out.Store(
    this->Cloud.InputId(point), shared.Curvature, shared.Radius, 0.0, 0, shared.Error);
  this->SharedMarks[point] = 1;
  return true;
}

void ItemEstimator::EstimateAnchors(std::int64_t begin,
  std::int64_t end,
  AnchorTable& table,
  EstimationScratch& scratch)
{
  constexpr std::int64_t Batch = 64;
  std::int64_t pending = 0;
  for (std::int64_t item = begin; item < end; ++item)
  {
    if (this->Progress.Stopped())
    {
      return;
    }
    const ScaleEstimate estimate = this->Points.EstimateAnchor(table.Points[item], scratch);
    table.Fits[item] = AnchorFit::Of(estimate.Fit, estimate.Radius, estimate.Error);
    if (++pending == Batch)
    {
      this->Progress.Advance(pending);
      pending = 0;
    }
  }
  this->Progress.Advance(pending);
}

void ItemEstimator::Estimate(std::int64_t begin, std::int64_t end, EstimationScratch& scratch)
{
  // Points are reported in batches (a block of the adjustment at once),
  // which keeps the shared counter off the per-point path.
  const std::int64_t batch = this->Points.GetRule().Adjusted ? 1 : 256;
  std::int64_t pending = 0;
  for (std::int64_t item = begin; item < end; ++item)
  {
    if (this->Progress.Stopped())
    {
      return;
    }
    if (this->Points.GetRule().Adjusted)
    {
      this->EstimateBlock(item, scratch);
    }
    else
    {
      this->PrefetchAhead(item, end);
      this->Points.EstimateFixed(this->Order.Point(item), scratch);
    }
    if (++pending == batch)
    {
      this->Progress.Advance(pending);
      pending = 0;
    }
  }
  this->Progress.Advance(pending);
}

/// Points are processed in grid order, their data and results sit in input
/// order: where that is random, each point's reads and writes miss the
/// cache. Fetching a few points ahead hides it; two steps, since the output
/// position itself has to be read first.
void ItemEstimator::PrefetchAhead(std::int64_t item, std::int64_t end) const
{
  constexpr std::int64_t Inputs = 16, Outputs = 8;
  if (item + Inputs < end)
  {
    this->Points.PrefetchInput(this->Order.Point(item + Inputs));
  }
  if (item + Outputs < end)
  {
    this->Points.PrefetchOutput(this->Order.Point(item + Outputs));
  }
}

/// The paper's sequence within one block: s carries over from point to
/// point; the block's first point repeats its search with the adjusted s.
/// Halo points take part in the sequence (their neighbor counts steer s)
/// but are not estimated: another process outputs them.
void ItemEstimator::EstimateBlock(std::int64_t block, EstimationScratch& scratch)
{
  // Neighbors found, the point itself excluded (as the estimator counts).
  const auto neighborCount = [&scratch]()
  { return std::max(0, static_cast<int>(scratch.Neighbors.Count) - 1); };
  DynamicAdjustment& adjustment = scratch.Adjustment;
  adjustment = DynamicAdjustment(this->Points.GetRule().Adjustment);
  bool firstPoint = true;
  for (std::int64_t k = this->Order.BlockStarts[block]; k < this->Order.BlockStarts[block + 1]; ++k)
  {
    const std::int64_t point = this->Order.Point(k);
    const bool own = this->Points.GetCloud().IsOwn(point);
    if (!this->Points.HasNormal(point))
    {
      if (own)
      {
        this->Points.StoreUnestimated(point, UnestimatedReason::NoNormal);
      }
      continue;
    }
    const double* x = &this->Points.GetCloud().Coordinates[3 * point];
    double s = adjustment.GetSurroundingsThreshold();
    this->Points.Gather(x, s, scratch);
    if (firstPoint)
    {
      adjustment.Adjust(neighborCount());
      s = adjustment.GetSurroundingsThreshold();
      this->Points.Gather(x, s, scratch);
      firstPoint = false;
    }
    const int target = adjustment.GetTargetNeighborCount();
    const double p = adjustment.Adjust(neighborCount());
    if (own && this->Points.Oriented())
    {
      this->Points.EstimateOriented(point, s, p, scratch, target);
    }
    else if (own)
    {
      this->Points.EstimateGathered(point, s, p, scratch, target);
    }
  }
}

} // namespace pcurv
