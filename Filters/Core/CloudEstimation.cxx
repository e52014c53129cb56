#include "CloudEstimation.h"
#include "ResultWriter.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <tuple>

namespace pcurv
{
namespace
{
constexpr double NaN = std::numeric_limits<double>::quiet_NaN();
/// A curvature is trusted when twice its reported standard error is within
/// this share of the cloud's curvature scale (WriteTrusted).
constexpr double TrustedErrorShare = 0.1;
/// A nearly flat cloud's curvature scale, times its median radius.
constexpr double FlatCloudCurvatureShare = 0.25;

/// How neighbourhoods and thresholds are chosen for every point.
struct NeighborhoodRule
{
  bool AutomaticScale = false; // per point, by AutomaticScaleRule
  AutomaticScaleRule Automatic;
  bool KNearest = false;
  int K = 0;
  double Radius = 0.0;             // RADIUS mode
  bool FixedPlaneDistance = false; // p = PlaneDistance, else Ratio times the radius
  double PlaneDistance = 0.0;
  double Ratio = 0.0;
  bool Adjusted = false; // dynamic variable adjustment instead of the above
  AdjustmentSettings Adjustment;
  double BlockLength = 0.0; // side of an adjustment block (a length)
  /// The radius the grid's cells are made for, and how far beyond its own
  /// points a process must see.
  double CellRadius = 0.0;
  double Reach = 0.0;
};

/// The adjustment's target counts within [1, 1e6] (NaN: 1): a count outside
/// it has no meaning, and beyond the int range it could not be reported in
/// Target_Neighbor_Count.
std::array<double, 3> UsableTargetCounts(const std::array<double, 3>& requested, bool& clamped)
{
  std::array<double, 3> counts = requested;
  clamped = false;
  for (double& count : counts)
  {
    const double usable = std::isnan(count) ? 1.0 : std::min(std::max(count, 1.0), 1e6);
    clamped = clamped || usable != count;
    count = usable;
  }
  return counts;
}

/// The rule of the dynamic adjustment: constants in the working unit, and
/// the blocks' size and reach.
void ChooseAdjustment(const EstimationSettings& settings,
  const WorkingUnit& unit,
  const std::array<double, 3>& targetCounts,
  double typicalRadius,
  NeighborhoodRule& rule)
{
  AdjustmentSettings& adjustment = rule.Adjustment;
  adjustment = settings.Adjustment;
  adjustment.TargetNeighborCounts = targetCounts;
  const double initial = settings.Adjustment.InitialSurroundingsThreshold;
  adjustment.MaximumSurroundingsThreshold = settings.MaximumSurroundingsFactor * initial;
  // Scale free: the initial s holds about the first target count.
  adjustment.LengthUnit =
    settings.AutomaticLengthUnit ? typicalRadius / initial : unit.FromInput(settings.LengthUnit);
  rule.CellRadius = adjustment.LengthUnit * initial;
  rule.BlockLength = settings.AdjustmentBlockLength * adjustment.LengthUnit;
  // A block's points, and every query they make.
  rule.Reach = std::sqrt(3.0) * rule.BlockLength +
    adjustment.MaximumSurroundingsThreshold * adjustment.LengthUnit;
}

/// The thresholds for every point from the settings and, where automatic,
/// from the cloud (global in a parallel run).
NeighborhoodRule ChooseThresholds(const EstimationSettings& settings,
  const CloudPoints& cloud,
  const Collectives& processes,
  const CloudBoxes& boxes,
  const WorkingUnit& unit,
  EstimationSummary& summary)
{
  NeighborhoodRule rule;
  rule.KNearest = settings.Neighborhood == NeighborhoodMode::KNearest;
  rule.K = settings.NumberOfNeighbors;
  rule.Ratio = settings.PlaneDistanceRatio;
  rule.Adjusted = settings.DynamicAdjustment;
  // The automatic neighbourhood is OrientedCircles' (the paper's fits need a
  // radius and a plane distance), and yields to thresholds the user fixed.
  if (!rule.Adjusted && settings.Neighborhood == NeighborhoodMode::Automatic &&
    settings.Mode == FitMode::OrientedCircles && settings.AutomaticThresholds)
  {
    rule.AutomaticScale = true;
    rule.Automatic.Tolerance = settings.AutomaticScaleTolerance;
    const double base = TypicalRadius(cloud, processes, boxes, rule.Automatic.BaseCount);
    rule.Automatic.LargestRadius = base * std::pow(2.0, 0.5 * (rule.Automatic.Levels - 1));
    rule.Automatic.TypicalRadius = base;
    rule.Radius = base; // reported as the used s: the typical first radius
    rule.PlaneDistance = 0.0;
    rule.CellRadius = 2.0 * base;
    rule.Reach = rule.Automatic.LargestRadius;
    // Sharing pays where neighbourhoods are wide (four times the first
    // radius: 256 neighbours); smaller ones are cheap to fit.
    rule.Automatic.Sharing.MinimumRadius = 4.0 * base;
    const double anchorCell = rule.Automatic.Sharing.CellFactor * base;
    rule.Automatic.ShareFits = settings.ShareFits && anchorCell > 0.0 && std::isfinite(anchorCell);
    if (rule.Automatic.ShareFits)
    {
      // A point's anchor is at most two cells away on each axis, and needs
      // the largest radius around it; every point of those cells decides
      // which one is the anchor (within three cells).
      rule.Reach += 2.0 * std::sqrt(3.0) * anchorCell;
    }
    return rule;
  }
  if (rule.Adjusted)
  {
    summary.TargetNeighborCounts =
      UsableTargetCounts(settings.Adjustment.TargetNeighborCounts, summary.TargetCountsClamped);
  }
  // The neighbour count the cloud's typical radius is measured for.
  const int typicalCount =
    rule.Adjusted ? static_cast<int>(summary.TargetNeighborCounts[0]) : settings.NumberOfNeighbors;
  const bool needsTypicalRadius =
    rule.Adjusted ? settings.AutomaticLengthUnit : (settings.AutomaticThresholds || rule.KNearest);
  const double typicalRadius =
    needsTypicalRadius ? TypicalRadius(cloud, processes, boxes, typicalCount) : 0.0;
  rule.CellRadius = typicalRadius;
  if (rule.Adjusted)
  {
    ChooseAdjustment(settings, unit, summary.TargetNeighborCounts, typicalRadius, rule);
    return rule;
  }
  if (!settings.AutomaticThresholds)
  {
    rule.FixedPlaneDistance = true;
    rule.PlaneDistance = unit.FromInput(settings.PlaneDistanceThreshold);
    rule.Radius = unit.FromInput(settings.SurroundingsThreshold);
  }
  else if (!rule.KNearest)
  {
    rule.Radius = typicalRadius;
    rule.PlaneDistance = settings.PlaneDistanceRatio * rule.Radius;
  }
  if (!rule.KNearest)
  {
    rule.CellRadius = rule.Radius;
    rule.Reach = rule.Radius;
  }
  return rule;
}

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

/// The order in which points are processed: the grid's order (cell by cell,
/// by coordinates within a cell), which is global. With fixed thresholds a
/// work item is one own point; with the dynamic adjustment it is one block:
/// the points (own and halo) in one cell of a lattice of side BlockLength,
/// processed in that order, each block started afresh. Blocks are defined
/// in space, not by counting points, so neither the threads nor the split
/// among processes change them.
struct ProcessingOrder
{
  std::vector<std::int64_t> Points;      // cloud point indices
  std::vector<std::int64_t> BlockStarts; // DVA: block b is Points[BlockStarts[b], BlockStarts[b+1])

