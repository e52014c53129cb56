/**
 * @file FilterProgress.h
 * @brief How the core's threads run under VTK and report to ParaView
 * (private to the module): vtkSMPTools threads, progress passed to the
 * filter's thread with the time left, and the filter's abort flag.
 */
#ifndef FilterProgress_h
#define FilterProgress_h

#include "Common/Progress.h"
#include "Common/TimeLeft.h"
#include "Common/WorkRunner.h"

#include <atomic>
#include <chrono>
#include <future>
#include <string>
#include <utility>

class vtkAlgorithm;

namespace pcurv
{

/// Progress from the core's threads, passed to a filter on the thread that
/// runs the filter: ParaView shows progress, and honors Abort, only from
/// there. The filter's abort flag travels back the same way. The filter's
/// progress text (what ParaView's progress bar shows) says the time left
/// (TimeLeftClock, Common/TimeLeft.h).
class AlgorithmProgress : public ProgressMonitor
{
public:
  AlgorithmProgress(vtkAlgorithm* algorithm, std::string label);
  /// From any thread: keeps the fraction; false once Pass saw an abort.
  bool Continue(double fraction) override;
  /// From the filter's thread: reports the newest fraction and the time
  /// left to the filter (a progress event even when the fraction has not
  /// moved, so that a GUI listening to them stays responsive), and reads
  /// its abort flag.
  void Pass();

private:
  vtkAlgorithm* Algorithm;
  std::string Label;
  std::chrono::steady_clock::time_point Start;
  TimeLeftClock Clock; // read and written by Pass alone
  std::atomic<double> Fraction{ 0.0 };
  std::atomic<bool> AbortRequested{ false };
};

/// `estimate()` (a whole estimation: its serial stages too, which take
/// seconds on millions of points) on a thread of its own, while the calling
/// thread, the filter's, passes `progress` on ten times a second: ParaView
/// then shows progress and honors Abort all along. For one process only:
/// a distributed run's collectives stay on the calling thread (MPI is
/// initialized for one thread), and it passes progress in the parallel
/// stages alone (SMPToolsRunner).
template<typename Estimate>
auto RunPassingProgress(AlgorithmProgress& progress, Estimate&& estimate)
{
  auto done = std::async(std::launch::async, std::forward<Estimate>(estimate));
  while (done.wait_for(std::chrono::milliseconds(100)) != std::future_status::ready)
  {
    progress.Pass();
  }
  progress.Pass();
  return done.get();
}

/// The core's work items on vtkSMPTools threads:
/// all cores unless the user chose otherwise (ParaView's bundled VTK
/// defaults to the sequential backend; STDThread is used then, unless a
/// backend was requested through the environment). With `progress`, the
/// calling thread only waits and passes the progress on, ten times a second
/// (null when the whole estimation runs in RunPassingProgress).
class SMPToolsRunner : public WorkRunner
{
public:
  explicit SMPToolsRunner(int maximumThreads, AlgorithmProgress* progress = nullptr)
    : MaximumThreads(maximumThreads)
    , Progress(progress)
  {
  }
  void For(std::int64_t count, std::int64_t grain, const RangeWork& work) override;

private:
  void RunParallel(std::int64_t count, std::int64_t grain, const RangeWork& work);

  int MaximumThreads;
  AlgorithmProgress* Progress;
};

} // namespace pcurv

#endif
