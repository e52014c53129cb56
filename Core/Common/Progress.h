/**
 * @file Progress.h
 * @brief How the core's stages report: the caller's progress monitor with
 * its stop request, and a stage's share of the whole, counted in finished
 * items from any thread. No VTK.
 */
#ifndef Progress_h
#define Progress_h

#include <atomic>
#include <cstdint>

namespace pcurv
{

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

} // namespace pcurv

#endif