  std::int64_t GetNumberOfItems() const
  {
    return this->BlockStarts.empty() ? static_cast<std::int64_t>(this->Points.size())
                                     : static_cast<std::int64_t>(this->BlockStarts.size()) - 1;
  }

  void MakePointwise(const PointGrid& grid, const CloudPoints& cloud)
  {
    for (std::int64_t j = 0; j < grid.GetNumberOfPoints(); ++j)
    {
      const std::int64_t point = grid.GetSortedId(j);
      if (cloud.IsOwn(point))
      {
        this->Points.push_back(point);
      }
    }
  }

  void MakeBlocks(const PointGrid& grid,
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
  }
};

/// Estimates the work items; one instance is shared by all threads, each
/// point written by one thread.
class ItemEstimator
{
public:
  ItemEstimator(const CloudPoints& cloud,
    const PointGrid& grid,
    const ProcessingOrder& order,
    const NeighborhoodRule& rule,
    const FitSettings& settings,
    const ResultWriter& out,
    StageProgress& progress)
    : Cloud(cloud)
    , Grid(grid)
    , Order(order)
    , Rule(rule)
    , Settings(settings)
    , Out(out)
    , Progress(progress)
    , Automatic(cloud, grid, rule.Automatic, settings)
  {
  }

  /// The first pass of shared fits: the anchors [begin, end) of `table`,
  /// own ones output.
  void EstimateAnchors(std::int64_t begin,
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
      const std::int64_t point = table.Points[item];
      table.Estimates[item] = this->Automatic.Estimate(point, scratch.Automatic);
      if (this->Cloud.IsOwn(point))
      {
        this->StoreScaleEstimate(point, table.Estimates[item]);
      }
      if (++pending == Batch)
      {
        this->Progress.Advance(pending);
        pending = 0;
      }
    }
    this->Progress.Advance(pending);
  }

