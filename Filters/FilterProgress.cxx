#include "FilterProgress.h"

#include "vtkSMPTools.h"
#include "vtkAlgorithm.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <future>
#include <string>
#include <utility>

namespace pcurv
{
namespace
{
struct RunnerFunctor
{
  const RangeWork& Run;

  void operator()(vtkIdType begin, vtkIdType end) { this->Run(begin, end); }
};
} // namespace

namespace
{
/// "35 s", "2 min", "1 h 5 min": coarse enough not to flicker, rounded up
/// below a minute (to 5 s) and to the nearest minute above.
std::string RoughDuration(double seconds)
{
  if (seconds < 57.5)
  {
    return std::to_string(5 * std::max(1, static_cast<int>(std::ceil(seconds / 5.0)))) + " s";
  }
  const long minutes = std::lround(seconds / 60.0);
  if (minutes < 60)
  {
    return std::to_string(minutes) + " min";
  }
  return std::to_string(minutes / 60) + " h " + std::to_string(minutes % 60) + " min";
}
} // namespace

std::string ProgressText(const std::string& label, double fraction, double elapsedSeconds)
{
  fraction = std::min(std::max(fraction, 0.0), 1.0);
  // Before a second has passed or 1 % is done, the pace says little (the
  // first stages are not the slowest).
  if (elapsedSeconds < 1.0 || fraction < 0.01 || fraction >= 1.0)
  {
    return label;
  }
  return label + ": about " + RoughDuration(elapsedSeconds * (1.0 - fraction) / fraction) + " left";
}

AlgorithmProgress::AlgorithmProgress(vtkAlgorithm* algorithm, std::string label)
  : Algorithm(algorithm)
  , Label(std::move(label))
  , Start(std::chrono::steady_clock::now())
{
}

bool AlgorithmProgress::Continue(double fraction)
{
  this->Fraction.store(fraction, std::memory_order_relaxed);
  return !this->AbortRequested.load(std::memory_order_relaxed);
}

void AlgorithmProgress::Pass()
{
  const double fraction = this->Fraction.load(std::memory_order_relaxed);
  const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - this->Start;
  this->Algorithm->SetProgressText(ProgressText(this->Label, fraction, elapsed.count()).c_str());
  this->Algorithm->UpdateProgress(fraction);
  if (this->Algorithm->GetAbortExecute())
  {
    this->AbortRequested.store(true, std::memory_order_relaxed);
  }
}

void SMPToolsRunner::RunParallel(std::int64_t count, std::int64_t grain, const RangeWork& work)
{
  RunnerFunctor functor{ work };
  std::string backend = vtkSMPTools::GetBackend();
  if (backend == "Sequential" && !std::getenv("VTK_SMP_BACKEND_IN_USE"))
  {
    backend = "STDThread";
  }
  vtkSMPTools::LocalScope(vtkSMPTools::Config{ this->MaximumThreads, backend, false },
    [&]() { vtkSMPTools::For(0, count, grain, functor); });
}

void SMPToolsRunner::For(std::int64_t count, std::int64_t grain, const RangeWork& work)
{
  if (!this->Progress)
  {
    this->RunParallel(count, grain, work);
    return;
  }
  std::future<void> done =
    std::async(std::launch::async, [&]() { this->RunParallel(count, grain, work); });
  while (done.wait_for(std::chrono::milliseconds(100)) != std::future_status::ready)
  {
    this->Progress->Pass();
  }
  done.get();
  this->Progress->Pass();
}

} // namespace pcurv
