#include "Estimation/CloudEstimation.h"
#include "Cloud/CloudStatistics.h"
#include "Cloud/Halo.h"
#include "Common/ScratchPool.h"
#include "Estimation/CloudNormals.h"
#include "Estimation/ItemEstimation.h"
#include "Estimation/RemoteCopies.h"
#include "Estimation/ResultStore.h"
#include "Outliers/SurfaceOutliers.h"

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
  WorkRunner& runner,
  EstimationSummary& summary)
{
  NeighborhoodRule rule;
  rule.KNearest = settings.Neighborhood == NeighborhoodMode::KNearest;
  rule.K = settings.NumberOfNeighbors;
  rule.Ratio = settings.PlaneDistanceRatio;
  rule.Adjusted = settings.DynamicAdjustment;
  // The automatic neighborhood is OrientedCircles' (the paper's fits need a
  // radius and a plane distance), and yields to thresholds the user fixed.
  if (!rule.Adjusted && settings.Neighborhood == NeighborhoodMode::Automatic &&
    settings.Mode == FitMode::OrientedCircles && settings.AutomaticThresholds)
  {
    rule.AutomaticScale = true;
    rule.Automatic.Tolerance = settings.AutomaticScaleTolerance;
    const double base = TypicalRadius(cloud, processes, boxes, rule.Automatic.BaseCount, &runner);
    rule.Automatic.TypicalRadius = base;
    rule.Automatic.SetLevels(rule.Automatic.Levels);
    rule.Radius = base; // reported as the used s: the typical first radius
    rule.PlaneDistance = 0.0;
    rule.CellRadius = 2.0 * base;
    // Which ladder a cloud gets is known only once its normals are (given
    // ones may be replaced): the halo reaches the longer one's radius.
    rule.Reach =
      rule.Automatic.LargestRadiusOf(std::max(rule.Automatic.Levels, rule.Automatic.WideLevels));
    // Sharing pays where neighborhoods are wide (four times the first
    // radius: 256 neighbors); smaller ones are cheap to fit.
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
  // The neighbor count the cloud's typical radius is measured for.
  const int typicalCount =
    rule.Adjusted ? static_cast<int>(summary.TargetNeighborCounts[0]) : settings.NumberOfNeighbors;
  const bool needsTypicalRadius =
    rule.Adjusted ? settings.AutomaticLengthUnit : (settings.AutomaticThresholds || rule.KNearest);
  const double typicalRadius =
    needsTypicalRadius ? TypicalRadius(cloud, processes, boxes, typicalCount, &runner) : 0.0;
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

/// Whether estimated normals follow the surface as exact normals of a noisy
/// cloud do (AutomaticScaleEstimator::NormalFollowsSurface), so that the
/// wide radii fit the fourth order too: at most of the points of the
/// cloud's spacing sample (the same points and counts for any split among
/// processes). Normals of a few nearest neighbors' planes share their
/// errors with their neighbors, and the fourth order's extra unknowns would
/// take those up: they fail. Normals whose scale grew with the noise pass
/// under light noise.
bool NormalsFollowTheSurface(const CloudPoints& cloud,
  const PointGrid& grid,
  const NeighborhoodRule& rule,
  const FitSettings& fit,
  const CloudBoxes& boxes,
  const Collectives& processes)
{
  const AutomaticScaleEstimator estimator(cloud, grid, rule.Automatic, fit);
  AutomaticScaleScratch scratch;
  const std::int64_t stride = std::max<std::int64_t>(1, boxes.BodyCount / 512);
  std::vector<std::int64_t> counts = { 0, 0 }; // following, tested
  for (std::int64_t i = 0; i < cloud.NumberOfOwnPoints; ++i)
  {
    if (InSpacingSample(&cloud.Coordinates[3 * i], boxes.Lower.data(), boxes.Upper.data(), stride))
    {
      const int follows = estimator.NormalFollowsSurface(i, scratch);
      counts[0] += follows > 0 ? 1 : 0;
      counts[1] += follows >= 0 ? 1 : 0;
    }
  }
  processes.Sum(counts);
  constexpr std::int64_t FewestTested = 16;
  return counts[1] >= FewestTested && 2 * counts[0] > counts[1];
}

/// The halo of `cloud` (distributed), the grid of its points and their
/// processing order.
void BuildGridAndOrder(CloudPoints& cloud,
  NeighborhoodRule& rule,
  const GridLattice& lattice,
  const EstimationRun& run,
  PointGrid& grid,
  ProcessingOrder& order)
{
  if (run.Processes.IsDistributed())
  {
    if (rule.KNearest)
    {
      rule.Reach = run.Processes.Max(LargestLocalKthDistance(cloud, lattice, rule.K));
    }
    ExchangeHalo(cloud, run.Processes, rule.Reach);
    RemoveRepeatedHalo(cloud);
  }
  grid.Build(cloud.Coordinates.data(), cloud.GetNumberOfPoints(), lattice, &run.Runner);
  if (rule.Adjusted)
  {
    order.MakeBlocks(grid, cloud, lattice, rule.BlockLength);
  }
  else
  {
    order.MakePointwise(grid, cloud);
  }
}

/// The automatic scale's choices that need the cloud's grid and normals:
/// the coordinates' lattice, whether the normals were estimated and follow
/// the surface (the fourth order), the normal field's fit and the levels.
void ChooseLadder(NeighborhoodRule& rule,
  const CloudPoints& cloud,
  const PointGrid& grid,
  const FitSettings& fit,
  const CloudBoxes& boxes,
  const EstimationSettings& settings,
  const EstimationRun& run,
  EstimationSummary& summary)
{
  // The lattice first: the gate's fits weigh the noise too.
  rule.Automatic.CoordinateStep = CoordinateSteps(cloud, grid, run.Processes);
  rule.Automatic.EstimatedNormals = settings.EstimateNormals || summary.GivenNormalsReplaced;
  rule.Automatic.FourthOrder = rule.Automatic.EstimatedNormals &&
    NormalsFollowTheSurface(cloud, grid, rule, fit, boxes, run.Processes);
  summary.FourthOrderFits = !rule.Automatic.EstimatedNormals || rule.Automatic.FourthOrder;
  rule.Automatic.NormalField = settings.NormalFieldFit && !rule.Automatic.EstimatedNormals;
  if (rule.Automatic.EstimatedNormals)
  {
    rule.Automatic.SetLevels(rule.Automatic.WideLevels);
  }
}

/// How many points of all processes `marks` marks.
std::int64_t CountMarked(const std::vector<unsigned char>& marks, const Collectives& processes)
{
  return processes.Sum(static_cast<std::int64_t>(
    std::count(marks.begin(), marks.end(), static_cast<unsigned char>(1))));
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
  const ResultStore& writer,
  EstimationSummary& summary)
{
  const GridLattice lattice = GlobalLattice(boxes, rule.CellRadius);
  PointGrid grid;
  ProcessingOrder order;
  BuildGridAndOrder(cloud, rule, lattice, run, grid, order);
  if (!ContinueBetweenSteps(run.Monitor, run.NormalsShare, run.Processes))
  {
    return false;
  }

  FitSettings fit;
  fit.Mode = settings.Mode;
  fit.MinimumPointsPerDirection = settings.MinimumPointsPerDirection;
  fit.MaximumOpposingFraction = settings.MaximumOpposingFraction;
  if (rule.AutomaticScale)
  {
    ChooseLadder(rule, cloud, grid, fit, boxes, settings, run, summary);
  }
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
  PointEstimator points(cloud, grid, rule, fit, writer);
  std::vector<unsigned char> jetMarks(rule.AutomaticScale ? cloud.GetNumberOfPoints() : 0, 0);
  points.MarkJetsIn(rule.AutomaticScale ? jetMarks.data() : nullptr);
  ItemEstimator anchorEstimator(order, points, anchorProgress);
  ScratchPool<EstimationScratch> scratches;
  run.Runner.For(static_cast<std::int64_t>(anchors.Points.size()),
    64,
    [&](std::int64_t begin, std::int64_t end)
    {
      const ScratchPool<EstimationScratch>::Lease scratch(scratches);
      anchorEstimator.EstimateAnchors(begin, end, anchors, *scratch);
    });
  StageProgress progress(run.Monitor,
    run.NormalsShare + anchorShare,
    1.0 - run.NormalsShare - anchorShare,
    order.GetNumberOfItems());
  std::vector<unsigned char> sharedMarks(shared ? cloud.GetNumberOfPoints() : 0, 0);
  const bool shareable = shared && anchors.AnyShareable(rule.Automatic.Sharing);
  points.UseAnchors(shared ? &anchors : nullptr, shareable, sharedMarks.data());
  ItemEstimator estimator(order, points, progress);
  if (!anchorProgress.Stopped())
  {
    run.Runner.For(order.GetNumberOfItems(),
      rule.Adjusted ? 1 : 1024,
      [&](std::int64_t begin, std::int64_t end)
      {
        const ScratchPool<EstimationScratch>::Lease scratch(scratches);
        estimator.Estimate(begin, end, *scratch);
      });
  }
  // Every process stops, or none: the steps after this one are collective.
  if (!run.Processes.Min(progress.Stopped() || anchorProgress.Stopped() ? 0 : 1))
  {
    return false;
  }
  summary.NumberOfSharedPoints = CountMarked(sharedMarks, run.Processes);
  summary.NumberOfJetPoints = CountMarked(jetMarks, run.Processes);
  return true;
}

/// The outlier flags and surface distances of the own points into their
/// buffers (every other input point, and every point when none were
/// looked for: not an outlier, no distance).
void StoreOutliers(const CurvatureBuffers& out,
  const CloudPoints& cloud,
  const SurfaceOutliers& outliers)
{
  const auto store = [&out](std::int64_t i, unsigned char flag, double distance)
  {
    if (out.Outlier)
    {
      out.Outlier[i] = flag;
    }
    if (out.SurfaceDistance)
    {
      out.SurfaceDistance.Set(i, distance);
    }
  };
  for (std::int64_t i = 0; i < cloud.GetNumberOfInputPoints(); ++i)
  {
    store(i, 0, NaN);
  }
  for (std::int64_t i = 0; i < static_cast<std::int64_t>(outliers.Flag.size()); ++i)
  {
    store(cloud.InputId(i), outliers.Flag[i], outliers.Distance[i]);
  }
}

/// The outliers moved onto the surface (where asked for) and their flags
/// stored; returns the repeats they made, taken out of `cloud`.
std::vector<RepeatedPoint> MoveOutliers(CloudPoints& cloud,
  const EstimationSettings& settings,
  const Collectives& processes,
  WorkRunner& runner,
  const CurvatureBuffers& out,
  RemoteCopies& remote,
  EstimationSummary& summary)
{
  SurfaceOutliers outliers;
  if (settings.MoveOutliers && settings.Mode == FitMode::OrientedCircles)
  {
    outliers = MoveOutliersOntoSurface(cloud, processes, runner);
    summary.NumberOfOutliers = outliers.Count;
  }
  if (out.Outlier || out.SurfaceDistance)
  {
    StoreOutliers(out, cloud, outliers);
  }
  // Outliers moved onto a point of the surface are its exact repeats (or,
  // that point in another process's part, take its results from there).
  remote.TakeOut(cloud, outliers);
  std::vector<RepeatedPoint> movedOutliers =
    outliers.Count > 0 ? RemoveRepeatedPoints(cloud) : std::vector<RepeatedPoint>{};
  remote.FindAnswers(cloud, processes);
  return movedOutliers;
}

/// The input points whose coordinates are not finite, stored as not
/// estimated; the cloud's flags of them released.
void StoreBadCoordinates(CloudPoints& cloud, const ResultStore& writer)
{
  for (std::int64_t i = 0; i < cloud.GetNumberOfInputPoints(); ++i)
  {
    if (!cloud.FiniteInput[i])
    {
      writer.StoreUnestimated(i, UnestimatedReason::BadCoordinate);
    }
  }
  cloud.ReleaseFiniteInput(); // not read again
}

/// The passes over every result at the end: the unestimated points'
/// counts, the input's unit, the clipped mean and the verdicts.
void FinishResults(const CurvatureBuffers& out,
  const std::uint8_t* reasons,
  std::int64_t numberOfPoints,
  const WorkingUnit& unit,
  const Collectives& processes,
  EstimationSummary& summary)
{
  summary.UnestimatedByReason = CountUnestimated(out, reasons, numberOfPoints);
  for (const std::int64_t count : summary.UnestimatedByReason)
  {
    summary.NumberOfUnestimatedPoints += count;
  }
  ToInputUnit(out, numberOfPoints, unit);
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
    WriteClippedMean(out, numberOfPoints, summary.MeanCurvatureClip);
  }
  const bool verdicts = out.Trusted || out.ShapeClass;
  if (processes.IsDistributed() ? processes.Max(verdicts ? 1.0 : 0.0) > 0.0 : verdicts)
  {
    summary.TrustedCurvatureScale = WriteTrustAndShape(out, numberOfPoints, processes);
  }
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
  // Before the normals, which they would pull too.
  RemoteCopies remote;
  const std::vector<RepeatedPoint> movedOutliers =
    MoveOutliers(cloud, settings, processes, runner, out, remote, summary);
  const double normalsShare =
    SettleNormals(cloud, settings, unit, processes, runner, monitor, out.Normals, summary);
  if (summary.Normals.Aborted)
  {
    summary.Aborted = true;
    return summary;
  }
  const CloudBoxes boxes = MeasureBoxes(cloud, processes);
  NeighborhoodRule rule =
    ChooseThresholds(settings, cloud, processes, boxes, unit, runner, summary);
  SummarizeThresholds(rule, unit, summary);
  if (!ContinueBetweenSteps(monitor, normalsShare, processes))
  {
    summary.Aborted = true;
    return summary;
  }

  const std::int64_t numberOfPoints = cloud.GetNumberOfInputPoints();
  std::vector<std::uint8_t> reasons(numberOfPoints, 0);
  const ResultStore writer(out, reasons.data(), settings.MinimumPointsPerDirection);
  StoreBadCoordinates(cloud, writer);
  const EstimationRun run{ processes, runner, monitor, normalsShare };
  if (!EstimateEveryPoint(std::move(cloud), rule, boxes, settings, run, writer, summary))
  {
    summary.Aborted = true;
    return summary;
  }
  for (const RepeatedPoint& moved : movedOutliers)
  {
    writer.Copy(moved.Original, moved.Copy, false);
  }
  remote.Deliver(writer, processes);
  for (const RepeatedPoint& repeat : repeats)
  {
    writer.Copy(repeat.Original, repeat.Copy);
  }
  FinishResults(out, reasons.data(), numberOfPoints, unit, processes, summary);
  return summary;
}

} // namespace pcurv