  /// The second pass of shared fits: the anchors are estimated already;
  /// where `shareable`, the other points look for anchors' fits to take,
  /// and those that took them are marked in `shared` (one per cloud point).
  void UseAnchors(const AnchorTable* table, bool shareable, unsigned char* shared)
  {
    this->Anchors = table;
    this->Shareable = shareable;
    this->SharedMarks = shared;
  }

  void Estimate(std::int64_t begin, std::int64_t end, EstimationScratch& scratch)
  {
    // Points are reported in batches (a block of the adjustment at once),
    // which keeps the shared counter off the per-point path.
    const std::int64_t batch = this->Rule.Adjusted ? 1 : 256;
    std::int64_t pending = 0;
    for (std::int64_t item = begin; item < end; ++item)
    {
      if (this->Progress.Stopped())
      {
        return;
      }
      if (this->Rule.Adjusted)
      {
        this->EstimateBlock(item, scratch);
      }
      else
      {
        this->PrefetchAhead(item, end);
        this->EstimateFixed(this->Order.Points[item], scratch);
      }
      if (++pending == batch)
      {
        this->Progress.Advance(pending);
        pending = 0;
      }
    }
    this->Progress.Advance(pending);
  }

private:
  /// Points are processed in grid order, their data and results sit in
  /// input order: where that is random, each point's reads and writes miss
  /// the cache. Fetching a few points ahead hides it; two steps, since the
  /// output position itself has to be read first.
  void PrefetchAhead(std::int64_t item, std::int64_t end) const
  {
    constexpr std::int64_t Inputs = 16, Outputs = 8;
    if (item + Inputs < end)
    {
      const std::int64_t point = this->Order.Points[item + Inputs];
      __builtin_prefetch(&this->Cloud.InputIds[point]);
      __builtin_prefetch(&this->Cloud.Coordinates[3 * point]);
      __builtin_prefetch(&this->Cloud.Normals[3 * point]);
    }
    if (item + Outputs < end)
    {
      this->Out.Prefetch(this->Cloud.InputIds[this->Order.Points[item + Outputs]]);
    }
  }

  bool HasNormal(std::int64_t point) const
  {
    const double* n = &this->Cloud.Normals[3 * point];
    return n[0] != 0.0 || n[1] != 0.0 || n[2] != 0.0;
  }

