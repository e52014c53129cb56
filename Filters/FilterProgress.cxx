#include "FilterProgress.h"

#include "vtkSMPTools.h"
#include "vtkAlgorithm.h"

#include <chrono>
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
  this->Algorithm->SetProgressText(
    this->Clock.Text(this->Label, fraction, elapsed.count()).c_str());
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
