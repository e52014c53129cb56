/**
 * @file WorkRunner.h
 * @brief How the core's parallel stages run and report: a thread's scratch
 * buffers, the progress monitor with its stop request, a stage's share of
 * the progress, and the runner that hands out ranges of work items to
 * threads (the caller's: VTK's SMP tools in the filter, plain threads in
 * the tests). Below both the curvatures (CloudEstimation.h) and the
 * normals (NormalEstimation.h), which use it. No VTK.
 */
#ifndef WorkRunner_h
#define WorkRunner_h

#include "AutomaticScale.h"
#include "DynamicAdjustment.h"
#include "OrientedCircleFit.h"
#include "PointGrid.h"
#include "PrincipalCurvatureCore.h"

#include <atomic>
#include <cstdint>
#include <functional>
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
  DynamicAdjustment Adjustment;
  std::vector<double> Distances;
  NeighborOffsets Neighbors;
  std::vector<std::pair<double, std::int64_t>> Ranked;
};

/// Told how far the work is (0 to 1); returns false to stop. Called from
/// any of the runner's threads, possibly from several at once: an
/// implementation must be thread-safe (the VTK glue stores the fraction for
/// the thread ParaView listens to, and reads its abort flag there).
class ProgressMonitor
{
public:
  virtual ~ProgressMonitor() = default;
  virtual bool Continue(double fraction) = 0;
};

/// One stage of the work, the part [first, first + share) of the whole,
/// counted in finished items from any thread; remembers a stop request.
class StageProgress
{
public:
  StageProgress(ProgressMonitor* monitor, double first, double share, std::int64_t items);
  /// `done` more items are finished; false once the monitor asked to stop.
  bool Advance(std::int64_t done);
  /// The part of the stage reached so far, `fraction` of it: for stages
  /// that are not counted in items.
  bool Reach(double fraction);
  bool Stopped() const { return this->Stop.load(std::memory_order_relaxed); }

private:
  ProgressMonitor* Monitor;
  double First, Share;
  std::int64_t Items;
  std::atomic<std::int64_t> Done{ 0 };
  std::atomic<bool> Stop{ false };
};

/// Runs the work items [0, count), possibly on several threads.
class WorkRunner
{
public:
  /// Estimates the items [begin, end) with a scratch no other thread uses
  /// meanwhile.
  using Work =
    std::function<void(std::int64_t begin, std::int64_t end, EstimationScratch& scratch)>;

  virtual ~WorkRunner() = default;
  /// Calls `work` on ranges of at least `grain` items (except the last)
  /// that together cover [0, count) once.
  virtual void For(std::int64_t count, std::int64_t grain, const Work& work) = 0;
};

/// The runner's ranges of at least `grain` items, for work that needs no
/// scratch (PointGrid::Build).
ParallelRanges RangesOf(WorkRunner& runner, std::int64_t grain);

/// All items in the calling thread.
class SerialRunner : public WorkRunner
{
public:
  void For(std::int64_t count, std::int64_t grain, const Work& work) override;
};

} // namespace pcurv

#endif