  void EstimateFixed(std::int64_t point, EstimationScratch& scratch)
  {
    if (!this->HasNormal(point))
    {
      this->Out.StoreUnestimated(this->Cloud.InputIds[point], UnestimatedReason::NoNormal);
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
    const double p =
      this->Rule.FixedPlaneDistance ? this->Rule.PlaneDistance : this->Rule.Ratio * s;
    if (this->Settings.Mode == FitMode::OrientedCircles)
    {
      this->EstimateOriented(point, s, p, scratch);
      return;
    }
    this->Grid.GatherOffsetsWithinRadius(x, s, scratch.Neighbors);
    this->EstimateGathered(point, s, p, scratch);
  }

  /// The paper's sequence within one block: s carries over from point to
  /// point; the block's first point repeats its search with the adjusted s.
  /// Halo points take part in the sequence (their neighbour counts steer s)
  /// but are not estimated: another process outputs them.
  void EstimateBlock(std::int64_t block, EstimationScratch& scratch)
  {
    DynamicAdjustment& adjustment = scratch.Adjustment;
    adjustment = DynamicAdjustment(this->Rule.Adjustment);
    bool firstPoint = true;
    for (std::int64_t k = this->Order.BlockStarts[block]; k < this->Order.BlockStarts[block + 1];
         ++k)
    {
      const std::int64_t point = this->Order.Points[k];
      if (!this->HasNormal(point))
      {
        if (this->Cloud.IsOwn(point))
        {
          this->Out.StoreUnestimated(this->Cloud.InputIds[point], UnestimatedReason::NoNormal);
        }
        continue;
      }
      const double* x = &this->Cloud.Coordinates[3 * point];
      double s = adjustment.GetSurroundingsThreshold();
      this->Grid.GatherOffsetsWithinRadius(x, s, scratch.Neighbors);
      if (firstPoint)
      {
        adjustment.Adjust(NeighborCount(scratch));
        s = adjustment.GetSurroundingsThreshold();
        this->Grid.GatherOffsetsWithinRadius(x, s, scratch.Neighbors);
        firstPoint = false;
      }
      const int target = adjustment.GetTargetNeighborCount();
      const double p = adjustment.Adjust(NeighborCount(scratch));
      if (this->Cloud.IsOwn(point) && this->Settings.Mode == FitMode::OrientedCircles)
      {
        this->EstimateOriented(point, s, p, scratch, target);
      }
      else if (this->Cloud.IsOwn(point))
      {
        this->EstimateGathered(point, s, p, scratch, target);
      }
    }
  }

  /// Neighbours found, the point itself excluded (as the estimator counts).
  static int NeighborCount(const EstimationScratch& scratch)
  {
    return std::max(0, static_cast<int>(scratch.Neighbors.Count) - 1);
  }

  void EstimateGathered(std::int64_t point,
    double s,
    double p,
    EstimationScratch& scratch,
    int target = 0)
  {
    const double* x = &this->Cloud.Coordinates[3 * point];
    const double* n = &this->Cloud.Normals[3 * point];
    PointCurvatureEstimator& estimator = scratch.Estimator;
    estimator.Begin({ { x[0], x[1], x[2] } }, { { n[0], n[1], n[2] } }, p, s);
    const NeighborOffsets& offsets = scratch.Neighbors;
    estimator.AddNeighborOffsets(
      offsets.Dx.data(), offsets.Dy.data(), offsets.Dz.data(), offsets.Count);
    this->Out.Store(this->Cloud.InputIds[point], estimator.Estimate(this->Settings), s, p, target);
  }

  /// FitMode::OrientedCircles: every neighbour within s, with its normal.
  void EstimateOriented(std::int64_t point,
    double s,
    double p,
    EstimationScratch& scratch,
    int target = 0)
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
    this->Out.Store(this->Cloud.InputIds[point],
      result.Curvature,
      s,
      p,
      target,
      ReportedStandardError(result, nullptr, this->Rule.Automatic.Precision));
  }

  void StoreScaleEstimate(std::int64_t point, const ScaleEstimate& estimate) const
  {
    this->Out.Store(
      this->Cloud.InputIds[point], estimate.Fit.Curvature, estimate.Radius, 0.0, 0, estimate.Error);
  }

  /// An own point with the automatic scale: an anchor's estimate is stored
  /// already; a point near an anchor whose radius is wide takes its fit;
  /// any other gathers its own neighbourhood.
  void EstimateAutomaticPoint(std::int64_t point, EstimationScratch& scratch)
  {
    if (this->Anchors && this->Anchors->EstimateOf[point] >= 0)
    {
      return;
    }
    if (this->Shareable && this->EstimateFromAnchors(point, scratch))
    {
      return;
    }
    this->StoreScaleEstimate(point, this->Automatic.Estimate(point, scratch.Automatic));
  }

