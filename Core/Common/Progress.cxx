#include "Common/Progress.h"

#include <algorithm>

namespace pcurv
{

StageProgress::StageProgress(ProgressMonitor* monitor,
  double first,
  double share,
  std::int64_t items)
  : Monitor(monitor)
  , First(first)
  , Share(share)
  , Items(std::max<std::int64_t>(items, 1))
{
}

bool StageProgress::Advance(std::int64_t done)
{
  if (!this->Monitor || done <= 0)
  {
    return !this->Stopped();
  }
  const std::int64_t reached = this->Done.fetch_add(done, std::memory_order_relaxed) + done;
  return this->Reach(static_cast<double>(reached) / static_cast<double>(this->Items));
}

bool StageProgress::Reach(double fraction)
{
  if (this->Monitor &&
    !this->Monitor->Continue(this->First + this->Share * std::min(std::max(fraction, 0.0), 1.0)))
  {
    this->Stop.store(true, std::memory_order_relaxed);
  }
  return !this->Stopped();
}

} // namespace pcurv
