/**
 * @file ItemEstimation.h
 * @brief The estimation's work items and their estimator: how every point's
 * neighborhood is chosen (NeighborhoodRule), the order points are
 * processed in (ProcessingOrder), one point's estimate with its rule
 * (PointEstimator) and a range of items with progress (ItemEstimator).
 * Internal to CloudEstimation. No VTK.
 */
#ifndef ItemEstimation_h
#define ItemEstimation_h

#include "Cloud/CloudPoints.h"
#include "Common/Progress.h"
#include "Estimation/ResultStore.h"
#include "Fits/PrincipalCurvatureCore.h"
#include "Neighbors/PointGrid.h"
#include "Scale/AutomaticScale.h"
#include "Scale/DynamicAdjustment.h"
#include "Scale/SharedFits.h"

#include <cstdint>
#include <utility>
#include <vector>

namespace pcurv
{

/// A thread's reusable buffers for the estimation's work items.
struct EstimationScratch
{
  PointCurvatureEstimator Estimator;
  OrientedCircleEstimator OrientedEstimator;
  AutomaticScaleScratch Automatic;
  SharedFitScratch Shared;
  DynamicAdjustment Adjustment;
  std::vector<double> Distances;
  NeighborOffsets Neighbors;
  std::vector<std::pair<double, std::int64_t>> Ranked;
};

/// How neighborhoods and thresholds are chosen for every point.
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

/// The order in which points are processed: the grid's order (cell by cell,
/// by coordinates within a cell), which is global. With fixed thresholds a
/// work item is one own point; with the dynamic adjustment it is one block:
/// the points (own and halo) in one cell of a lattice of side BlockLength,
/// processed in that order, each block started afresh. Blocks are defined
/// in space, not by counting points, so neither the threads nor the split
/// among processes change them.
class ProcessingOrder
{
public:
  ProcessingOrder() = default;
  // Not copied: the order may point into its own list.
  ProcessingOrder(const ProcessingOrder&) = delete;
  ProcessingOrder& operator=(const ProcessingOrder&) = delete;

  /// DVA: block b is items [BlockStarts[b], BlockStarts[b+1]) of the order.
  std::vector<std::int64_t> BlockStarts;

  std::int64_t GetNumberOfItems() const
  {
    return this->BlockStarts.empty() ? this->Size
                                     : static_cast<std::int64_t>(this->BlockStarts.size()) - 1;
  }

  /// The cloud point index of the k-th point in the order.
  std::int64_t Point(std::int64_t k) const { return this->List[k]; }

  /// One item per own point, in the grid's order (read from the grid, which
  /// must outlive the order, when every point is own: no copy).
  void MakePointwise(const PointGrid& grid, const CloudPoints& cloud);
  /// One item per block of side `blockLength` with an own point.
  void MakeBlocks(const PointGrid& grid,
    const CloudPoints& cloud,
    const GridLattice& lattice,
    double blockLength);

private:
  /// Publishes Points as the order.
  void UsePoints();

  std::vector<std::int64_t> Points; // cloud point indices, unless the grid's are used
  const std::int64_t* List = nullptr;
  std::int64_t Size = 0;
};

/// One point's estimate with the rule, written to the results; shared by
/// all threads (each point written by one).
class PointEstimator
{
public:
  PointEstimator(const CloudPoints& cloud,
    const PointGrid& grid,
    const NeighborhoodRule& rule,
    const FitSettings& settings,
    const ResultStore& out);

  /// The anchors of shared fits, estimated already: where `shareable`, the
  /// other points look for anchors' fits to take, and those that took them
  /// are marked in `shared` (one per cloud point).
  void UseAnchors(const AnchorTable* table, bool shareable, unsigned char* shared);

  bool HasNormal(std::int64_t point) const
  {
    const double* n = &this->Cloud.Normals[3 * point];
    return n[0] != 0.0 || n[1] != 0.0 || n[2] != 0.0;
  }

  const CloudPoints& GetCloud() const { return this->Cloud; }
  const NeighborhoodRule& GetRule() const { return this->Rule; }
  bool Oriented() const { return this->Settings.Mode == FitMode::OrientedCircles; }
  void StoreUnestimated(std::int64_t point, UnestimatedReason reason) const
  {
    this->Out.StoreUnestimated(this->Cloud.InputId(point), reason);
  }
  /// The offsets of the neighbors within s into scratch.Neighbors.
  void Gather(const double* x, double s, EstimationScratch& scratch) const
  {
    this->Grid.GatherOffsetsWithinRadius(x, s, scratch.Neighbors);
  }
  /// Asks for the cache lines of a point's data, then of its results.
  void PrefetchInput(std::int64_t point) const;
  void PrefetchOutput(std::int64_t point) const;

  /// An own point with a fixed radius, k nearest or the automatic scale.
  void EstimateFixed(std::int64_t point, EstimationScratch& scratch);
  /// The paper's fits on the neighbors gathered in scratch.Neighbors.
  void EstimateGathered(std::int64_t point,
    double s,
    double p,
    EstimationScratch& scratch,
    int target = 0);
  /// FitMode::OrientedCircles: every neighbor within s, with its normal.
  void EstimateOriented(std::int64_t point,
    double s,
    double p,
    EstimationScratch& scratch,
    int target = 0);
  /// Marks (1) the points whose automatic-scale estimate is a height jet's
  /// in `marks` (one per cloud point), or nowhere (null).
  void MarkJetsIn(unsigned char* marks) { this->JetMarks = marks; }
  /// An anchor of the shared fits (its own point's results output).
  ScaleEstimate EstimateAnchor(std::int64_t point, EstimationScratch& scratch);

private:
  void StoreScaleEstimate(std::int64_t point, const ScaleEstimate& estimate) const;
  void EstimateAutomaticPoint(std::int64_t point, EstimationScratch& scratch);
  bool EstimateFromAnchors(std::int64_t point, EstimationScratch& scratch);

  const CloudPoints& Cloud;
  const PointGrid& Grid;
  NeighborhoodRule Rule;
  FitSettings Settings;
  const ResultStore& Out;
  AutomaticScaleEstimator Automatic;
  const AnchorTable* Anchors = nullptr; // the anchors, estimated already
  bool Shareable = false;               // some anchor's fit may be shared
  unsigned char* SharedMarks = nullptr;
  unsigned char* JetMarks = nullptr;
};

/// Estimates ranges of work items (points, or the adjustment's blocks) in
/// the processing order, reporting progress and stopping when asked.
class ItemEstimator
{
public:
  ItemEstimator(const ProcessingOrder& order, PointEstimator& points, StageProgress& progress)
    : Order(order)
    , Points(points)
    , Progress(progress)
  {
  }

  /// The first pass of shared fits: the anchors [begin, end) of `table`.
  void EstimateAnchors(std::int64_t begin,
    std::int64_t end,
    AnchorTable& table,
    EstimationScratch& scratch);

  /// The items [begin, end) of the processing order.
  void Estimate(std::int64_t begin, std::int64_t end, EstimationScratch& scratch);

private:
  void PrefetchAhead(std::int64_t item, std::int64_t end) const;
  void EstimateBlock(std::int64_t block, EstimationScratch& scratch);

  const ProcessingOrder& Order;
  PointEstimator& Points;
  StageProgress& Progress;
};

} // namespace pcurv

#endif