  /// The anchors around the point whose fits the sharing rule lets it
  /// blend (AutomaticScaleEstimator::FromAnchors).
  bool EstimateFromAnchors(std::int64_t point, EstimationScratch& scratch)
  {
    const SharedEstimate shared =
      this->Automatic.FromAnchors(point, *this->Anchors, scratch.Automatic);
    if (!shared.Curvature.Valid)
    {
      return false;
    }
    this->Out.Store(
      this->Cloud.InputIds[point], shared.Curvature, shared.Radius, 0.0, 0, shared.Error);
    this->SharedMarks[point] = 1;
    return true;
  }

  const CloudPoints& Cloud;
  const PointGrid& Grid;
  const ProcessingOrder& Order;
  NeighborhoodRule Rule;
  FitSettings Settings;
  const ResultWriter& Out;
  StageProgress& Progress;
  AutomaticScaleEstimator Automatic;
  const AnchorTable* Anchors = nullptr; // the anchors, estimated already
  bool Shareable = false;               // some anchor's fit may be shared
  unsigned char* SharedMarks = nullptr;
};

/// CurvatureBuffers::Trusted from the reported standard errors, in the
/// input's unit; returns the cloud's curvature scale it used. Collective:
/// every process calls it when any has the buffer.
double WriteTrusted(const CurvatureBuffers& out,
  std::int64_t numberOfPoints,
  const Collectives& processes)
{
  std::vector<double> largest(static_cast<std::size_t>(numberOfPoints), NaN);
  std::vector<double> radii(static_cast<std::size_t>(numberOfPoints), NaN);
  for (std::int64_t i = 0; i < numberOfPoints; ++i)
  {
    if (out.Valid[i])
    {
      largest[i] = std::max(std::fabs(out.Minimum.Get(i)), std::fabs(out.Maximum.Get(i)));
      radii[i] = out.Surroundings.Get(i);
    }
  }
  // The curvatures that matter in this cloud: its large ones, or, where it
  // is (nearly) flat, a bending its typical neighbourhood resolves well (a
  // quarter of one over its radius: a larger share would let the errors of
  // gently curved parts, which take large radii, pass as trusted).
  const double typicalRadius = MagnitudeQuantile(radii.data(), numberOfPoints, 0.5, processes);
  const double scale = std::max(MagnitudeQuantile(largest.data(), numberOfPoints, 0.95, processes),
    typicalRadius > 0.0 ? FlatCloudCurvatureShare / typicalRadius : 0.0);
  for (std::int64_t i = 0; i < numberOfPoints; ++i)
  {
    const double error = out.StandardError ? out.StandardError.Get(i) : NaN;
    out.Trusted[i] = out.Valid[i] && 2.0 * error <= TrustedErrorShare * scale ? 1 : 0;
  }
  return scale;
}

/// The used thresholds of the summary, in the input's unit.
void SummarizeThresholds(const NeighborhoodRule& rule,
  const WorkingUnit& unit,
  EstimationSummary& summary)
{
  if (rule.Adjusted)
  {
    summary.UsedLengthUnit = unit.ToInputLength(rule.Adjustment.LengthUnit);
  }
  else if (!rule.KNearest)
  {
    summary.UsedSurroundingsThreshold = unit.ToInputLength(rule.Radius);
    summary.UsedPlaneDistanceThreshold = unit.ToInputLength(rule.PlaneDistance);
  }
}
} // namespace

namespace
{
/// Replaces the normals of the own points of `cloud` by estimated ones
/// (writing them to out.Normals too). Distributed, every process estimates
/// the whole cloud, gathered, and keeps its own part: the grid's order, not
/// the split, decides the result. Reported to `monitor` as the part [0,
/// share) of the whole: the plane fits (most of the time) counted, the
/// orientation at the end; Aborted when any process was asked to stop
/// (every process then stops: what follows is collective).
NormalSummary ReplaceNormals(CloudPoints& cloud,
  const NormalSettings& settings,
  const Collectives& processes,
  WorkRunner& runner,
  ProgressMonitor* monitor,
  double share,
  const RealBuffer& out)
{
  CloudPoints whole;
  std::int64_t first = 0;
  if (processes.IsDistributed())
  {
    std::vector<std::int64_t> lengths;
    whole.Coordinates = processes.Gather(std::vector<double>(cloud.Coordinates.begin(),
                                           cloud.Coordinates.begin() + 3 * cloud.NumberOfOwnPoints),
      &lengths);
    whole.NumberOfOwnPoints = static_cast<std::int64_t>(whole.Coordinates.size() / 3);
    for (int p = 0; p < processes.GetLocalProcessId(); ++p)
    {
      first += lengths[p] / 3;
    }
  }
  const CloudPoints& estimated = processes.IsDistributed() ? whole : cloud;
  StageProgress planes(monitor, 0.0, 0.8 * share, estimated.NumberOfOwnPoints);
  // The cloud's own normals are unknown until estimated (not read by the
  // estimate): released meanwhile, they are not part of its peak memory.
  std::vector<double>().swap(cloud.Normals);
  std::vector<double> normals;
  NormalSummary summary = EstimateNormals(estimated, settings, runner, normals, &planes);
  summary.Aborted =
    !processes.Min(planes.Stopped() ? 0 : 1) || !StageProgress(monitor, 0.0, share, 1).Reach(1.0);
  cloud.DropHalo(); // the normals back, zero
  if (!normals.empty())
  {
    std::copy_n(normals.begin() + 3 * first, 3 * cloud.NumberOfOwnPoints, cloud.Normals.begin());
  }
  if (out)
  {
    for (std::int64_t i = 0; i < 3 * cloud.GetNumberOfInputPoints(); ++i)
    {
      out.Set(i, 0.0);
    }
    for (std::int64_t i = 0; i < cloud.NumberOfOwnPoints; ++i)
    {
      out.SetRange(3 * cloud.InputIds[i], &cloud.Normals[3 * i], 3);
    }
  }
  return summary;
}

} // namespace

NormalSummary EstimateCloudNormals(CloudPoints cloud,
  const NormalSettings& settings,
  const Collectives& processes,
  WorkRunner& runner,
  const RealBuffer& out,
  ProgressMonitor* monitor)
{
  const std::vector<RepeatedPoint> repeats = RemoveRepeatedPoints(cloud);
  const double scale = WorkingLengthScale(cloud, processes);
  cloud.ScaleCoordinates(scale);
  NormalSettings scaled = settings;
  for (double& c : scaled.Viewpoint)
  {
    c *= scale;
  }
  const NormalSummary summary = ReplaceNormals(cloud, scaled, processes, runner, monitor, 1.0, out);
  for (const RepeatedPoint& repeat : repeats)
  {
    if (out)
    {
      out.CopyRange(3 * repeat.Original, 3 * repeat.Copy, 3);
    }
  }
  return summary;
}

namespace
{
/// Between the serial steps of an estimation (each up to a second or so on
/// a million points): false once the monitor asks to stop, on any process
/// (all of them ask here, in the same order: what follows is collective).
/// `reached` is the part already reported: the progress does not move.
bool ContinueBetweenSteps(ProgressMonitor* monitor, double reached, const Collectives& processes)
{
  const bool local = !monitor || monitor->Continue(reached);
  return processes.IsDistributed() ? processes.Min(local ? 1 : 0) == 1 : local;
}
} // namespace

const char* UnestimatedReasonName(UnestimatedReason reason)
{
  switch (reason)
  {
    case UnestimatedReason::BadCoordinate:
      return "Bad_Coordinate";
    case UnestimatedReason::NoNormal:
      return "No_Normal";
    case UnestimatedReason::TooFewNeighbors:
      return "Too_Few_Neighbors";
    case UnestimatedReason::TooFewDirections:
      return "Too_Few_Directions";
    case UnestimatedReason::ReachesAcross:
      return "Reaches_Across_Surface";
    case UnestimatedReason::FitFailed:
      return "Fit_Failed";
    default:
      return "None";
  }
}

namespace
{
/// Who runs an estimation and whom it tells, for its steps.
struct EstimationRun
{
  const Collectives& Processes;
  WorkRunner& Runner;
  ProgressMonitor* Monitor;
  double NormalsShare; // the part of the progress the normals took
};

/// The anchors of the shared fits (serial: Abort is asked for along the
/// way, and every process agrees on it afterwards, their loops differing
/// in length). False when stopped on some process.
bool ChooseAnchors(AnchorTable& anchors,
  const CloudPoints& cloud,
  const PointGrid& grid,
  const GridLattice& lattice,
  const NeighborhoodRule& rule,
  const EstimationRun& run)
{
  const bool chosen = anchors.Choose(
    cloud,
    grid,
    lattice,
    rule.Automatic.Sharing.CellFactor * rule.Automatic.TypicalRadius,
    [&](std::int64_t point)
    {
      const double* n = &cloud.Normals[3 * point];
      return n[0] != 0.0 || n[1] != 0.0 || n[2] != 0.0;
    },
    [&]() { return !run.Monitor || run.Monitor->Continue(run.NormalsShare); });
  const bool everyProcessGoesOn =
    run.Processes.IsDistributed() ? run.Processes.Min(chosen ? 1 : 0) == 1 : chosen;
  return everyProcessGoesOn && ContinueBetweenSteps(run.Monitor, run.NormalsShare, run.Processes);
}

/// The estimation proper, on the working copy `cloud` (consumed: it, its
/// grid and the anchors are freed on return, before the passes over the
/// results, which on large clouds would otherwise add to the peak memory).
/// False when stopped on some process.
bool EstimateEveryPoint(CloudPoints cloud,
  NeighborhoodRule& rule,
  const CloudBoxes& boxes,
  const EstimationSettings& settings,
  const EstimationRun& run,
  const ResultWriter& writer,
  EstimationSummary& summary)
{
  const GridLattice lattice = GlobalLattice(boxes, rule.CellRadius);
  if (run.Processes.IsDistributed())
  {
    if (rule.KNearest)
    {
      rule.Reach = run.Processes.Max(LargestLocalKthDistance(cloud, lattice, rule.K));
    }
    ExchangeHalo(cloud, run.Processes, rule.Reach);
    RemoveRepeatedHalo(cloud);
  }
  PointGrid grid;
  grid.Build(cloud.Coordinates.data(), cloud.GetNumberOfPoints(), lattice);
  ProcessingOrder order;
  if (rule.Adjusted)
  {
    order.MakeBlocks(grid, cloud, lattice, rule.BlockLength);
  }
  else
  {
    order.MakePointwise(grid, cloud);
  }
  if (!ContinueBetweenSteps(run.Monitor, run.NormalsShare, run.Processes))
  {
    return false;
  }

  FitSettings fit;
  fit.Mode = settings.Mode;
  fit.MinimumPointsPerDirection = settings.MinimumPointsPerDirection;
  fit.MaximumOpposingFraction = settings.MaximumOpposingFraction;
  // With shared fits the anchors come first, and take most of the time.
  AnchorTable anchors;
  const bool shared = rule.AutomaticScale && rule.Automatic.ShareFits;
  if (shared && !ChooseAnchors(anchors, cloud, grid, lattice, rule, run))
  {
    return false;
  }
  const double anchorShare = shared ? 0.7 * (1.0 - run.NormalsShare) : 0.0;
  StageProgress anchorProgress(
    run.Monitor, run.NormalsShare, anchorShare, static_cast<std::int64_t>(anchors.Points.size()));
  ItemEstimator anchorEstimator(cloud, grid, order, rule, fit, writer, anchorProgress);
  run.Runner.For(static_cast<std::int64_t>(anchors.Points.size()),
    64,
    [&](std::int64_t begin, std::int64_t end, EstimationScratch& scratch)
    { anchorEstimator.EstimateAnchors(begin, end, anchors, scratch); });
  StageProgress progress(run.Monitor,
    run.NormalsShare + anchorShare,
    1.0 - run.NormalsShare - anchorShare,
    order.GetNumberOfItems());
  ItemEstimator estimator(cloud, grid, order, rule, fit, writer, progress);
  std::vector<unsigned char> sharedMarks(shared ? cloud.GetNumberOfPoints() : 0, 0);
  const bool shareable = shared && anchors.AnyShareable(rule.Automatic.Sharing);
  estimator.UseAnchors(shared ? &anchors : nullptr, shareable, sharedMarks.data());
  if (!anchorProgress.Stopped())
  {
    run.Runner.For(order.GetNumberOfItems(),
      rule.Adjusted ? 1 : 1024,
      [&](std::int64_t begin, std::int64_t end, EstimationScratch& scratch)
      { estimator.Estimate(begin, end, scratch); });
  }
  // Every process stops, or none: the steps after this one are collective.
  if (!run.Processes.Min(progress.Stopped() || anchorProgress.Stopped() ? 0 : 1))
  {
    return false;
  }
  summary.NumberOfSharedPoints = run.Processes.Sum(static_cast<std::int64_t>(
    std::count(sharedMarks.begin(), sharedMarks.end(), static_cast<unsigned char>(1))));
  return true;
}
} // namespace

EstimationSummary EstimateCloud(CloudPoints cloud,
  const EstimationSettings& settings,
  const Collectives& processes,
  WorkRunner& runner,
  ProgressMonitor* monitor,
  const CurvatureBuffers& out)
{
  EstimationSummary summary;
  const std::vector<RepeatedPoint> repeats = RemoveRepeatedPoints(cloud);
  summary.NumberOfRepeatedPoints = static_cast<std::int64_t>(repeats.size());
  const WorkingUnit unit{ WorkingLengthScale(cloud, processes) };
  cloud.ScaleCoordinates(unit.Scale);
  // The normals' plane fits cost about as much as the curvatures, their
  // orientation a little more; the shares of the progress bar follow.
  const double normalsShare = settings.EstimateNormals ? 0.45 : 0.0;
  if (settings.EstimateNormals)
  {
    NormalSettings normals = settings.Normals;
    for (double& c : normals.Viewpoint)
    {
      c *= unit.Scale;
    }
    summary.Normals =
      ReplaceNormals(cloud, normals, processes, runner, monitor, normalsShare, out.Normals);
    if (summary.Normals.Aborted)
    {
      summary.Aborted = true;
      return summary;
    }
  }
  const CloudBoxes boxes = MeasureBoxes(cloud, processes);
  NeighborhoodRule rule = ChooseThresholds(settings, cloud, processes, boxes, unit, summary);
  SummarizeThresholds(rule, unit, summary);
  if (!ContinueBetweenSteps(monitor, normalsShare, processes))
  {
    summary.Aborted = true;
    return summary;
  }

  const std::int64_t numberOfPoints = cloud.GetNumberOfInputPoints();
  std::vector<std::uint8_t> reasons(numberOfPoints, 0);
  const ResultWriter writer(out, reasons.data(), settings.MinimumPointsPerDirection);
  for (std::int64_t i = 0; i < numberOfPoints; ++i)
  {
    if (!cloud.FiniteInput[i])
    {
      writer.StoreUnestimated(i, UnestimatedReason::BadCoordinate);
    }
  }
  const EstimationRun run{ processes, runner, monitor, normalsShare };
  if (!EstimateEveryPoint(std::move(cloud), rule, boxes, settings, run, writer, summary))
  {
    summary.Aborted = true;
    return summary;
  }
  for (const RepeatedPoint& repeat : repeats)
  {
    writer.Copy(repeat.Original, repeat.Copy);
  }
  summary.UnestimatedByReason = writer.CountUnestimated(numberOfPoints);
  for (const std::int64_t count : summary.UnestimatedByReason)
  {
    summary.NumberOfUnestimatedPoints += count;
  }
  writer.ToInputUnit(numberOfPoints, unit);
  // Computed when asked for by any process (the quantile is collective; an
  // empty piece has no buffer).
  const bool clipped = processes.IsDistributed() ? processes.Max(out.ClippedMean ? 1.0 : 0.0) > 0.0
                                                 : static_cast<bool>(out.ClippedMean);
  if (clipped)
  {
    summary.MeanCurvatureClip = MagnitudeQuantile(out.Mean, numberOfPoints, 0.95, processes);
  }
  if (out.ClippedMean)
  {
    writer.WriteClippedMean(numberOfPoints, summary.MeanCurvatureClip);
  }
  const bool trusted = processes.IsDistributed() ? processes.Max(out.Trusted ? 1.0 : 0.0) > 0.0
                                                 : out.Trusted != nullptr;
  if (trusted)
  {
    summary.TrustedCurvatureScale = WriteTrusted(out, numberOfPoints, processes);
  }
  return summary;
}

} // namespace pcurv
